#pragma once
// One descriptor per kind of exercise (docs/conventions.md, "Adding an exercise type"): everything
// that differs between press targets, find the lump, trace and detect lumps, said once beside its
// code: its name and file section, its checks, the metrics it measures and their default weights,
// what it places on the mesh and how the tissue changes there, how hard it asks the trainee to
// press, and the task that scores it. The file reader and writer, the validator, the geometry, the
// demands, the scorer and the windows read the descriptor; nothing else asks which kind an
// exercise is.

#include "engine/exercise/Exercise.h"
#include "engine/exercise/ExerciseChecker.h"
#include "engine/exercise/ExerciseDemands.h"
#include "engine/exercise/ExerciseEditing.h"
#include "engine/exercise/ExerciseTask.h"
#include "engine/exercise/ExerciseView.h"

#include <nlohmann/json_fwd.hpp>

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace palpate {

class JsonReader;
class ExerciseGeometry;
struct PlacedGeometry;
class GeometryPlacer;
using Json = nlohmann::ordered_json;

/// A metric's default weight in a kind's rubric.
struct MetricWeight {
    Metric metric;
    double weight;
};

class ExerciseKind {
public:
    virtual ~ExerciseKind() = default;

    virtual ExerciseType type() const = 0;
    /// "press_targets": the file's "type" value and the key of the kind's section.
    virtual std::string_view key() const = 0;
    /// "Press targets": the kind's name for people, English; translated in the context
    /// kExerciseTextContext.
    virtual const char* label() const = 0;

    /// The trainee examines the surface (coverage is measured, search and palpation told apart, the
    /// exercise's "coverage" section applies).
    virtual bool palpation() const { return false; }
    /// The exercise changes the tissue where it places things (an inclusion, lumps): it needs the
    /// coherent slope-ring model, and a recording carries the change for its replay.
    virtual bool changesTissue() const { return false; }
    /// The trainee ends the exercise (Finish) instead of it ending when the task is done.
    virtual bool finishedByTrainee() const { return false; }
    /// The exercise may carry a staircase of adaptive difficulty (docs/scoring.md, "Staircase").
    virtual bool adaptive() const { return false; }
    /// Whether the trainee sees the score so far by default (an exercise's "show_live_score" says
    /// otherwise): not where its changes would give the answer away.
    virtual bool showsLiveScore() const { return true; }

    /// The metrics only some kinds measure that this one does (every kind measures the metrics
    /// whose row says so, MetricRow::everyKind).
    virtual std::span<const Metric> ownMetrics() const = 0;
    /// The default weights of the rubric (docs/scoring.md lists them); a metric not listed has 0.
    virtual std::span<const MetricWeight> defaultWeights() const = 0;
    /// Whether the kind measures the metric (its line appears in the report and may be weighted).
    bool measures(Metric metric) const;
    /// The default weight of a metric (0 when not listed or not measured).
    double defaultWeight(Metric metric) const;
    /// The default weight for this exercise: defaultWeight unless the exercise's content moves
    /// weight between lines (detect lumps without lumps: reporting nothing is the finding).
    virtual double defaultWeight(const Exercise& exercise, Metric metric) const { (void)exercise; return defaultWeight(metric); }
    /// Whether a measured metric counts for this exercise (an exercise without lumps has nothing
    /// to find: sensitivity does not count).
    virtual bool counts(const Exercise& exercise, Metric metric) const {
        (void)exercise;
        (void)metric;
        return true;
    }

    /// The keys the kind's section may hold.
    virtual std::vector<std::string> sectionKeys() const = 0;
    /// Reads the kind's section (present and an object) into `exercise`; problems go to `reader`.
    virtual void readSection(JsonReader& reader, const Json& section, Exercise& exercise) const = 0;
    /// The kind's section as the file writes it.
    virtual Json writeSection(const Exercise& exercise) const = 0;
    /// The kind's own checks, each naming its key.
    virtual void validate(const Exercise& exercise, ExerciseChecker& check) const = 0;

    /// Snaps what the kind places (targets, the inclusion, the path, lumps) to the mesh and says
    /// how the tissue changes; the first problem goes to `error`, naming the key.
    virtual void place(const Exercise& exercise, GeometryPlacer& placer, PlacedGeometry& placed, std::string& error) const = 0;
    /// How hard or how deep the exercise asks the trainee to press (docs/lod.md).
    virtual std::vector<ExerciseDemand> demands(const Exercise& exercise) const = 0;
    /// The task that scores a session of the exercise.
    virtual std::unique_ptr<ExerciseTask> makeTask(std::shared_ptr<const ExerciseGeometry> geometry, double periodS) const = 0;

    /// What the viewport draws of the exercise for `audience`; `guidance` (a running or finished
    /// session) marks progress, `selected` (the instructor's) is the item being edited.
    virtual ExerciseDrawing draw(const ExerciseGeometry& geometry, MarkerAudience audience,
                                 const ScoreGuidance* guidance, int selected) const = 0;
    /// What the exercise editor edits of the kind: the points it places and their numbers, the
    /// section's numbers.
    virtual const ExerciseEditing& editing() const = 0;

    /// What the trainee is told at this point of the session.
    virtual GuidanceView guidance(const Exercise& exercise, const ScoreGuidance& guidance) const = 0;
};

/// The translation context of the kinds' texts (labels), the engine's own.
inline constexpr const char* kExerciseTextContext = "palpate::Exercises";

/// Every kind, in the order the windows list them.
std::span<const ExerciseKind* const> exerciseKinds();
/// The descriptor of a kind.
const ExerciseKind& exerciseKind(ExerciseType type);
/// The kind whose key this is ("press_targets"); null when none.
const ExerciseKind* findExerciseKind(std::string_view key);
/// Whether the trainee sees the live score of this exercise: its "show_live_score", else its
/// kind's default.
bool showsLiveScore(const Exercise& exercise);
/// The kind's key ("press_targets").
std::string_view exerciseTypeName(ExerciseType type);
/// The type whose kind has this key.
std::optional<ExerciseType> parseExerciseType(std::string_view name);

}  // namespace palpate
