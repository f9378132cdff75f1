#include "engine/exercise/RecordedExercise.h"

#include "engine/exercise/ExerciseKind.h"

#include "engine/scene/HapticScene.h"
#include "engine/core/MeshHash.h"
#include "engine/exercise/ExerciseFile.h"
#include "engine/exercise/ExerciseGeometry.h"

#include <memory>

namespace palpate {

std::optional<Exercise> recordedExercise(const RecordingHeader& header, std::vector<std::string>& errors) {
    return exerciseFromRecordingNote(header.note, errors);
}

std::function<std::string(HapticScene&)> recordedExercisePhysics(const RecordingHeader& header) {
    std::vector<std::string> errors;
    const std::optional<Exercise> exercise = recordedExercise(header, errors);
    if (!exercise || !exerciseKind(exercise->type).changesTissue()) return {};
    // The geometry is built once, on the first scene of the recorded mesh, and shared by the
    // copies of the function (the player rebuilds scenes when it seeks back).
    auto geometry = std::make_shared<std::shared_ptr<const ExerciseGeometry>>();
    const std::uint64_t recordedHash = header.scene.meshHash;
    return [exercise = *exercise, geometry, recordedHash](HapticScene& scene) -> std::string {
        if (meshHash(scene.mesh()) != recordedHash) return {};  // another mesh switched in: not the exercise's
        if (!*geometry) {
            std::string problem;
            *geometry = ExerciseGeometry::build(exercise, scene.mesh(), problem);
            if (!*geometry) return "the recorded exercise: " + problem;
        }
        return applyExercisePhysics(**geometry, scene);
    };
}

}  // namespace palpate
