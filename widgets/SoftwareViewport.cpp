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
    setContextMenuPolicy(Qt::PreventContextMenu);  // right-drag pans; no menu from the window either
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
    auto project = [&](const glm::vec3& pointMm, glm::vec3& viewMm) {
        const glm::vec4 pv = view * glm::vec4(pointMm, 1.0f);
        const glm::vec4 clip = projection * pv;
        viewMm = glm::vec3(pv);
        const bool inFront = clip.w > 1e-6f && clip.z > -clip.w;
        const float w = inFront ? clip.w : 1.0f;
        return ProjectedVertex{(clip.x / w * 0.5f + 0.5f) * size.x, (0.5f - clip.y / w * 0.5f) * size.y, inFront};
    };
    const auto positions = mScene.positionsMm();
    mProjected.resize(positions.size());
    mViewMm.resize(positions.size());
    for (std::size_t v = 0; v < positions.size(); ++v) mProjected[v] = project(positions[v], mViewMm[v]);

    // Painter's algorithm: farthest triangle first. Good enough for one convex-ish organ; a triangle
    // crossing the near plane is dropped rather than clipped. With the ghost on, the rest shape of
    // every triangle with a displaced corner joins the sort (flagged by kGhostBit), so that it shows
    // over the dent and hides behind the tissue in front of it.
    const auto indices = mScene.indices();
    const auto weights = mScene.pressedWeights();
    const auto rest = mScene.restPositionsMm();
    auto onScreen = [&](const ProjectedVertex& a, const ProjectedVertex& b, const ProjectedVertex& c) {
        if (!a.inFront || !b.inFront || !c.inFront) return false;
        const float minX = std::min({a.xPx, b.xPx, c.xPx}), maxX = std::max({a.xPx, b.xPx, c.xPx});
        const float minY = std::min({a.yPx, b.yPx, c.yPx}), maxY = std::max({a.yPx, b.yPx, c.yPx});
        return !(maxX < 0.0f || minX > size.x || maxY < 0.0f || minY > size.y);
    };
    mOrder.clear();
    for (std::uint32_t t = 0; 3 * t + 2 < indices.size(); ++t) {
        const std::uint32_t a = indices[3 * t], b = indices[3 * t + 1], c = indices[3 * t + 2];
        if (onScreen(mProjected[a], mProjected[b], mProjected[c]))
            mOrder.emplace_back(mViewMm[a].z + mViewMm[b].z + mViewMm[c].z, t);  // more negative is farther
        if (mShowRestGhost && (weights[a] > 0.0f || weights[b] > 0.0f || weights[c] > 0.0f)) {
            glm::vec3 va, vb, vc;
            const ProjectedVertex pa = project(rest[a], va), pb = project(rest[b], vb), pc = project(rest[c], vc);
            if (onScreen(pa, pb, pc)) mOrder.emplace_back(va.z + vb.z + vc.z, t | kGhostBit);
        }
    }
    std::sort(mOrder.begin(), mOrder.end());

    const glm::vec3 light = glm::normalize(style::kLightDirView);
    const auto rings = mScene.rings();
    const QColor wire = toQColor(style::kWire);
    const QColor ghostFill = toQColor(style::kGhost, style::kGhostFillAlpha);
    const QPen ghostPen(toQColor(style::kGhost, style::kGhostWireAlpha), 0);
    // Without antialiasing, abutting polygons leave pinholes; an outline in the fill colour (or the
    // wire colour) closes them.
    painter.setRenderHint(QPainter::Antialiasing, false);
    QPointF corners[3];
    for (const auto& [depth, entry] : mOrder) {
        const std::uint32_t t = entry & ~kGhostBit;
        const std::uint32_t a = indices[3 * t], b = indices[3 * t + 1], c = indices[3 * t + 2];
        if (entry & kGhostBit) {
            glm::vec3 unused;
            const ProjectedVertex pa = project(rest[a], unused), pb = project(rest[b], unused), pc = project(rest[c], unused);
            corners[0] = {pa.xPx, pa.yPx};
            corners[1] = {pb.xPx, pb.yPx};
            corners[2] = {pc.xPx, pc.yPx};
            painter.setPen(ghostPen);
            painter.setBrush(ghostFill);
            painter.drawConvexPolygon(corners, 3);
            continue;
        }
        glm::vec3 n = glm::cross(mViewMm[b] - mViewMm[a], mViewMm[c] - mViewMm[a]);
        const float length = glm::length(n);
        n = length > 0.0f ? n / length : glm::vec3(0.0f, 0.0f, 1.0f);
        // Two-sided, independent of winding: turn the normal towards the eye (at the origin).
        const glm::vec3 centre = (mViewMm[a] + mViewMm[b] + mViewMm[c]) / 3.0f;
        if (glm::dot(n, -centre) < 0.0f) n = -n;
        const float diffuse = std::max(glm::dot(n, light), 0.0f);
        // The lowest ring among the corners colours the triangle (as the GL geometry shader does);
        // outside the rings the displacement tints it.
        const std::uint8_t ring = std::min({rings[a], rings[b], rings[c]});
        glm::vec3 base;
        float ambient = style::kAmbient;
        if (style::hasRingColour(ring)) {
            base = style::kRingColours[ring];
            ambient = style::kRingAmbient;
        } else {
            const float pressed = (weights[a] + weights[b] + weights[c]) / 3.0f;
            base = glm::mix(style::kTissue, style::kPressed, pressed);
        }
        const glm::vec3 rgb = glm::min(base * (ambient + (1.0f - ambient) * diffuse), glm::vec3(1.0f));
        const QColor fill = toQColor(rgb);
        QColor outline = fill;
        if (mWireframe) {
            const float alpha = style::kWireAlpha;
            outline = QColor::fromRgbF((1 - alpha) * fill.redF() + alpha * wire.redF(),
                                       (1 - alpha) * fill.greenF() + alpha * wire.greenF(),
                                       (1 - alpha) * fill.blueF() + alpha * wire.blueF());
        }
        painter.setPen(QPen(outline, 0));
        painter.setBrush(fill);
        corners[0] = {mProjected[a].xPx, mProjected[a].yPx};
        corners[1] = {mProjected[b].xPx, mProjected[b].yPx};
        corners[2] = {mProjected[c].xPx, mProjected[c].yPx};
        painter.drawConvexPolygon(corners, 3);
    }
    paintExerciseMarkers(painter, mExerciseMarkers, mCamera, sizePx);
    paintSceneOverlay(painter, mScene, mCamera, sizePx, mShowRestGhost);
}

void SoftwareViewport::mousePressEvent(QMouseEvent* event) {
    if (handleMousePress(*event)) update();
}

void SoftwareViewport::mouseMoveEvent(QMouseEvent* event) {
    if (handleMouseMove(*event)) update();
}

void SoftwareViewport::mouseReleaseEvent(QMouseEvent* event) {
    if (handleMouseRelease(*event)) update();
}

void SoftwareViewport::wheelEvent(QWheelEvent* event) {
    if (handleWheel(*event)) update();
    event->accept();
}

}  // namespace palpate
