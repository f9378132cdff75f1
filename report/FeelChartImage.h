#pragma once
// The feel chart as a PNG, for palpate-cli bench feel --png (a process with no QApplication): the
// chart (FeelChart.h, tick cost as a fraction of "previous"'s) on a white background.

#include "engine/bench/FeelBench.h"

#include <string>
#include <vector>

namespace palpate {

/// Renders `rows` into a widthPx x heightPx PNG at `path`. Creates a QApplication (offscreen when
/// there is no display) if the process has none. Returns "" or why it cannot
/// (bad size, no writable file, a non-widget Qt application already running).
std::string renderFeelChartPng(const std::vector<FeelRow>& rows, const std::string& path, int widthPx = 1400,
                               int heightPx = 900);

}  // namespace palpate
