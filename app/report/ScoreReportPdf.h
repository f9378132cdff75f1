#pragma once
// A printable score report (one A4 page) for the trainee's file or an instructor: title, trainee,
// exercise, date, the score, the breakdown table and the force-time plot. Text is drawn as text,
// so the PDF is searchable (and tests read it back with pdftotext).

#include "engine/exercise/ScoreReport.h"

#include <QString>

#include <utility>
#include <vector>

namespace palpate {

/// `forceTimeSeries` is (time s, |F| N); an empty series leaves the plot out. The report's force
/// window (guidance forceMinN..forceMaxN, when it has one) is shaded on the plot. False with a
/// message naming the file when it cannot be written.
bool writeScoreReportPdf(const QString& path, const QString& traineeName, const QString& exerciseName,
                         const ScoreReport& report,
                         const std::vector<std::pair<double, double>>& forceTimeSeries, QString* error);

}  // namespace palpate
