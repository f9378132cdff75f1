#include "engine/scoring/Proficiency.h"
#include "engine/exercise/ExerciseKind.h"

#include <cmath>

namespace palpate {

const MetricStandard* ProficiencyStandard::find(const std::string& metric) const {
    for (const MetricStandard& m : metrics)
        if (m.metric == metric) return &m;
    return nullptr;
}

ProficiencyStandard buildProficiencyStandard(const Exercise& exercise, const std::vector<MetricValues>& experts,
                                             const ProficiencyParams& params) {
    ProficiencyStandard standard;
    standard.expertSessions = experts.size();
    if (experts.size() < params.minExpertSessions) {
        standard.problem = "no standard: " + std::to_string(experts.size()) + " expert session" +
                           (experts.size() == 1 ? "" : "s") + " of '" + exercise.name + "', at least " +
                           std::to_string(params.minExpertSessions) + " needed";
        return standard;
    }
    const Rubric rubric = effectiveRubric(exercise);
    for (std::size_t i = 0; i < kMetricCount; ++i) {
        const Metric metric = Metric(i);
        if (!exerciseKind(exercise.type).measures(metric)) continue;
        const std::string name(metricName(metric));
        std::vector<double> values;
        for (const MetricValues& e : experts)
            if (const auto it = e.find(name); it != e.end() && it->second && std::isfinite(*it->second))
                values.push_back(*it->second);
        if (values.empty()) continue;
        MetricStandard line;
        line.metric = name;
        line.expertSessions = values.size();
        double sum = 0.0;
        for (double v : values) sum += v;
        line.mean = sum / double(values.size());
        if (values.size() >= 2) {
            double squares = 0.0;
            for (double v : values) squares += (v - line.mean) * (v - line.mean);
            line.sd = std::sqrt(squares / double(values.size() - 1));
        }
        const RubricItem& item = rubric[i];
        line.higherIsBetter = !(item.fullMarks < item.zeroMarks);
        line.passMark = line.higherIsBetter ? line.mean - params.markSd * line.sd : line.mean + params.markSd * line.sd;
        line.deciding = item.weight > 0.0 && values.size() >= params.minExpertSessions;
        standard.metrics.push_back(line);
    }
    bool anyDeciding = false;
    for (const MetricStandard& m : standard.metrics) anyDeciding |= m.deciding;
    if (!anyDeciding)
        standard.problem = "no standard: the expert sessions of '" + exercise.name +
                           "' measure no metric the rubric weights";
    return standard;
}

SessionVerdict judgeSession(const ProficiencyStandard& standard, const MetricValues& session) {
    SessionVerdict verdict;
    verdict.passed = standard.valid();
    for (const MetricStandard& m : standard.metrics) {
        std::optional<bool> passed;
        if (const auto it = session.find(m.metric); it != session.end() && it->second) passed = m.passes(*it->second);
        verdict.metrics.emplace_back(m.metric, passed);
        if (m.deciding && !passed.value_or(false)) verdict.passed = false;
    }
    return verdict;
}

ProficiencyProgress judgeSessions(const ProficiencyStandard& standard, const std::vector<MetricValues>& sessions,
                                  const ProficiencyParams& params) {
    ProficiencyProgress progress;
    if (!standard.valid()) return progress;
    int inARow = 0;
    for (const MetricValues& s : sessions) {
        SessionVerdict v = judgeSession(standard, s);
        inARow = v.passed ? inARow + 1 : 0;
        v.consecutivePasses = inARow;
        if (!progress.proficientAt && inARow >= params.passesInARow) progress.proficientAt = progress.sessions.size();
        progress.sessions.push_back(std::move(v));
    }
    return progress;
}

}  // namespace palpate
