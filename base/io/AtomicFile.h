#pragma once
// Writing a file so that a crash or a full disk never leaves half of it: write a temporary with a
// unique name next to it, fsync it, then rename it over the target (rename is atomic on POSIX file
// systems). On any failure the temporary is removed and the message names the path and the reason
// ("x.json: writing failed: No space left on device"). Presets, exercises, meshes and the level
// cache are written this way.

#include <functional>
#include <string>

namespace palpate {

/// Writes `text` to `path` atomically. Returns "" or the problem, naming the path.
std::string writeFileAtomically(const std::string& path, const std::string& text);

/// For writers that need a path (a mesh library): `write` writes the whole file to the temporary
/// path it is given (next to `path`, unique, with path's extension) and returns "" or its problem;
/// the temporary is then fsync'ed and renamed over `path`. Returns "" or the problem, naming `path`;
/// the temporary never survives a failure.
std::string writeFileAtomicallyVia(const std::string& path,
                                   const std::function<std::string(const std::string& temporaryPath)>& write);

}  // namespace palpate
