#include "engine/exercise/ExerciseTravel.h"

#include "base/io/AtomicFile.h"
#include "base/io/FileLimits.h"
#include "base/io/InputFile.h"

#include <filesystem>
#include <system_error>

namespace palpate {

namespace {

/// What copyIntoFolder copies: a mesh or a preset, the larger limit of the two.
constexpr InputKind kCopiedFile{"a file to copy beside the exercise", kMeshFile.maxBytes};

/// Whether `target` holds exactly `bytes` (read through the bounded reader, never past their size).
bool holdsBytes(const std::filesystem::path& target, const std::string& bytes) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(target, ec) || std::filesystem::file_size(target, ec) != bytes.size() || ec)
        return false;
    std::string ignored;
    const auto there = readInputFile(target.string(), InputKind{"a file beside the exercise", bytes.size()}, ignored);
    return there && *there == bytes;
}

/// Enough names to find a free one among copies of one file; more means something is wrong.
constexpr int kMaxNames = 1000;

}  // namespace

std::optional<PlacedFile> placeInFolder(const std::string& bytes, const std::string& name, const std::string& folder,
                                        std::string& error) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path wanted(name);
    const std::string stem = wanted.stem().string(), extension = wanted.extension().string();
    for (int n = 1; n <= kMaxNames; ++n) {
        const std::string candidate = n == 1 ? name : stem + "-" + std::to_string(n) + extension;
        const fs::path target = fs::path(folder) / candidate;
        if (fs::exists(target, ec) || fs::is_symlink(target, ec)) {
            if (holdsBytes(target, bytes)) return PlacedFile{candidate, false};
            continue;
        }
        if (const std::string problem = writeFileAtomically(target.string(), bytes); !problem.empty()) {
            error = problem;
            return std::nullopt;
        }
        return PlacedFile{candidate, true};
    }
    error = (fs::path(folder) / name).string() + ": " + std::to_string(kMaxNames) + " names like it are taken";
    return std::nullopt;
}

std::optional<std::string> copyIntoFolder(const std::string& file, const std::string& folder, std::string& error) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path source(file);
    if (!fs::is_regular_file(source, ec)) {
        error = file + ": not a file to copy beside the exercise";
        return std::nullopt;
    }
    // Already in the folder: its own copy.
    const fs::path there = fs::path(folder) / source.filename();
    if (fs::exists(there, ec) && fs::equivalent(source, there, ec)) return source.filename().string();
    std::string problem;
    const std::optional<std::string> bytes = readInputFile(file, kCopiedFile, problem);
    if (!bytes) {
        error = file + ": cannot be read to copy beside the exercise (" + problem + ")";
        return std::nullopt;
    }
    const auto placed = placeInFolder(*bytes, source.filename().string(), folder, problem);
    if (!placed) {
        error = file + ": not copied beside the exercise: " + problem;
        return std::nullopt;
    }
    return placed->name;
}

}  // namespace palpate
