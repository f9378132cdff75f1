#include "widgets/ExerciseMarkers.h"

#include "widgets/OrbitCamera.h"

#include <QFont>
#include <QGuiApplication>
#include <QPainter>
#include <QPainterPath>

#include <glm/geometric.hpp>

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
    const Exercise& exercise = geometry.exercise();
    const auto normalOf = [&](VertexId v) {
        return v < geometry.normals().size() ? geometry.normals()[v] : glm::vec3(0.0f);
    };
    switch (exercise.type) {
        case ExerciseType::PressTargets: {
            const auto& targets = geometry.targets();
            for (std::size_t i = 0; i < targets.size(); ++i) {
                ExerciseMarker m;
                m.kind = ExerciseMarker::Kind::Target;
                if (guidance && guidance->targetIndex >= 0) {
                    if (int(i) < guidance->targetIndex) m.kind = ExerciseMarker::Kind::DoneTarget;
                    else if (int(i) == guidance->targetIndex) m.kind = ExerciseMarker::Kind::CurrentTarget;
                } else if (guidance && guidance->completed) {
                    m.kind = ExerciseMarker::Kind::DoneTarget;
                }
                m.positionMm = targets[i].pointMm;
                m.normal = normalOf(targets[i].vertex);
                m.label = QString::number(i + 1);
                // The tolerance circle helps the instructor place targets and the trainee aim.
                m.radiusMm = targets[i].def.toleranceMm;
                m.selected = int(i) == selectedIndex;
                out.markers.push_back(m);
            }
            break;
        }
        case ExerciseType::FindLump: {
            if (audience == MarkerAudience::Instructor && geometry.lumpVertex() != kNoVertex) {
                ExerciseMarker m;
                m.kind = ExerciseMarker::Kind::Inclusion;
                m.positionMm = geometry.lumpCentreMm();
                m.normal = normalOf(geometry.lumpVertex());
                m.radiusMm = exercise.findLump.inclusion.radiusMm;
                m.label = QStringLiteral("lump");
                m.selected = selectedIndex == 0;
                out.markers.push_back(m);
            }
            break;
        }
        case ExerciseType::Trace: {
            out.pathMm = geometry.pathMm();
            for (std::size_t i = 0; i < exercise.trace.path.size() && i < geometry.pathMm().size(); ++i) {
                ExerciseMarker m;
                m.kind = ExerciseMarker::Kind::PathPoint;
                m.positionMm = geometry.pathMm()[i];
                const VertexId v = i < geometry.pathVertices().size() ? geometry.pathVertices()[i] : kNoVertex;
                m.normal = normalOf(v);
                m.label = i == 0 ? QStringLiteral("start") : (i + 1 == exercise.trace.path.size() ? QStringLiteral("end") : QString());
                m.selected = int(i) == selectedIndex;
                out.markers.push_back(m);
            }
            break;
        }
    }
    return out;
}

void paintExerciseMarkers(QPainter& painter, const ExerciseMarkers& markers, const OrbitCamera& camera, QSize sizePx) {
    if (markers.empty()) return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    const glm::vec2 size(float(sizePx.width()), float(sizePx.height()));

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
