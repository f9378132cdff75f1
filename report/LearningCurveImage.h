#pragma once
// A trainee's learning curve as a PNG (palpate-cli trainee curve --png; docs/scoring.md,
// "Proficiency"): one small plot per metric, the session number along x, the side of the experts'
// pass mark that passes shaded, the mark drawn, each session's point green when it passed.

#include "results/LearningCurveData.h"

#include <string>

namespace palpate {

/// Renders the curve into a widthPx x heightPx PNG at `path` (a QApplication is made offscreen
/// when the process has none). "" or why it cannot.
std::string renderLearningCurvePng(const LearningCurveData& data, const std::string& path, int widthPx = 1200,
                                   int heightPx = 800);

}  // namespace palpate
