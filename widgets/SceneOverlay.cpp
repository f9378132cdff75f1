#include "widgets/SceneOverlay.h"

#include "widgets/OrbitCamera.h"
#include "widgets/RenderScene.h"
#include "widgets/SceneStyle.h"

#include <QCoreApplication>
#include <QFont>
#include <QFontMetricsF>
#include <QGuiApplication>
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

QFont legendFont() {
    QFont font = QGuiApplication::font();
    font.setPixelSize(11);  // pixels, not points: the same size on every paint device
    return font;
}

struct LegendLayout {
    int rings = 0;  // rows for the touched vertex and rings 1.., then one for the ghost
    bool ghost = false;
    double rowPx = 0.0;
    QRectF box;
    int rows() const { return rings + (ghost ? 1 : 0); }
};

constexpr double kLegendPaddingPx = 6.0;
constexpr double kLegendGapPx = 6.0;  // between swatch and label

LegendLayout legendLayout(const RenderScene& scene, QSize sizePx, bool showRestGhost) {
    LegendLayout layout;
    if (scene.empty()) return layout;
    layout.rings = scene.highestRing() + 1;
    layout.ghost = showRestGhost;
    if (layout.rows() == 0) return layout;
    const QFontMetricsF metrics(legendFont());
    layout.rowPx = std::max<double>(style::kLegendSwatchPx + 3, metrics.height());
    double labelPx = 0.0;
    for (int r = 0; r < layout.rings; ++r) labelPx = std::max(labelPx, metrics.horizontalAdvance(ringLegendLabel(r)));
    if (layout.ghost) labelPx = std::max(labelPx, metrics.horizontalAdvance(QCoreApplication::translate("palpate::SceneOverlay", "rest shape")));
    const double width = 2 * kLegendPaddingPx + style::kLegendSwatchPx + kLegendGapPx + std::ceil(labelPx);
    const double height = 2 * kLegendPaddingPx + layout.rows() * layout.rowPx;
    layout.box = QRectF(style::kLegendMarginPx, sizePx.height() - style::kLegendMarginPx - height, width, height);
    return layout;
}

void paintLegend(QPainter& painter, const LegendLayout& layout) {
    if (layout.rows() == 0) return;
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0, 0, 0, 150));
    painter.drawRoundedRect(layout.box, 4.0, 4.0);
    painter.setFont(legendFont());
    const double swatch = style::kLegendSwatchPx;
    for (int row = 0; row < layout.rows(); ++row) {
        const bool ghostRow = row >= layout.rings;
        const double top = layout.box.top() + kLegendPaddingPx + row * layout.rowPx;
        const QRectF swatchRect(layout.box.left() + kLegendPaddingPx, top + 0.5 * (layout.rowPx - swatch), swatch, swatch);
        painter.setPen(Qt::NoPen);
        painter.setBrush(ghostRow ? toQColor(style::kGhost, 0.6f) : toQColor(style::kRingColours[std::size_t(row)]));
        painter.drawRect(swatchRect);
        painter.setPen(QColor(230, 230, 230));
        const QRectF labelRect(swatchRect.right() + kLegendGapPx, top, layout.box.right() - swatchRect.right(), layout.rowPx);
        painter.drawText(labelRect, Qt::AlignLeft | Qt::AlignVCenter,
                         ghostRow ? QCoreApplication::translate("palpate::SceneOverlay", "rest shape") : ringLegendLabel(row));
    }
}

}  // namespace

QString ringLegendLabel(int ring) {
    return ring == 0 ? QCoreApplication::translate("palpate::SceneOverlay", "touched")
                     : QCoreApplication::translate("palpate::SceneOverlay", "ring %1").arg(ring);
}

QRectF sceneLegendRect(const RenderScene& scene, QSize sizePx, bool showRestGhost) {
    return legendLayout(scene, sizePx, showRestGhost).box;
}

QColor toQColor(const glm::vec3& rgb, float alpha) { return QColor::fromRgbF(rgb.x, rgb.y, rgb.z, alpha); }

void paintSceneOverlay(QPainter& painter, const RenderScene& scene, const OrbitCamera& camera, QSize sizePx,
                       bool showRestGhost) {
    if (scene.empty()) return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    paintLegend(painter, legendLayout(scene, sizePx, showRestGhost));
    if (!scene.hasTool()) {
        painter.restore();
        return;
    }
    const glm::vec2 size(float(sizePx.width()), float(sizePx.height()));

    if (scene.touched() != kNoVertex) {
        if (const auto p = camera.projectToPixel(scene.positionsMm()[scene.touched()], size))
            paintRing(painter, toPoint(*p), style::kTouchedMarkerRadiusPx, toQColor(style::kTouchedHighlight));
    }
    // A tool with a size: its sphere's outline where the proxy holds it on the tissue, and a thin
    // line to the device's position (inside the tissue while pressing) when they differ.
    const auto proxy = camera.projectToPixel(scene.proxyMm(), size);
    if (scene.toolRadiusMm() > 0.0f && proxy) {
        // A direction across the line of sight: the sphere's rim is its radius along it.
        const glm::vec3 view = glm::normalize(scene.proxyMm() - camera.eyeMm());
        glm::vec3 sideways = glm::cross(view, glm::vec3(0.0f, 0.0f, 1.0f));
        if (glm::length(sideways) < 1e-3f) sideways = glm::cross(view, glm::vec3(0.0f, 1.0f, 0.0f));
        sideways = glm::normalize(sideways);
        if (const auto rim = camera.projectToPixel(scene.proxyMm() + scene.toolRadiusMm() * sideways, size)) {
            const double radiusPx = double(glm::length(*rim - *proxy));
            const QColor colour = toQColor(style::kTool);
            painter.setPen(QPen(colour, 2.0));
            painter.setBrush(toQColor(style::kTool, 0.25f));
            painter.drawEllipse(toPoint(*proxy), radiusPx, radiusPx);
            if (const auto device = camera.projectToPixel(scene.toolTipMm(), size);
                device && glm::length(*device - *proxy) > 1.0f) {
                painter.setPen(QPen(colour, 1.0, Qt::DashLine));
                painter.drawLine(toPoint(*proxy), toPoint(*device));
            }
        }
    }
    const auto tip = scene.toolRadiusMm() > 0.0f ? proxy : camera.projectToPixel(scene.toolTipMm(), size);
    const float forceN = glm::length(scene.forceN());
    if (tip && forceN > 1e-4f) {
        const float lengthMm = std::min(forceN * style::kArrowDiagonalsPerN, style::kArrowMaxDiagonals) * scene.diagonalMm();
        const glm::vec3 startMm = scene.toolRadiusMm() > 0.0f ? scene.proxyMm() : scene.toolTipMm();
        const glm::vec3 endMm = startMm + scene.forceN() / forceN * lengthMm;
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
