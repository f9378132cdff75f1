#include "engine/accuracy/SweepCsv.h"

#include "engine/core/Rings.h"
#include "engine/models/ModelRegistry.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <functional>
#include <optional>
#include <string_view>

namespace palpate {

namespace {

/// Splits one line at commas; a field may be double-quoted ("a,b", "" for a quote). Returns the
/// fields, or nullopt with `problem` set for an unterminated quote.
std::optional<std::vector<std::string>> splitFields(std::string_view line, std::string& error) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                fields.back() += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                fields.back() += c;
            }
        } else if (c == '"' && fields.back().empty()) {
            quoted = true;
        } else if (c == ',') {
            fields.emplace_back();
        } else {
            fields.back() += c;
        }
    }
    if (quoted) {
        error = "a quoted field is not closed";
        return std::nullopt;
    }
    return fields;
}

/// Locale-independent (a GUI may have set LC_NUMERIC to a comma locale): std::from_chars.
bool parseDouble(const std::string& text, double& out) {
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && ptr == end && std::isfinite(out);
}

bool parseUnsigned(const std::string& text, unsigned long long& out) {
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && ptr == end && !text.empty();
}

/// One column: its header name and how its text goes into a point ("" or the problem).
struct Column {
    const char* name;
    std::function<std::string(const std::string&, SweepPoint&)> read;
    bool optional = false;  ///< the organ sweep's columns: a punch sweep written before them has none
};

/// Empty (not measured) is NaN; otherwise a number >= 0.
std::string readOptionalNonNegative(const std::string& text, double& out) {
    if (text.empty()) {
        out = std::numeric_limits<double>::quiet_NaN();
        return {};
    }
    if (!parseDouble(text, out)) return "'" + text + "' is not a number (or empty: not measured)";
    if (out < 0.0) return "'" + text + "' is negative";
    return {};
}

std::string readNonNegative(const std::string& text, double& out) {
    if (!parseDouble(text, out)) return "'" + text + "' is not a number";
    if (out < 0.0) return "'" + text + "' is negative";
    return {};
}

std::string readFinite(const std::string& text, double& out) {
    if (!parseDouble(text, out)) return "'" + text + "' is not a number";
    return {};
}

const std::vector<Column>& columns() {
    static const std::vector<Column> kColumns = {
        {"shape",
         [](const std::string& t, SweepPoint& p) -> std::string {
             const auto shape = parseShape(t);
             if (!shape) return "'" + t + "' is not a shape (sphere, stomach)";
             p.shape = *shape;
             return {};
         }},
        {"vertices",
         [](const std::string& t, SweepPoint& p) -> std::string {
             unsigned long long n = 0;
             if (!parseUnsigned(t, n) || n == 0) return "'" + t + "' is not a positive vertex count";
             p.vertices = std::size_t(n);
             return {};
         }},
        {"series",
         [](const std::string& t, SweepPoint& p) -> std::string {
             if (t.empty()) return "empty (every point needs its series name)";
             p.series = t;
             return {};
         }},
        {"model",
         [](const std::string& t, SweepPoint& p) -> std::string {
             const auto def = modelDefForName(t);
             if (!def) return "'" + t + "' is not a model (see palpate-cli bench models)";
             p.model = modelName(*def);  // the current name: a sweep written before may say "palpate"
             return {};
         }},
        {"rings",
         [](const std::string& t, SweepPoint& p) -> std::string {
             unsigned long long n = 0;
             if (!parseUnsigned(t, n) || n > unsigned(kMaxRings))
                 return "'" + t + "' is not a ring count in 0.." + std::to_string(kMaxRings);
             p.rings = int(n);
             return {};
         }},
        {"tick_us", [](const std::string& t, SweepPoint& p) { return readNonNegative(t, p.tickUs); }},
        {"displacement_error",
         [](const std::string& t, SweepPoint& p) { return readOptionalNonNegative(t, p.error.displacementError); }},
        {"force_error", [](const std::string& t, SweepPoint& p) { return readOptionalNonNegative(t, p.error.forceError); }},
        {"indentation_mm", [](const std::string& t, SweepPoint& p) { return readFinite(t, p.error.indentationMm); }},
        {"force_n", [](const std::string& t, SweepPoint& p) { return readFinite(t, p.error.forceN); }},
        {"reference_force_n", [](const std::string& t, SweepPoint& p) { return readFinite(t, p.error.referenceForceN); }},
        {"vertices_compared",
         [](const std::string& t, SweepPoint& p) -> std::string {
             unsigned long long n = 0;
             if (!parseUnsigned(t, n) || n > 2'000'000'000ULL) return "'" + t + "' is not a vertex count";
             p.error.verticesCompared = int(n);
             return {};
         }},
        {"pareto",
         [](const std::string& t, SweepPoint& p) -> std::string {
             if (t != "0" && t != "1") return "'" + t + "' is not 0 or 1";
             p.pareto = t == "1";
             return {};
         }},
        {"site",
         [](const std::string& t, SweepPoint& p) -> std::string {
             p.site = t;
             return {};
         },
         true},
        {"displacement_error_hyperelastic",
         [](const std::string& t, SweepPoint& p) { return readOptionalNonNegative(t, p.hyperelasticDisplacementError); },
         true},
        {"force_error_hyperelastic",
         [](const std::string& t, SweepPoint& p) { return readOptionalNonNegative(t, p.hyperelasticForceError); }, true},
    };
    return kColumns;
}

}  // namespace

std::vector<SweepPoint> parseSweepCsv(const std::string& text, std::string* error) {
    auto fail = [&](const std::string& message) {
        if (error) *error = message;
        return std::vector<SweepPoint>{};
    };
    if (error) error->clear();

    std::vector<SweepPoint> points;
    std::vector<int> columnOf;  // header field index -> index into columns()
    bool haveHeader = false;
    std::size_t lineNumber = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string_view line(text.data() + start, end - start);
        start = end + 1;
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (line.find_first_not_of(" \t") == std::string_view::npos) {
            if (end == text.size()) break;
            continue;
        }
        const std::string where = "line " + std::to_string(lineNumber);
        std::string problem;
        const auto fields = splitFields(line, problem);
        if (!fields) return fail(where + ": " + problem);

        if (!haveHeader) {
            std::vector<bool> seen(columns().size(), false);
            for (std::size_t i = 0; i < fields->size(); ++i) {
                const std::string& name = (*fields)[i];
                int found = -1;
                for (std::size_t c = 0; c < columns().size(); ++c)
                    if (name == columns()[c].name) found = int(c);
                if (found < 0)
                    return fail(where + ", column " + std::to_string(i + 1) + " (" + name +
                                "): unknown column (is this a sweep CSV?)");
                if (seen[std::size_t(found)])
                    return fail(where + ", column " + std::to_string(i + 1) + " (" + name + "): repeated");
                seen[std::size_t(found)] = true;
                columnOf.push_back(found);
            }
            for (std::size_t c = 0; c < columns().size(); ++c)
                if (!seen[c] && !columns()[c].optional) return fail(where + ": the header has no column '" + columns()[c].name + "'");
            haveHeader = true;
            continue;
        }

        if (fields->size() != columnOf.size())
            return fail(where + ": " + std::to_string(fields->size()) + " fields, the header has " +
                        std::to_string(columnOf.size()));
        SweepPoint point;
        for (std::size_t i = 0; i < fields->size(); ++i) {
            const Column& column = columns()[std::size_t(columnOf[i])];
            if (const std::string e = column.read((*fields)[i], point); !e.empty())
                return fail(where + ", column " + std::to_string(i + 1) + " (" + column.name + "): " + e);
        }
        points.push_back(std::move(point));
    }
    if (!haveHeader) return fail("line 1: empty (expected the header " + std::string(columns().front().name) + ",...)");
    return points;
}

}  // namespace palpate
