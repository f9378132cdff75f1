#pragma once
// The levels of a mesh file, cached next to it so that a 1M-vertex mesh is decimated once: folder
// "<mesh file>.levels/" with "levels.json" (format, version, the source's meshHash, the options,
// each level's file, counts and hash) and "level<k>.obj" per coarse level. Any doubt (no index,
// another format or version, another source hash or options, a missing, unreadable or altered
// level file) regenerates; the cache is a help, never a source of truth. Mappings are recomputed
// on load (they are fast next to decimation, and one thing less to go stale). docs/lod.md.

#include "engine/lod/MeshLevels.h"

#include <atomic>
#include <optional>
#include <string>

namespace palpate {

inline constexpr int kLevelCacheVersion = 1;

/// "<meshPath>.levels".
std::string levelCacheDir(const std::string& meshPath);

/// The cached levels, or nullopt with `error` saying what made the cache unusable.
std::optional<MeshLevels> readLevelCache(const std::string& cacheDir, const TissueMesh& source, const LevelDef& options,
                                         std::string& error, const LodProgressFn& progress = {},
                                         const std::atomic<bool>* cancel = nullptr);

/// Writes the coarse levels and then the index, each atomically (base/io/AtomicFile.h), so a crash
/// leaves either no index or a complete cache. Returns "" or the problem, naming the path.
std::string writeLevelCache(const std::string& cacheDir, const MeshLevels& levels, const LevelDef& options);

struct LevelCacheResult {
    MeshLevels levels;
    bool fromCache = false;
    std::string cacheStatus;  ///< "read from <dir>", or why the levels were generated
    std::string writeError;   ///< "" or why the cache could not be written (the levels are still good)
};

/// Reads the cache beside `meshPath`, or generates (and caches, unless cancelled) the levels.
/// `useCache` false generates without reading or writing. Throws as generateLevels does.
LevelCacheResult loadOrGenerateLevels(const std::string& meshPath, const TissueMesh& source, const LevelDef& options,
                                      const LodProgressFn& progress = {}, const std::atomic<bool>* cancel = nullptr,
                                      bool useCache = true);

}  // namespace palpate
