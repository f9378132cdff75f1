#pragma once
// What a learning curve shows (docs/scoring.md, "Proficiency"): per metric the trainee's values,
// session by session, against the experts' pass mark. The results make it; report/ draws it.

#include <QString>

#include <optional>
#include <vector>

namespace palpate {

struct LearningCurveMetric {
    QString key;                           ///< the metric's key ("sensitivity"); report/ names it
    std::vector<std::optional<double>> values;  ///< per session, oldest first; nullopt: not measured
    std::optional<double> passMark;        ///< none: no standard for it
    bool higherIsBetter = true;
    std::optional<double> expertMean;
};

struct LearningCurveData {
    QString title;
    std::vector<LearningCurveMetric> metrics;
    std::vector<bool> passed;              ///< per session (empty: no standard)
    std::optional<int> proficientAtSession;  ///< 1-based
};

}  // namespace palpate
