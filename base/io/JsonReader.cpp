#include "base/io/JsonReader.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>

namespace palpate {

JsonReader::JsonReader(std::vector<std::string>& errors, std::string source)
    : mErrors(errors), mSource(std::move(source)) {}

namespace {

/// Objects and arrays within one another; Palpate's files nest four or five levels.
constexpr int kMaxJsonDepth = 64;

/// Where the parser is: one frame per open object or array, so that a problem the parser meets
/// (a number beyond a double, a key given twice) names its key path ("slope_ring.spring_k").
class KeyPathTracker {
public:
    std::string path() const {
        std::string p;
        for (const Frame& f : mFrames) {
            if (f.array) {
                p += '[';
                p += std::to_string(f.index);
                p += ']';
            }
            else if (!f.key.empty()) p = JsonReader::join(p, f.key);
        }
        return p;
    }
    /// The first key that appeared twice in one object, by path; "" when none.
    const std::string& duplicate() const { return mDuplicate; }
    /// Where the text first nests deeper than kMaxJsonDepth; nullopt when it never does.
    const std::optional<std::string>& tooDeep() const { return mTooDeep; }

    bool event(int depth, nlohmann::detail::parse_event_t event, const Json& parsed) {
        using E = nlohmann::detail::parse_event_t;
        switch (event) {
            case E::object_start:
            case E::array_start:
                // Deeper values are discarded as they are parsed (no file of ours nests past a few
                // levels; writing or comparing a deep value recurses once per level).
                if (depth >= kMaxJsonDepth && !mTooDeep) mTooDeep = path();
                push(event == E::array_start);
                return depth < kMaxJsonDepth;
            case E::key: {
                Frame& f = mFrames.back();
                f.key = parsed.get<std::string>();
                if (!f.keys.insert(f.key).second && mDuplicate.empty()) mDuplicate = path();
                break;
            }
            case E::object_end:
            case E::array_end:
                mFrames.pop_back();
                next();
                break;
            case E::value: next(); break;
        }
        return true;
    }

private:
    struct Frame {
        bool array = false;
        std::size_t index = 0;
        std::string key;
        std::set<std::string> keys;
    };
    void push(bool array) {
        mFrames.emplace_back();
        mFrames.back().array = array;
    }
    void next() {
        if (!mFrames.empty() && mFrames.back().array) ++mFrames.back().index;
    }
    std::vector<Frame> mFrames;
    std::string mDuplicate;
    std::optional<std::string> mTooDeep;
};

/// The text between the first pair of single quotes of nlohmann's message ("number overflow
/// parsing '1e400'"), or "a number".
std::string quotedToken(const std::string& what) {
    const auto a = what.find('\'');
    const auto b = a == std::string::npos ? a : what.find('\'', a + 1);
    if (b == std::string::npos) return "a number";
    return what.substr(a + 1, b - a - 1);
}

}  // namespace

std::optional<Json> JsonReader::parse(const std::string& text) {
    KeyPathTracker tracker;
    try {
        Json j = Json::parse(text, [&tracker](int depth, nlohmann::detail::parse_event_t event, Json& parsed) {
            return tracker.event(depth, event, parsed);
        });
        if (tracker.tooDeep()) {
            error(*tracker.tooDeep(), "nested more than " + std::to_string(kMaxJsonDepth) + " levels deep");
            return std::nullopt;
        }
        if (!tracker.duplicate().empty()) {
            error(tracker.duplicate(), "appears twice");
            return std::nullopt;
        }
        return j;
    } catch (const Json::parse_error& e) {
        std::string what = e.what();
        what = what.substr(std::min(what.size(), what.find(']') + 2));
        // The parser quotes what it last read: from a file that is not JSON at all (a preset path
        // pointing at a file of secrets) that is the file's own text, which an error must not
        // repeat. The line and column say where.
        if (const auto quote = what.find("; last read: '"); quote != std::string::npos) {
            const auto next = what.find("'; ", quote + 14);
            what.erase(quote, next == std::string::npos ? std::string::npos : next + 1 - quote);
        }
        mErrors.push_back(mSource + ": not valid JSON at byte " + std::to_string(e.byte) + ": " + what);
    } catch (const Json::out_of_range& e) {
        // nlohmann refuses a number beyond a double's range (1e400) while parsing; the tracker
        // knows at which key.
        if (tracker.tooDeep())
            error(*tracker.tooDeep(), "nested more than " + std::to_string(kMaxJsonDepth) + " levels deep");
        else error(tracker.path(), quotedToken(e.what()) + " is too large for a double (at most about 1.8e308)");
    } catch (const Json::exception& e) {
        mErrors.push_back(mSource + ": not valid JSON: " + e.what());
    }
    return std::nullopt;
}

void JsonReader::error(const std::string& key, const std::string& problem) {
    mErrors.push_back(mSource + ": " + (key.empty() ? std::string("(top level)") : key) + ": " + problem);
}

bool JsonReader::object(const Json& j, const std::string& key, const std::vector<std::string>& allowed) {
    if (!j.is_object()) {
        error(key, "must be an object");
        return false;
    }
    for (const auto& item : j.items())
        if (std::find(allowed.begin(), allowed.end(), item.key()) == allowed.end())
            error(join(key, item.key()), "unknown key");
    return true;
}

bool JsonReader::number(const Json& parent, const std::string& path, const char* key, double& out, bool required) {
    if (!parent.contains(key)) {
        if (required) error(join(path, key), "missing");
        return false;
    }
    const Json& v = parent.at(key);
    if (!v.is_number()) {
        error(join(path, key), "must be a number");
        return false;
    }
    out = v.get<double>();
    return true;
}

bool JsonReader::number(const Json& parent, const std::string& path, const char* key, double lo, double hi, double& out,
                        bool required) {
    double x = 0.0;
    if (!number(parent, path, key, x, required)) return false;
    if (!std::isfinite(x) || x < lo || x > hi) {
        std::ostringstream s;
        s << x << " is out of range [" << lo << ", " << hi << "]";
        error(join(path, key), s.str());
        return false;
    }
    out = x;
    return true;
}

bool JsonReader::wholeNumber(const Json& parent, const std::string& path, const char* key, double lo, double hi,
                             int& out, bool required) {
    double x = 0.0;
    if (!number(parent, path, key, lo, hi, x, required)) return false;
    if (std::floor(x) != x) {
        error(join(path, key), "must be a whole number");
        return false;
    }
    out = int(x);
    return true;
}

bool JsonReader::formatAndVersion(const Json& top, const char* format, int newestVersion) {
    const std::size_t before = errorCount();
    std::string given;
    text(top, "", "format", given, true);
    if (!given.empty() && given != format) error("format", "is '" + given + "', expected '" + format + "'");
    double version = 0.0;
    if (number(top, "", "version", version, true) &&
        (std::floor(version) != version || version < 1 || version > newestVersion))
        error("version", "version " + Json(version).dump() + " is not supported (this build reads 1 to " +
                             std::to_string(newestVersion) + ")");
    return errorCount() == before;
}

bool JsonReader::text(const Json& parent, const std::string& path, const char* key, std::string& out, bool required) {
    if (!parent.contains(key)) {
        if (required) error(join(path, key), "missing");
        return false;
    }
    if (!parent.at(key).is_string()) {
        error(join(path, key), "must be a string");
        return false;
    }
    out = parent.at(key).get<std::string>();
    return true;
}

bool JsonReader::boolean(const Json& parent, const std::string& path, const char* key, bool& out, bool required) {
    if (!parent.contains(key)) {
        if (required) error(join(path, key), "missing");
        return false;
    }
    if (!parent.at(key).is_boolean()) {
        error(join(path, key), "must be true or false");
        return false;
    }
    out = parent.at(key).get<bool>();
    return true;
}

std::string JsonReader::join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
}

}  // namespace palpate
