#include "widgets/Viewport.h"

#include <QMouseEvent>
#include <QWheelEvent>

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
    if (!(event.buttons() & Qt::LeftButton)) return false;
    const QPointF d = event.position() - mLastDragPx;
    mLastDragPx = event.position();
    mCamera.orbit(float(d.x()), float(d.y()));
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
