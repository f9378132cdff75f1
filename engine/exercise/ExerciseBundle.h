#pragma once
// An exercise bundle (docs/scoring.md, "Exercise bundles"): one file holding an exercise, its
// mesh, its tissue preset and the scripted paths beside it (`NAME.*.path`), to hand to a trainee's
// computer as it is. Versioned JSON ("format": "palpate-exercise-bundle"), each file as base64
// under a plain name. Importing writes the files into a folder, never over a file there.

#include "engine/exercise/ExerciseFile.h"

#include <optional>
#include <string>
#include <vector>

namespace palpate {

/// Bundles the exercise file `exercisePath` into `bundlePath` (written atomically; never one of
/// its inputs). Its mesh and preset are found as the exercise names them (`findResource` for
/// resources/). Returns "" or the problem, naming the file.
std::string writeExerciseBundle(const std::string& exercisePath, const std::string& bundlePath,
                                const ResourceFinder& findResource);

/// What an import wrote.
struct ImportedBundle {
    std::string exercisePath;        ///< the exercise file written into the folder
    std::vector<std::string> files;  ///< every file written or found there already, by name
};

/// Writes the bundle's files into `folder` (which must exist): each under its name, or name-2,
/// name-3, ... when a different file holds the name (one with the same bytes is used as it is),
/// and the exercise naming them as they were written. nullopt with `error` naming the bundle and
/// the key when the bundle is not one (format, version, a name that is not a plain file name, bad
/// base64, an exercise that does not parse); nothing is written then.
std::optional<ImportedBundle> importExerciseBundle(const std::string& bundlePath, const std::string& folder,
                                                   std::string& error);

/// A bundle read and checked, nothing written yet.
struct ParsedBundle {
    struct File {
        enum class Role { Mesh, Preset, Path } role;
        std::string name;
        std::string bytes;
    };
    Exercise exercise;         ///< its mesh and preset name files of the bundle
    std::string exerciseFile;  ///< the name the exercise file had ("detect_lumps.json")
    std::vector<File> files;
};

/// Reads a bundle's text (the fuzz target's entry): nullopt with `error` naming `sourceName` and
/// the key when it is not one.
std::optional<ParsedBundle> parseExerciseBundle(const std::string& text, const std::string& sourceName,
                                                std::string& error);

}  // namespace palpate
