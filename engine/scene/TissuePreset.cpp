#include "engine/scene/TissuePreset.h"

#include "base/io/AtomicFile.h"
#include "engine/core/HapticRate.h"
#include "base/io/InputFile.h"
#include "base/io/JsonFields.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace palpate {

namespace {

constexpr const char* kFormat = "palpate-tissue-preset";

constexpr FieldDef<TissueProperties> kTissueFields[] = {
    field<&TissueProperties::youngsModulusKPa>(
        {.key = "youngsModulusKPa",
         .jsonKey = "youngs_modulus_kpa",
         .unit = "kPa",
         .lo = 0,
         .hi = 1e9,
         .lower = Bound::Open,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Young's modulus E:"),
         .name = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Young's modulus"),
         .tip = PALPATE_TRANSLATE_NOOP("palpate::Parameters",
                                       "Stiffness of the tissue, kPa (soft tissue: about 1 to 30 kPa)."),
         .decimals = 4,
         .step = 0.1,
         .required = true}),
    field<&TissueProperties::poissonRatio>(
        {.key = "poissonRatio",
         .jsonKey = "poisson_ratio",
         .lo = 0,
         .hi = 0.4999,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Poisson's ratio ν:"),
         .name = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Poisson's ratio"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "How the tissue bulges sideways when pressed, 0..0.4999 (soft tissue is nearly incompressible: about "
             "0.45 to 0.49; 0.5 would be incompressible)."),
         .decimals = 4,
         .step = 0.01,
         .required = true}),
    field<&TissueProperties::toolRadiusMm>(
        {.key = "toolRadiusMm",
         .jsonKey = "tool_radius_mm",
         .unit = "mm",
         .lo = 0.01,
         .hi = 1000,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Tool radius a:"),
         .name = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "tool radius"),
         .tip = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Radius of the probe's flat tip, mm (0.01..1000)."),
         .decimals = 3,
         .step = 0.5}),
    field<&TissueProperties::staticFriction>(
        {.key = "staticFriction",
         .jsonKey = "static_friction",
         .lo = 0,
         .hi = 5,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Static friction μs:"),
         .name = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "static friction coefficient"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "Coulomb friction between tool and tissue: the tool sticks until the sideways force exceeds μs times "
             "the normal force (0..5; 0 and 0: no friction). Moist soft tissue: about 0.3."),
         .decimals = 3,
         .step = 0.05}),
    field<&TissueProperties::dynamicFriction>(
        {.key = "dynamicFriction",
         .jsonKey = "dynamic_friction",
         .lo = 0,
         .hi = 5,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Sliding friction μd:"),
         .name = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "sliding friction coefficient"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "While the tool slides, the sideways force is μd times the normal force (0..5, at most μs)."),
         .decimals = 3,
         .step = 0.05}),
    field<&TissueProperties::stiffeningExponent>(
        {.key = "stiffeningExponent",
         .jsonKey = "stiffening_exponent",
         .lo = 0,
         .hi = 100,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Stiffening b (reference):"),
         .name = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "stiffening exponent"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "How fast the tissue stiffens with strain: b of the exponential law of the hyperelastic reference "
             "(0..100; 0: neo-Hookean). It does not change the force by itself: Charts > Stiffening > Compute "
             "solves the reference with it, and Apply knots puts the model's stiffening knots into the tissue."),
         .decimals = 4,
         .step = 0.5}),
};

constexpr FieldDef<PresetStabilityMargin> kMarginFields[] = {
    // Any finite margin up to 1 (far beyond a bound it is a large negative number).
    field<&PresetStabilityMargin::margin>(
        {.key = "margin", .jsonKey = "margin", .lo = -1e308, .hi = 1, .required = true}),
    field<&PresetStabilityMargin::dtS>(
        {.key = "dtS", .jsonKey = "dt_s", .unit = "s", .lo = 1e-6, .hi = 1, .required = true}),
};

/// A model's section: read through its table, then checked by its validator, each problem at the
/// key of the field it names. Returns whether the section is valid.
template <class S>
bool readSection(JsonReader& r, const Json& j, const char* section, FieldTable<S> table, S& s,
                 Problems (*validate)(const S&)) {
    const std::size_t before = r.errorCount();
    readFields(r, j.at(section), section, table, s);
    if (r.errorCount() != before) return false;
    const Problems problems = validate(s);
    reportProblems(r, table, section, problems);
    return problems.empty();
}

/// A preset section of one model's own parameters (ModelDescriptor::section): how it is read
/// and checked, written, compared and copied. A model with a new parameter struct adds a row.
struct ModelSectionIo {
    const char* section;
    bool (*read)(JsonReader& r, const Json& j, const char* section, ModelDef& def);
    Json (*write)(const ModelDef& def);
    bool (*same)(const ModelDef& a, const ModelDef& b);
    void (*copy)(ModelDef& to, const ModelDef& from);
};

template <auto Member, auto Fields, auto Validate>
constexpr ModelSectionIo sectionOf(const char* section) {
    return {section,
            [](JsonReader& r, const Json& j, const char* name, ModelDef& def) {
                return readSection(r, j, name, Fields(), def.*Member, Validate);
            },
            [](const ModelDef& def) { return Json(fieldsToJson(Fields(), def.*Member)); },
            [](const ModelDef& a, const ModelDef& b) { return sameFields(Fields(), a.*Member, b.*Member); },
            [](ModelDef& to, const ModelDef& from) { to.*Member = from.*Member; }};
}

constexpr ModelSectionIo kModelSections[] = {
    sectionOf<&ModelDef::slopeRing, slopeRingFields, validateSlopeRingParams>("slope_ring"),
    sectionOf<&ModelDef::massSpring, massSpringFields, validateMassSpringParams>("mass_spring"),
    sectionOf<&ModelDef::radiusOfInfluence, radiusOfInfluenceFields, validateRadiusOfInfluenceParams>(
        "radius_of_influence"),
    sectionOf<&ModelDef::ffd, ffdFields, validateFfdParams>("ffd"),
};

const ModelSectionIo& sectionOfModel(const ModelDef& def) {
    const std::string_view section = modelDescriptor(def).section;
    for (const ModelSectionIo& io : kModelSections)
        if (section == io.section) return io;
    throw std::logic_error("no preset section '" + std::string(section) + "' for the model " + modelName(def));
}

}  // namespace

ContactDef contactDefOf(const TissueProperties& tissue) {
    return {.toolRadiusMm = tissue.toolRadiusMm,
            .staticFriction = tissue.staticFriction,
            .dynamicFriction = tissue.dynamicFriction};
}

double presetToolRadiusMm(const TissuePreset& preset) { return modelToolRadiusMm(presetModelDef(preset)); }

ModelDef presetModelDef(const TissuePreset& preset) {
    ModelDef def = preset.model;
    def.contact = contactDefOf(preset.tissue.value_or(TissueProperties{}));
    return def;
}

std::string presetModelName(const TissuePreset& preset) { return modelName(presetModelDef(preset)); }

void setPresetModel(TissuePreset& preset, const ModelDef& def) {
    preset.model.kind = def.kind;
    preset.model.slopeRingMethod = def.slopeRingMethod;
    sectionOfModel(def).copy(preset.model, def);
}

bool presetUsesSlopeRingParams(const TissuePreset& preset) { return slopeRingParamsOf(preset.model) != nullptr; }

FieldTable<TissueProperties> tissueFields() { return kTissueFields; }
FieldTable<PresetStabilityMargin> stabilityMarginFields() { return kMarginFields; }

Problems validateTissueProperties(const TissueProperties& tissue) {
    Problems problems;
    checkFields(tissueFields(), tissue, problems);
    if (!hasProblem(problems, "dynamicFriction") && !hasProblem(problems, "staticFriction") &&
        tissue.dynamicFriction > tissue.staticFriction)
        problems.push_back({.field = "dynamicFriction",
                            .message = "sliding friction coefficient " + formatNumber(tissue.dynamicFriction) +
                                       " is above the static one " + formatNumber(tissue.staticFriction) +
                                       " (a sliding tool cannot hold more than a sticking one)"});
    return problems;
}

bool samePreset(const TissuePreset& a, const TissuePreset& b) {
    const bool sameTissue = a.tissue.has_value() == b.tissue.has_value() &&
                            (!a.tissue || (sameFields(tissueFields(), *a.tissue, *b.tissue) &&
                                           a.tissue->source == b.tissue->source &&
                                           a.tissue->stiffeningSource == b.tissue->stiffeningSource));
    const bool sameModel = a.model.kind == b.model.kind && a.model.slopeRingMethod == b.model.slopeRingMethod &&
                           std::all_of(std::begin(kModelSections), std::end(kModelSections),
                                       [&](const ModelSectionIo& io) { return io.same(a.model, b.model); });
    return a.name == b.name && a.description == b.description && sameModel &&
           sameFields(octreeFields(), a.octree, b.octree) && a.hapticRateHz == b.hapticRateHz && sameTissue;
}

namespace {

PresetLoadResult parsePresetText(const std::string& textIn, const std::string& source) {
    PresetLoadResult result;
    JsonReader r(result.errors, source);
    const std::optional<Json> parsed = r.parse(textIn);
    if (!parsed) return result;
    const Json& j = *parsed;
    if (!r.object(j, "",
                  {"format", "version", "name", "description", "model", "slope_ring", "mass_spring",
                   "radius_of_influence", "ffd", "octree", "haptic_rate_hz", "tissue", "needs", "stability_margin"}))
        return result;

    std::string format;
    r.text(j, "", "format", format, true);
    if (!format.empty() && format != kFormat) r.error("format", "is '" + format + "', expected '" + kFormat + "'");
    double version = 0.0;
    if (r.number(j, "", "version", 1, 1e9, version, true) &&
        (std::floor(version) != version || int(version) > kTissuePresetVersion))
        r.error("version", "version " + formatNumber(version) + " is not supported (this build reads up to " +
                               std::to_string(kTissuePresetVersion) + ")");

    TissuePreset preset;
    r.text(j, "", "name", preset.name, true);
    r.text(j, "", "description", preset.description);
    if (j.contains("model")) {
        std::string model;
        r.text(j, "", "model", model);
        if (const auto def = modelDefForName(model)) {
            preset.model.kind = def->kind;
            preset.model.slopeRingMethod = def->slopeRingMethod;
        } else if (j.at("model").is_string()) {
            std::string names;
            for (const std::string& n : modelNames()) names += (names.empty() ? "" : ", ") + n;
            r.error("model", "unknown model '" + model + "' (use one of " + names + ")");
        }
    }
    r.number(j, "", "haptic_rate_hz", kMinHapticRateHz, kMaxHapticRateHz, preset.hapticRateHz);

    // Each model's own section, read whatever the model (a hand-written preset may keep several)
    // and checked by the model's validator.
    for (const ModelSectionIo& io : kModelSections)
        if (j.contains(io.section)) io.read(r, j, io.section, preset.model);
    if (j.contains("octree")) readSection(r, j, "octree", octreeFields(), preset.octree, validateOctreeDef);
    if (j.contains("tissue")) {
        const Json& t = j.at("tissue");
        TissueProperties tissue;
        const std::size_t before = r.errorCount();
        if (t.is_object()) {
            // "source" beside the table's fields; readFields checks the keys.
            Json numbers = t;
            numbers.erase("source");
            numbers.erase("stiffening_source");
            readFields(r, numbers, "tissue", tissueFields(), tissue);
            r.text(t, "tissue", "source", tissue.source, true);
            if (t.contains("stiffening_source")) r.text(t, "tissue", "stiffening_source", tissue.stiffeningSource, false);
        } else {
            r.error("tissue", "must be an object");
        }
        if (r.errorCount() == before) {
            reportProblems(r, tissueFields(), "tissue", validateTissueProperties(tissue));
            if (r.errorCount() == before) preset.tissue = tissue;
        }
    }
    if (j.contains("needs") && r.object(j.at("needs"), "needs", {"max_error", "budget_us"})) {
        // Read any finite number here; validateLodNeeds says what is out of range, by key.
        LodNeeds needs;
        const bool complete = j.at("needs").contains("max_error") && j.at("needs").contains("budget_us");
        r.number(j.at("needs"), "needs", "max_error", needs.maxErrorFraction, true);
        r.number(j.at("needs"), "needs", "budget_us", needs.budgetUs, true);
        if (complete) {
            for (const std::string& problem : messagesOf(validateLodNeeds(needs)))
                result.errors.push_back(source + ": " + problem);
            preset.needs = needs;
        }
    }
    // Informational (the panel writes it on save): checked for type and range, never enforced.
    if (j.contains("stability_margin")) {
        PresetStabilityMargin margin;
        const std::size_t before = r.errorCount();
        readFields(r, j.at("stability_margin"), "stability_margin", stabilityMarginFields(), margin);
        if (r.errorCount() == before) {
            Problems problems;
            checkFields(stabilityMarginFields(), margin, problems);
            reportProblems(r, stabilityMarginFields(), "stability_margin", problems);
            if (problems.empty()) preset.stabilityMargin = margin;
        }
    }
    if (result.errors.empty()) result.preset = preset;
    return result;
}

}  // namespace

PresetLoadResult parseTissuePreset(const std::string& text, const std::string& source) {
    // Text that did not come through readInputFile (a recording's copy) has the file's limit too.
    if (const std::string problem = sizeLimitProblem(text.size(), kPresetFile); !problem.empty())
        return {std::nullopt, {source + ": " + problem}};
    // No exception of the JSON library leaves the loader: what it refuses is the file's problem.
    try {
        return parsePresetText(text, source);
    } catch (const Json::exception& e) {
        return {std::nullopt, {source + ": cannot be read: " + e.what()}};
    }
}

PresetLoadResult loadTissuePreset(const std::string& path) {
    std::string error;
    const auto text = readInputFile(path, kPresetFile, error);
    if (!text) return {std::nullopt, {error}};
    return parseTissuePreset(*text, path);
}

std::string tissuePresetToJson(const TissuePreset& preset) {
    Json j{{"format", kFormat},
           {"version", preset.model.kind == ModelKind::SlopeRing ? 1 : kTissuePresetVersion},
           {"name", preset.name},
           {"description", preset.description},
           {"model", presetModelName(preset)},
           {"haptic_rate_hz", preset.hapticRateHz},
           {"slope_ring", fieldsToJson(slopeRingFields(), preset.model.slopeRing)},
           {"octree", fieldsToJson(octreeFields(), preset.octree)}};
    // Only the section of the model in use (slope_ring always: the slope-ring methods and
    // volumetric-rings run on it, and the GUI keeps it for a switch back).
    const ModelSectionIo& own = sectionOfModel(preset.model);
    if (!j.contains(own.section)) j[own.section] = own.write(preset.model);
    if (preset.tissue) {
        j["tissue"] = fieldsToJson(tissueFields(), *preset.tissue);
        j["tissue"]["source"] = preset.tissue->source;
        if (!preset.tissue->stiffeningSource.empty()) j["tissue"]["stiffening_source"] = preset.tissue->stiffeningSource;
    }
    if (preset.needs)
        j["needs"] = {{"max_error", preset.needs->maxErrorFraction}, {"budget_us", preset.needs->budgetUs}};
    if (preset.stabilityMargin && std::isfinite(preset.stabilityMargin->margin) &&
        std::isfinite(preset.stabilityMargin->dtS))
        j["stability_margin"] = fieldsToJson(stabilityMarginFields(), *preset.stabilityMargin);
    return j.dump(2) + "\n";
}

std::string saveTissuePreset(const TissuePreset& preset, const std::string& path) {
    if (preset.needs)
        if (const auto problems = validateLodNeeds(*preset.needs); !problems.empty())
            return path + ": not saved: " + problems.front().message;
    // Never a file the reader refuses.
    const std::string text = tissuePresetToJson(preset);
    if (const std::string problem = sizeLimitProblem(text.size(), kPresetFile); !problem.empty())
        return path + ": not saved: the preset would be " + problem + " (its description is " +
               std::to_string(preset.description.size()) + " bytes)";
    return writeFileAtomically(path, text);
}

}  // namespace palpate
