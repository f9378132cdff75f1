#include "widgets/ExerciseMarkers.h"

#include "engine/exercise/ExerciseKind.h"
#include "widgets/ExerciseText.h"

#include "report/HeatColour.h"

#include "widgets/OrbitCamera.h"

#include <QCoreApplication>
#include <QFont>
#include <QLinearGradient>
#include <QLocale>
#include <QGuiApplication>
#include <QPainter>
#include <QPainterPath>

#include <glm/geometric.hpp>

#include <algorithm>
#include <algorithm>
#include <cmath>

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
        out.markers.push_back(m);
    }
    return out;
}

void paintExerciseMarkers(QPainter& painter, const ExerciseMarkers& markers, const OrbitCamera& camera, QSize sizePx) {
    if (markers.empty()) return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    const glm::vec2 size(float(sizePx.width()), float(sizePx.height()));

    if (!markers.heat.empty()) {
        // Under everything else; only the side facing the camera (no depth test here).
        painter.setPen(Qt::NoPen);
        for (const HeatPoint& h : markers.heat) {
            if (glm::dot(h.normal, camera.eyeMm() - h.positionMm) <= 0.0f) continue;
            const auto centre = camera.projectToPixel(h.positionMm, size);
            if (!centre) continue;
            glm::vec3 u, v;
            tangentFrame(h.normal, u, v);
            const auto edge = camera.projectToPixel(h.positionMm + 1.6f * u, size);
            const float radiusPx = edge ? std::clamp(glm::length(*edge - *centre), 1.5f, 12.0f) : 2.0f;
            QColor colour = heatColour(h.forceN, markers.heatMinN, markers.heatMaxN);
            colour.setAlphaF(0.8f);
            painter.setBrush(colour);
            painter.drawEllipse(toPoint(*centre), radiusPx, radiusPx);
        }
        // The scale, bottom left.
        QFont small = QGuiApplication::font();
        small.setPixelSize(11);
        painter.setFont(small);
        const QRectF bar(12.0, double(size.y) - 34.0, 140.0, 10.0);
        QLinearGradient gradient(bar.topLeft(), bar.topRight());
        gradient.setColorAt(0.0, heatColour(markers.heatMinN, markers.heatMinN, markers.heatMaxN));
        gradient.setColorAt(1.0, heatColour(markers.heatMaxN, markers.heatMinN, markers.heatMaxN));
        painter.setBrush(gradient);
        painter.setPen(QPen(QColor(0, 0, 0, 160), 1.0));
        painter.drawRect(bar);
        const QString label = QCoreApplication::translate("palpate::ExerciseMarkers",
                                                          "examined from %1 N to %2 N (excessive)")
                                  .arg(QLocale().toString(markers.heatMinN, 'g', 3),
                                       QLocale().toString(markers.heatMaxN, 'g', 3));
        painter.setPen(QColor(0, 0, 0, 200));
        painter.drawText(bar.bottomLeft() + QPointF(1, 15), label);
        painter.setPen(Qt::white);
        painter.drawText(bar.bottomLeft() + QPointF(0, 14), label);
    }

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
            const QPointF at = toPoint(*centre) + QPointF(radiusPx + 3.0, -radiusPx - 2.0);
            painter.setPen(QColor(0, 0, 0, int(220 * colour.alphaF())));
            painter.drawText(at + QPointF(1, 1), marker.label);
            painter.setPen(colour);
            painter.drawText(at, marker.label);
        }
    }
    painter.restore();
}

}  // namespace palpate
