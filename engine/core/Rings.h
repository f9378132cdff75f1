#pragma once
// Rings of a vertex: ring r = the vertices at edge-graph distance exactly r (ring 0 = the vertex).
// Computed by a bounded breadth-first walk into preallocated buffers: no allocation per query.

#include "engine/core/TissueMesh.h"

#include <cstdint>
#include <span>
#include <vector>

namespace palpate {

inline constexpr int kMaxRings = 8;

/// The rings of one vertex, flat: ring r is vertices[ringStart[r] .. ringStart[r+1]).
struct RingSet {
    std::vector<VertexId> vertices;
    std::uint32_t ringStart[kMaxRings + 2] = {};
    int ringCount = 0;  ///< rings beyond ring 0

    std::span<const VertexId> ring(int r) const {
        return {vertices.data() + ringStart[r], vertices.data() + ringStart[r + 1]};
    }
    std::size_t size() const { return ringStart[ringCount + 1]; }
};

class RingFinder {
public:
    explicit RingFinder(const TissueMesh& mesh);

    /// Fills `out` with rings 0..ringCount of `centre`. `out` must come from makeRingSet() (capacity).
    void find(VertexId centre, int ringCount, RingSet& out);

    /// A RingSet with capacity for any vertex of the mesh.
    RingSet makeRingSet() const;

private:
    const std::uint32_t* mStart;
    const VertexId* mNeighbours;
    std::size_t mVertexCount;
    std::vector<std::uint32_t> mStamp;
    std::uint32_t mGeneration = 0;
};

}  // namespace palpate
