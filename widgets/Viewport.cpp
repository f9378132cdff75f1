#include "widgets/Viewport.h"

#include <QMouseEvent>
#include <QWheelEvent>
#include <QWidget>

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

bool Viewport::handleMousePress(const QMouseEvent& event) {
    mLastDragPx = event.position();
    return false;
}

bool Viewport::handleMouseMove(const QMouseEvent& event) {
    const Qt::MouseButtons buttons = event.buttons();
    if (!(buttons & (Qt::LeftButton | Qt::RightButton | Qt::MiddleButton))) return false;
    const QPointF d = event.position() - mLastDragPx;
    mLastDragPx = event.position();
    if (buttons & Qt::LeftButton) {
        mCamera.orbit(float(d.x()), float(d.y()));
    } else {
        const QSize size = widget()->size();
        mCamera.pan(float(d.x()), float(d.y()), glm::vec2(float(size.width()), float(size.height())));
    }
    return true;
}

bool Viewport::handleWheel(const QWheelEvent& event) {
    // angleDelta is in eighths of a degree; a notch is 15 degrees. Touchpads send fractions.
    const float steps = float(event.angleDelta().y()) / 120.0f;
    if (steps == 0.0f) return false;
    mCamera.zoom(steps);
    return true;
}

}  // namespace palpate
