#pragma once
// Reads back what sweepToCsv writes, so that a committed sweep (docs/bench/sweep.csv) can be charted
// without measuring again. Strict like the preset reader: a bad value is an error naming the line,
// the column and the problem, never a silent default.

#include "engine/accuracy/AccuracySweep.h"

#include <string>
#include <vector>

namespace palpate {

/// Parses sweep CSV text (header line first; columns may come in any order, every column of
/// sweepToCsv must be present). Empty lines are skipped. On failure returns no points and sets
/// `error` (when given) to "line L, column C (name): problem"; on success clears it.
std::vector<SweepPoint> parseSweepCsv(const std::string& text, std::string* error);

}  // namespace palpate
