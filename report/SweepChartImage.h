#pragma once
// The speed-vs-accuracy chart as a PNG, for palpate-cli sweep --png (a process with no
// QApplication): one chart per shape side by side on a white background, the same axes in both.

#include "engine/accuracy/AccuracySweep.h"

#include <optional>
#include <string>
#include <vector>

namespace palpate {

/// Renders `points` into a widthPx x heightPx PNG at `path`. Creates a QApplication (offscreen when
/// there is no display) if the process has none. Returns "" or why it cannot
/// (bad size, no writable file, a non-widget Qt application already running).
std::string renderSweepChartPng(const std::vector<SweepPoint>& points, const std::string& path, int widthPx = 1400,
                                int heightPx = 900);

/// The same, with the tissue and tool the sweep was calibrated for named in the titles.
std::string renderSweepChartPng(const std::vector<SweepPoint>& points, const std::optional<ToolContact>& contact,
                                const std::string& path, int widthPx = 1400, int heightPx = 900);

}  // namespace palpate
