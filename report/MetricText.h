#pragma once
// A metric as people read it in the window and the PDF: its translated name and description and
// its value in their locale, all from the metric's row (engine/exercise/Metric.h,
// docs/scoring.md "Metrics").

#include "engine/exercise/Metric.h"

#include <QLocale>
#include <QString>

#include <string_view>

namespace palpate {

/// "Completion", "Peak force" (translated in the metric rows' context).
QString metricNameText(Metric metric);
/// The name of a metric stored by its key (results, learning curves); the key itself if no metric
/// has it (a result written by a later version).
QString metricNameText(std::string_view key);
/// One line for people, translated.
QString metricDescriptionText(Metric metric);
/// "85 %", "3,20 mm", "2 findings": the row's display in the locale.
QString localMetricValueText(Metric metric, double value, const QLocale& locale = QLocale());

/// A score as every view shows it (the card, the PDF, History, the live score): one decimal, in
/// the locale ("85.3", "85,3"), so that the same session reads the same everywhere.
QString scoreText(double score, const QLocale& locale = QLocale());

/// "Work done 34 %: the lines that count mistakes earn that share of their points." when the
/// session did less than all of its work (docs/scoring.md, "The rubric"); "" otherwise.
QString workDoneText(double workDone, const QLocale& locale = QLocale());

}  // namespace palpate
