#pragma once
// A graded exercise: what the trainee must do on which tissue, in how long, and how it is graded.
// Four types: press a sequence of surface targets with a force inside a window and hold it; find
// a hidden stiff inclusion by palpation and mark it; trace a path on the surface keeping contact
// and the force in a band; examine the surface for zero or more lumps under it and mark each. Stored as versioned JSON (ExerciseFile.h); every key is in
// docs/scoring.md.

#include "engine/core/MeshUnit.h"
#include "engine/lod/LodNeeds.h"
#include "engine/exercise/Metric.h"
#include "engine/exercise/PalpationResult.h"
#include "engine/exercise/Rubric.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

inline constexpr int kExerciseVersion = 1;

/// The text of the Mark event with which a trainee ends a detect-lumps examination (every other
/// mark is a finding).
inline constexpr const char* kExaminationDoneMark = "examination done";

/// A point on the tissue surface: a vertex of the mesh file (in the file's own numbering, as a
/// mesh viewer shows it), or a point in the mesh's frame, snapped to the nearest vertex at rest.
struct SurfacePoint {
    std::optional<std::uint32_t> vertex;
    glm::vec3 pointMm{0.0f};  ///< used when `vertex` is empty
};

/// Press targets: one target.
struct PressTarget {
    SurfacePoint at;
    double forceMinN = 1.0;    ///< the window [forceMinN, forceMaxN] on |F| rendered
    double forceMaxN = 2.0;
    double holdS = 1.0;        ///< time to stay on the target inside the window without a break
    double toleranceMm = 3.0;  ///< the contact point must be this close to the target
};

struct PressTargetsDef {
    std::vector<PressTarget> targets;  ///< done in this order
};

/// Find the lump: a stiffer region of the tissue (the physics changes: CoherentSlopeRing's
/// compliance factors).
struct InclusionDef {
    SurfacePoint centre;            ///< snapped to a vertex
    double radiusMm = 10.0;         ///< vertices this close to the centre (at rest) are in it
    double stiffnessFactor = 0.25;  ///< their slopes are multiplied by this, in (0, 1]: smaller is stiffer
};

struct FindLumpDef {
    InclusionDef inclusion;
};

/// Detect lumps: one lump hidden under the surface (docs/scoring.md, "Lumps under the surface"): a
/// sphere of `radiusMm` whose top lies `depthMm` below the surface point `at`, `contrast` times
/// stiffer than the tissue. Pressing above it is soft until the surface has sunk to the lump's top,
/// then stiffer: a deeper lump needs a firmer press to be felt.
struct LumpDef {
    SurfacePoint at;          ///< the surface point above the lump's centre, snapped to a vertex
    double radiusMm = 6.0;
    double depthMm = 2.0;     ///< from the surface to the lump's top, >= 0
    double contrast = 4.0;    ///< lump stiffness / tissue stiffness, > 1
};

/// Adaptive difficulty (docs/scoring.md, "Staircase"): the level of one lump property across a
/// trainee's trials, made harder after `down` passed trials in a row and easier after `up` failed
/// ones, between the easiest and the hardest level.
struct StaircaseDef {
    enum class Parameter { Contrast, DepthMm };
    Parameter parameter = Parameter::Contrast;  ///< every lump of the exercise takes the level
    double start = 4.0;      ///< the first trial's level
    double step = 0.5;       ///< the change per move, > 0
    double easiest = 6.0;    ///< contrast: high is easy; depth: shallow is easy
    double hardest = 1.2;
    int down = 2;
    int up = 1;
};

struct DetectLumpsDef {
    std::vector<LumpDef> lumps;      ///< may be empty: then every finding is a false alarm
    double toleranceMm = 5.0;        ///< a finding within a lump's radius plus this of its centre can hit it
    std::optional<StaircaseDef> staircase;
};

/// Trace: a polyline on the surface.
struct TraceDef {
    std::vector<SurfacePoint> path;  ///< at least 2 points, each snapped to a vertex
    double forceMinN = 0.5;          ///< the band [forceMinN, forceMaxN] on |F|
    double forceMaxN = 1.5;
    double toleranceMm = 4.0;        ///< a path point is covered by contact this close to it
};

/// An exercise's name and description in another language; an empty field falls back to the
/// exercise's own (docs/scoring.md, "Translations").
struct ExerciseTextDef {
    std::string name;
    std::string description;
};

struct Exercise {
    std::string name;  ///< also the key results are stored and grouped under, in every language
    std::string description;
    /// "translations": language code ("de", "ms", "pt_BR") -> the words shown to a user of that
    /// language. The name above stays the exercise's identity.
    std::map<std::string, ExerciseTextDef> translations;
    ExerciseType type = ExerciseType::PressTargets;
    std::string meshPath;           ///< as written: absolute, relative to the file, or to resources/
    /// "mesh_unit": the unit of the mesh file's coordinates (docs/meshes.md, "Units"); the mesh is
    /// scaled to mm by it wherever it is loaded. Absent in a file: mm.
    MeshUnit meshUnit;
    std::string tissuePresetPath;   ///< the same
    double timeLimitS = 60.0;       ///< ticks after it are not scored
    double displacementLimitMm = 10.0;  ///< tissue displaced further than this counts as damage
    double excessiveForceN = 3.0;   ///< |F| above this is excessive
    /// "show_live_score": whether the trainee sees the score while the exercise runs. Absent: the
    /// kind's default (ExerciseKind::showsLiveScore; hidden in detect lumps, where it would say
    /// which marks hit). docs/scoring.md, "Live and replayed scores are the same".
    std::optional<bool> showLiveScore;
    PressTargetsDef pressTargets;   ///< type PressTargets
    FindLumpDef findLump;           ///< type FindLump
    TraceDef trace;                 ///< type Trace
    DetectLumpsDef detectLumps;     ///< type DetectLumps
    /// "coverage": which contacts examine the surface (find the lump, detect lumps).
    CoverageDef coverage;
    /// The rubric lines the exercise sets; metrics without one use defaultRubricItem().
    std::array<std::optional<RubricItem>, kMetricCount> rubric{};
    /// "needs": the accuracy target and haptic budget the model must meet (docs/lod.md); absent
    /// means the exercise states none. Checked by parseExercise and saveExercise (validateLodNeeds).
    std::optional<LodNeeds> needs;
    /// The file it was read from (relative paths resolve from its folder); not saved.
    std::string sourcePath;
};

/// The name and description a user of `language` ("de", or "de_AT", which falls back to "de") reads:
/// the translation's fields where it gives them, the exercise's own otherwise.
ExerciseTextDef exerciseTextIn(const Exercise& exercise, const std::string& language);
/// Whether `code` is a language code a translation may be filed under: two or three lower-case
/// letters, then optionally "_" and two upper-case letters.
bool isLanguageCode(const std::string& code);

/// Every problem, each naming the key as in the JSON file ("press_targets.targets[1].force_max_n:
/// ..."); empty when valid. Vertex ids are checked against a mesh later (ExerciseGeometry).
Problems validateExercise(const Exercise& exercise);

/// The default rubric line for a metric of this exercise (docs/scoring.md lists them): weights per
/// type, thresholds from the exercise's own numbers (time limit, tolerances, excessive force).
RubricItem defaultRubricItem(const Exercise& exercise, Metric metric);
/// The rubric the exercise is graded by: its own lines, defaults for the rest; zero weight for
/// metrics of other types.
Rubric effectiveRubric(const Exercise& exercise);

}  // namespace palpate
