#include "engine/bench/FeelCsv.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <sstream>

namespace palpate {

namespace {

std::string number(double v) {
    if (!std::isfinite(v)) return {};
    std::ostringstream s;
    s.precision(7);
    s << v;
    return s.str();
}

std::string whole(std::uint64_t v) { return std::to_string(v); }

std::string quoted(const std::string& text) {
    std::string q = "\"";
    for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

std::string verdictCell(GoalVerdict v) { return v == GoalVerdict::NotApplicable ? std::string() : goalVerdictName(v); }

/// One column: its name, how a row is written, and how a cell is read back into a row ("" or the
/// problem with the cell).
struct Column {
    const char* name;
    std::function<std::string(const FeelRow&)> write;
    std::function<std::string(FeelRow&, const std::string&)> read;
};

std::string parseDouble(const std::string& cell, double& out) {
    if (cell.empty()) {
        out = std::numeric_limits<double>::quiet_NaN();
        return {};
    }
    double v = 0.0;
    const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
    if (ec != std::errc() || end != cell.data() + cell.size()) return "'" + cell + "' is not a number";
    out = v;
    return {};
}

template <typename Int>
std::string parseWhole(const std::string& cell, Int& out) {
    if (cell.empty()) {
        out = 0;
        return {};
    }
    std::uint64_t v = 0;
    const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
    if (ec != std::errc() || end != cell.data() + cell.size()) return "'" + cell + "' is not a whole number >= 0";
    out = Int(v);
    return {};
}

/// A column of a LoopFeel (quiet or loaded): written empty without that run; a cell read creates it.
/// A figure of a LoopFeel that is a number (empty without that run).
Column loopNumberColumn(const char* name, std::optional<LoopFeel> FeelRow::*run, double LoopFeel::*field) {
    return {name, [run, field](const FeelRow& r) { return (r.*run) ? number((*(r.*run)).*field) : std::string(); },
            [run, field](FeelRow& r, const std::string& cell) -> std::string {
                if (cell.empty()) return {};
                if (!(r.*run)) r.*run = LoopFeel{};
                return parseDouble(cell, (*(r.*run)).*field);
            }};
}

template <typename T>
Column loopColumn(const char* name, std::optional<LoopFeel> FeelRow::*run, T LoopFeel::*field) {
    return {name,
            [run, field](const FeelRow& r) {
                return (r.*run) ? whole(std::uint64_t((*(r.*run)).*field)) : std::string();
            },
            [run, field](FeelRow& r, const std::string& cell) -> std::string {
                if (cell.empty()) return {};
                if (!(r.*run)) r.*run = LoopFeel{};
                return parseWhole(cell, (*(r.*run)).*field);
            }};
}

Column doubleColumn(const char* name, double FeelRow::*field) {
    return {name, [field](const FeelRow& r) { return number(r.*field); },
            [field](FeelRow& r, const std::string& cell) { return parseDouble(cell, r.*field); }};
}

Column metricColumn(const char* name, double FeelMetrics::*field) {
    return {name, [field](const FeelRow& r) { return number(r.metrics.*field); },
            [field](FeelRow& r, const std::string& cell) { return parseDouble(cell, r.metrics.*field); }};
}

/// Written only: recomputed from the other columns when read.
Column derivedColumn(const char* name, std::function<std::string(const FeelRow&)> write) {
    return {name, std::move(write), [](FeelRow&, const std::string&) { return std::string(); }};
}

const std::vector<Column>& columns() {
    static const std::vector<Column> kColumns = {
        {"shape", [](const FeelRow& r) { return std::string(shapeName(r.shape)); },
         [](FeelRow& r, const std::string& cell) -> std::string {
             const auto shape = parseShape(cell);
             if (!shape) return "'" + cell + "' is not a shape (sphere, stomach)";
             r.shape = *shape;
             return {};
         }},
        {"vertices", [](const FeelRow& r) { return whole(r.vertices); },
         [](FeelRow& r, const std::string& cell) { return parseWhole(cell, r.vertices); }},
        {"model", [](const FeelRow& r) { return r.model; },
         [](FeelRow& r, const std::string& cell) -> std::string {
             if (cell.empty()) return "the model is empty";
             r.model = cell;
             return {};
         }},
        doubleColumn("tool_radius_mm", &FeelRow::toolRadiusMm),
        doubleColumn("depth_mm", &FeelRow::depthMm),
        doubleColumn("speed_mm_per_s", &FeelRow::speedMmPerS),
        doubleColumn("slide_length_mm", &FeelRow::slideLengthMm),
        {"stats_ticks", [](const FeelRow& r) { return whole(r.metrics.ticks); },
         [](FeelRow& r, const std::string& cell) { return parseWhole(cell, r.metrics.ticks); }},
        {"contact_ticks", [](const FeelRow& r) { return whole(r.contactTicks); },
         [](FeelRow& r, const std::string& cell) { return parseWhole(cell, r.contactTicks); }},
        metricColumn("mean_force_n", &FeelMetrics::meanForceN),
        metricColumn("max_step_pct", &FeelMetrics::maxStepPct),
        metricColumn("max_normal_step_pct", &FeelMetrics::maxNormalStepPct),
        metricColumn("ripple_pct", &FeelMetrics::ripplePct),
        metricColumn("mean_normal_force_n", &FeelMetrics::meanNormalN),
        metricColumn("mean_tangential_force_n", &FeelMetrics::meanTangentialN),
        metricColumn("friction_ratio", &FeelMetrics::frictionRatio),
        {"dynamic_friction",
         [](const FeelRow& r) { return r.dynamicFriction ? number(*r.dynamicFriction) : std::string(); },
         [](FeelRow& r, const std::string& cell) -> std::string {
             if (cell.empty()) return {};
             double v = 0.0;
             if (std::string problem = parseDouble(cell, v); !problem.empty()) return problem;
             r.dynamicFriction = v;
             return {};
         }},
        derivedColumn("friction_deviation_pct",
                      [](const FeelRow& r) {
                          const auto d = r.frictionDeviationPct();
                          return d ? number(*d) : std::string();
                      }),
        doubleColumn("tick_ns", &FeelRow::tickNs),
        doubleColumn("previous_tick_ns", &FeelRow::previousTickNs),
        derivedColumn("speedup_vs_previous",
                      [](const FeelRow& r) {
                          return r.speedupVsPrevious() > 0.0 ? number(r.speedupVsPrevious()) : std::string();
                      }),
        {"timing_passes", [](const FeelRow& r) { return whole(std::uint64_t(r.timingPasses)); },
         [](FeelRow& r, const std::string& cell) { return parseWhole(cell, r.timingPasses); }},
        loopColumn("quiet_ticks", &FeelRow::quiet, &LoopFeel::ticks),
        loopColumn("quiet_window_ticks", &FeelRow::quiet, &LoopFeel::windowTicks),
        loopColumn("quiet_contact_ticks", &FeelRow::quiet, &LoopFeel::contactTicks),
        loopColumn("quiet_dropouts", &FeelRow::quiet, &LoopFeel::dropouts),
        loopColumn("quiet_overruns", &FeelRow::quiet, &LoopFeel::overruns),
        loopNumberColumn("quiet_max_step_pct", &FeelRow::quiet, &LoopFeel::maxStepPct),
        loopColumn("load_processes", &FeelRow::loaded, &LoopFeel::loadProcesses),
        loopColumn("loaded_ticks", &FeelRow::loaded, &LoopFeel::ticks),
        loopColumn("loaded_window_ticks", &FeelRow::loaded, &LoopFeel::windowTicks),
        loopColumn("loaded_contact_ticks", &FeelRow::loaded, &LoopFeel::contactTicks),
        loopColumn("loaded_dropouts", &FeelRow::loaded, &LoopFeel::dropouts),
        loopColumn("loaded_overruns", &FeelRow::loaded, &LoopFeel::overruns),
        loopNumberColumn("loaded_max_step_pct", &FeelRow::loaded, &LoopFeel::maxStepPct),
        derivedColumn("step_goal", [](const FeelRow& r) { return verdictCell(stepGoal(r)); }),
        derivedColumn("dropout_goal", [](const FeelRow& r) { return verdictCell(dropoutGoal(r)); }),
        derivedColumn("friction_goal", [](const FeelRow& r) { return verdictCell(frictionGoal(r)); }),
        derivedColumn("speed_goal", [](const FeelRow& r) { return verdictCell(speedGoal(r)); }),
        {"note", [](const FeelRow& r) { return quoted(r.note); },
         [](FeelRow& r, const std::string& cell) -> std::string {
             r.note = cell;
             return {};
         }},
    };
    return kColumns;
}

/// Splits one CSV line: commas, double-quoted cells with "" for a quote. False on an open quote.
bool splitLine(const std::string& line, std::vector<std::string>& cells) {
    cells.assign(1, {});
    bool inQuotes = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (inQuotes) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                cells.back() += '"';
                ++i;
            } else if (c == '"') {
                inQuotes = false;
            } else {
                cells.back() += c;
            }
        } else if (c == '"') {
            inQuotes = true;
        } else if (c == ',') {
            cells.emplace_back();
        } else {
            cells.back() += c;
        }
    }
    return !inQuotes;
}

}  // namespace

const std::vector<std::string>& feelCsvColumns() {
    static const std::vector<std::string> kNames = [] {
        std::vector<std::string> names;
        for (const Column& c : columns()) names.push_back(c.name);
        return names;
    }();
    return kNames;
}

std::string feelToCsv(const std::vector<FeelRow>& rows) {
    std::string out;
    for (const Column& c : columns()) {
        if (!out.empty()) out += ',';
        out += c.name;
    }
    out += '\n';
    for (const FeelRow& r : rows) {
        bool first = true;
        for (const Column& c : columns()) {
            if (!first) out += ',';
            out += c.write(r);
            first = false;
        }
        out += '\n';
    }
    return out;
}

std::vector<FeelRow> parseFeelCsv(const std::string& text, std::string* error) {
    auto fail = [&](const std::string& message) {
        if (error) *error = message;
        return std::vector<FeelRow>{};
    };
    if (error) error->clear();
    std::istringstream in(text);
    std::string line;
    std::vector<std::string> cells;
    if (!std::getline(in, line)) return fail("line 1: no header");
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!splitLine(line, cells)) return fail("line 1: a quote is not closed");
    std::map<std::string, const Column*> byName;
    for (const Column& c : columns()) byName[c.name] = &c;
    std::vector<const Column*> readers;  // per cell of a line; null for a column this reader does not know
    for (const std::string& name : cells) {
        const auto it = byName.find(name);
        readers.push_back(it == byName.end() ? nullptr : it->second);
    }
    for (const char* required : {"shape", "vertices", "model", "max_step_pct", "tick_ns", "previous_tick_ns"})
        if (std::find(cells.begin(), cells.end(), required) == cells.end())
            return fail(std::string("line 1: the column '") + required + "' is missing");

    std::vector<FeelRow> rows;
    for (int lineNumber = 2; std::getline(in, line); ++lineNumber) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) continue;
        if (!splitLine(line, cells)) return fail("line " + std::to_string(lineNumber) + ": a quote is not closed");
        if (cells.size() != readers.size())
            return fail("line " + std::to_string(lineNumber) + ": " + std::to_string(cells.size()) +
                        " cells, the header has " + std::to_string(readers.size()));
        FeelRow row;
        for (std::size_t i = 0; i < cells.size(); ++i) {
            if (!readers[i]) continue;
            if (const std::string problem = readers[i]->read(row, cells[i]); !problem.empty())
                return fail("line " + std::to_string(lineNumber) + ", column " + readers[i]->name + ": " + problem);
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

}  // namespace palpate
