#pragma once
// Exercise files: versioned JSON ("format": "palpate-exercise", "version": 1). Unknown keys, wrong
// types, missing keys and out-of-range values are errors that name the file and the key, so that
// a typo never silently falls back to a default. Saving is atomic (the GUI authors exercises).
// docs/scoring.md documents every key.

#include "engine/exercise/Exercise.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

struct ExerciseLoadResult {
    std::optional<Exercise> exercise;
    std::vector<std::string> errors;  ///< each names the source and the key
    std::string error() const { return errors.empty() ? std::string() : errors.front(); }
};

/// Parses exercise JSON text; `sourceName` (a path) prefixes every message and becomes the
/// exercise's sourcePath (relative mesh and preset paths resolve from its folder).
ExerciseLoadResult parseExercise(const std::string& text, const std::string& sourceName);
/// Reads and parses a file; a missing file, a directory or unreadable bytes are errors too.
ExerciseLoadResult loadExercise(const std::string& path);
/// The exercise as JSON text (what saveExercise writes); `indent` < 0 gives one line.
std::string exerciseToJson(const Exercise& exercise, int indent = 2);
/// Validates, then writes atomically (temporary file, then rename). Returns "" or the problems.
std::string saveExercise(const Exercise& exercise, const std::string& path);

/// Finds a resource by a path relative to resources/ ("meshes/sphere_1442.off"); "" when absent.
/// The CLI and the GUI pass theirs (app/cli/DefaultScene's findResource).
using ResourceFinder = std::function<std::string(const std::string& relativePath)>;
/// Where a path named by the exercise (mesh, tissue preset) is: itself if absolute; else beside
/// the exercise file; else what `findResource` finds under resources/. "" when none exists.
std::string resolveExercisePath(const Exercise& exercise, const std::string& path,
                                const ResourceFinder& findResource = {});

/// A recording's header note for a session of this exercise: `text` (free, for people), then a
/// line "palpate-exercise: " and the exercise as one-line JSON. A replay reads the exercise back
/// from it (the inclusion of find-the-lump changes the physics). "" with `error` when the
/// exercise does not fit a note (64 KiB).
std::string exerciseRecordingNote(const Exercise& exercise, const std::string& text, std::string& error);
/// The exercise a recording's note carries, or nullopt when it carries none (errors says why when
/// one is there but does not parse).
std::optional<Exercise> exerciseFromRecordingNote(const std::string& note, std::vector<std::string>& errors);

}  // namespace palpate
