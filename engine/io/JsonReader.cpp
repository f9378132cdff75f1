#include "engine/io/JsonReader.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace palpate {

JsonReader::JsonReader(std::vector<std::string>& errors, std::string source)
    : mErrors(errors), mSource(std::move(source)) {}

std::optional<Json> JsonReader::parse(const std::string& text) {
    try {
        return Json::parse(text);
    } catch (const Json::parse_error& e) {
        const std::string what = e.what();
        mErrors.push_back(mSource + ": not valid JSON at byte " + std::to_string(e.byte) + ": " +
                          what.substr(std::min(what.size(), what.find(']') + 2)));
    } catch (const Json::out_of_range&) {
        // nlohmann refuses a number beyond a double's range (1e400) while parsing.
        mErrors.push_back(mSource + ": not valid JSON: a number is too large for a double (at most about 1.8e308)");
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

std::string JsonReader::join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
}

}  // namespace palpate
