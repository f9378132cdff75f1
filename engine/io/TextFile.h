#pragma once
// Reading a whole text file (a preset, an exercise) with the problems people meet named: a missing
// path, a directory given by mistake, a file that cannot be opened. The counterpart of AtomicFile.

#include <optional>
#include <string>

namespace palpate {

/// The file's bytes, or nullopt with `error` naming the path and the problem. `kind` says what the
/// file should have been ("an exercise file", "a preset file") in the directory message.
std::optional<std::string> readTextFile(const std::string& path, const std::string& kind, std::string& error);

}  // namespace palpate
