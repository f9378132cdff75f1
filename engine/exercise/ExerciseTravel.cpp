#include "engine/exercise/ExerciseTravel.h"

#include "base/io/AtomicFile.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

namespace palpate {

namespace {

/// The whole file, or nullopt when it cannot be read.
std::optional<std::string> readAll(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) return std::nullopt;
    return bytes;
}

/// Enough names to find a free one among copies of one file; more means something is wrong.
constexpr int kMaxNames = 1000;

}  // namespace

std::optional<std::string> copyIntoFolder(const std::string& file, const std::string& folder, std::string& error) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path source(file);
    if (!fs::is_regular_file(source, ec)) {
        error = file + ": not a file to copy beside the exercise";
        return std::nullopt;
    }
    const std::optional<std::string> bytes = readAll(source);
    if (!bytes) {
        error = file + ": cannot be read to copy beside the exercise";
        return std::nullopt;
    }
    const std::string stem = source.stem().string(), extension = source.extension().string();
    for (int n = 1; n <= kMaxNames; ++n) {
        const std::string name = n == 1 ? source.filename().string() : stem + "-" + std::to_string(n) + extension;
        const fs::path target = fs::path(folder) / name;
        if (fs::exists(target, ec)) {
            // The same file, or one with the same bytes, is used as it is.
            if (fs::equivalent(source, target, ec)) return name;
            if (fs::is_regular_file(target, ec) && readAll(target) == bytes) return name;
            continue;
        }
        if (const std::string problem = writeFileAtomically(target.string(), *bytes); !problem.empty()) {
            error = file + ": not copied beside the exercise: " + problem;
            return std::nullopt;
        }
        return name;
    }
    error = file + ": not copied beside the exercise: " + std::to_string(kMaxNames) + " names like it are taken in " +
            folder;
    return std::nullopt;
}

}  // namespace palpate
