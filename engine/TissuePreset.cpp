#include "engine/TissuePreset.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace palpate {

namespace {

using Json = nlohmann::ordered_json;  // keeps the written key order readable
constexpr const char* kFormat = "palpate-tissue-preset";

/// Reads one JSON object, checking every key against a list and recording errors by key path.
class Reader {
public:
    Reader(std::vector<std::string>& errors, std::string source) : mErrors(errors), mSource(std::move(source)) {}

    void error(const std::string& key, const std::string& problem) { mErrors.push_back(mSource + ": " + key + ": " + problem); }

    bool object(const Json& j, const std::string& key, const std::vector<std::string>& allowed) {
        if (!j.is_object()) {
            error(key, "must be an object");
            return false;
        }
        for (const auto& item : j.items())
            if (std::find(allowed.begin(), allowed.end(), item.key()) == allowed.end())
                error(join(key, item.key()), "unknown key");
        return true;
    }

    template <typename Assign>
    void number(const Json& parent, const std::string& path, const char* key, double lo, double hi, Assign assign,
                bool required = false) {
        if (!parent.contains(key)) {
            if (required) error(join(path, key), "missing");
            return;
        }
        const Json& v = parent.at(key);
        if (!v.is_number()) {
            error(join(path, key), "must be a number");
            return;
        }
        const double x = v.get<double>();
        if (!std::isfinite(x) || x < lo || x > hi) {
            std::ostringstream s;
            s << x << " is out of range [" << lo << ", " << hi << "]";
            error(join(path, key), s.str());
            return;
        }
        assign(x);
    }

    void text(const Json& parent, const std::string& path, const char* key, std::string& out, bool required = false) {
        if (!parent.contains(key)) {
            if (required) error(join(path, key), "missing");
            return;
        }
        if (!parent.at(key).is_string()) {
            error(join(path, key), "must be a string");
            return;
        }
        out = parent.at(key).get<std::string>();
    }

    static std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

private:
    std::vector<std::string>& mErrors;
    std::string mSource;
};

bool isWhole(double x) { return std::floor(x) == x; }

}  // namespace

PresetLoadResult parseTissuePreset(const std::string& textIn, const std::string& source) {
    PresetLoadResult result;
    Reader r(result.errors, source);
    Json j;
    try {
        j = Json::parse(textIn);
    } catch (const Json::parse_error& e) {
        result.errors.push_back(source + ": not valid JSON at byte " + std::to_string(e.byte) + ": " +
                                std::string(e.what()).substr(std::string(e.what()).find(']') + 2));
        return result;
    }
    if (!r.object(j, "", {"format", "version", "name", "description", "model", "slope_ring", "octree",
                          "haptic_rate_hz", "tissue"}))
        return result;

    std::string format;
    r.text(j, "", "format", format, true);
    if (!format.empty() && format != kFormat) r.error("format", "is '" + format + "', expected '" + kFormat + "'");
    r.number(j, "", "version", 1, 1e9, [&](double v) {
        if (!isWhole(v) || int(v) > kTissuePresetVersion)
            r.error("version", "version " + std::to_string(v) + " is not supported (this build reads up to " +
                                   std::to_string(kTissuePresetVersion) + ")");
    }, true);

    TissuePreset preset;
    r.text(j, "", "name", preset.name, true);
    r.text(j, "", "description", preset.description);
    if (j.contains("model")) {
        std::string model;
        r.text(j, "", "model", model);
        if (const auto m = parseMethod(model)) preset.method = *m;
        else if (j.at("model").is_string()) r.error("model", "unknown model '" + model + "' (use palpate, proposed, hybrid or previous)");
    }
    r.number(j, "", "haptic_rate_hz", 10, 10000, [&](double v) { preset.hapticRateHz = v; });

    if (j.contains("slope_ring")) {
        const Json& s = j.at("slope_ring");
        const std::string path = "slope_ring";
        if (r.object(s, path, {"ring_count", "slopes_mm_per_n", "slope_limit_mm_per_n", "contact_stiffness_n_per_mm",
                               "force_relaxation", "spring_stiffness_n_per_mm", "damping_ratio", "vertex_mass_kg"})) {
            SlopeRingParams& p = preset.params;
            r.number(s, path, "ring_count", 0, kMaxRings, [&](double v) {
                if (!isWhole(v)) r.error("slope_ring.ring_count", "must be a whole number");
                else p.ringCount = int(v);
            }, true);
            if (!s.contains("slopes_mm_per_n")) {
                r.error("slope_ring.slopes_mm_per_n", "missing");
            } else if (!s.at("slopes_mm_per_n").is_array()) {
                r.error("slope_ring.slopes_mm_per_n", "must be an array of numbers");
            } else {
                const Json& a = s.at("slopes_mm_per_n");
                if (a.size() != std::size_t(p.ringCount + 1))
                    r.error("slope_ring.slopes_mm_per_n", "has " + std::to_string(a.size()) + " values; ring_count " +
                                                              std::to_string(p.ringCount) + " needs " +
                                                              std::to_string(p.ringCount + 1));
                for (std::size_t i = 0; i < a.size() && i <= std::size_t(kMaxRings); ++i) {
                    if (!a[i].is_number()) {
                        r.error("slope_ring.slopes_mm_per_n[" + std::to_string(i) + "]", "must be a number");
                        continue;
                    }
                    p.slopeMagnitudeMmPerN[i] = a[i].get<double>();
                }
            }
            r.number(s, path, "slope_limit_mm_per_n", 0, 1e9, [&](double v) { p.slopeLimitMmPerN = v; });
            r.number(s, path, "contact_stiffness_n_per_mm", 0, 1e9, [&](double v) { p.contactStiffnessNPerMm = v; });
            r.number(s, path, "force_relaxation", 0, 1, [&](double v) { p.forceRelaxation = v; });
            r.number(s, path, "spring_stiffness_n_per_mm", 0, 1e9, [&](double v) { p.springStiffnessNPerMm = v; });
            r.number(s, path, "damping_ratio", 0, 100, [&](double v) { p.dampingRatio = v; });
            r.number(s, path, "vertex_mass_kg", 0, 1e9, [&](double v) { p.vertexMassKg = v; });
            if (result.errors.empty())
                for (const std::string& e : validateSlopeRingParams(p)) r.error("slope_ring", e);
        }
    }
    if (j.contains("octree")) {
        const Json& o = j.at("octree");
        if (r.object(o, "octree", {"max_depth", "leaf_capacity"})) {
            r.number(o, "octree", "max_depth", 1, 20, [&](double v) {
                if (!isWhole(v)) r.error("octree.max_depth", "must be a whole number");
                preset.octree.maxDepth = int(v);
            });
            r.number(o, "octree", "leaf_capacity", 1, 100000, [&](double v) {
                if (!isWhole(v)) r.error("octree.leaf_capacity", "must be a whole number");
                preset.octree.leafCapacity = int(v);
            });
        }
    }
    if (j.contains("tissue")) {
        const Json& t = j.at("tissue");
        if (r.object(t, "tissue", {"youngs_modulus_kpa", "poisson_ratio", "tool_radius_mm", "source"})) {
            TissueProperties tissue;
            r.number(t, "tissue", "youngs_modulus_kpa", 1e-6, 1e9, [&](double v) { tissue.youngsModulusKPa = v; }, true);
            r.number(t, "tissue", "poisson_ratio", 0.0, 0.4999, [&](double v) { tissue.poissonRatio = v; }, true);
            r.number(t, "tissue", "tool_radius_mm", 0.01, 1000, [&](double v) { tissue.toolRadiusMm = v; });
            r.text(t, "tissue", "source", tissue.source, true);
            preset.tissue = tissue;
        }
    }
    if (result.errors.empty()) result.preset = preset;
    return result;
}

PresetLoadResult loadTissuePreset(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (ec || !fs::exists(status)) return {std::nullopt, {path + ": no such file"}};
    if (fs::is_directory(status)) return {std::nullopt, {path + ": is a directory, not a preset file"}};
    std::ifstream in(path, std::ios::binary);
    if (!in) return {std::nullopt, {path + ": cannot be opened for reading"}};
    std::ostringstream text;
    text << in.rdbuf();
    return parseTissuePreset(text.str(), path);
}

std::string tissuePresetToJson(const TissuePreset& preset) {
    const SlopeRingParams& p = preset.params;
    Json slopes = Json::array();
    for (int r = 0; r <= p.ringCount; ++r) slopes.push_back(p.slopeMagnitudeMmPerN[std::size_t(r)]);
    Json j{{"format", kFormat},
           {"version", kTissuePresetVersion},
           {"name", preset.name},
           {"description", preset.description},
           {"model", std::string(methodName(preset.method))},
           {"haptic_rate_hz", preset.hapticRateHz},
           {"slope_ring",
            {{"ring_count", p.ringCount},
             {"slopes_mm_per_n", slopes},
             {"slope_limit_mm_per_n", p.slopeLimitMmPerN},
             {"contact_stiffness_n_per_mm", p.contactStiffnessNPerMm},
             {"force_relaxation", p.forceRelaxation},
             {"spring_stiffness_n_per_mm", p.springStiffnessNPerMm},
             {"damping_ratio", p.dampingRatio},
             {"vertex_mass_kg", p.vertexMassKg}}},
           {"octree", {{"max_depth", preset.octree.maxDepth}, {"leaf_capacity", preset.octree.leafCapacity}}}};
    if (preset.tissue)
        j["tissue"] = {{"youngs_modulus_kpa", preset.tissue->youngsModulusKPa},
                       {"poisson_ratio", preset.tissue->poissonRatio},
                       {"tool_radius_mm", preset.tissue->toolRadiusMm},
                       {"source", preset.tissue->source}};
    return j.dump(2) + "\n";
}

std::string saveTissuePreset(const TissuePreset& preset, const std::string& path) {
    const std::string temporary = path + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) return path + ": cannot be written";
        out << tissuePresetToJson(preset);
        out.flush();
        if (!out) return path + ": writing failed";
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        return path + ": cannot be replaced: " + ec.message();
    }
    return {};
}

}  // namespace palpate
