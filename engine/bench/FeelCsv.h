#pragma once
// The feel bench's rows as CSV (palpate-cli bench feel --csv, docs/bench/feel.csv) and back, for the
// Charts dock's feel chart: one row per model and mesh, units in the column names, empty cells for
// figures not measured, the goals' verdicts (PASS, FAIL, empty when a goal does not apply).

#include "engine/bench/FeelBench.h"

#include <string>
#include <vector>

namespace palpate {

/// The header's column names, in order.
const std::vector<std::string>& feelCsvColumns();

/// The header line and one line per row.
std::string feelToCsv(const std::vector<FeelRow>& rows);

/// Reads what feelToCsv writes (columns found by name, so added columns and another order are
/// read too; shape, vertices, model, max_step_pct, tick_ns and previous_tick_ns are required). On
/// failure returns no rows and sets `error` to "line N: ..." naming the column.
std::vector<FeelRow> parseFeelCsv(const std::string& text, std::string* error = nullptr);

}  // namespace palpate
