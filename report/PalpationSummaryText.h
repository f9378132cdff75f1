#pragma once
// A palpation score in sentences (docs/scoring.md, "Detection", "Coverage", "Force by phase",
// "Feedback"): the lines the score card and the PDF report show beyond the metrics.

#include "engine/exercise/ScoreReport.h"

#include <QStringList>

namespace palpate {

/// One line each: lumps found and false alarms (with sensitivity and predictive value), the mean
/// localisation, the surface examined, the force searching and palpating, then the feedback.
/// Empty for exercises that are not palpation.
QStringList palpationSummaryLines(const ScoreReport& report);

}  // namespace palpate
