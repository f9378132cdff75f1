#pragma once
// The one reader of Palpate's versioned JSON files (tissue presets, exercises): parses the text,
// checks every object's keys against the keys it may hold and records each problem at its key
// path ("slope_ring.damping_ratio: ..."), so a typo never falls back to a default silently and
// every message names the file and the key. Include from .cpp files only (it brings nlohmann/json).

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace palpate {

using Json = nlohmann::ordered_json;  // keeps the written key order readable

class JsonReader {
public:
    /// Problems go to `errors`, each prefixed with `source` (a path).
    JsonReader(std::vector<std::string>& errors, std::string source);

    /// The parsed text, or nullopt with the problem recorded, at its key path where it has one:
    /// bad syntax at byte N, a number too large for a double ("slope_ring.spring_k: 1e400 is too
    /// large for a double"), a key given twice in one object ("slope_ring.spring_k: appears
    /// twice"), values nested more than 64 levels deep. No exception leaves it.
    std::optional<Json> parse(const std::string& text);

    void error(const std::string& key, const std::string& problem);
    std::size_t errorCount() const { return mErrors.size(); }

    /// Whether `j` is an object; each key it holds that `allowed` lacks is an error ("unknown key").
    bool object(const Json& j, const std::string& key, const std::vector<std::string>& allowed);
    /// parent[key] as a number into `out`; false when absent (an error when required) or not a number.
    bool number(const Json& parent, const std::string& path, const char* key, double& out, bool required = false);
    /// As above, and within [lo, hi] ("x is out of range [lo, hi]" otherwise).
    bool number(const Json& parent, const std::string& path, const char* key, double lo, double hi, double& out,
                bool required = false);
    /// A whole number within [lo, hi].
    bool wholeNumber(const Json& parent, const std::string& path, const char* key, double lo, double hi, int& out,
                     bool required = false);
    /// parent[key] as a string into `out`.
    bool text(const Json& parent, const std::string& path, const char* key, std::string& out, bool required = false);
    /// The top-level "format" (must be `format`) and "version" (a whole number from 1 to
    /// `newestVersion`), both required; false after recording what is wrong.
    bool formatAndVersion(const Json& top, const char* format, int newestVersion);
    /// parent[key] as true or false into `out`.
    bool boolean(const Json& parent, const std::string& path, const char* key, bool& out, bool required = false);

    /// "path.key", or "key" at the top level.
    static std::string join(const std::string& path, const std::string& key);

private:
    std::vector<std::string>& mErrors;
    std::string mSource;
};

}  // namespace palpate
