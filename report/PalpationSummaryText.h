#pragma once
// A palpation score in sentences (docs/scoring.md, "Detection", "Coverage", "Force by phase",
// "Feedback"): the lines the score card and the PDF report show beyond the metrics, in the
// user's language and the locale's numbers.

#include "engine/exercise/ScoreReport.h"

#include <QLocale>
#include <QStringList>

namespace palpate {

/// One line each: lumps found and false alarms (with sensitivity and predictive value), the mean
/// localisation, the surface examined, the force searching and palpating, then the feedback.
/// Empty for exercises that are not palpation.
QStringList palpationSummaryLines(const ScoreReport& report, const QLocale& locale = QLocale());

/// A feedback sentence said from its key and figures (translated, numbers in `locale`); one of a
/// key this build does not know is its English text.
QString feedbackText(const PalpationFeedback& feedback, const QLocale& locale = QLocale());

}  // namespace palpate
