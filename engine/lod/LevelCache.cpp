#include "engine/lod/LevelCache.h"

#include "base/io/AtomicFile.h"
#include "base/io/InputFile.h"
#include "engine/core/MeshHash.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>

namespace palpate {

namespace {

using Json = nlohmann::ordered_json;
constexpr const char* kFormat = "palpate-mesh-levels";
constexpr const char* kIndexName = "levels.json";

std::string hex64(std::uint64_t v) {
    char text[19];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
    return text;
}

Json optionsJson(const LevelDef& o) {
    return Json{{"vertex_ratio", o.vertexRatio},
                {"min_vertices", o.minVertices},
                {"max_coarse_levels", o.maxCoarseLevels},
                {"max_normal_deviation_deg", o.guards.maxNormalDeviationDeg},
                {"max_aspect_ratio", o.guards.maxAspectRatio}};
}

/// OBJ text with 9 significant digits: every float comes back bit for bit, so the reloaded
/// level's meshHash equals the one stored in the index.
std::string objText(const TissueMesh& mesh) {
    std::string out;
    out.reserve(mesh.vertexCount() * 48 + mesh.triangleCount() * 24);
    out += "# palpate mesh level\n";
    char line[128];
    for (const glm::vec3& p : mesh.restPositionsMm()) {
        std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", double(p.x), double(p.y), double(p.z));
        out += line;
    }
    for (const auto& t : mesh.triangles()) {
        std::snprintf(line, sizeof line, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1);
        out += line;
    }
    return out;
}

}  // namespace

std::string levelCacheDir(const std::string& meshPath) { return meshPath + ".levels"; }

std::optional<MeshLevels> readLevelCache(const std::string& dir, const TissueMesh& source, const LevelDef& options,
                                         std::string& error, const LodProgressFn& progress,
                                         const std::atomic<bool>* cancel) {
    namespace fs = std::filesystem;
    const fs::path indexPath = fs::path(dir) / kIndexName;
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(indexPath, ec))) {
        error = "no cache at " + dir;
        return std::nullopt;
    }
    // The bounded reader: a FIFO or a huge file in the cache's place is refused, not read.
    std::string readError;
    const std::optional<std::string> text = readInputFile(indexPath.string(), kLevelCacheIndexFile, readError);
    if (!text) {
        error = readError;
        return std::nullopt;
    }
    Json j;
    try {
        j = Json::parse(*text);
    } catch (const std::exception& e) {
        error = indexPath.string() + ": corrupt: " + e.what();
        return std::nullopt;
    }
    const std::uint64_t hash = meshHash(source);
    try {
        if (j.at("format").get<std::string>() != kFormat) {
            error = indexPath.string() + ": not a levels index";
            return std::nullopt;
        }
        if (j.at("version").get<int>() != kLevelCacheVersion) {
            error = indexPath.string() + ": version " + j.at("version").dump() + " (this build writes " +
                    std::to_string(kLevelCacheVersion) + ")";
            return std::nullopt;
        }
        if (j.at("source_hash").get<std::string>() != hex64(hash)) {
            error = "stale: the mesh changed since the cache was made (hash " + j.at("source_hash").get<std::string>() +
                    ", now " + hex64(hash) + ")";
            return std::nullopt;
        }
        if (j.at("options") != optionsJson(options)) {
            error = "stale: made with other level options";
            return std::nullopt;
        }
        MeshLevels out;
        out.sourceHash = hash;
        MeshLevel fine;
        fine.mesh = source;
        fine.targetVertices = source.vertexCount();
        out.levels.push_back(std::move(fine));
        for (const auto& n : j.at("notes")) out.notes.push_back(n.get<std::string>());
        const Json& levels = j.at("levels");
        std::size_t k = 0;
        for (const Json& entry : levels) {
            ++k;
            if (progress) progress(double(k - 1) / double(levels.size()), "reading level " + std::to_string(k));
            const std::string file = entry.at("file").get<std::string>();
            if (file.find('/') != std::string::npos || file.find('\\') != std::string::npos || file.empty() || file[0] == '.') {
                error = indexPath.string() + ": level file name '" + file + "' is not a plain name in the cache folder";
                return std::nullopt;
            }
            auto loaded = TissueMesh::load((fs::path(dir) / file).string());
            if (!loaded.mesh) {
                error = "corrupt: " + loaded.error();
                return std::nullopt;
            }
            if (hex64(meshHash(*loaded.mesh)) != entry.at("hash").get<std::string>()) {
                error = "corrupt: " + file + " is not the level the index describes (hash differs)";
                return std::nullopt;
            }
            MeshLevel level;
            level.mesh = std::move(*loaded.mesh);
            level.targetVertices = entry.at("target_vertices").get<std::size_t>();
            level.seconds = entry.at("seconds").get<double>();
            if (const std::string problem = levelTopologyProblem(source, level.mesh); !problem.empty()) {
                error = "corrupt: " + file + ": " + problem;
                return std::nullopt;
            }
            if (level.mesh.vertexCount() >= out.levels.back().mesh.vertexCount()) {
                error = "corrupt: " + file + " is not coarser than the level before it";
                return std::nullopt;
            }
            if (!mapLevelToSource(source, level, cancel)) {
                error = "cancelled";
                out.cancelled = true;
                return std::nullopt;
            }
            out.levels.push_back(std::move(level));
        }
        if (progress) progress(1.0, "done");
        return out;
    } catch (const std::exception& e) {
        // Missing keys and wrong types (nlohmann throws out_of_range / type_error).
        error = indexPath.string() + ": corrupt: " + e.what();
        return std::nullopt;
    }
}

std::string writeLevelCache(const std::string& dir, const MeshLevels& levels, const LevelDef& options) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) return dir + ": cannot be created: " + ec.message();
    // Drop the old index first: from here until the new one is in place, the cache reads as absent.
    fs::remove(fs::path(dir) / kIndexName, ec);
    Json j{{"format", kFormat},
           {"version", kLevelCacheVersion},
           {"source_hash", hex64(levels.sourceHash)},
           {"source_vertices", levels.levels.empty() ? 0 : levels.levels.front().mesh.vertexCount()},
           {"options", optionsJson(options)},
           {"notes", levels.notes},
           {"levels", Json::array()}};
    for (std::size_t k = 1; k < levels.levels.size(); ++k) {
        const MeshLevel& l = levels.levels[k];
        const std::string file = "level" + std::to_string(k) + ".obj";
        if (const std::string e = writeFileAtomically((fs::path(dir) / file).string(), objText(l.mesh)); !e.empty()) return e;
        j["levels"].push_back({{"file", file},
                               {"target_vertices", l.targetVertices},
                               {"vertices", l.mesh.vertexCount()},
                               {"triangles", l.mesh.triangleCount()},
                               {"hash", hex64(meshHash(l.mesh))},
                               {"seconds", l.seconds}});
    }
    return writeFileAtomically((fs::path(dir) / kIndexName).string(), j.dump(2) + "\n");
}

LevelCacheResult loadOrGenerateLevels(const std::string& meshPath, const TissueMesh& source, const LevelDef& options,
                                      const LodProgressFn& progress, const std::atomic<bool>* cancel, bool useCache) {
    if (const std::string e = joinedMessages(validateLevelDef(options)); !e.empty()) throw std::invalid_argument(e);
    LevelCacheResult result;
    const std::string dir = levelCacheDir(meshPath);
    if (useCache) {
        std::string why;
        if (auto cached = readLevelCache(dir, source, options, why, progress, cancel)) {
            result.levels = std::move(*cached);
            result.fromCache = true;
            result.cacheStatus = "read from " + dir;
            return result;
        }
        if (cancel && cancel->load()) {
            result.levels.cancelled = true;
            result.cacheStatus = "cancelled";
            return result;
        }
        result.cacheStatus = "generated (" + why + ")";
    } else {
        result.cacheStatus = "generated (cache not used)";
    }
    result.levels = generateLevels(source, options, progress, cancel);
    if (useCache && !result.levels.cancelled) result.writeError = writeLevelCache(dir, result.levels, options);
    return result;
}

}  // namespace palpate
