#include "engine/core/Rings.h"

#include <algorithm>

namespace palpate {

RingFinder::RingFinder(const TissueMesh& mesh)
    : mStart(mesh.neighbourStart().data()),
      mNeighbours(mesh.neighbours().data()),
      mVertexCount(mesh.vertexCount()),
      mStamp(mesh.vertexCount(), 0) {}

RingSet RingFinder::makeRingSet() const {
    RingSet set;
    set.vertices.resize(mVertexCount);
    return set;
}

void RingFinder::find(VertexId centre, int ringCount, RingSet& out) {
    ringCount = std::clamp(ringCount, 0, kMaxRings);
    if (++mGeneration == 0) {  // wrapped: clear once every 2^32 queries
        std::fill(mStamp.begin(), mStamp.end(), 0u);
        mGeneration = 1;
    }
    VertexId* v = out.vertices.data();
    std::uint32_t count = 0;
    v[count++] = centre;
    mStamp[centre] = mGeneration;
    out.ringStart[0] = 0;
    out.ringStart[1] = 1;
    for (int r = 1; r <= ringCount; ++r) {
        const std::uint32_t from = out.ringStart[r - 1], to = out.ringStart[r];
        for (std::uint32_t i = from; i < to; ++i) {
            const VertexId u = v[i];
            for (std::uint32_t k = mStart[u]; k < mStart[u + 1]; ++k) {
                const VertexId w = mNeighbours[k];
                if (mStamp[w] == mGeneration) continue;
                mStamp[w] = mGeneration;
                v[count++] = w;
            }
        }
        out.ringStart[r + 1] = count;
    }
    out.ringCount = ringCount;
}

}  // namespace palpate
