#pragma once
// What the viewport draws of an exercise over the mesh: press targets (numbered, the current one
// highlighted, done ones ticked), the trace path, and the inclusion of find-the-lump (shown to the
// instructor who places it, hidden from the trainee who must find it), plus the trainee's mark.
// Both renderers paint them with QPainter over the scene, like the tool marker (SceneOverlay).

#include "engine/exercise/ExerciseGeometry.h"
#include "engine/exercise/ExerciseView.h"
#include "engine/exercise/ScoreReport.h"

#include <QColor>
#include <QSize>
#include <QString>

#include <glm/vec3.hpp>

#include <optional>
#include <vector>

class QPainter;

namespace palpate {

class OrbitCamera;

struct ExerciseMarker {
    using Kind = SurfaceMarkerKind;
    Kind kind = Kind::Target;
    glm::vec3 positionMm{0.0f};
    glm::vec3 normal{0.0f};  ///< outward rest normal (zero: unknown); markers facing away are faded
    QString label;           ///< drawn beside it ("1", "2", ...); may be empty
    double radiusMm = 0.0;   ///< > 0: a circle of this radius on the surface (tolerance, inclusion)
    bool selected = false;   ///< the one the instructor is editing: drawn larger
    /// > 0: a sphere inside the tissue (a lump) drawn through the surface, joined to the marker by
    /// a dashed line its depth long, so the instructor sees how deep and how large it is.
    double bodyRadiusMm = 0.0;
    glm::vec3 bodyCentreMm{0.0f};
};

/// One examined vertex of the coverage heat map (docs/scoring.md, "Coverage").
struct HeatPoint {
    glm::vec3 positionMm{0.0f};
    glm::vec3 normal{0.0f};
    float forceN = 0.0f;  ///< the largest force that covered it
};

struct ExerciseMarkers {
    std::vector<ExerciseMarker> markers;
    std::vector<glm::vec3> pathMm;  ///< the trace polyline (empty: none)
    /// The coverage heat map: only the examined vertices (the rest keep the tissue's colour), and
    /// the scale's ends (the coverage force and the largest force).
    std::vector<HeatPoint> heat;
    double heatMinN = 0.0, heatMaxN = 0.0;
    bool empty() const { return markers.empty() && pathMm.empty() && heat.empty(); }
    /// Whether a lump inside the tissue is shown: then the surface is drawn see-through.
    bool seeThrough() const {
        for (const ExerciseMarker& m : markers)
            if (m.bodyRadiusMm > 0.0) return true;
        return false;
    }
};

/// The heat map of a palpation score over `geometry`'s rest surface: a point per examined vertex.
void addCoverageHeat(ExerciseMarkers& markers, const ExerciseGeometry& geometry, const PalpationSummary& palpation);
/// The heat map's colour for a force on the scale [minN, maxN] (tests look for it).
QColor heatColour(double forceN, double minN, double maxN);

/// The markers of an exercise placed on a mesh, as its kind draws them (ExerciseKind::draw).
/// `guidance` (a running session) marks the current and the achieved targets; `selectedIndex`
/// (instructor) is the item being edited.
ExerciseMarkers exerciseMarkers(const ExerciseGeometry& geometry, MarkerAudience audience,
                                const ScoreGuidance* guidance = nullptr, int selectedIndex = -1);

/// The colour a marker of this kind is drawn in (tests look for it).
QColor exerciseMarkerColour(ExerciseMarker::Kind kind);

/// Paints the markers for a viewport of `sizePx` seen through `camera` (no depth test: markers on
/// the far side are drawn faded, so the instructor sees every target).
void paintExerciseMarkers(QPainter& painter, const ExerciseMarkers& markers, const OrbitCamera& camera,
                          QSize sizePx);

}  // namespace palpate
