#pragma once
// Writing a file so that a crash never leaves half of it: write a temporary next to it, then rename
// over it (rename is atomic on POSIX file systems). Presets and exercises are saved this way.

#include <string>

namespace palpate {

/// Writes `text` to `path` atomically. Returns "" or the problem, naming the path.
std::string writeFileAtomically(const std::string& path, const std::string& text);

}  // namespace palpate
