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
#include <optional>
#include <vector>

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

QFont labelFont() {
    QFont font = QGuiApplication::font();
    font.setPixelSize(style::kLabelFontPx);
    font.setBold(true);
    return font;
}

QString forceLabelText(float forceN) { return QStringLiteral("%1 N").arg(double(forceN), 0, 'f', 2); }

/// Whether vertex `v` counts as displaced for the patch outline.
bool displaced(const RenderScene& scene, VertexId v) {
    return scene.pressedWeights()[v] > style::kOutlineDisplacementMm / style::kFullTintDisplacementMm;
}

/// The boundary of the displaced patch: the edges between triangles with a displaced corner and
/// triangles without one (or the mesh's own border), projected, into `lines`. Returns the patch's
/// pixel bounds (empty when nothing is displaced).
QRectF patchOutline(const RenderScene& scene, const OrbitCamera& camera, const glm::vec2& size, std::vector<QLineF>& lines) {
    lines.clear();
    const auto indices = scene.indices();
    const auto positions = scene.positionsMm();
    const std::size_t n = scene.vertexCount();
    QRectF bounds;
    for (VertexId v = 0; v < n; ++v) {
        if (!displaced(scene, v)) continue;
        for (const std::uint32_t t : scene.vertexTriangles(v)) {
            const std::uint32_t* corner = &indices[3 * t];
            // Each patch triangle once: from its lowest displaced corner.
            bool first = true;
            for (int k = 0; k < 3; ++k)
                if (corner[k] < v && displaced(scene, corner[k])) first = false;
            if (!first) continue;
            for (int k = 0; k < 3; ++k) {
                const VertexId a = corner[k], b = corner[(k + 1) % 3];
                if (displaced(scene, a) || displaced(scene, b)) continue;
                // The triangle across edge ab: the patch's border when it has no displaced corner.
                bool inside = false;
                for (const std::uint32_t u : scene.vertexTriangles(a)) {
                    if (u == t) continue;
                    const std::uint32_t* other = &indices[3 * u];
                    const bool hasB = other[0] == b || other[1] == b || other[2] == b;
                    if (!hasB) continue;
                    for (int j = 0; j < 3; ++j)
                        if (displaced(scene, other[j])) inside = true;
                }
                if (inside) continue;
                const auto pa = camera.projectToPixel(positions[a], size), pb = camera.projectToPixel(positions[b], size);
                if (!pa || !pb) continue;
                lines.emplace_back(toPoint(*pa), toPoint(*pb));
                bounds |= QRectF(toPoint(*pa), toPoint(*pb)).normalized().adjusted(-0.5, -0.5, 0.5, 0.5);
            }
        }
    }
    return lines.empty() ? QRectF() : bounds;
}

/// Draws the patch's outline; returns its pixel bounds.
QRectF paintPatchOutline(QPainter& painter, const RenderScene& scene, const OrbitCamera& camera, const glm::vec2& size) {
    static std::vector<QLineF> lines;  // GUI thread only; kept so that a frame does not allocate
    const QRectF bounds = patchOutline(scene, camera, size, lines);
    if (lines.empty()) return {};
    const QColor outline = toQColor(style::kPatchOutline);
    painter.setPen(QPen(QColor(0, 0, 0, 170), 4.0, Qt::SolidLine, Qt::RoundCap));
    painter.drawLines(lines.data(), int(lines.size()));
    painter.setPen(QPen(outline, 1.75, Qt::SolidLine, Qt::RoundCap));
    painter.drawLines(lines.data(), int(lines.size()));
    // A patch of a few pixels (a fine mesh) gets a circle around it, so the eye finds it.
    const double minRadius = style::kPatchMarkerMinRadiusPx;
    if (std::max(bounds.width(), bounds.height()) < 2.0 * minRadius) {
        painter.setBrush(Qt::NoBrush);
        painter.setPen(QPen(QColor(0, 0, 0, 170), 4.0));
        painter.drawEllipse(bounds.center(), minRadius, minRadius);
        painter.setPen(QPen(outline, 1.75, Qt::DashLine));
        painter.drawEllipse(bounds.center(), minRadius, minRadius);
    }
    return bounds;
}

QFont legendFont() {
    QFont font = QGuiApplication::font();
    font.setPixelSize(11);  // pixels, not points: the same size on every paint device
    return font;
}

struct LegendLayout {
    int rings = 0;  // rows for the touched vertex and rings 1.., then one for the ghost, one for the dent
    bool ghost = false;
    float dentMm = 0.0f;  // > 0: the dent's row (the patch outline and its depth)
    double rowPx = 0.0;
    QRectF box;
    bool dent() const { return dentMm > 0.0f; }
    int rows() const { return rings + (ghost ? 1 : 0) + (dent() ? 1 : 0); }
};

QString dentLegendLabel(float depthMm) {
    return QCoreApplication::translate("palpate::SceneOverlay", "dent %1 mm deep").arg(double(depthMm), 0, 'f', 1);
}

constexpr double kLegendPaddingPx = 6.0;
constexpr double kLegendGapPx = 6.0;  // between swatch and label

LegendLayout legendLayout(const RenderScene& scene, QSize sizePx, bool showRestGhost) {
    LegendLayout layout;
    if (scene.empty()) return layout;
    layout.rings = scene.highestRing() + 1;
    layout.ghost = showRestGhost;
    if (const float deepestMm = deepestDisplacementMm(scene); deepestMm > style::kOutlineDisplacementMm)
        layout.dentMm = deepestMm;
    if (layout.rows() == 0) return layout;
    const QFontMetricsF metrics(legendFont());
    layout.rowPx = std::max<double>(style::kLegendSwatchPx + 3, metrics.height());
    double labelPx = 0.0;
    for (int r = 0; r < layout.rings; ++r) labelPx = std::max(labelPx, metrics.horizontalAdvance(ringLegendLabel(r)));
    if (layout.ghost) labelPx = std::max(labelPx, metrics.horizontalAdvance(QCoreApplication::translate("palpate::SceneOverlay", "rest shape")));
    if (layout.dent()) labelPx = std::max(labelPx, metrics.horizontalAdvance(dentLegendLabel(layout.dentMm)));
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
        const bool ghostRow = layout.ghost && row == layout.rings;
        const bool dentRow = layout.dent() && row == layout.rows() - 1;
        const double top = layout.box.top() + kLegendPaddingPx + row * layout.rowPx;
        const QRectF swatchRect(layout.box.left() + kLegendPaddingPx, top + 0.5 * (layout.rowPx - swatch), swatch, swatch);
        if (dentRow) {
            // The outline's own look: a light line on the dark plate.
            painter.setBrush(Qt::NoBrush);
            painter.setPen(QPen(toQColor(style::kPatchOutline), 1.75));
            painter.drawRect(swatchRect.adjusted(1, 1, -1, -1));
            painter.setPen(QColor(230, 230, 230));
            const QRectF labelRect(swatchRect.right() + kLegendGapPx, top, layout.box.right() - swatchRect.right(), layout.rowPx);
            painter.drawText(labelRect, Qt::AlignLeft | Qt::AlignVCenter, dentLegendLabel(layout.dentMm));
            continue;
        }
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

double contrastRatio(const QColor& a, const QColor& b) {
    auto luminance = [](const QColor& c) {
        auto linear = [](double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
        return 0.2126 * linear(c.redF()) + 0.7152 * linear(c.greenF()) + 0.0722 * linear(c.blueF());
    };
    const double la = luminance(a), lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

float deepestDisplacementMm(const RenderScene& scene) {
    const auto positions = scene.positionsMm();
    const auto rest = scene.restPositionsMm();
    const auto weights = scene.pressedWeights();
    float deepestMm = 0.0f;
    for (std::size_t v = 0; v < positions.size(); ++v)
        if (weights[v] > 0.0f) deepestMm = std::max(deepestMm, glm::length(positions[v] - rest[v]));
    return deepestMm;
}

namespace {

struct ForceLabel {
    QRectF plate;
    QString text;
};

/// The arrow's end and the label beside it, kept inside the viewport.
std::optional<ForceLabel> forceLabel(const RenderScene& scene, const OrbitCamera& camera, QSize sizePx,
                                     std::optional<glm::vec2>* arrowFrom = nullptr, std::optional<glm::vec2>* arrowTo = nullptr) {
    if (scene.empty() || !scene.hasTool()) return std::nullopt;
    const glm::vec2 size(float(sizePx.width()), float(sizePx.height()));
    const bool sized = scene.toolRadiusMm() > 0.0f;
    const auto tip = camera.projectToPixel(sized ? scene.proxyMm() : scene.toolTipMm(), size);
    const float forceN = glm::length(scene.forceN());
    if (!tip || !(forceN > 1e-4f)) return std::nullopt;
    const float lengthMm = std::min(forceN * style::kArrowDiagonalsPerN, style::kArrowMaxDiagonals) * scene.diagonalMm();
    const glm::vec3 startMm = sized ? scene.proxyMm() : scene.toolTipMm();
    const auto end = camera.projectToPixel(startMm + scene.forceN() / forceN * lengthMm, size);
    if (!end) return std::nullopt;
    if (arrowFrom) *arrowFrom = tip;
    if (arrowTo) *arrowTo = end;
    ForceLabel label;
    label.text = forceLabelText(forceN);
    const QFontMetricsF metrics(labelFont());
    constexpr double kPadXPx = 6.0, kPadYPx = 3.0, kOffsetPx = 8.0;
    const QSizeF box(std::ceil(metrics.horizontalAdvance(label.text)) + 2 * kPadXPx, std::ceil(metrics.height()) + 2 * kPadYPx);
    QPointF topLeft(double(end->x) + kOffsetPx, double(end->y) - kOffsetPx - box.height());
    topLeft.setX(std::clamp(topLeft.x(), 2.0, std::max(2.0, sizePx.width() - box.width() - 2.0)));
    topLeft.setY(std::clamp(topLeft.y(), 2.0, std::max(2.0, sizePx.height() - box.height() - 2.0)));
    label.plate = QRectF(topLeft, box);
    // Beside the dent, never over it: when the force points at the viewer the arrow is short and
    // its end lies on the patch.
    static std::vector<QLineF> lines;  // GUI thread only
    QRectF patch = patchOutline(scene, camera, size, lines);
    if (!patch.isEmpty()) {
        const double minRadius = style::kPatchMarkerMinRadiusPx;
        if (std::max(patch.width(), patch.height()) < 2.0 * minRadius)
            patch = QRectF(patch.center() - QPointF(minRadius, minRadius), QSizeF(2 * minRadius, 2 * minRadius));
        patch.adjust(-4.0, -4.0, 4.0, 4.0);
        if (label.plate.intersects(patch)) {
            // To the right of the patch, or to its left where the viewport ends.
            double x = patch.right() + kOffsetPx;
            if (x + box.width() > sizePx.width() - 2.0) x = patch.left() - kOffsetPx - box.width();
            label.plate.moveLeft(std::max(2.0, x));
            label.plate.moveTop(std::clamp(patch.center().y() - 0.5 * box.height(), 2.0,
                                           std::max(2.0, sizePx.height() - box.height() - 2.0)));
        }
    }
    return label;
}

}  // namespace

QRectF displacedPatchRect(const RenderScene& scene, const OrbitCamera& camera, QSize sizePx) {
    std::vector<QLineF> lines;
    return patchOutline(scene, camera, glm::vec2(float(sizePx.width()), float(sizePx.height())), lines);
}

QRectF forceLabelRect(const RenderScene& scene, const OrbitCamera& camera, QSize sizePx) {
    const auto label = forceLabel(scene, camera, sizePx);
    return label ? label->plate : QRectF();
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
    const glm::vec2 size(float(sizePx.width()), float(sizePx.height()));
    paintPatchOutline(painter, scene, camera, size);
    paintLegend(painter, legendLayout(scene, sizePx, showRestGhost));
    if (!scene.hasTool()) {
        painter.restore();
        return;
    }

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
            painter.setBrush(Qt::NoBrush);  // the dent under the tool must stay visible
            painter.drawEllipse(toPoint(*proxy), radiusPx, radiusPx);
            if (const auto device = camera.projectToPixel(scene.toolTipMm(), size);
                device && glm::length(*device - *proxy) > 1.0f) {
                painter.setPen(QPen(colour, 1.0, Qt::DashLine));
                painter.drawLine(toPoint(*proxy), toPoint(*device));
            }
        }
    }
    const auto tip = scene.toolRadiusMm() > 0.0f ? proxy : camera.projectToPixel(scene.toolTipMm(), size);
    std::optional<glm::vec2> from, to;
    if (const auto label = forceLabel(scene, camera, sizePx, &from, &to)) {
        const QColor colour = toQColor(style::kForceArrow);
        paintArrow(painter, toPoint(*from), toPoint(*to), colour);
        // An opaque plate: the label reads the same over tissue, rings and background.
        painter.setPen(Qt::NoPen);
        painter.setBrush(toQColor(style::kLabelPlate));
        painter.drawRoundedRect(label->plate, 3.0, 3.0);
        painter.setFont(labelFont());
        painter.setPen(colour);
        painter.drawText(label->plate, Qt::AlignCenter, label->text);
    }
    if (tip) paintDisc(painter, toPoint(*tip), style::kToolMarkerRadiusPx, toQColor(style::kTool));
    painter.restore();
}

}  // namespace palpate
