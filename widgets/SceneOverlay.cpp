#include "widgets/SceneOverlay.h"

#include "widgets/OrbitCamera.h"
#include "widgets/RenderScene.h"
#include "widgets/SceneStyle.h"

#include <QPainter>
#include <QPainterPath>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace palpate {

namespace {

QPointF toPoint(const glm::vec2& p) { return {p.x, p.y}; }

void paintDisc(QPainter& painter, const QPointF& centre, float radiusPx, const QColor& fill) {
    painter.setPen(QPen(QColor(0, 0, 0, 200), 1.0));
    painter.setBrush(fill);
    painter.drawEllipse(centre, radiusPx, radiusPx);
}

/// A ring, so the pressed (tinted) surface under it stays visible.
void paintRing(QPainter& painter, const QPointF& centre, float radiusPx, const QColor& colour) {
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(QColor(0, 0, 0, 160), 4.5));
    painter.drawEllipse(centre, radiusPx, radiusPx);
    painter.setPen(QPen(colour, 2.5));
    painter.drawEllipse(centre, radiusPx, radiusPx);
}

void paintArrow(QPainter& painter, const QPointF& from, const QPointF& to, const QColor& colour) {
    const QPointF d = to - from;
    const double lengthPx = std::hypot(d.x(), d.y());
    if (lengthPx < 2.0) return;  // seen end-on: a dot would only hide the tool marker
    const QPointF u = d / lengthPx, n(-u.y(), u.x());
    const double headPx = std::min(12.0, 0.4 * lengthPx);
    painter.setPen(QPen(colour, 2.5, Qt::SolidLine, Qt::RoundCap));
    painter.drawLine(from, to - u * headPx * 0.5);
    painter.setPen(Qt::NoPen);
    painter.setBrush(colour);
    const QPointF head[3] = {to, to - u * headPx + n * headPx * 0.45, to - u * headPx - n * headPx * 0.45};
    painter.drawPolygon(head, 3);
}

}  // namespace

QColor toQColor(const glm::vec3& rgb, float alpha) { return QColor::fromRgbF(rgb.x, rgb.y, rgb.z, alpha); }

void paintSceneOverlay(QPainter& painter, const RenderScene& scene, const OrbitCamera& camera, QSize sizePx) {
    if (scene.empty() || !scene.hasTool()) return;
    const glm::vec2 size(float(sizePx.width()), float(sizePx.height()));
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);

    if (scene.touched() != kNoVertex) {
        if (const auto p = camera.projectToPixel(scene.positionsMm()[scene.touched()], size))
            paintRing(painter, toPoint(*p), style::kTouchedMarkerRadiusPx, toQColor(style::kTouchedHighlight));
    }
    const auto tip = camera.projectToPixel(scene.toolTipMm(), size);
    const float forceN = glm::length(scene.forceN());
    if (tip && forceN > 1e-4f) {
        const float lengthMm = std::min(forceN * style::kArrowDiagonalsPerN, style::kArrowMaxDiagonals) * scene.diagonalMm();
        const glm::vec3 endMm = scene.toolTipMm() + scene.forceN() / forceN * lengthMm;
        if (const auto end = camera.projectToPixel(endMm, size)) {
            const QColor colour = toQColor(style::kForceArrow);
            paintArrow(painter, toPoint(*tip), toPoint(*end), colour);
            painter.setPen(colour);
            painter.drawText(toPoint(*end) + QPointF(6.0, -6.0), QStringLiteral("%1 N").arg(forceN, 0, 'f', 2));
        }
    }
    if (tip) paintDisc(painter, toPoint(*tip), style::kToolMarkerRadiusPx, toQColor(style::kTool));
    painter.restore();
}

}  // namespace palpate
