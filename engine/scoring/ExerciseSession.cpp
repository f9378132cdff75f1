#include "engine/scoring/ExerciseSession.h"

#include "engine/exercise/ExerciseKind.h"

#include "engine/record/RecordingSession.h"

namespace palpate {

std::optional<ExerciseAssets> loadExerciseAssets(const Exercise& exercise, const ResourceFinder& findResource,
                                                 std::vector<std::string>& errors) {
    const std::string source = exercise.sourcePath.empty() ? "exercise '" + exercise.name + "'" : exercise.sourcePath;
    ExerciseAssets a;
    a.exercise = exercise;
    a.meshPath = resolveExercisePath(exercise, exercise.meshPath, findResource);
    a.presetPath = resolveExercisePath(exercise, exercise.tissuePresetPath, findResource);
    if (a.meshPath.empty())
        errors.push_back(source + ": mesh: " + exercise.meshPath +
                         " was found neither beside the exercise file nor under resources/");
    if (a.presetPath.empty())
        errors.push_back(source + ": tissue_preset: " + exercise.tissuePresetPath +
                         " was found neither beside the exercise file nor under resources/");
    if (!errors.empty()) return std::nullopt;
    auto loaded = TissueMesh::load(a.meshPath, exercise.meshUnit);
    if (!loaded.mesh) {
        errors.push_back(source + ": mesh: " + loaded.error());
        return std::nullopt;
    }
    a.mesh = std::move(*loaded.mesh);
    auto preset = loadTissuePreset(a.presetPath);
    if (!preset.preset) {
        for (const auto& e : preset.errors) errors.push_back(source + ": tissue_preset: " + e);
        return std::nullopt;
    }
    a.preset = *preset.preset;
    std::string error;
    a.geometry = ExerciseGeometry::build(exercise, *a.mesh, error);
    if (!a.geometry) {
        errors.push_back(source + ": " + error);
        return std::nullopt;
    }
    if (exerciseKind(exercise.type).changesTissue() &&
        (a.preset.model.kind != ModelKind::SlopeRing || a.preset.model.slopeRingMethod != SlopeRingMethod::Coherent)) {
        errors.push_back(source + ": tissue_preset: " + a.presetPath + " uses the " + presetModelName(a.preset) +
                         " model; an exercise's lumps need the coherent model");
        return std::nullopt;
    }
    return a;
}

std::unique_ptr<HapticScene> createExerciseScene(const ExerciseAssets& a, std::string& error) {
    std::unique_ptr<HapticScene> scene;
    try {
        scene = HapticScene::create(*a.mesh, a.preset);
    } catch (const std::exception& e) {
        error = a.exercise.name + ": the scene cannot be built: " + e.what();
        return nullptr;
    }
    error = applyExercisePhysics(*a.geometry, *scene);
    if (!error.empty()) return nullptr;
    return scene;
}

RecordingHeader makeExerciseRecordingHeader(const ExerciseAssets& a, const std::string& deviceUri,
                                            const DeviceSpec& deviceSpec, const SafetyFilterDef& safety,
                                            const std::string& noteText, std::string& error) {
    RecordingHeader header = makeRecordingHeader(*a.mesh, a.meshPath, a.preset, deviceUri, deviceSpec, safety);
    Exercise carried = a.exercise;
    carried.meshPath = a.meshPath;
    carried.tissuePresetPath = a.presetPath;
    header.note = exerciseRecordingNote(carried, noteText, error);
    return header;
}

}  // namespace palpate
