#pragma once
// A trainee's learning curve as a PNG (palpate-cli trainee curve --png; docs/scoring.md,
// "Proficiency"): one small plot per metric, the session number along x, the side of the experts'
// pass mark that passes shaded, the mark drawn, each session's point green when it passed.

#include "results/LearningCurveData.h"

#include <QString>

#include <string>

class QChartView;
class QWidget;

namespace palpate {

/// Renders the curve into a widthPx x heightPx PNG at `path` (a QApplication is made offscreen
/// when the process has none). "" or why it cannot.
std::string renderLearningCurvePng(const LearningCurveData& data, const std::string& path, int widthPx = 1200,
                                   int heightPx = 800);

/// The key of the learning curve's score series (the session's score out of 100), which a front
/// end puts first.
inline constexpr const char* kLearningCurveScoreKey = "score";

/// One metric's chart, as the PNG draws each (sessions along x, the pass mark and its passing side
/// shaded, each session's point green when the session passed), for a window to show large.
QChartView* learningCurveMetricChart(const LearningCurveMetric& metric, const std::vector<bool>& passed,
                                     double textScale, QWidget* parent);

/// The title and heading of one metric's chart: its name (the score's "Score").
QString learningCurveMetricTitle(const LearningCurveMetric& metric);

}  // namespace palpate
