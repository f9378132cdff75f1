#include "widgets/SoftwareViewport.h"

#include "widgets/SceneOverlay.h"
#include "widgets/SceneStyle.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>

namespace palpate {

SoftwareViewport::SoftwareViewport(QWidget* parent) : QWidget(parent) {
    setAttribute(Qt::WA_OpaquePaintEvent);  // every pixel is painted: Qt need not clear first
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(160, 120);
}

QImage SoftwareViewport::grabImage() { return grab().toImage(); }

void SoftwareViewport::sceneChanged(bool) { update(); }

void SoftwareViewport::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    paintScene(painter, size());
    countFrame();
}

void SoftwareViewport::paintScene(QPainter& painter, QSize sizePx) {
    painter.fillRect(QRect(QPoint(0, 0), sizePx), toQColor(style::kBackground));
    if (mScene.empty() || sizePx.isEmpty()) return;

    const glm::vec2 size(float(sizePx.width()), float(sizePx.height()));
    const glm::mat4 view = mCamera.view();
    const glm::mat4 projection = mCamera.projection(size.x / size.y);
    const auto positions = mScene.positionsMm();
    mProjected.resize(positions.size());
    mViewMm.resize(positions.size());
    for (std::size_t v = 0; v < positions.size(); ++v) {
        const glm::vec4 pv = view * glm::vec4(positions[v], 1.0f);
        const glm::vec4 clip = projection * pv;
        mViewMm[v] = glm::vec3(pv);
        const bool inFront = clip.w > 1e-6f && clip.z > -clip.w;
        const float w = inFront ? clip.w : 1.0f;
        mProjected[v] = {(clip.x / w * 0.5f + 0.5f) * size.x, (0.5f - clip.y / w * 0.5f) * size.y, inFront};
    }

    // Painter's algorithm: farthest triangle first. Good enough for one convex-ish organ; a triangle
    // crossing the near plane is dropped rather than clipped.
    const auto indices = mScene.indices();
    mOrder.clear();
    for (std::uint32_t t = 0; 3 * t + 2 < indices.size(); ++t) {
        const std::uint32_t a = indices[3 * t], b = indices[3 * t + 1], c = indices[3 * t + 2];
        if (!mProjected[a].inFront || !mProjected[b].inFront || !mProjected[c].inFront) continue;
        const float minX = std::min({mProjected[a].xPx, mProjected[b].xPx, mProjected[c].xPx});
        const float maxX = std::max({mProjected[a].xPx, mProjected[b].xPx, mProjected[c].xPx});
        const float minY = std::min({mProjected[a].yPx, mProjected[b].yPx, mProjected[c].yPx});
        const float maxY = std::max({mProjected[a].yPx, mProjected[b].yPx, mProjected[c].yPx});
        if (maxX < 0.0f || minX > size.x || maxY < 0.0f || minY > size.y) continue;
        mOrder.emplace_back(mViewMm[a].z + mViewMm[b].z + mViewMm[c].z, t);  // more negative is farther
    }
    std::sort(mOrder.begin(), mOrder.end());

    const glm::vec3 light = glm::normalize(style::kLightDirView);
    const auto weights = mScene.pressedWeights();
    const QColor wire = toQColor(style::kWire);
    // Without antialiasing, abutting polygons leave pinholes; an outline in the fill colour (or the
    // wire colour) closes them.
    painter.setRenderHint(QPainter::Antialiasing, false);
    QPointF corners[3];
    for (const auto& [depth, t] : mOrder) {
        const std::uint32_t a = indices[3 * t], b = indices[3 * t + 1], c = indices[3 * t + 2];
        glm::vec3 n = glm::cross(mViewMm[b] - mViewMm[a], mViewMm[c] - mViewMm[a]);
        const float length = glm::length(n);
        n = length > 0.0f ? n / length : glm::vec3(0.0f, 0.0f, 1.0f);
        // Two-sided, independent of winding: turn the normal towards the eye (at the origin).
        const glm::vec3 centre = (mViewMm[a] + mViewMm[b] + mViewMm[c]) / 3.0f;
        if (glm::dot(n, -centre) < 0.0f) n = -n;
        const float diffuse = std::max(glm::dot(n, light), 0.0f);
        const float pressed = (weights[a] + weights[b] + weights[c]) / 3.0f;
        const glm::vec3 base = glm::mix(style::kTissue, style::kPressed, pressed);
        const glm::vec3 rgb = glm::min(base * (style::kAmbient + (1.0f - style::kAmbient) * diffuse), glm::vec3(1.0f));
        const QColor fill = toQColor(rgb);
        QColor outline = fill;
        if (mWireframe) {
            const float a = style::kWireAlpha;
            outline = QColor::fromRgbF((1 - a) * fill.redF() + a * wire.redF(), (1 - a) * fill.greenF() + a * wire.greenF(),
                                       (1 - a) * fill.blueF() + a * wire.blueF());
        }
        painter.setPen(QPen(outline, 0));
        painter.setBrush(fill);
        corners[0] = {mProjected[a].xPx, mProjected[a].yPx};
        corners[1] = {mProjected[b].xPx, mProjected[b].yPx};
        corners[2] = {mProjected[c].xPx, mProjected[c].yPx};
        painter.drawConvexPolygon(corners, 3);
    }
    paintSceneOverlay(painter, mScene, mCamera, sizePx);
}

void SoftwareViewport::mousePressEvent(QMouseEvent* event) {
    if (handleMousePress(*event)) update();
}

void SoftwareViewport::mouseMoveEvent(QMouseEvent* event) {
    if (handleMouseMove(*event)) update();
}

void SoftwareViewport::wheelEvent(QWheelEvent* event) {
    if (handleWheel(*event)) update();
    event->accept();
}

}  // namespace palpate
