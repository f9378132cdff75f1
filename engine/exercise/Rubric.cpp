#include "engine/exercise/Rubric.h"

#include "engine/exercise/ScoreReport.h"

#include <algorithm>
#include <cmath>

namespace palpate {

double subScore(const RubricItem& item, double value) {
    if (!std::isfinite(value)) return 0.0;
    const double span = item.fullMarks - item.zeroMarks;
    if (span == 0.0) return value == item.fullMarks ? 1.0 : 0.0;  // refused by validation; defined anyway
    return std::clamp((value - item.zeroMarks) / span, 0.0, 1.0);
}

void applyRubric(const Rubric& rubric, ScoreReport& report) {
    const MetricResult* completion = report.find(Metric::Completion);
    const bool nothingDone = completion && completion->value <= 0.0;
    double totalWeight = 0.0;
    for (const MetricResult& m : report.metrics) totalWeight += rubric[std::size_t(m.metric)].weight;
    double score = 0.0;
    for (MetricResult& m : report.metrics) {
        const RubricItem& item = rubric[std::size_t(m.metric)];
        m.weight = item.weight;
        m.fullMarks = item.fullMarks;
        m.zeroMarks = item.zeroMarks;
        m.subScore = m.measured && !nothingDone ? subScore(item, m.value) : 0.0;
        // Time is graded only for a task that was completed (giving up early is not fast).
        if (m.metric == Metric::TimeS && !report.guidance.completed) m.subScore = 0.0;
        // No points for the absence of errors without the work they guard.
        const MetricRow& row = metricRow(m.metric);
        if (row.countsErrors) m.subScore *= std::clamp(report.workDone, 0.0, 1.0);
        if (row.creditTimes != Metric::Count)
            if (const MetricResult* by = report.find(row.creditTimes); by && by->measured)
                m.subScore *= std::clamp(by->value, 0.0, 1.0);
        m.contribution = totalWeight > 0.0 ? 100.0 * item.weight * m.subScore / totalWeight : 0.0;
        score += m.contribution;
    }
    report.score = std::clamp(score, 0.0, 100.0);
}

}  // namespace palpate
