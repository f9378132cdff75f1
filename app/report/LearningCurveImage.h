#pragma once
// A trainee's learning curve as a PNG (palpate-cli trainee curve --png; docs/scoring.md,
// "Proficiency"): one small plot per metric, the session number along x, the side of the experts'
// pass mark that passes shaded, the mark drawn, each session's point green when it passed.

#include <QString>

#include <optional>
#include <string>
#include <vector>

namespace palpate {

struct LearningCurveMetric {
    QString name;                          ///< the metric's name
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

/// Renders the curve into a widthPx x heightPx PNG at `path` (a QApplication is made offscreen
/// when the process has none). False with `error` when it cannot.
bool renderLearningCurvePng(const LearningCurveData& data, const std::string& path, std::string* error,
                            int widthPx = 1200, int heightPx = 800);

}  // namespace palpate
