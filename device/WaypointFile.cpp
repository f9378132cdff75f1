#include "device/WaypointFile.h"

#include "base/io/InputFile.h"

#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>
#include <system_error>

namespace palpate {
namespace {

constexpr const char* kColumnNames[4] = {"t_s", "x_mm", "y_mm", "z_mm"};

bool isSeparator(char c) { return c == ' ' || c == '\t' || c == ',' || c == '\v' || c == '\f'; }

/// A token as it may appear in a message: printable ASCII kept, the rest escaped, long ones cut.
std::string quoted(std::string_view token) {
    static const char* kHex = "0123456789abcdef";
    std::string out = "'";
    const std::size_t shown = token.size() < 32 ? token.size() : 32;
    for (std::size_t i = 0; i < shown; ++i) {
        const auto c = static_cast<unsigned char>(token[i]);
        if (c >= 0x20 && c < 0x7f && c != '\'') {
            out += char(c);
        } else {
            out += "\\x";
            out += kHex[c >> 4];
            out += kHex[c & 15];
        }
    }
    if (shown < token.size()) out += "...";
    out += "'";
    return out;
}

std::string numberText(double value) {
    std::ostringstream s;
    s << value;
    return s.str();
}

/// Parses a whole token as a double; a leading '+' is accepted (from_chars does not take it).
bool parseDouble(std::string_view token, double& value) {
    if (!token.empty() && token.front() == '+') {
        token.remove_prefix(1);
        if (!token.empty() && (token.front() == '+' || token.front() == '-')) return false;  // "+-1"
    }
    if (token.empty()) return false;
    const char* begin = token.data();
    const char* end = begin + token.size();
    const auto result = std::from_chars(begin, end, value, std::chars_format::general);
    return result.ec == std::errc() && result.ptr == end;
}

}  // namespace

std::string parseWaypoints(std::string_view text, std::string_view sourceName, std::vector<Waypoint>& out) {
    std::string error;
    out.clear();
    error.clear();
    const std::string source(sourceName);
    auto fail = [&](std::size_t lineNumber, const std::string& problem) {
        out.clear();
        error = source + ":" + std::to_string(lineNumber) + ": " + problem;
        return error;
    };

    std::size_t lineNumber = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
        ++lineNumber;
        std::size_t eol = text.find('\n', pos);
        if (eol == std::string_view::npos) eol = text.size();
        std::string_view line = text.substr(pos, eol - pos);
        pos = eol + 1;

        if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);

        std::string_view tokens[4];
        std::size_t tokenCount = 0;
        std::size_t i = 0;
        while (i < line.size()) {
            while (i < line.size() && isSeparator(line[i])) ++i;
            if (i >= line.size()) break;
            const std::size_t start = i;
            while (i < line.size() && !isSeparator(line[i])) ++i;
            if (tokenCount < 4) tokens[tokenCount] = line.substr(start, i - start);
            ++tokenCount;
        }
        if (tokenCount == 0) continue;  // blank or comment-only line
        if (tokenCount != 4)
            return fail(lineNumber, "expected 4 numbers (t_s x_mm y_mm z_mm), found " +
                                        std::to_string(tokenCount) + " field" + (tokenCount == 1 ? "" : "s"));

        double values[4];
        for (std::size_t c = 0; c < 4; ++c) {
            if (!parseDouble(tokens[c], values[c]))
                return fail(lineNumber, quoted(tokens[c]) + " is not a number (column " + std::to_string(c + 1) +
                                            ", " + kColumnNames[c] + ")");
            if (!std::isfinite(values[c]))
                return fail(lineNumber, std::string(kColumnNames[c]) + " is not finite (" + quoted(tokens[c]) + ")");
            if (c > 0 && std::fabs(values[c]) > kMaxWaypointCoordinateMm)
                return fail(lineNumber, std::string(kColumnNames[c]) + " = " + numberText(values[c]) +
                                            " mm is beyond +-" + numberText(kMaxWaypointCoordinateMm) +
                                            " mm (metres instead of millimetres?)");
        }
        if (!out.empty() && !(values[0] > out.back().timeS))
            return fail(lineNumber, "t_s = " + numberText(values[0]) + " s is not after the previous waypoint's " +
                                        numberText(out.back().timeS) + " s (times must increase)");
        out.push_back(Waypoint{values[0], glm::vec3(float(values[1]), float(values[2]), float(values[3]))});
    }
    if (out.empty()) {
        error = source + ": no waypoints (expected lines of 't_s x_mm y_mm z_mm')";
        return error;
    }
    return {};
}

std::string loadWaypointFile(const std::string& path, std::vector<Waypoint>& out) {
    std::string error;
    out.clear();
    if (path.empty()) {
        error = "waypoint file: no path given";
        return error;
    }
    // The one bounded reader: a FIFO, a device or a directory is refused before a byte is read.
    const std::optional<std::string> text = readInputFile(path, kWaypointFile, error);
    if (!text) return error;
    return parseWaypoints(*text, path, out);
}

std::string parseWaypointButtons(std::string_view text, std::string_view sourceName, WaypointButtons& out) {
    std::string error;
    out = {};
    std::size_t lineNumber = 0;
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        std::string_view line = text.substr(0, end);
        text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        const bool mark = line.starts_with("# mark-at ");
        const bool done = line.starts_with("# done-at ");
        if (!mark && !done) continue;
        std::string_view number = line.substr(10);
        while (!number.empty() && (number.front() == ' ' || number.front() == '\t')) number.remove_prefix(1);
        while (!number.empty() && (number.back() == ' ' || number.back() == '\t')) number.remove_suffix(1);
        double timeS = 0.0;
        const auto [ptr, ec] = std::from_chars(number.data(), number.data() + number.size(), timeS);
        const auto where = std::string(sourceName) + ":" + std::to_string(lineNumber) + ": ";
        if (ec != std::errc() || ptr != number.data() + number.size() || !std::isfinite(timeS) || timeS < 0.0) {
            error = where + "'" + std::string(line.substr(2, 7)) + "' needs a time in seconds >= 0, not '" +
                    std::string(number) + "'";
            out = {};
            return error;
        }
        if (mark) {
            out.marksS.push_back(timeS);
        } else if (out.doneS) {
            error = where + "a second 'done-at' (the examination is finished once)";
            out = {};
            return error;
        } else {
            out.doneS = timeS;
        }
    }
    return {};
}

std::string loadWaypointButtons(const std::string& path, WaypointButtons& out) {
    std::string error;
    const std::optional<std::string> text = readInputFile(path, kWaypointFile, error);
    if (!text) return error;
    return parseWaypointButtons(*text, path, out);
}

}  // namespace palpate
