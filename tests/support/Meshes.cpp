#include "tests/support/Meshes.h"

#include <map>
#include <mutex>
#include <stdexcept>
#include <utility>

namespace palpate::test {

const TissueMesh& generatedMesh(GeneratedShape shape, std::size_t vertices) {
    static std::mutex guard;
    static std::map<std::pair<int, std::size_t>, TissueMesh> cache;
    const std::lock_guard lock(guard);
    const auto key = std::make_pair(int(shape), vertices);
    auto it = cache.find(key);
    if (it == cache.end()) {
        auto generated = generateMesh(shape, vertices);
        if (!generated.mesh) throw std::runtime_error("generated mesh: " + generated.error());
        it = cache.emplace(key, std::move(*generated.mesh)).first;
    }
    return it->second;
}

TissueMesh sphereMesh(std::size_t vertices) { return generatedMesh(GeneratedShape::Sphere, vertices); }

VertexId sideVertex(const TissueMesh& mesh) {
    VertexId best = 0;
    for (VertexId v = 1; v < mesh.vertexCount(); ++v)
        if (mesh.restPositionsMm()[v].x > mesh.restPositionsMm()[best].x) best = v;
    return best;
}

}  // namespace palpate::test
