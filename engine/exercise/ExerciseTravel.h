#pragma once
// An exercise that travels (docs/scoring.md, "Exercises that travel"): its mesh and tissue preset
// are named relative to resources/ or to the exercise's own folder, so that the folder opens on
// another computer. A file that is neither is copied into the folder when the exercise is saved;
// a bundle's files are placed the same way when it is imported.

#include <optional>
#include <string>

namespace palpate {

/// Where placeInFolder put the bytes.
struct PlacedFile {
    std::string name;      ///< the file's name in the folder
    bool written = false;  ///< false: a file with the same bytes was there already
};

/// Writes `bytes` into `folder` under `name`, or under name-2.ext, name-3.ext, ... when a
/// different file holds the name; a file there with the same bytes is used as it is. Never
/// overwrites, and a partial file never stays (written atomically). nullopt and why otherwise,
/// naming the file.
std::optional<PlacedFile> placeInFolder(const std::string& bytes, const std::string& name, const std::string& folder,
                                        std::string& error);

/// Copies `file` into `folder` as placeInFolder does (a file that is already there is its own
/// copy). Returns the name in `folder`, or nullopt and why, naming the file.
std::optional<std::string> copyIntoFolder(const std::string& file, const std::string& folder, std::string& error);

}  // namespace palpate
