#include "engine/exercise/ExerciseFile.h"

#include "base/io/AtomicFile.h"
#include "base/io/InputFile.h"
#include "base/io/JsonReader.h"
#include "engine/record/RecordingFormat.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace palpate {

namespace {

constexpr const char* kFormat = "palpate-exercise";
constexpr const char* kNoteMarker = "palpate-exercise: ";

/// {"vertex": N} or {"point_mm": [x, y, z]} inside `j` (other keys are the caller's).
void readSurfacePoint(JsonReader& r, const Json& j, const std::string& path, SurfacePoint& out) {
    const bool hasVertex = j.contains("vertex"), hasPoint = j.contains("point_mm");
    if (hasVertex == hasPoint) {
        r.error(path, hasVertex ? "give vertex or point_mm, not both" : "needs vertex or point_mm");
        return;
    }
    if (hasVertex) {
        const Json& v = j.at("vertex");
        if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > 0xFFFFFFFELL)
            r.error(JsonReader::join(path, "vertex"), "must be a vertex number (0 or more) of the mesh file");
        else out.vertex = std::uint32_t(v.get<long long>());
        return;
    }
    const Json& p = j.at("point_mm");
    if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() || !p[2].is_number()) {
        r.error(JsonReader::join(path, "point_mm"), "must be an array of three numbers (x, y, z in mm)");
        return;
    }
    out.pointMm = glm::vec3(float(p[0].get<double>()), float(p[1].get<double>()), float(p[2].get<double>()));
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

Json pointJson(const SurfacePoint& p) {
    Json j = Json::object();
    if (p.vertex) j["vertex"] = *p.vertex;
    else j["point_mm"] = {double(p.pointMm.x), double(p.pointMm.y), double(p.pointMm.z)};
    return j;
}

constexpr const char* kStaircaseParameters[] = {"contrast", "depth_mm"};

void readStaircase(JsonReader& r, const Json& j, const std::string& path, StaircaseDef& out) {
    if (!r.object(j, path, {"parameter", "start", "step", "easiest", "hardest", "down", "up"})) return;
    std::string parameter;
    if (r.text(j, path, "parameter", parameter, true)) {
        if (parameter == kStaircaseParameters[0]) out.parameter = StaircaseDef::Parameter::Contrast;
        else if (parameter == kStaircaseParameters[1]) out.parameter = StaircaseDef::Parameter::DepthMm;
        else r.error(JsonReader::join(path, "parameter"), "unknown parameter '" + parameter + "' (use contrast or depth_mm)");
    }
    r.number(j, path, "start", out.start, true);
    r.number(j, path, "step", out.step, true);
    r.number(j, path, "easiest", out.easiest, true);
    r.number(j, path, "hardest", out.hardest, true);
    double down = out.down, up = out.up;
    if (r.number(j, path, "down", down)) {
        if (down != std::floor(down) || down < 1 || down > 10)
            r.error(JsonReader::join(path, "down"), "must be a whole number from 1 to 10");
        else out.down = int(down);
    }
    if (r.number(j, path, "up", up)) {
        if (up != std::floor(up) || up < 1 || up > 10) r.error(JsonReader::join(path, "up"), "must be a whole number from 1 to 10");
        else out.up = int(up);
    }
}

void readDetectLumps(JsonReader& r, const Json& s, DetectLumpsDef& out) {
    const std::string path = "detect_lumps";
    if (!r.object(s, path, {"lumps", "tolerance_mm", "staircase"})) return;
    r.number(s, path, "tolerance_mm", out.toleranceMm);
    if (!s.contains("lumps")) {
        r.error("detect_lumps.lumps", "missing (an exercise without lumps says \"lumps\": [])");
    } else if (!s.at("lumps").is_array()) {
        r.error("detect_lumps.lumps", "must be an array of lumps");
    } else {
        const Json& a = s.at("lumps");
        for (std::size_t i = 0; i < a.size() && i <= std::size_t(kMaxLumps); ++i) {
            const std::string key = "detect_lumps.lumps[" + std::to_string(i) + "]";
            LumpDef lump;
            if (r.object(a[i], key, {"vertex", "point_mm", "radius_mm", "depth_mm", "contrast"})) {
                readSurfacePoint(r, a[i], key, lump.at);
                r.number(a[i], key, "radius_mm", lump.radiusMm, true);
                r.number(a[i], key, "depth_mm", lump.depthMm, true);
                r.number(a[i], key, "contrast", lump.contrast, true);
            }
            out.lumps.push_back(lump);
        }
    }
    if (s.contains("staircase")) {
        StaircaseDef staircase;
        readStaircase(r, s.at("staircase"), "detect_lumps.staircase", staircase);
        out.staircase = staircase;
    }
}

}  // namespace

namespace {

ExerciseLoadResult parseExerciseText(const std::string& textIn, const std::string& source) {
    ExerciseLoadResult result;
    JsonReader r(result.errors, source);
    const std::optional<Json> parsed = r.parse(textIn);
    if (!parsed) return result;
    const Json& j = *parsed;
    if (!r.object(j, "",
                  {"format", "version", "name", "description", "type", "mesh", "mesh_unit", "tissue_preset", "time_limit_s",
                   "rubric", "press_targets", "find_lump", "trace", "detect_lumps", "coverage", "damage", "force", "needs"}))
        return result;

    std::string format;
    r.text(j, "", "format", format, true);
    if (!format.empty() && format != kFormat) r.error("format", "is '" + format + "', expected '" + kFormat + "'");
    double version = 0.0;
    if (r.number(j, "", "version", version, true) &&
        (std::floor(version) != version || version < 1 || version > kExerciseVersion))
        r.error("version", "version " + Json(version).dump() + " is not supported (this build reads 1 to " +
                               std::to_string(kExerciseVersion) + ")");

    Exercise e;
    e.sourcePath = source;
    r.text(j, "", "name", e.name, true);
    r.text(j, "", "description", e.description);
    std::string type;
    r.text(j, "", "type", type, true);
    bool typeKnown = false;
    if (j.contains("type") && j.at("type").is_string()) {
        if (const auto t = parseExerciseType(type)) {
            e.type = *t;
            typeKnown = true;
        } else {
            r.error("type", "unknown type '" + type + "' (use press_targets, find_lump, trace or detect_lumps)");
        }
    }
    r.text(j, "", "mesh", e.meshPath, true);
    if (j.contains("mesh_unit")) readMeshUnit(r, j.at("mesh_unit"), e.meshUnit);
    r.text(j, "", "tissue_preset", e.tissuePresetPath, true);
    r.number(j, "", "time_limit_s", e.timeLimitS, true);

    if (j.contains("damage") && r.object(j.at("damage"), "damage", {"displacement_limit_mm"}))
        r.number(j.at("damage"), "damage", "displacement_limit_mm", e.displacementLimitMm);
    if (j.contains("force") && r.object(j.at("force"), "force", {"excessive_n"}))
        r.number(j.at("force"), "force", "excessive_n", e.excessiveForceN);

    // The section of the type, and no other.
    for (const ExerciseType t :
         {ExerciseType::PressTargets, ExerciseType::FindLump, ExerciseType::Trace, ExerciseType::DetectLumps}) {
        const std::string key(exerciseTypeName(t));
        if (typeKnown && t == e.type && !j.contains(key)) r.error(key, "missing (type is " + type + ")");
        if (typeKnown && t != e.type && j.contains(key)) r.error(key, "given, but type is " + type);
    }
    if (j.contains("press_targets") && (!typeKnown || e.type == ExerciseType::PressTargets)) {
        const Json& s = j.at("press_targets");
        const std::string path = "press_targets";
        if (r.object(s, path, {"targets", "force_min_n", "force_max_n", "hold_s", "tolerance_mm"})) {
            PressTarget defaults;
            r.number(s, path, "force_min_n", defaults.forceMinN);
            r.number(s, path, "force_max_n", defaults.forceMaxN);
            r.number(s, path, "hold_s", defaults.holdS);
            r.number(s, path, "tolerance_mm", defaults.toleranceMm);
            if (!s.contains("targets")) {
                r.error("press_targets.targets", "missing");
            } else if (!s.at("targets").is_array()) {
                r.error("press_targets.targets", "must be an array of targets");
            } else {
                const Json& a = s.at("targets");
                for (std::size_t i = 0; i < a.size() && i <= std::size_t(kMaxPressTargets); ++i) {
                    const std::string key = "press_targets.targets[" + std::to_string(i) + "]";
                    PressTarget t = defaults;
                    if (r.object(a[i], key,
                                 {"vertex", "point_mm", "force_min_n", "force_max_n", "hold_s", "tolerance_mm"})) {
                        readSurfacePoint(r, a[i], key, t.at);
                        r.number(a[i], key, "force_min_n", t.forceMinN);
                        r.number(a[i], key, "force_max_n", t.forceMaxN);
                        r.number(a[i], key, "hold_s", t.holdS);
                        r.number(a[i], key, "tolerance_mm", t.toleranceMm);
                    }
                    e.pressTargets.targets.push_back(t);
                }
            }
        }
    }
    if (j.contains("find_lump") && (!typeKnown || e.type == ExerciseType::FindLump)) {
        const Json& s = j.at("find_lump");
        if (r.object(s, "find_lump", {"inclusion"})) {
            if (!s.contains("inclusion")) {
                r.error("find_lump.inclusion", "missing");
            } else {
                const Json& inc = s.at("inclusion");
                const std::string path = "find_lump.inclusion";
                if (r.object(inc, path, {"centre", "radius_mm", "stiffness_factor"})) {
                    InclusionDef& d = e.findLump.inclusion;
                    if (!inc.contains("centre")) r.error(path + ".centre", "missing");
                    else if (r.object(inc.at("centre"), path + ".centre", {"vertex", "point_mm"}))
                        readSurfacePoint(r, inc.at("centre"), path + ".centre", d.centre);
                    r.number(inc, path, "radius_mm", d.radiusMm, true);
                    r.number(inc, path, "stiffness_factor", d.stiffnessFactor, true);
                }
            }
        }
    }
    if (j.contains("trace") && (!typeKnown || e.type == ExerciseType::Trace)) {
        const Json& s = j.at("trace");
        if (r.object(s, "trace", {"path", "force_min_n", "force_max_n", "tolerance_mm"})) {
            TraceDef& t = e.trace;
            r.number(s, "trace", "force_min_n", t.forceMinN, true);
            r.number(s, "trace", "force_max_n", t.forceMaxN, true);
            r.number(s, "trace", "tolerance_mm", t.toleranceMm);
            if (!s.contains("path")) {
                r.error("trace.path", "missing");
            } else if (!s.at("path").is_array()) {
                r.error("trace.path", "must be an array of points");
            } else {
                const Json& a = s.at("path");
                for (std::size_t i = 0; i < a.size() && i <= std::size_t(kMaxTracePathPoints); ++i) {
                    const std::string key = "trace.path[" + std::to_string(i) + "]";
                    SurfacePoint p;
                    if (r.object(a[i], key, {"vertex", "point_mm"})) readSurfacePoint(r, a[i], key, p);
                    t.path.push_back(p);
                }
            }
        }
    }
    if (j.contains("detect_lumps") && (!typeKnown || e.type == ExerciseType::DetectLumps))
        readDetectLumps(r, j.at("detect_lumps"), e.detectLumps);
    if (j.contains("coverage") && r.object(j.at("coverage"), "coverage", {"min_force_n", "radius_mm"})) {
        if (typeKnown && e.type != ExerciseType::FindLump && e.type != ExerciseType::DetectLumps)
            r.error("coverage", "given, but type is " + type + " (coverage is scored for find_lump and detect_lumps)");
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
    for (const std::string& problem : validateExercise(e)) result.errors.push_back(source + ": " + problem);
    if (e.needs)
        for (const std::string& problem : validateLodNeeds(*e.needs)) result.errors.push_back(source + ": " + problem);
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
    j["damage"] = {{"displacement_limit_mm", e.displacementLimitMm}};
    j["force"] = {{"excessive_n", e.excessiveForceN}};
    switch (e.type) {
        case ExerciseType::PressTargets: {
            Json targets = Json::array();
            for (const PressTarget& t : e.pressTargets.targets) {
                Json o = pointJson(t.at);
                o["force_min_n"] = t.forceMinN;
                o["force_max_n"] = t.forceMaxN;
                o["hold_s"] = t.holdS;
                o["tolerance_mm"] = t.toleranceMm;
                targets.push_back(o);
            }
            j["press_targets"] = {{"targets", targets}};
            break;
        }
        case ExerciseType::FindLump: {
            const InclusionDef& d = e.findLump.inclusion;
            j["find_lump"] = {{"inclusion",
                               {{"centre", pointJson(d.centre)},
                                {"radius_mm", d.radiusMm},
                                {"stiffness_factor", d.stiffnessFactor}}}};
            break;
        }
        case ExerciseType::Trace: {
            Json path = Json::array();
            for (const SurfacePoint& p : e.trace.path) path.push_back(pointJson(p));
            j["trace"] = {{"path", path},
                          {"force_min_n", e.trace.forceMinN},
                          {"force_max_n", e.trace.forceMaxN},
                          {"tolerance_mm", e.trace.toleranceMm}};
            break;
        }
        case ExerciseType::DetectLumps: {
            Json lumps = Json::array();
            for (const LumpDef& l : e.detectLumps.lumps) {
                Json o = pointJson(l.at);
                o["radius_mm"] = l.radiusMm;
                o["depth_mm"] = l.depthMm;
                o["contrast"] = l.contrast;
                lumps.push_back(o);
            }
            Json d = {{"lumps", lumps}, {"tolerance_mm", e.detectLumps.toleranceMm}};
            if (const auto& st = e.detectLumps.staircase)
                d["staircase"] = {{"parameter", kStaircaseParameters[int(st->parameter)]},
                                  {"start", st->start},
                                  {"step", st->step},
                                  {"easiest", st->easiest},
                                  {"hardest", st->hardest},
                                  {"down", st->down},
                                  {"up", st->up}};
            j["detect_lumps"] = d;
            break;
        }
    }
    // Only for the palpation types, and only when not the defaults: older files write back unchanged.
    if ((e.type == ExerciseType::FindLump || e.type == ExerciseType::DetectLumps) &&
        (e.coverage.minForceN != CoverageDef{}.minForceN || e.coverage.radiusMm != CoverageDef{}.radiusMm))
        j["coverage"] = {{"min_force_n", e.coverage.minForceN}, {"radius_mm", e.coverage.radiusMm}};
    Json rubric = Json::object();
    for (std::size_t i = 0; i < kMetricCount; ++i)
        if (e.rubric[i])
            rubric[std::string(metricName(Metric(i)))] = {
                {"weight", e.rubric[i]->weight}, {"full", e.rubric[i]->fullMarks}, {"zero", e.rubric[i]->zeroMarks}};
    if (!rubric.empty()) j["rubric"] = rubric;
    if (e.needs) j["needs"] = {{"max_error", e.needs->maxErrorFraction}, {"budget_us", e.needs->budgetUs}};
    return indent < 0 ? j.dump() : j.dump(indent) + "\n";
}

std::string saveExercise(const Exercise& exercise, const std::string& path) {
    auto problems = validateExercise(exercise);
    if (exercise.needs)
        for (const std::string& problem : validateLodNeeds(*exercise.needs)) problems.push_back(problem);
    if (!problems.empty()) {
        std::string text = path + ": not saved, the exercise is invalid:";
        for (const auto& p : problems) text += "\n  " + p;
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
