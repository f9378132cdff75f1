#pragma once
// What scoring a session gives: the score, each metric with its value, sub-score, weight and
// contribution, the state of the task (for the GUI's guidance and score card), and warnings (a
// recording with gaps, a replay that differs). The same structure comes from a live session and
// from a recording; for one session both are equal bit for bit.

#include "engine/exercise/Metric.h"
#include "engine/exercise/PalpationResult.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

struct MetricResult {
    Metric metric = Metric::Completion;
    double value = 0.0;
    bool measured = true;       ///< false: nothing to measure (no target pressed, no mark): sub-score 0
    double subScore = 0.0;      ///< 0..1 (Rubric)
    double weight = 0.0;
    double contribution = 0.0;  ///< points of the 0..100 score: 100 w s / sum(w)
    double fullMarks = 0.0, zeroMarks = 0.0;  ///< the rubric line it was graded by
};

/// Press targets: how each target went.
struct TargetResult {
    bool achieved = false;
    double achievedAtS = 0.0;       ///< exercise time when its hold was complete
    double errorMm = 0.0;           ///< mean distance while pressing inside its window
    bool errorMeasured = false;
    double onTargetS = 0.0;         ///< time on it in contact
    double inWindowS = 0.0;         ///< of which inside the force window
};

/// Where the trainee is in the task: what the GUI shows while the session runs.
struct ScoreGuidance {
    double exerciseTimeS = 0.0;     ///< scored (unpaused) time so far
    double timeLeftS = 0.0;
    bool completed = false;         ///< the task is done (then the exercise is over)
    bool timeUp = false;            ///< the time limit passed before completion
    bool over() const { return completed || timeUp; }
    double forceN = 0.0;            ///< |F| at the last scored tick
    bool contact = false;
    // Press targets.
    int targetIndex = -1;           ///< current target (-1: none left or not a press exercise)
    int targetCount = 0;
    double holdProgress = 0.0;      ///< 0..1 of the current target's hold
    double forceMinN = 0.0, forceMaxN = 0.0;  ///< the current window (press) or band (trace)
    bool onTarget = false;          ///< contact point within the target's tolerance, in contact
    double distanceToTargetMm = 0.0;
    // Find the lump.
    bool marked = false;
    // Detect lumps: findings marked so far, and the covered share of the surface.
    int findings = 0;
    double coverageFraction = 0.0;
    // Trace.
    double pathCovered = 0.0;       ///< 0..1
    double distanceToPathMm = 0.0;
};

struct ScoreReport {
    std::string exerciseName;
    ExerciseType type = ExerciseType::PressTargets;
    double score = 0.0;                     ///< 0..100
    /// 0..1: how much of the work was done (ExerciseTask::workDone); the metrics that count errors
    /// are weighted by it (docs/scoring.md, "The rubric").
    double workDone = 1.0;
    std::vector<MetricResult> metrics;      ///< the metrics of the exercise's type, in Metric order
    std::vector<TargetResult> targets;      ///< press targets only
    ScoreGuidance guidance;
    std::uint64_t ticksScored = 0;
    std::uint64_t ticksAfterEnd = 0;        ///< ticks after completion or the time limit (not scored)
    std::uint64_t firstTick = 0, lastTick = 0;
    std::uint64_t marks = 0;                ///< marks seen (button presses and Mark events)
    std::vector<std::string> warnings;
    /// Find the lump and detect lumps: coverage, the heat map, force by phase, detection, feedback.
    std::optional<PalpationSummary> palpation;
    /// The guidance aids shown while the session ran (filled by the GUI; empty from the CLI).
    std::vector<GuidanceAid> aids;

    /// The line for a metric (nullptr when the type does not measure it).
    const MetricResult* find(Metric metric) const;
};

/// `{"score", "metrics": {name: value|null}, "rubric": {name: {value, sub_score, weight,
/// contribution, full, zero}}, ...}` as text (what `palpate-cli score --json` prints).
std::string scoreReportToJson(const ScoreReport& report, int indent = 2);
/// The breakdown as a table for people.
std::string scoreReportToText(const ScoreReport& report);

}  // namespace palpate
