#pragma once
// What every chart image shares (palpate-cli sweep --png, bench feel --png): the size it may have,
// the chart's fonts scaled for it, and drawing a laid-out widget into a PNG file.

#include <QFont>
#include <QWidget>

#include <string>

class QChart;

namespace palpate {

inline constexpr int kChartImageMinSidePx = 200;
inline constexpr int kChartImageMaxSidePx = 16000;

/// "" when an image of this size can be written to `path`; else what is wrong with it.
std::string chartImageProblem(int widthPx, int heightPx, const std::string& path);

/// The chart's title, legend and axis fonts from `base`, scaled by `textScale`.
void applyChartFonts(QChart& chart, const QFont& base, double textScale);

/// Lays `widget` out off screen at this size and writes it to `path` as a PNG on white. "" on
/// success, else why the file could not be written. Needs a ChartApplication alive.
std::string renderWidgetPng(QWidget& widget, int widthPx, int heightPx, const std::string& path);

}  // namespace palpate
