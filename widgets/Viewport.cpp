#include "widgets/Viewport.h"

#include "widgets/SceneStyle.h"

#include <QMouseEvent>
#include <QWheelEvent>
#include <QWidget>

#include <algorithm>
#include <cmath>

namespace palpate {

QString rendererName(RendererKind kind) {
    return kind == RendererKind::OpenGL ? QStringLiteral("OpenGL") : QStringLiteral("software");
}

void Viewport::setMesh(const TissueMesh& mesh) {
    mScene.setMesh(mesh);
    mCamera.reset(mScene.positionsMm());
    sceneChanged(true);
}

void Viewport::clearMesh() {
    mScene.clear();
    sceneChanged(true);
}

void Viewport::setSnapshot(const SceneSnapshot& snapshot) {
    mScene.setSnapshot(snapshot);
    sceneChanged(false);
}

void Viewport::setWireframe(bool on) {
    mWireframe = on;
    sceneChanged(false);
}

void Viewport::setShowRestGhost(bool on) {
    mShowRestGhost = on;
    sceneChanged(false);
}

std::optional<VertexId> Viewport::pickVertex(QPoint pixel) {
    return pickVertexAt(QPointF(pixel) + QPointF(0.5, 0.5), widget()->size());
}

std::optional<VertexId> Viewport::pickVertexAt(QPointF pointPx, QSize sizePx) const {
    if (mScene.empty() || sizePx.isEmpty()) return std::nullopt;
    const auto ray = mCamera.rayThroughPixel(glm::vec2(float(pointPx.x()), float(pointPx.y())),
                                             glm::vec2(float(sizePx.width()), float(sizePx.height())));
    return mScene.pick(ray.originMm, ray.direction);
}

void Viewport::resetCamera() {
    mCamera.reset(mScene.positionsMm());
    sceneChanged(false);
}

void Viewport::fitCamera() {
    mCamera.frame(mScene.positionsMm());
    sceneChanged(false);
}

void Viewport::setTouchMode(bool on) {
    if (on == mTouchMode) return;
    mTouchMode = on;
    if (!on && mTouching) {
        mTouching = false;
        if (mTouchHandlers.released) mTouchHandlers.released();
    }
}

void Viewport::setTouchDepthMm(double depthMm) {
    if (!std::isfinite(depthMm)) return;
    depthMm = std::clamp(depthMm, 0.0, kMaxTouchDepthMm);
    if (depthMm == mTouchDepthMm) return;
    mTouchDepthMm = depthMm;
    if (mTouchHandlers.depthChanged) mTouchHandlers.depthChanged(depthMm);
}

void Viewport::touchAt(QPointF pointPx) {
    // Sub-pixel: the event's own position, on the positions drawn now (deformed).
    const auto vertex = pickVertexAt(pointPx, widget()->size());
    if (vertex && mTouchHandlers.moved) mTouchHandlers.moved(*vertex, pointPx);
}

float Viewport::surfaceOpacity() const { return mExerciseMarkers.seeThrough() ? style::kSeeThroughOpacity : 1.0f; }

void Viewport::setExerciseMarkers(ExerciseMarkers markers) {
    mExerciseMarkers = std::move(markers);
    sceneChanged(false);
}

bool Viewport::handleMousePress(const QMouseEvent& event) {
    mLastDragPx = event.position();
    mPressPx = event.position();
    mClickCandidate = false;
    if (mTouchMode && event.button() == Qt::LeftButton) {
        mTouching = true;
        touchAt(event.position());
    } else if (mPickHandler && event.button() == Qt::LeftButton) {
        mClickCandidate = true;
    }
    return false;
}

bool Viewport::handleMouseRelease(const QMouseEvent& event) {
    if (mClickCandidate && event.button() == Qt::LeftButton) {
        mClickCandidate = false;
        const QPointF d = event.position() - mPressPx;
        if (std::hypot(d.x(), d.y()) < kClickSlopPx && mPickHandler) {
            if (const auto vertex = pickVertexAt(event.position(), widget()->size())) {
                // Copy first: the handler may replace itself (e.g. leave placing mode).
                const auto handler = mPickHandler;
                handler(*vertex);
            }
        }
        return false;
    }
    if (!mTouching || event.button() != Qt::LeftButton) return false;
    mTouching = false;
    if (mTouchHandlers.released) mTouchHandlers.released();
    return false;
}

bool Viewport::handleMouseMove(const QMouseEvent& event) {
    const Qt::MouseButtons buttons = event.buttons();
    if (!(buttons & (Qt::LeftButton | Qt::RightButton | Qt::MiddleButton))) return false;
    const QPointF d = event.position() - mLastDragPx;
    mLastDragPx = event.position();
    if (mTouchMode) {
        // Left touches, right orbits, middle pans (a drag off the mesh keeps the last target).
        if (mTouching && (buttons & Qt::LeftButton)) touchAt(event.position());
        if (buttons & Qt::RightButton) {
            mCamera.orbit(float(d.x()), float(d.y()));
            return true;
        }
        if (buttons & Qt::MiddleButton) {
            const QSize size = widget()->size();
            mCamera.pan(float(d.x()), float(d.y()), glm::vec2(float(size.width()), float(size.height())));
            return true;
        }
        return false;
    }
    if (buttons & Qt::LeftButton) {
        mCamera.orbit(float(d.x()), float(d.y()));
    } else {
        const QSize size = widget()->size();
        mCamera.pan(float(d.x()), float(d.y()), glm::vec2(float(size.width()), float(size.height())));
    }
    return true;
}

bool Viewport::handleWheel(const QWheelEvent& event) {
    // angleDelta is in eighths of a degree; a notch is 15 degrees. Touchpads send fractions. Some
    // platforms turn Shift+wheel into horizontal scrolling: then take the other axis.
    const QPoint delta = event.angleDelta();
    const bool shift = event.modifiers() & Qt::ShiftModifier;
    const float steps = float(delta.y() == 0 && shift ? delta.x() : delta.y()) / 120.0f;
    if (steps == 0.0f) return false;
    if (mTouchMode && !shift) {
        setTouchDepthMm(mTouchDepthMm + double(steps) * kTouchDepthStepMm);
        return false;
    }
    mCamera.zoom(steps);
    return true;
}

}  // namespace palpate
