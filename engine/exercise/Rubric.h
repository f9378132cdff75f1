#pragma once
// How metrics become a score: each metric gets a 0..1 sub-score, linear between a "zero marks"
// and a "full marks" value (either way round: full below zero means lower is better), and the
// score is 100 * sum(w_i s_i) / sum(w_i) over the exercise's rubric. docs/scoring.md has the rules
// and the defaults.

#include "engine/exercise/Metric.h"

#include <array>
#include <optional>

namespace palpate {

struct ScoreReport;

/// One rubric line.
struct RubricItem {
    double weight = 0.0;     ///< relative weight, >= 0 (0: reported, not scored)
    double fullMarks = 1.0;  ///< at or beyond this value the sub-score is 1
    double zeroMarks = 0.0;  ///< at or beyond this value (away from fullMarks) it is 0; != fullMarks
};

/// One item per metric; items of metrics that do not apply to the exercise type are ignored.
using Rubric = std::array<RubricItem, kMetricCount>;

/// The sub-score rule: (value - zero) / (full - zero), clamped to [0, 1].
double subScore(const RubricItem& item, double value);

/// Fills each metric's sub-score, weight and contribution in `report` and its score. A metric
/// without a value (report says not measured) scores 0. A session that did nothing of the task
/// (completion 0) scores 0 in every line: the other lines grade how the task was done. Time
/// scores only when the task was completed. A metric that counts errors (MetricRow::countsErrors)
/// earns its sub-score times the report's work done.
void applyRubric(const Rubric& rubric, ScoreReport& report);

}  // namespace palpate
