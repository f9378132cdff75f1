#pragma once
// An exercise that travels (docs/scoring.md, "Exercises that travel"): its mesh and tissue preset
// are named relative to resources/ or to the exercise's own folder, so that the folder opens on
// another computer. A file that is neither is copied into the folder when the exercise is saved.

#include <optional>
#include <string>

namespace palpate {

/// Copies `file` into `folder` under its own name, or under name-2.ext, name-3.ext, ... when a
/// different file holds the name; a file there with the same bytes is used as it is. Never
/// overwrites, and a partial copy never stays (written atomically). Returns the name in `folder`,
/// or nullopt and why, naming the file.
std::optional<std::string> copyIntoFolder(const std::string& file, const std::string& folder, std::string& error);

}  // namespace palpate
