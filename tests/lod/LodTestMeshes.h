#pragma once
// Shared by the level-of-detail tests: generated meshes and their levels, made once per process
// (decimation and mapping of a few thousand vertices take a fraction of a second, but every test
// needs them).

#include "engine/core/MeshGenerator.h"
#include "engine/lod/MeshLevels.h"
#include "tests/support/Meshes.h"

#include <gtest/gtest.h>

#include <map>
#include <utility>

namespace palpate::test {

inline const TissueMesh& generated(GeneratedShape shape, std::size_t vertices) { return generatedMesh(shape, vertices); }

/// Levels with the default guards down to 200 vertices.
inline const MeshLevels& levelsOf(GeneratedShape shape, std::size_t vertices) {
    static std::map<std::pair<int, std::size_t>, MeshLevels> cache;
    const auto key = std::make_pair(int(shape), vertices);
    auto it = cache.find(key);
    if (it == cache.end()) {
        LevelDef options;
        options.minVertices = 200;
        it = cache.emplace(key, generateLevels(generated(shape, vertices), options)).first;
    }
    return it->second;
}

}  // namespace palpate::test
