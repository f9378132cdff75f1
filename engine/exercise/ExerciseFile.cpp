#include "engine/exercise/ExerciseFile.h"

#include "base/io/AtomicFile.h"
#include "base/io/InputFile.h"
#include "base/io/JsonReader.h"
#include "engine/exercise/ExerciseKind.h"
#include "engine/exercise/kinds/Kinds.h"
#include "engine/record/RecordingFormat.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace palpate {

namespace {

constexpr const char* kFormat = "palpate-exercise";
constexpr const char* kNoteMarker = "palpate-exercise: ";

/// Keys joined for a message: "a, b or c" (`last` " and " instead of " or ").
std::string joinedKeys(const std::vector<std::string>& keys, const char* last) {
    std::string text;
    for (std::size_t i = 0; i < keys.size(); ++i) text += (i == 0 ? "" : i + 1 == keys.size() ? last : ", ") + keys[i];
    return text;
}

/// Every kind's key, or the palpation kinds', for messages.
std::vector<std::string> kindKeys(bool palpationOnly) {
    std::vector<std::string> keys;
    for (const ExerciseKind* kind : exerciseKinds())
        if (!palpationOnly || kind->palpation()) keys.emplace_back(kind->key());
    return keys;
}

/// "mesh_unit": a unit's name ("cm") or a number of mm per file unit (2.5), as parseMeshUnit
/// takes them (docs/meshes.md, "Units").
void readMeshUnit(JsonReader& r, const Json& v, MeshUnit& out) {
    if (!v.is_string() && !v.is_number()) {
        r.error("mesh_unit", "must be mm, cm, m, in or a number of mm per file unit");
        return;
    }
    std::string problem;
    // A number's own spelling (dump() round-trips a double), so that the factor read is the one written.
    if (const auto unit = parseMeshUnit(v.is_string() ? v.get<std::string>() : v.dump(), problem)) out = *unit;
    else r.error("mesh_unit", problem);
}

/// The file's "mesh_unit" value: the name, or the factor for a unit without one.
Json meshUnitJson(const MeshUnit& unit) {
    if (!unit.name.empty()) return unit.name;
    return unit.mmPerUnit;
}

}  // namespace

namespace {

/// "translations": {"de": {"name": ..., "description": ...}, ...} (docs/scoring.md, "Translations").
/// A key that is no language code is refused here; an entry with neither text by validateExercise.
void readTranslations(JsonReader& r, const Json& translations, Exercise& e) {
    if (!translations.is_object()) {
        r.error("translations", "must be an object of language codes, e.g. {\"de\": {\"name\": ...}}");
        return;
    }
    for (const auto& [code, words] : translations.items()) {
        if (!isLanguageCode(code)) {
            // Not quoted: a key may hold anything, and a code is at most six plain letters.
            r.error("translations", "a key of " + std::to_string(code.size()) +
                                        " bytes is not a language code (use two letters such as de, or de_AT)");
            continue;
        }
        const std::string key = "translations." + code;
        if (!r.object(words, key, {"name", "description"})) continue;
        ExerciseTextDef& text = e.translations[code];
        r.text(words, key, "name", text.name);
        r.text(words, key, "description", text.description);
    }
}

ExerciseLoadResult parseExerciseText(const std::string& textIn, const std::string& source) {
    ExerciseLoadResult result;
    JsonReader r(result.errors, source);
    const std::optional<Json> parsed = r.parse(textIn);
    if (!parsed) return result;
    const Json& j = *parsed;
    std::vector<std::string> keys = {"format",      "version",   "name",          "description",  "type",
                                     "mesh",        "mesh_unit", "tissue_preset", "time_limit_s", "show_live_score",
                                     "rubric",      "coverage",  "damage",        "force",        "needs",
                                     "translations"};
    for (const ExerciseKind* kind : exerciseKinds()) keys.emplace_back(kind->key());
    if (!r.object(j, "", keys)) return result;

    r.formatAndVersion(j, kFormat, kExerciseVersion);

    Exercise e;
    e.sourcePath = source;
    r.text(j, "", "name", e.name, true);
    r.text(j, "", "description", e.description);
    if (j.contains("translations")) readTranslations(r, j.at("translations"), e);
    std::string type;
    r.text(j, "", "type", type, true);
    bool typeKnown = false;
    if (j.contains("type") && j.at("type").is_string()) {
        if (const auto t = parseExerciseType(type)) {
            e.type = *t;
            typeKnown = true;
        } else {
            r.error("type", "unknown type '" + type + "' (use " + joinedKeys(kindKeys(false), " or ") + ")");
        }
    }
    r.text(j, "", "mesh", e.meshPath, true);
    if (j.contains("mesh_unit")) readMeshUnit(r, j.at("mesh_unit"), e.meshUnit);
    r.text(j, "", "tissue_preset", e.tissuePresetPath, true);
    r.number(j, "", "time_limit_s", e.timeLimitS, true);
    if (bool show = true; r.boolean(j, "", "show_live_score", show)) e.showLiveScore = show;

    if (j.contains("damage") && r.object(j.at("damage"), "damage", {"displacement_limit_mm"}))
        r.number(j.at("damage"), "damage", "displacement_limit_mm", e.displacementLimitMm);
    if (j.contains("force") && r.object(j.at("force"), "force", {"excessive_n"}))
        r.number(j.at("force"), "force", "excessive_n", e.excessiveForceN);

    // The section of the type, and no other.
    for (const ExerciseKind* kind : exerciseKinds()) {
        const std::string key(kind->key());
        if (typeKnown && kind->type() == e.type && !j.contains(key)) r.error(key, "missing (type is " + type + ")");
        if (typeKnown && kind->type() != e.type && j.contains(key)) r.error(key, "given, but type is " + type);
        if (j.contains(key) && (!typeKnown || kind->type() == e.type) && r.object(j.at(key), key, kind->sectionKeys()))
            kind->readSection(r, j.at(key), e);
    }
    if (j.contains("coverage") && r.object(j.at("coverage"), "coverage", {"min_force_n", "radius_mm"})) {
        if (typeKnown && !exerciseKind(e.type).palpation())
            r.error("coverage", "given, but type is " + type + " (coverage is scored for " + joinedKeys(kindKeys(true), " and ") + ")");
        r.number(j.at("coverage"), "coverage", "min_force_n", e.coverage.minForceN);
        r.number(j.at("coverage"), "coverage", "radius_mm", e.coverage.radiusMm);
    }
    if (j.contains("needs") && r.object(j.at("needs"), "needs", {"max_error", "budget_us"})) {
        LodNeeds needs;
        const bool hasError = r.number(j.at("needs"), "needs", "max_error", needs.maxErrorFraction, true);
        const bool hasBudget = r.number(j.at("needs"), "needs", "budget_us", needs.budgetUs, true);
        if (hasError && hasBudget) e.needs = needs;
    }
    if (j.contains("rubric")) {
        const Json& s = j.at("rubric");
        if (s.is_object()) {
            for (const auto& item : s.items()) {
                const std::string key = "rubric." + item.key();
                const auto metric = parseMetric(item.key());
                if (!metric) {
                    r.error(key, "unknown metric (docs/scoring.md lists them)");
                    continue;
                }
                if (!r.object(item.value(), key, {"weight", "full", "zero"})) continue;
                // Lines may set only some fields; the rest are the defaults (computed once the
                // whole exercise is read, below).
                e.rubric[std::size_t(*metric)] = RubricItem{std::nan(""), std::nan(""), std::nan("")};
                RubricItem& line = *e.rubric[std::size_t(*metric)];
                r.number(item.value(), key, "weight", line.weight);
                r.number(item.value(), key, "full", line.fullMarks);
                r.number(item.value(), key, "zero", line.zeroMarks);
            }
        } else {
            r.error("rubric", "must be an object (metric name: {weight, full, zero})");
        }
    }
    if (!result.errors.empty()) return result;

    for (std::size_t i = 0; i < kMetricCount; ++i) {
        if (!e.rubric[i]) continue;
        const RubricItem d = defaultRubricItem(e, Metric(i));
        RubricItem& line = *e.rubric[i];
        if (std::isnan(line.weight)) line.weight = d.weight;
        if (std::isnan(line.fullMarks)) line.fullMarks = d.fullMarks;
        if (std::isnan(line.zeroMarks)) line.zeroMarks = d.zeroMarks;
    }
    for (const std::string& problem : messagesOf(validateExercise(e))) result.errors.push_back(source + ": " + problem);
    if (e.needs)
        for (const std::string& problem : messagesOf(validateLodNeeds(*e.needs)))
            result.errors.push_back(source + ": " + problem);
    if (result.errors.empty()) result.exercise = std::move(e);
    return result;
}

}  // namespace

ExerciseLoadResult parseExercise(const std::string& text, const std::string& source) {
    // Text that did not come through readInputFile (a recording's note) has the file's limit too.
    if (const std::string problem = sizeLimitProblem(text.size(), kExerciseFile); !problem.empty())
        return {std::nullopt, {source + ": " + problem}};
    // No exception of the JSON library leaves the loader: what it refuses is the file's problem.
    try {
        return parseExerciseText(text, source);
    } catch (const Json::exception& e) {
        return {std::nullopt, {source + ": cannot be read: " + e.what()}};
    }
}

ExerciseLoadResult loadExercise(const std::string& path) {
    std::string error;
    const auto text = readInputFile(path, kExerciseFile, error);
    if (!text) return {std::nullopt, {error}};
    return parseExercise(*text, path);
}

std::string exerciseToJson(const Exercise& e, int indent) {
    Json j{{"format", kFormat},
           {"version", kExerciseVersion},
           {"name", e.name},
           {"description", e.description},
           {"type", std::string(exerciseTypeName(e.type))},
           {"mesh", e.meshPath}};
    // Only when not mm: a file written before units existed reads and writes back byte for byte.
    if (!e.meshUnit.isMillimetres()) j["mesh_unit"] = meshUnitJson(e.meshUnit);
    j["tissue_preset"] = e.tissuePresetPath;
    j["time_limit_s"] = e.timeLimitS;
    if (e.showLiveScore) j["show_live_score"] = *e.showLiveScore;  // absent: the kind's default, as older files
    j["damage"] = {{"displacement_limit_mm", e.displacementLimitMm}};
    j["force"] = {{"excessive_n", e.excessiveForceN}};
    const ExerciseKind& kind = exerciseKind(e.type);
    j[std::string(kind.key())] = kind.writeSection(e);
    // Only for the palpation types, and only when not the defaults: older files write back unchanged.
    if (kind.palpation() &&
        (e.coverage.minForceN != CoverageDef{}.minForceN || e.coverage.radiusMm != CoverageDef{}.radiusMm))
        j["coverage"] = {{"min_force_n", e.coverage.minForceN}, {"radius_mm", e.coverage.radiusMm}};
    Json rubric = Json::object();
    for (std::size_t i = 0; i < kMetricCount; ++i)
        if (e.rubric[i])
            rubric[std::string(metricName(Metric(i)))] = {
                {"weight", e.rubric[i]->weight}, {"full", e.rubric[i]->fullMarks}, {"zero", e.rubric[i]->zeroMarks}};
    if (!rubric.empty()) j["rubric"] = rubric;
    if (e.needs) j["needs"] = {{"max_error", e.needs->maxErrorFraction}, {"budget_us", e.needs->budgetUs}};
    if (!e.translations.empty()) {
        Json translations = Json::object();
        for (const auto& [code, text] : e.translations) {
            Json words = Json::object();
            if (!text.name.empty()) words["name"] = text.name;
            if (!text.description.empty()) words["description"] = text.description;
            translations[code] = words;
        }
        j["translations"] = translations;
    }
    return indent < 0 ? j.dump() : j.dump(indent) + "\n";
}

std::string saveExercise(const Exercise& exercise, const std::string& path) {
    auto problems = validateExercise(exercise);
    if (exercise.needs)
        for (const Problem& problem : validateLodNeeds(*exercise.needs)) problems.push_back(problem);
    if (!problems.empty()) {
        std::string text = path + ": not saved, the exercise is invalid:";
        for (const Problem& p : problems) text += "\n  " + p.message;
        return text;
    }
    // Never a file the reader refuses.
    const std::string text = exerciseToJson(exercise);
    if (const std::string problem = sizeLimitProblem(text.size(), kExerciseFile); !problem.empty())
        return path + ": not saved: the exercise would be " + problem + " (its description is " +
               std::to_string(exercise.description.size()) + " bytes)";
    return writeFileAtomically(path, text);
}

std::string resolveExercisePath(const Exercise& exercise, const std::string& path, const ResourceFinder& findResource) {
    namespace fs = std::filesystem;
    if (path.empty()) return {};
    std::error_code ec;
    const fs::path p(path);
    // Whatever exists there counts (a FIFO, a directory): its loader then says what is wrong with
    // it, rather than "not found".
    if (p.is_absolute()) return fs::exists(p, ec) ? path : std::string();
    if (!exercise.sourcePath.empty()) {
        const fs::path beside = fs::path(exercise.sourcePath).parent_path() / p;
        if (fs::exists(beside, ec)) return fs::weakly_canonical(beside, ec).string();
    }
    if (findResource) return findResource(path);
    return {};
}

std::string exerciseRecordingNote(const Exercise& exercise, const std::string& text, std::string& error) {
    std::string note = text;
    if (!note.empty() && note.back() != '\n') note += '\n';
    note += kNoteMarker;
    note += exerciseToJson(exercise, -1);
    if (note.size() > kMaxNoteBytes) {
        error = "the exercise '" + exercise.name + "' is too large to go into a recording's note (" +
                std::to_string(note.size()) + " bytes, at most " + std::to_string(kMaxNoteBytes) + ")";
        return {};
    }
    return note;
}

std::optional<Exercise> exerciseFromRecordingNote(const std::string& note, std::vector<std::string>& errors) {
    std::size_t at = note.rfind(kNoteMarker);
    while (at != std::string::npos && at != 0 && note[at - 1] != '\n')
        at = at == 0 ? std::string::npos : note.rfind(kNoteMarker, at - 1);
    if (at == std::string::npos) return std::nullopt;
    const std::size_t begin = at + std::string(kNoteMarker).size();
    const std::size_t end = note.find('\n', begin);
    auto parsed = parseExercise(note.substr(begin, end == std::string::npos ? std::string::npos : end - begin),
                                "recording note");
    if (!parsed.exercise) {
        errors = parsed.errors;
        return std::nullopt;
    }
    parsed.exercise->sourcePath.clear();
    return parsed.exercise;
}

}  // namespace palpate
