#include "widgets/ExerciseMarkers.h"

#include "engine/exercise/ExerciseKind.h"
#include "widgets/ExerciseText.h"

#include "report/HeatColour.h"

#include "widgets/OrbitCamera.h"

#include <QCoreApplication>
#include <QFont>
#include <QFontMetricsF>
#include <QImage>
#include <QLinearGradient>
#include <QList>
#include <QLocale>
#include <QGuiApplication>
#include <QPainter>
#include <QPainterPath>
#include <QRadialGradient>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace palpate {

namespace {

constexpr float kMarkerRadiusPx = 7.0f;
constexpr float kSelectedRadiusPx = 10.0f;
constexpr int kCirclePoints = 48;

QPointF toPoint(const glm::vec2& p) { return {p.x, p.y}; }

/// Two unit vectors spanning the tangent plane of `normal`.
void tangentFrame(const glm::vec3& normal, glm::vec3& u, glm::vec3& v) {
    const glm::vec3 helper = std::abs(normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    u = glm::normalize(glm::cross(normal, helper));
    v = glm::cross(normal, u);
}

bool facesAway(const ExerciseMarker& marker, const OrbitCamera& camera) {
    if (glm::dot(marker.normal, marker.normal) < 1e-12f) return false;
    return glm::dot(marker.normal, camera.eyeMm() - marker.positionMm) < 0.0f;
}

/// The marker's radius as a circle in the surface's tangent plane, projected (an ellipse seen
/// obliquely), so that the instructor sees the tolerance or the inclusion at its true size.
void paintSurfaceCircle(QPainter& painter, const ExerciseMarker& marker, const OrbitCamera& camera,
                        const glm::vec2& size, const QColor& colour) {
    glm::vec3 normal = marker.normal;
    if (glm::dot(normal, normal) < 1e-12f) normal = glm::normalize(camera.eyeMm() - marker.positionMm);
    glm::vec3 u, v;
    tangentFrame(normal, u, v);
    QPainterPath path;
    bool started = false;
    for (int i = 0; i <= kCirclePoints; ++i) {
        const float a = 2.0f * 3.14159265f * float(i) / float(kCirclePoints);
        const glm::vec3 p = marker.positionMm + float(marker.radiusMm) * (std::cos(a) * u + std::sin(a) * v);
        const auto px = camera.projectToPixel(p, size);
        if (!px) {
            started = false;
            continue;
        }
        if (!started) path.moveTo(toPoint(*px));
        else path.lineTo(toPoint(*px));
        started = true;
    }
    QColor fill = colour;
    fill.setAlphaF(0.18f * colour.alphaF());
    painter.setBrush(fill);
    painter.setPen(QPen(colour, 1.5, Qt::DashLine));
    painter.drawPath(path);
}

/// A lump inside the tissue, seen through the surface: a shaded ball at its centre and true size
/// (its outline the sphere's silhouette for this camera), and a dashed line up to the surface
/// point above it, so depth and size read at a glance. Drawn without a depth test on purpose.
/// A marker's lump as the viewport shows it: its centre and its silhouette's radius, in pixels;
/// nullopt when it has none or it is behind the camera.
struct ProjectedBall {
    glm::vec2 centre{0.0f};
    float radiusPx = 0.0f;
};
std::optional<ProjectedBall> projectedBall(const ExerciseMarker& marker, const OrbitCamera& camera,
                                           const glm::vec2& size) {
    if (!(marker.bodyRadiusMm > 0.0)) return std::nullopt;
    const auto centre = camera.projectToPixel(marker.bodyCentreMm, size);
    if (!centre) return std::nullopt;
    glm::vec3 u, v;
    tangentFrame(glm::normalize(camera.eyeMm() - marker.bodyCentreMm), u, v);
    const auto rim = camera.projectToPixel(marker.bodyCentreMm + float(marker.bodyRadiusMm) * u, size);
    if (!rim) return std::nullopt;
    return ProjectedBall{*centre, std::max(3.0f, glm::length(*rim - *centre))};
}

void paintBody(QPainter& painter, const ExerciseMarker& marker, const OrbitCamera& camera, const glm::vec2& size,
               QColor colour) {
    const auto ball = projectedBall(marker, camera, size);
    if (!ball) return;
    const float radiusPx = ball->radiusPx;
    const QPointF c = toPoint(ball->centre);
    if (const auto top = camera.projectToPixel(marker.positionMm, size)) {
        painter.setPen(QPen(colour, 1.5, Qt::DotLine));
        painter.drawLine(toPoint(*top), c);
    }
    QRadialGradient shade(c - QPointF(0.35 * radiusPx, 0.35 * radiusPx), 1.3 * radiusPx);
    QColor light = colour.lighter(160), dark = colour.darker(160);
    light.setAlphaF(0.75f * colour.alphaF());
    dark.setAlphaF(0.55f * colour.alphaF());
    shade.setColorAt(0.0, light);
    shade.setColorAt(1.0, dark);
    painter.setBrush(shade);
    painter.setPen(QPen(colour, marker.selected ? 2.5 : 1.5));
    painter.drawEllipse(c, radiusPx, radiusPx);
}

/// The heat map's dots for one camera and size, drawn once into an image kept until the camera,
/// the size or the heat map changes: a fully examined organ has thousands of dots, and the window
/// repaints at 60 Hz while the view stands still (drawn every frame they cost 5x the frame).
struct HeatLayer {
    glm::mat4 viewProjection{0.0f};
    QSize sizePx;
    qreal pixelRatio = 0.0;
    double minN = 0.0, maxN = 0.0, checksum = 0.0;
    std::size_t points = 0;
    QImage image;
};

double heatChecksum(const std::vector<HeatPoint>& heat) {
    double sum = 0.0;
    for (const HeatPoint& h : heat)
        sum += double(h.forceN) + double(h.positionMm.x + 2.0f * h.positionMm.y + 3.0f * h.positionMm.z);
    return sum;
}

void drawHeatDots(QPainter& painter, const ExerciseMarkers& markers, const OrbitCamera& camera, const glm::vec2& size) {
    // Batched by colour and size (whole pixels), each batch one drawPoints with a round pen,
    // without antialiasing (the dots overlap).
    const OrbitCamera::PixelProjection project(camera, size);
    const glm::vec3 eye = camera.eyeMm();
    std::map<std::pair<QRgb, int>, QList<QPointF>> batches;
    for (const HeatPoint& h : markers.heat) {
        if (glm::dot(h.normal, eye - h.positionMm) <= 0.0f) continue;  // only the side facing the camera
        const auto centre = project(h.positionMm);
        if (!centre) continue;
        glm::vec3 u, v;
        tangentFrame(h.normal, u, v);
        const auto edge = project(h.positionMm + 1.6f * u);
        const float radiusPx = edge ? std::clamp(glm::length(*edge - *centre), 1.5f, 12.0f) : 2.0f;
        QColor colour = heatColour(h.forceN, markers.heatMinN, markers.heatMaxN);
        colour.setAlphaF(0.8f);
        batches[{colour.rgba(), int(std::lround(2.0f * radiusPx))}].append(toPoint(*centre));
    }
    painter.setRenderHint(QPainter::Antialiasing, false);
    for (const auto& [key, points] : batches) {
        painter.setPen(QPen(QColor::fromRgba(key.first), key.second, Qt::SolidLine, Qt::RoundCap));
        painter.drawPoints(points.constData(), int(points.size()));
    }
}

/// The heat map under everything else (no depth test here), and its scale, bottom right (the
/// ring legend is bottom left).
void paintHeat(QPainter& painter, const ExerciseMarkers& markers, const OrbitCamera& camera, QSize sizePx) {
    const glm::vec2 size(float(sizePx.width()), float(sizePx.height()));
    static thread_local HeatLayer layer;  // the GUI thread's, shared by its viewport's frames
    const qreal ratio = painter.device() ? painter.device()->devicePixelRatioF() : 1.0;
    const glm::mat4 viewProjection = camera.projection(size.x / std::max(size.y, 1.0f)) * camera.view();
    const double checksum = heatChecksum(markers.heat);
    if (layer.viewProjection != viewProjection || layer.sizePx != sizePx || layer.pixelRatio != ratio ||
        layer.minN != markers.heatMinN || layer.maxN != markers.heatMaxN || layer.points != markers.heat.size() ||
        layer.checksum != checksum) {
        layer = HeatLayer{viewProjection,
                          sizePx,
                          ratio,
                          markers.heatMinN,
                          markers.heatMaxN,
                          checksum,
                          markers.heat.size(),
                          QImage((QSizeF(sizePx) * ratio).toSize(), QImage::Format_ARGB32_Premultiplied)};
        layer.image.setDevicePixelRatio(ratio);
        layer.image.fill(Qt::transparent);
        QPainter layerPainter(&layer.image);
        drawHeatDots(layerPainter, markers, camera, size);
    }
    painter.drawImage(QPointF(0.0, 0.0), layer.image);

    QFont small = QGuiApplication::font();
    small.setPixelSize(11);
    painter.setFont(small);
    const QString label = QCoreApplication::translate("palpate::ExerciseMarkers",
                                                      "examined from %1 N to %2 N (excessive)")
                              .arg(QLocale().toString(markers.heatMinN, 'g', 3),
                                   QLocale().toString(markers.heatMaxN, 'g', 3));
    const double labelWidth = QFontMetricsF(small).horizontalAdvance(label);
    const double width = std::max(140.0, labelWidth);
    const QRectF bar(double(size.x) - 12.0 - width, double(size.y) - 34.0, 140.0, 10.0);
    QLinearGradient gradient(bar.topLeft(), bar.topRight());
    gradient.setColorAt(0.0, heatColour(markers.heatMinN, markers.heatMinN, markers.heatMaxN));
    gradient.setColorAt(1.0, heatColour(markers.heatMaxN, markers.heatMinN, markers.heatMaxN));
    painter.setBrush(gradient);
    painter.setPen(QPen(QColor(0, 0, 0, 160), 1.0));
    painter.drawRect(bar);
    painter.setPen(QColor(0, 0, 0, 200));
    painter.drawText(bar.bottomLeft() + QPointF(1, 15), label);
    painter.setPen(Qt::white);
    painter.drawText(bar.bottomLeft() + QPointF(0, 14), label);
}

}  // namespace

QColor heatColour(double forceN, double minN, double maxN) { return coverageHeatColour(forceN, minN, maxN); }

void addCoverageHeat(ExerciseMarkers& markers, const ExerciseGeometry& geometry, const PalpationSummary& palpation) {
    const auto& rest = geometry.restMm();
    const auto& normals = geometry.normals();
    markers.heat.clear();
    // From the force that examines (amber) to the exercise's excessive force (red): a fixed scale
    // that means something, where the session's own largest force made a mouse's constant press
    // all red.
    markers.heatMinN = palpation.coverage.minForceN;
    markers.heatMaxN = geometry.exercise().excessiveForceN;
    double largestN = 0.0;
    for (std::size_t v = 0; v < palpation.peakForceN.size() && v < rest.size(); ++v) {
        const float f = palpation.peakForceN[v];
        if (!(f > 0.0f)) continue;
        markers.heat.push_back({rest[v], normals[v], f});
        largestN = std::max(largestN, double(f));
    }
    if (!(markers.heatMaxN > markers.heatMinN)) markers.heatMaxN = std::max(largestN, markers.heatMinN);
}

QColor exerciseMarkerColour(ExerciseMarker::Kind kind) {
    switch (kind) {
        case ExerciseMarker::Kind::Target: return QColor(255, 255, 255);
        case ExerciseMarker::Kind::CurrentTarget: return QColor(0, 200, 255);
        case ExerciseMarker::Kind::DoneTarget: return QColor(60, 200, 90);
        case ExerciseMarker::Kind::PathPoint: return QColor(255, 170, 0);
        case ExerciseMarker::Kind::Inclusion: return QColor(200, 60, 255);
        case ExerciseMarker::Kind::Mark: return QColor(255, 40, 40);
    }
    return Qt::white;
}

ExerciseMarkers exerciseMarkers(const ExerciseGeometry& geometry, MarkerAudience audience,
                                const ScoreGuidance* guidance, int selectedIndex) {
    ExerciseMarkers out;
    const ExerciseDrawing drawing =
        exerciseKind(geometry.exercise().type).draw(geometry, audience, guidance, selectedIndex);
    out.pathMm = drawing.pathMm;
    for (const SurfaceMarker& s : drawing.markers) {
        ExerciseMarker m;
        m.kind = s.kind;
        m.positionMm = s.positionMm;
        m.normal = s.normal;
        m.label = exerciseText(s.label);
        m.radiusMm = s.radiusMm;
        m.selected = s.selected;
        m.bodyRadiusMm = s.bodyRadiusMm;
        m.bodyCentreMm = s.bodyCentreMm;
        out.markers.push_back(m);
    }
    return out;
}

void paintExerciseMarkers(QPainter& painter, const ExerciseMarkers& markers, const OrbitCamera& camera, QSize sizePx) {
    if (markers.empty()) return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    const glm::vec2 size(float(sizePx.width()), float(sizePx.height()));

    if (!markers.heat.empty()) paintHeat(painter, markers, camera, sizePx);

    if (markers.pathMm.size() >= 2) {
        QPainterPath path;
        bool started = false;
        for (const glm::vec3& p : markers.pathMm) {
            const auto px = camera.projectToPixel(p, size);
            if (!px) {
                started = false;
                continue;
            }
            if (!started) path.moveTo(toPoint(*px));
            else path.lineTo(toPoint(*px));
            started = true;
        }
        painter.setBrush(Qt::NoBrush);
        painter.setPen(QPen(QColor(0, 0, 0, 170), 5.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        painter.drawPath(path);
        painter.setPen(QPen(exerciseMarkerColour(ExerciseMarker::Kind::PathPoint), 3.0, Qt::SolidLine, Qt::RoundCap,
                            Qt::RoundJoin));
        painter.drawPath(path);
    }

    QFont font = QGuiApplication::font();
    font.setPixelSize(12);
    font.setBold(true);
    painter.setFont(font);
    for (const ExerciseMarker& marker : markers.markers) {
        const auto centre = camera.projectToPixel(marker.positionMm, size);
        if (!centre) continue;
        QColor colour = exerciseMarkerColour(marker.kind);
        if (facesAway(marker, camera)) colour.setAlphaF(0.35f);
        if (marker.bodyRadiusMm > 0.0) paintBody(painter, marker, camera, size, colour);
        if (marker.radiusMm > 0.0) paintSurfaceCircle(painter, marker, camera, size, colour);
        const float radiusPx = marker.selected ? kSelectedRadiusPx : kMarkerRadiusPx;
        painter.setPen(QPen(QColor(0, 0, 0, int(200 * colour.alphaF())), marker.selected ? 3.0 : 1.5));
        painter.setBrush(colour);
        if (marker.kind == ExerciseMarker::Kind::Mark) {
            // A cross: where the trainee says the lump is.
            const QPointF c = toPoint(*centre);
            painter.setPen(QPen(colour, 3.0, Qt::SolidLine, Qt::RoundCap));
            painter.drawLine(c + QPointF(-radiusPx, -radiusPx), c + QPointF(radiusPx, radiusPx));
            painter.drawLine(c + QPointF(-radiusPx, radiusPx), c + QPointF(radiusPx, -radiusPx));
        } else {
            painter.drawEllipse(toPoint(*centre), radiusPx, radiusPx);
        }
        if (!marker.label.isEmpty()) {
            // Beside the marker, on the side away from its lump (never across the ball) and
            // inside the viewport.
            const QFontMetricsF metrics(font);
            const double textWidth = metrics.horizontalAdvance(marker.label);
            glm::vec2 away(1.0f, -1.0f);
            const std::optional<ProjectedBall> ball = projectedBall(marker, camera, size);
            if (ball) {
                const glm::vec2 towards = ball->centre - *centre;
                away = {towards.x > 0.0f ? -1.0f : 1.0f, towards.y > 0.0f ? -1.0f : 1.0f};
            }
            if (away.x > 0.0f && centre->x + radiusPx + 3.0f + float(textWidth) > size.x) away.x = -1.0f;
            if (away.x < 0.0f && centre->x - radiusPx - 3.0f - float(textWidth) < 0.0f) away.x = 1.0f;
            const double x = away.x > 0.0f ? radiusPx + 3.0 : -radiusPx - 3.0 - textWidth;
            double y = away.y < 0.0f ? -radiusPx - 2.0 : radiusPx + 12.0;
            QPointF at = toPoint(*centre) + QPointF(x, y);
            // Pushed to its ball's side by the viewport's edge: then above or below the ball.
            if (ball) {
                const QRectF text(at.x(), at.y() - metrics.ascent(), textWidth, metrics.height());
                const QRectF disc(toPoint(ball->centre) - QPointF(ball->radiusPx, ball->radiusPx),
                                  QSizeF(2.0 * ball->radiusPx, 2.0 * ball->radiusPx));
                if (text.intersects(disc))
                    at.setY(away.y < 0.0f ? std::min(at.y(), disc.top() - 2.0 - metrics.descent())
                                          : std::max(at.y(), disc.bottom() + 2.0 + metrics.ascent()));
            }
            at.setY(std::clamp(at.y(), metrics.ascent(), double(size.y) - metrics.descent()));
            // The label in a lighter tint of the marker's colour on a dark shadow, so it reads over the
            // tissue as over the background; a faded marker's label (a lump seen from the side, on the
            // far half) stays nearly opaque while the marker itself is faded.
            QColor text = exerciseMarkerColour(marker.kind).lighter(140);
            text.setAlphaF(colour.alphaF() < 1.0f ? 0.9f : 1.0f);
            painter.setPen(QColor(0, 0, 0, int(230 * text.alphaF())));
            painter.drawText(at + QPointF(1, 1), marker.label);
            painter.setPen(text);
            painter.drawText(at, marker.label);
        }
    }
    painter.restore();
}

}  // namespace palpate
