#pragma once
// The part of scoring that differs between kinds of exercise: what the trainee must do, tick by
// tick, and the metrics only that task has. The Scorer (engine/scoring) keeps what every session
// measures (time, force, damage, path) and hands each tick of exercise time to the task its kind
// made (ExerciseKind::makeTask). docs/scoring.md defines each metric.

#include "engine/core/TissueMesh.h"
#include "engine/exercise/ScoreReport.h"

#include <glm/vec3.hpp>

#include <array>
#include <optional>

namespace palpate {

/// One tick of exercise time, as a task sees it.
struct TaskTick {
    double dtS = 0.0;                ///< its length
    double elapsedS = 0.0;           ///< exercise time so far, this tick included
    double forceN = 0.0;             ///< |F| rendered
    bool contact = false;
    bool haveContactPoint = false;   ///< the tool's position is known
    glm::vec3 contactPointMm{0.0f};  ///< the tip on the touched vertex's rest tangent plane
    VertexId touched = kNoVertex;
    double maxDisplacementMm = 0.0;  ///< the deepest any vertex is displaced now
    bool mark = false;               ///< the trainee marked (a button or a Mark event)
    bool done = false;               ///< the trainee said the examination is done
};

/// The metric lines of a report, filled in any order and read in Metric order.
struct MeasuredMetrics {
    std::array<std::optional<MetricResult>, kMetricCount> lines{};

    /// `measured` false: nothing to measure (the line scores 0 and shows no value).
    void put(Metric metric, double value, bool measured = true) {
        MetricResult line;
        line.metric = metric;
        line.measured = measured;
        line.value = measured ? value : 0.0;
        lines[std::size_t(metric)] = line;
    }
};

class ExerciseTask {
public:
    virtual ~ExerciseTask() = default;

    /// Before the first tick: the kind's part of the guidance (the first target's window, ...).
    virtual void start(ScoreGuidance& guidance) { (void)guidance; }
    /// One tick of exercise time; keeps the kind's part of `guidance`. True when this tick
    /// completed the task (the exercise is then over).
    virtual bool step(const TaskTick& tick, ScoreGuidance& guidance) = 0;
    /// The share of the task done, 0..1 (the completion metric).
    virtual double completion(const ScoreGuidance& guidance) const = 0;
    /// How much of the work was done, 0..1: the metrics that count errors earn their points in
    /// this proportion (docs/scoring.md, "The rubric"), so that doing nothing earns nothing for
    /// making no mistakes. The completion unless the kind says otherwise.
    virtual double workDone(const ScoreGuidance& guidance) const { return completion(guidance); }
    /// The shortest tool path from `startMm` through what was done (the economy metric); none when
    /// nothing was done or the kind has no such path.
    virtual std::optional<double> idealPathMm(const glm::vec3& startMm) const {
        (void)startMm;
        return std::nullopt;
    }
    /// The kind's own metrics and report parts (targets, the palpation summary). `detail`: also
    /// what only the end needs (heat map, force by phase).
    virtual void report(ScoreReport& report, MeasuredMetrics& metrics, bool detail) const = 0;
};

}  // namespace palpate
