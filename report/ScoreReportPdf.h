#pragma once
// The printable score report (A4, as many pages as it needs) for the trainee's file or an
// instructor: who, which exercise, when and on which device; the score; a row per press target
// and per metric, their text wrapped in its column and the table continued on the next page when
// long; the force over time with each target's own force window shaded over the time it was the
// current target. Text is drawn as text, so the PDF is searchable (and tests read it back with
// pdftotext). docs/scoring.md describes what it holds.

#include "report/ScoreReportContent.h"

#include <QString>

namespace palpate {

/// Writes the report to `path` atomically (a temporary file renamed over it: a failure leaves what
/// was there). False with a message naming the file when it cannot be written. Works without a
/// QApplication (it makes one on the offscreen platform for the drawing, ChartApplication.h).
bool writeScoreReportPdf(const QString& path, const ScoreReportContent& content, QString* error);

}  // namespace palpate
