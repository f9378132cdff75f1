#include "engine/scene/TissuePreset.h"

#include "engine/io/AtomicFile.h"
#include "engine/io/TextFile.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
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

/// A JSON key of a model's section and the params field its validator names.
struct KeyField {
    const char* key;
    const char* field;
};
constexpr KeyField kMassSpringKeys[] = {
    {"vertex_mass_kg", "vertexMassKg"},
    {"anchor_stiffness_n_per_mm", "anchorStiffnessNPerMm"},
    {"edge_stiffness_n_per_mm", "edgeStiffnessNPerMm"},
    {"contact_stiffness_n_per_mm", "contactStiffnessNPerMm"},
    {"damping_ratio", "dampingRatio"},
    {"substeps", "substeps"},
    {"max_substeps", "maxSubsteps"},
    {"cg_max_iterations", "cgMaxIterations"},
    {"cg_tolerance", "cgTolerance"},
    {"local_ring_count", "localRingCount"},
    {"local_integrator", "localIntegrator"},
    {"rest_epsilon_mm", "restEpsilonMm"},
};
constexpr KeyField kRadiusOfInfluenceKeys[] = {
    {"radius_mm", "radiusMm"},
    {"degree", "degree"},
    {"coefficients", "coefficients"},
    {"stiffness_n_per_mm", "stiffnessNPerMm"},
};
constexpr KeyField kFfdKeys[] = {
    {"control_points_per_axis", "controlPointsPerAxis"},
    {"moved_per_axis", "movedPerAxis"},
    {"margin_fraction", "marginFraction"},
    {"stiffness_n_per_mm", "stiffnessNPerMm"},
};

template <std::size_t N>
std::vector<std::string> keysOf(const KeyField (&table)[N]) {
    std::vector<std::string> keys;
    for (const KeyField& k : table) keys.emplace_back(k.key);
    return keys;
}

/// Reports a validator's messages at the key of the field each names ("radiusMm = ..." under
/// "radius_of_influence.radius_mm").
template <std::size_t N>
void reportValidation(Reader& r, const std::string& section, const KeyField (&table)[N],
                      const std::vector<std::string>& problems) {
    for (const std::string& problem : problems) {
        std::string path = section;
        const std::size_t end = problem.find_first_of(" [:");
        const std::string field = problem.substr(0, end);
        for (const KeyField& k : table)
            if (field == k.field) path = section + "." + k.key;
        r.error(path, problem);
    }
}

/// A whole number in [lo, hi] into `out`.
void wholeNumber(Reader& r, const Json& parent, const std::string& path, const char* key, double lo, double hi, int& out) {
    r.number(parent, path, key, lo, hi, [&](double v) {
        if (!isWhole(v)) r.error(Reader::join(path, key), "must be a whole number");
        else out = int(v);
    });
}

void readMassSpring(Reader& r, const Json& s, MassSpringParams& p) {
    const std::string path = "mass_spring";
    if (!r.object(s, path, keysOf(kMassSpringKeys))) return;
    const double big = 1e12;
    r.number(s, path, "vertex_mass_kg", -big, big, [&](double v) { p.vertexMassKg = v; });
    r.number(s, path, "anchor_stiffness_n_per_mm", -big, big, [&](double v) { p.anchorStiffnessNPerMm = v; });
    r.number(s, path, "edge_stiffness_n_per_mm", -big, big, [&](double v) { p.edgeStiffnessNPerMm = v; });
    r.number(s, path, "contact_stiffness_n_per_mm", -big, big, [&](double v) { p.contactStiffnessNPerMm = v; });
    r.number(s, path, "damping_ratio", -big, big, [&](double v) { p.dampingRatio = v; });
    wholeNumber(r, s, path, "substeps", -1e9, 1e9, p.substeps);
    wholeNumber(r, s, path, "max_substeps", -1e9, 1e9, p.maxSubsteps);
    wholeNumber(r, s, path, "cg_max_iterations", -1e9, 1e9, p.cgMaxIterations);
    r.number(s, path, "cg_tolerance", -big, big, [&](double v) { p.cgTolerance = v; });
    wholeNumber(r, s, path, "local_ring_count", -1e9, 1e9, p.localRingCount);
    r.number(s, path, "rest_epsilon_mm", -big, big, [&](double v) { p.restEpsilonMm = v; });
    if (s.contains("local_integrator")) {
        std::string name;
        r.text(s, path, "local_integrator", name);
        if (const auto integrator = parseIntegrator(name)) p.localIntegrator = *integrator;
        else if (s.at("local_integrator").is_string())
            r.error(path + ".local_integrator", "unknown integrator '" + name + "' (use symplectic, rk4 or implicit)");
    }
}

void readRadiusOfInfluence(Reader& r, const Json& s, RadiusOfInfluenceParams& p) {
    const std::string path = "radius_of_influence";
    if (!r.object(s, path, keysOf(kRadiusOfInfluenceKeys))) return;
    const double big = 1e12;
    r.number(s, path, "radius_mm", -big, big, [&](double v) { p.radiusMm = v; });
    r.number(s, path, "stiffness_n_per_mm", -big, big, [&](double v) { p.stiffnessNPerMm = v; });
    const bool haveDegree = s.contains("degree");
    wholeNumber(r, s, path, "degree", 2, kMaxProfileDegree, p.degree);
    if (!s.contains("coefficients")) {
        // Without coefficients, (1 - rho)^degree.
        if (haveDegree) p.coefficients = powerProfileCoefficients(p.degree);
        return;
    }
    const Json& a = s.at("coefficients");
    const std::string key = path + ".coefficients";
    if (!a.is_array()) {
        r.error(key, "must be an array of numbers");
        return;
    }
    if (a.size() != std::size_t(p.degree + 1)) {
        r.error(key, "has " + std::to_string(a.size()) + " values; degree " + std::to_string(p.degree) + " needs " +
                         std::to_string(p.degree + 1));
        return;
    }
    p.coefficients.fill(0.0);
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (!a[i].is_number()) {
            r.error(key + "[" + std::to_string(i) + "]", "must be a number");
            continue;
        }
        p.coefficients[i] = a[i].get<double>();
    }
}

void readFfd(Reader& r, const Json& s, FfdParams& p) {
    const std::string path = "ffd";
    if (!r.object(s, path, keysOf(kFfdKeys))) return;
    wholeNumber(r, s, path, "control_points_per_axis", -1e9, 1e9, p.controlPointsPerAxis);
    wholeNumber(r, s, path, "moved_per_axis", -1e9, 1e9, p.movedPerAxis);
    r.number(s, path, "margin_fraction", -1e12, 1e12, [&](double v) { p.marginFraction = v; });
    r.number(s, path, "stiffness_n_per_mm", -1e12, 1e12, [&](double v) { p.stiffnessNPerMm = v; });
}

Json massSpringJson(const MassSpringParams& p) {
    return {{"vertex_mass_kg", p.vertexMassKg},
            {"anchor_stiffness_n_per_mm", p.anchorStiffnessNPerMm},
            {"edge_stiffness_n_per_mm", p.edgeStiffnessNPerMm},
            {"contact_stiffness_n_per_mm", p.contactStiffnessNPerMm},
            {"damping_ratio", p.dampingRatio},
            {"substeps", p.substeps},
            {"max_substeps", p.maxSubsteps},
            {"cg_max_iterations", p.cgMaxIterations},
            {"cg_tolerance", p.cgTolerance},
            {"local_ring_count", p.localRingCount},
            {"local_integrator", std::string(integratorName(p.localIntegrator))},
            {"rest_epsilon_mm", p.restEpsilonMm}};
}

Json radiusOfInfluenceJson(const RadiusOfInfluenceParams& p) {
    Json coefficients = Json::array();
    for (int k = 0; k <= std::clamp(p.degree, 0, kMaxProfileDegree); ++k) coefficients.push_back(p.coefficients[std::size_t(k)]);
    return {{"radius_mm", p.radiusMm},
            {"degree", p.degree},
            {"coefficients", coefficients},
            {"stiffness_n_per_mm", p.stiffnessNPerMm}};
}

Json ffdJson(const FfdParams& p) {
    return {{"control_points_per_axis", p.controlPointsPerAxis},
            {"moved_per_axis", p.movedPerAxis},
            {"margin_fraction", p.marginFraction},
            {"stiffness_n_per_mm", p.stiffnessNPerMm}};
}

bool isMassSpring(ModelKind kind) {
    return kind == ModelKind::MassSpringSymplectic || kind == ModelKind::MassSpringRk4 ||
           kind == ModelKind::MassSpringImplicit || kind == ModelKind::MassSpringLocal;
}

}  // namespace

ModelDef presetModelDef(const TissuePreset& preset) {
    ModelDef def;
    def.kind = preset.modelKind;
    def.slopeRingMethod = preset.method;
    def.slopeRing = preset.params;
    def.massSpring = preset.massSpring;
    def.radiusOfInfluence = preset.radiusOfInfluence;
    def.ffd = preset.ffd;
    def.volumetricRings.slopeRing = preset.params;
    return def;
}

std::string presetModelName(const TissuePreset& preset) { return modelName(presetModelDef(preset)); }

void setPresetModel(TissuePreset& preset, const ModelDef& def) {
    preset.modelKind = def.kind;
    switch (def.kind) {
        case ModelKind::SlopeRing:
            preset.method = def.slopeRingMethod;
            preset.params = def.slopeRing;
            break;
        case ModelKind::VolumetricRings: preset.params = def.volumetricRings.slopeRing; break;
        case ModelKind::RadiusOfInfluence: preset.radiusOfInfluence = def.radiusOfInfluence; break;
        case ModelKind::Ffd: preset.ffd = def.ffd; break;
        default: preset.massSpring = def.massSpring; break;
    }
}

bool presetUsesSlopeRingParams(const TissuePreset& preset) {
    return preset.modelKind == ModelKind::SlopeRing || preset.modelKind == ModelKind::VolumetricRings;
}

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
    if (!r.object(j, "", {"format", "version", "name", "description", "model", "slope_ring", "mass_spring",
                          "radius_of_influence", "ffd", "octree", "haptic_rate_hz", "tissue", "needs",
                          "stability_margin"}))
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
        if (const auto def = modelDefForName(model)) {
            preset.modelKind = def->kind;
            if (def->kind == ModelKind::SlopeRing) preset.method = def->slopeRingMethod;
        } else if (j.at("model").is_string()) {
            std::string names;
            for (const std::string& n : modelNames()) names += (names.empty() ? "" : ", ") + n;
            r.error("model", "unknown model '" + model + "' (use one of " + names + ")");
        }
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
    // Each registry model's own section, read whatever the model (a hand-written preset may keep
    // several) and checked by the model's validator, each message at the key it names.
    if (j.contains("mass_spring")) {
        const std::size_t before = result.errors.size();
        readMassSpring(r, j.at("mass_spring"), preset.massSpring);
        if (result.errors.size() == before)
            reportValidation(r, "mass_spring", kMassSpringKeys, validateMassSpringParams(preset.massSpring));
    }
    if (j.contains("radius_of_influence")) {
        const std::size_t before = result.errors.size();
        readRadiusOfInfluence(r, j.at("radius_of_influence"), preset.radiusOfInfluence);
        if (result.errors.size() == before)
            reportValidation(r, "radius_of_influence", kRadiusOfInfluenceKeys,
                             validateRadiusOfInfluenceParams(preset.radiusOfInfluence));
    }
    if (j.contains("ffd")) {
        const std::size_t before = result.errors.size();
        readFfd(r, j.at("ffd"), preset.ffd);
        if (result.errors.size() == before) reportValidation(r, "ffd", kFfdKeys, validateFfdParams(preset.ffd));
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
    if (j.contains("needs") && r.object(j.at("needs"), "needs", {"max_error", "budget_us"})) {
        // Read any finite number here; validateLodNeeds says what is out of range, by key.
        const double inf = std::numeric_limits<double>::infinity();
        LodNeeds needs;
        bool complete = true;
        for (const char* key : {"max_error", "budget_us"})
            if (!j.at("needs").contains(key)) complete = false;
        r.number(j.at("needs"), "needs", "max_error", -inf, inf, [&](double v) { needs.maxErrorFraction = v; }, true);
        r.number(j.at("needs"), "needs", "budget_us", -inf, inf, [&](double v) { needs.budgetUs = v; }, true);
        if (complete) {
            for (const std::string& problem : validateLodNeeds(needs)) result.errors.push_back(source + ": " + problem);
            preset.needs = needs;
        }
    }
    // Informational (the panel writes it on save): checked for type and range, never enforced.
    if (j.contains("stability_margin") && r.object(j.at("stability_margin"), "stability_margin", {"margin", "dt_s"})) {
        PresetStabilityMargin margin;
        const std::size_t before = result.errors.size();
        // Any finite margin up to 1 (far beyond a bound it is a large negative number).
        r.number(j.at("stability_margin"), "stability_margin", "margin", -std::numeric_limits<double>::max(), 1.0,
                 [&](double v) { margin.margin = v; }, true);
        r.number(j.at("stability_margin"), "stability_margin", "dt_s", 1e-6, 1.0, [&](double v) { margin.dtS = v; }, true);
        if (result.errors.size() == before) preset.stabilityMargin = margin;
    }
    if (result.errors.empty()) result.preset = preset;
    return result;
}

PresetLoadResult loadTissuePreset(const std::string& path) {
    std::string error;
    const auto text = readTextFile(path, "a preset file", error);
    if (!text) return {std::nullopt, {error}};
    return parseTissuePreset(*text, path);
}

std::string tissuePresetToJson(const TissuePreset& preset) {
    const SlopeRingParams& p = preset.params;
    Json slopes = Json::array();
    for (int r = 0; r <= p.ringCount; ++r) slopes.push_back(p.slopeMagnitudeMmPerN[std::size_t(r)]);
    Json j{{"format", kFormat},
           {"version", preset.modelKind == ModelKind::SlopeRing ? 1 : kTissuePresetVersion},
           {"name", preset.name},
           {"description", preset.description},
           {"model", presetModelName(preset)},
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
    // Only the section of the model in use (slope_ring always: the slope-ring methods and
    // volumetric-rings run on it, and the GUI keeps it for a switch back).
    if (isMassSpring(preset.modelKind)) j["mass_spring"] = massSpringJson(preset.massSpring);
    if (preset.modelKind == ModelKind::RadiusOfInfluence) j["radius_of_influence"] = radiusOfInfluenceJson(preset.radiusOfInfluence);
    if (preset.modelKind == ModelKind::Ffd) j["ffd"] = ffdJson(preset.ffd);
    if (preset.tissue)
        j["tissue"] = {{"youngs_modulus_kpa", preset.tissue->youngsModulusKPa},
                       {"poisson_ratio", preset.tissue->poissonRatio},
                       {"tool_radius_mm", preset.tissue->toolRadiusMm},
                       {"source", preset.tissue->source}};
    if (preset.needs) j["needs"] = {{"max_error", preset.needs->maxErrorFraction}, {"budget_us", preset.needs->budgetUs}};
    if (preset.stabilityMargin && std::isfinite(preset.stabilityMargin->margin) && std::isfinite(preset.stabilityMargin->dtS))
        j["stability_margin"] = {{"margin", preset.stabilityMargin->margin}, {"dt_s", preset.stabilityMargin->dtS}};
    return j.dump(2) + "\n";
}

std::string saveTissuePreset(const TissuePreset& preset, const std::string& path) {
    if (preset.needs)
        if (const auto problems = validateLodNeeds(*preset.needs); !problems.empty())
            return path + ": not saved: " + problems.front();
    return writeFileAtomically(path, tissuePresetToJson(preset));
}

}  // namespace palpate
