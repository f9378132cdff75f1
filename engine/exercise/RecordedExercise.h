#pragma once
// The exercise a recording carries (in its header's note, ExerciseFile's exerciseRecordingNote)
// and the physics it gave the session's scenes. RecordingPlayer applies that physics by default,
// so any replay of an exercise session (record replay, the GUI's player, scoring) reproduces it
// bit for bit.

#include "engine/record/RecordingFormat.h"
#include "engine/exercise/Exercise.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

class HapticScene;

/// The exercise in the header's note, or nullopt (with `errors` when one is there but does not read).
std::optional<Exercise> recordedExercise(const RecordingHeader& header, std::vector<std::string>& errors);

/// For ReplayDef::prepareScene: applies the recorded exercise's physics (find the lump's
/// inclusion) to scenes on the recorded mesh. Empty when the note carries no exercise or the
/// exercise changes no physics.
std::function<std::string(HapticScene&)> recordedExercisePhysics(const RecordingHeader& header);

}  // namespace palpate
