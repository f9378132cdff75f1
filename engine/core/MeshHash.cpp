#include "engine/core/MeshHash.h"

#include <cstring>

namespace palpate {

namespace {

struct Fnv {
    std::uint64_t hash = 1469598103934665603ull;
    void u32(std::uint32_t v) {
        for (int i = 0; i < 4; ++i) {
            hash ^= (v >> (8 * i)) & 0xFFu;
            hash *= 1099511628211ull;
        }
    }
    void u64(std::uint64_t v) {
        u32(std::uint32_t(v));
        u32(std::uint32_t(v >> 32));
    }
    void f32(float v) {
        std::uint32_t bits;
        std::memcpy(&bits, &v, 4);
        u32(bits);
    }
};

}  // namespace

std::uint64_t meshHash(const TissueMesh& mesh) {
    Fnv f;
    f.u64(mesh.vertexCount());
    for (const glm::vec3& p : mesh.restPositionsMm()) {
        f.f32(p.x);
        f.f32(p.y);
        f.f32(p.z);
    }
    f.u64(mesh.triangleCount());
    for (const auto& t : mesh.triangles()) {
        f.u32(t[0]);
        f.u32(t[1]);
        f.u32(t[2]);
    }
    return f.hash;
}

}  // namespace palpate
