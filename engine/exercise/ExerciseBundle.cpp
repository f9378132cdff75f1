#include "engine/exercise/ExerciseBundle.h"

#include "base/io/AtomicFile.h"
#include "base/io/Base64.h"
#include "base/io/FileLimits.h"
#include "base/io/InputFile.h"
#include "base/io/JsonReader.h"
#include "engine/exercise/ExerciseTravel.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <system_error>

namespace palpate {

namespace {

constexpr const char* kFormat = "palpate-exercise-bundle";
constexpr int kVersion = 1;
/// An exercise, its mesh and preset, and its scripted paths: a handful; more is not a bundle.
constexpr std::size_t kMaxFiles = 64;

const char* roleKey(ParsedBundle::File::Role role) {
    switch (role) {
        case ParsedBundle::File::Role::Mesh: return "mesh";
        case ParsedBundle::File::Role::Preset: return "preset";
        case ParsedBundle::File::Role::Path: return "path";
    }
    return "";
}

const InputKind& roleKind(ParsedBundle::File::Role role) {
    switch (role) {
        case ParsedBundle::File::Role::Mesh: return kMeshFile;
        case ParsedBundle::File::Role::Preset: return kPresetFile;
        case ParsedBundle::File::Role::Path: return kWaypointFile;
    }
    return kMeshFile;
}

/// A name that stays in the folder it is written to: no separator, not "." or "..", no control
/// character, not empty, at most 255 bytes.
bool plainFileName(const std::string& name) {
    if (name.empty() || name.size() > 255 || name == "." || name == "..") return false;
    return std::none_of(name.begin(), name.end(), [](char c) {
        return c == '/' || c == '\\' || static_cast<unsigned char>(c) < 0x20 || c == 0x7F;
    });
}

/// The scripted paths beside an exercise: `STEM.*.path` in its folder, by name.
std::vector<std::filesystem::path> scriptedPaths(const std::filesystem::path& exercise) {
    namespace fs = std::filesystem;
    std::vector<fs::path> out;
    std::error_code ec;
    const std::string prefix = exercise.stem().string() + ".";
    for (fs::directory_iterator it(exercise.parent_path().empty() ? fs::path(".") : exercise.parent_path(), ec), end;
         !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() > prefix.size() + 5 && name.compare(0, prefix.size(), prefix) == 0 &&
            it->path().extension() == ".path" && it->is_regular_file(ec))
            out.push_back(it->path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

std::string writeExerciseBundle(const std::string& exercisePath, const std::string& bundlePath,
                                const ResourceFinder& findResource) {
    namespace fs = std::filesystem;
    const ExerciseLoadResult loaded = loadExercise(exercisePath);
    if (!loaded.exercise) return loaded.error();
    Exercise exercise = *loaded.exercise;
    struct Input {
        ParsedBundle::File::Role role;
        std::string path;
    };
    std::vector<Input> inputs;
    const std::string mesh = resolveExercisePath(exercise, exercise.meshPath, findResource);
    if (mesh.empty()) return exercisePath + ": mesh: '" + exercise.meshPath + "' is not found";
    inputs.push_back({ParsedBundle::File::Role::Mesh, mesh});
    if (!exercise.tissuePresetPath.empty()) {
        const std::string preset = resolveExercisePath(exercise, exercise.tissuePresetPath, findResource);
        if (preset.empty()) return exercisePath + ": tissue_preset: '" + exercise.tissuePresetPath + "' is not found";
        inputs.push_back({ParsedBundle::File::Role::Preset, preset});
    }
    for (const fs::path& p : scriptedPaths(fs::path(exercisePath)))
        inputs.push_back({ParsedBundle::File::Role::Path, p.string()});

    // The bundle is never written over one of its inputs.
    std::error_code ec;
    const fs::path out(bundlePath);
    if (fs::exists(out, ec)) {
        if (fs::equivalent(out, fs::path(exercisePath), ec))
            return bundlePath + ": is the exercise itself; choose another file for the bundle";
        for (const Input& in : inputs)
            if (fs::equivalent(out, fs::path(in.path), ec))
                return bundlePath + ": is the exercise's " + roleKey(in.role) + "; choose another file for the bundle";
    }

    Json files = Json::array();
    std::vector<std::string> names;
    for (const Input& in : inputs) {
        std::string error;
        const std::optional<std::string> bytes = readInputFile(in.path, roleKind(in.role), error);
        if (!bytes) return error;
        std::string name = fs::path(in.path).filename().string();
        // Two inputs of one name (a mesh and a preset both "organ.json"): the later is renamed.
        while (std::find(names.begin(), names.end(), name) != names.end())
            name = std::string(roleKey(in.role)) + "-" + name;
        names.push_back(name);
        if (in.role == ParsedBundle::File::Role::Mesh) exercise.meshPath = name;
        if (in.role == ParsedBundle::File::Role::Preset) exercise.tissuePresetPath = name;
        files.push_back(Json{{"name", name}, {"role", roleKey(in.role)}, {"base64", encodeBase64(*bytes)}});
    }
    Json bundle{{"format", kFormat},
                {"version", kVersion},
                {"exercise_file", fs::path(exercisePath).filename().string()},
                {"exercise", Json::parse(exerciseToJson(exercise))},
                {"files", std::move(files)}};
    const std::string text = bundle.dump(1) + "\n";
    if (const std::string problem = sizeLimitProblem(text.size(), kExerciseBundleFile); !problem.empty())
        return bundlePath + ": " + problem;
    return writeFileAtomically(bundlePath, text);
}

std::optional<ParsedBundle> parseExerciseBundle(const std::string& text, const std::string& sourceName,
                                                std::string& error) {
    std::vector<std::string> errors;
    const auto fail = [&]() -> std::optional<ParsedBundle> {
        error = errors.empty() ? sourceName + ": not an exercise bundle" : errors.front();
        return std::nullopt;
    };
    if (const std::string problem = sizeLimitProblem(text.size(), kExerciseBundleFile); !problem.empty()) {
        error = sourceName + ": " + problem;
        return std::nullopt;
    }
    JsonReader r(errors, sourceName);
    const std::optional<Json> parsed = r.parse(text);
    if (!parsed) return fail();
    const Json& j = *parsed;
    if (!r.object(j, "", {"format", "version", "exercise_file", "exercise", "files"})) return fail();
    r.formatAndVersion(j, kFormat, kVersion);
    ParsedBundle out;
    if (r.text(j, "", "exercise_file", out.exerciseFile, true) && !plainFileName(out.exerciseFile))
        r.error("exercise_file", "'" + out.exerciseFile + "' is not a plain file name");
    if (r.errorCount() > 0) return fail();
    if (!j.contains("files") || !j["files"].is_array()) {
        r.error("files", j.contains("files") ? "must be a list" : "is missing");
        return fail();
    }
    const Json& files = j["files"];
    if (files.size() > kMaxFiles) {
        r.error("files", "holds " + std::to_string(files.size()) + " files, at most " + std::to_string(kMaxFiles));
        return fail();
    }
    for (std::size_t i = 0; i < files.size(); ++i) {
        const std::string path = "files[" + std::to_string(i) + "]";
        if (!r.object(files[i], path, {"name", "role", "base64"})) continue;
        ParsedBundle::File file{ParsedBundle::File::Role::Path, {}, {}};
        std::string role, base64;
        const bool named = r.text(files[i], path, "name", file.name, true);
        if (named && !plainFileName(file.name)) r.error(path + ".name", "'" + file.name + "' is not a plain file name");
        if (named && std::any_of(out.files.begin(), out.files.end(),
                                 [&](const ParsedBundle::File& f) { return f.name == file.name; }))
            r.error(path + ".name", "'" + file.name + "' appears twice");
        if (r.text(files[i], path, "role", role, true)) {
            if (role == "mesh") file.role = ParsedBundle::File::Role::Mesh;
            else if (role == "preset") file.role = ParsedBundle::File::Role::Preset;
            else if (role == "path") file.role = ParsedBundle::File::Role::Path;
            else r.error(path + ".role", "is '" + role + "', expected mesh, preset or path");
        }
        if (r.text(files[i], path, "base64", base64, true)) {
            std::optional<std::string> bytes = decodeBase64(base64);
            if (!bytes) r.error(path + ".base64", "is not base64");
            else if (const std::string problem = sizeLimitProblem(bytes->size(), roleKind(file.role)); !problem.empty())
                r.error(path + ".base64", problem);
            else file.bytes = std::move(*bytes);
        }
        out.files.push_back(std::move(file));
    }
    if (r.errorCount() > 0) return fail();
    const auto count = [&](ParsedBundle::File::Role role) {
        return std::count_if(out.files.begin(), out.files.end(),
                             [role](const ParsedBundle::File& f) { return f.role == role; });
    };
    if (count(ParsedBundle::File::Role::Mesh) != 1) r.error("files", "must hold one mesh");
    if (count(ParsedBundle::File::Role::Preset) > 1) r.error("files", "holds more than one preset");
    if (!j.contains("exercise") || !j["exercise"].is_object())
        r.error("exercise", j.contains("exercise") ? "must be an object" : "is missing");
    if (r.errorCount() > 0) return fail();
    // The exercise is read as an exercise file is, its messages naming the bundle's key.
    ExerciseLoadResult exercise = parseExercise(j["exercise"].dump(), sourceName + ": exercise");
    if (!exercise.exercise) {
        error = exercise.error();
        return std::nullopt;
    }
    out.exercise = std::move(*exercise.exercise);
    const auto holds = [&](const std::string& name, ParsedBundle::File::Role role) {
        return std::any_of(out.files.begin(), out.files.end(),
                           [&](const ParsedBundle::File& f) { return f.role == role && f.name == name; });
    };
    if (!holds(out.exercise.meshPath, ParsedBundle::File::Role::Mesh))
        r.error("exercise.mesh", "'" + out.exercise.meshPath + "' is not the bundle's mesh");
    const bool hasPreset = count(ParsedBundle::File::Role::Preset) == 1;
    if (hasPreset != !out.exercise.tissuePresetPath.empty() ||
        (hasPreset && !holds(out.exercise.tissuePresetPath, ParsedBundle::File::Role::Preset)))
        r.error("exercise.tissue_preset", "'" + out.exercise.tissuePresetPath + "' is not the bundle's preset");
    if (r.errorCount() > 0) return fail();
    return out;
}

std::optional<ImportedBundle> importExerciseBundle(const std::string& bundlePath, const std::string& folder,
                                                   std::string& error) {
    namespace fs = std::filesystem;
    const std::optional<std::string> text = readInputFile(bundlePath, kExerciseBundleFile, error);
    if (!text) return std::nullopt;
    std::optional<ParsedBundle> bundle = parseExerciseBundle(*text, bundlePath, error);
    if (!bundle) return std::nullopt;
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) {
        error = folder + ": not a folder to import the exercise into";
        return std::nullopt;
    }
    ImportedBundle out;
    std::vector<fs::path> written;  // removed again when a later file fails
    const auto place = [&](const std::string& bytes, const std::string& name) -> std::optional<std::string> {
        const auto placed = placeInFolder(bytes, name, folder, error);
        if (!placed) return std::nullopt;
        if (placed->written) written.push_back(fs::path(folder) / placed->name);
        out.files.push_back(placed->name);
        return placed->name;
    };
    const auto undo = [&]() -> std::optional<ImportedBundle> {
        for (const fs::path& p : written) fs::remove(p, ec);
        return std::nullopt;
    };
    Exercise& exercise = bundle->exercise;
    for (const ParsedBundle::File& f : bundle->files) {
        if (f.role == ParsedBundle::File::Role::Path) continue;
        const auto name = place(f.bytes, f.name);
        if (!name) return undo();
        (f.role == ParsedBundle::File::Role::Mesh ? exercise.meshPath : exercise.tissuePresetPath) = *name;
    }
    const auto exerciseName = place(exerciseToJson(exercise), bundle->exerciseFile);
    if (!exerciseName) return undo();
    out.exercisePath = (fs::path(folder) / *exerciseName).string();
    // The scripted paths follow the exercise's name (STEM.good.path beside STEM.json).
    const std::string oldPrefix = fs::path(bundle->exerciseFile).stem().string() + ".";
    const std::string newPrefix = fs::path(*exerciseName).stem().string() + ".";
    for (const ParsedBundle::File& f : bundle->files) {
        if (f.role != ParsedBundle::File::Role::Path) continue;
        const std::string name = f.name.compare(0, oldPrefix.size(), oldPrefix) == 0
                                     ? newPrefix + f.name.substr(oldPrefix.size())
                                     : f.name;
        if (!place(f.bytes, name)) return undo();
    }
    return out;
}

}  // namespace palpate
