#pragma once
// Setting up a session of an exercise (the GUI's trainee mode, `palpate-cli run --exercise`):
// its mesh and tissue preset loaded, a scene with its physics (find the lump's inclusion), and a
// recording header whose note carries the exercise, so that the recording replays and scores on
// its own.
//
//   std::vector<std::string> errors;
//   auto assets = loadExerciseAssets(exercise, findResource, errors);
//   auto scene = createExerciseScene(*assets, error);            // to the HapticLoop
//   RecordingHeader header = makeExerciseRecordingHeader(*assets, uri, spec, safety, "", error);
//   auto session = RecordingSession::start(loop, path, header, error);
//   LiveScorer live(path, exercise);

#include "engine/scene/HapticScene.h"
#include "engine/scene/TissuePreset.h"
#include "engine/record/RecordingFormat.h"
#include "engine/exercise/ExerciseFile.h"
#include "engine/exercise/ExerciseGeometry.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

struct ExerciseAssets {
    Exercise exercise;
    std::string meshPath;    ///< resolved (absolute)
    std::string presetPath;  ///< resolved (absolute)
    std::optional<TissueMesh> mesh;
    TissuePreset preset;
    std::shared_ptr<const ExerciseGeometry> geometry;  ///< the exercise on this mesh
};

/// Resolves and loads the exercise's mesh and tissue preset and places the exercise on the mesh.
/// nullopt with `errors` (naming the exercise file and the key) on failure.
std::optional<ExerciseAssets> loadExerciseAssets(const Exercise& exercise, const ResourceFinder& findResource,
                                                 std::vector<std::string>& errors);

/// A scene on the exercise's mesh with its preset's model (any registry model for press targets
/// and trace), parameters and octree, and the exercise's physics applied. Null with `error`.
std::unique_ptr<HapticScene> createExerciseScene(const ExerciseAssets& assets, std::string& error);

/// makeRecordingHeader for the exercise's scene, with a note that carries the exercise (its paths
/// resolved) after `noteText`. `error` set (and the note empty) if the exercise does not fit.
RecordingHeader makeExerciseRecordingHeader(const ExerciseAssets& assets, const std::string& deviceUri,
                                            const DeviceSpec& deviceSpec, const SafetyFilterDef& safety,
                                            const std::string& noteText, std::string& error);

}  // namespace palpate
