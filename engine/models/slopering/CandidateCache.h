#pragma once
// The coherent method's touched-vertex search (CoherentSlopeRing): the K rest vertices nearest to
// a centre, and the triangle-inequality certificate that makes them enough on most ticks. Any
// other vertex at rest is at least radiusMm() - |tool - centre| from the tool, which proves the
// nearest cached candidate is the nearest rest vertex without touching the octree
// (docs/method.md). The cache is search state, not model state: it is retaken from the const
// searches (findTouched, warm), hence the owner keeps it `mutable`.

#include "engine/core/Octree.h"
#include "engine/core/TissueMesh.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <cstddef>

namespace palpate {

class CandidateCache {
public:
    /// Candidates kept: the K in "the K nearest rest vertices".
    static constexpr int kCacheSize = 16;
    /// The centre is placed beyond the tool, away from the surface (kCentreOffset times the tool's
    /// distance to it), and ahead along the tool's motion (kLeadTicks ticks sideways,
    /// kAxialLeadTicks along the offset direction, at most half the distance): the bound then
    /// decays slowly as the tool moves.
    static constexpr float kCentreOffset = 0.5f;
    static constexpr float kLeadTicks = 10.0f;
    static constexpr float kAxialLeadTicks = 60.0f;
    /// Relative margin on the triangle-inequality bounds: float distances are within a few ulps
    /// (~1e-7) of the true ones, so a bound shrunk by 1e-5 of its terms holds for the computed ones.
    static constexpr float kRoundingMargin = 1e-5f;

    /// Empty, as after construction: the next search retakes the cache around the tool.
    void clear() {
        mCount = 0;
        mPreviousToolMm = glm::vec3(0.0f);
    }

    /// Improves (best, best2) with the cached rest vertices that could still beat it, retaking the
    /// cache up to twice, and returns true when the result is certified to be the nearest over
    /// every vertex at rest. `displaced(v)` says that v is not at rest (the caller counted it at
    /// its current position): it is skipped. Allocation-free; the cache refresh queries the octree.
    template <typename Displaced>
    bool certifyNearest(const Octree& octree, const glm::vec3& tool, VertexId& best, float& best2,
                        const Displaced& displaced) {
        const glm::vec3 previousTool = mPreviousToolMm;
        mPreviousToolMm = tool;
        for (int attempt = 0; attempt < 3; ++attempt) {
            // 0: the cache as it is; 1: retaken around a centre beyond the tool (lasts longer);
            // 2: around the tool itself (the tightest bound here). A first cache is centred on the tool.
            if (attempt > 0 || mCount == 0) refresh(octree, tool, tool - previousTool, attempt == 1);
            // Lower bounds by the triangle inequality, shrunk by a relative margin that covers the
            // rounding of the float distances they are computed from.
            const float shift = glm::length(tool - mCentreMm) * (1.0f + kRoundingMargin);
            for (int i = 0; i < mCount; ++i) {
                const float lower = mDistanceMm[i] * (1.0f - kRoundingMargin) - shift;  // |tool - rest| >= this
                if (lower > 0.0f && lower * lower > best2) break;  // sorted: no later entry can win
                const VertexId v = mIds[i];
                if (displaced(v)) continue;             // counted by the caller at its current position
                const glm::vec3 d = mRestMm[i] - tool;  // at rest: its position is its rest position
                const float d2 = d.x * d.x + d.y * d.y + d.z * d.z;
                if (d2 < best2 || (d2 == best2 && v < best)) {
                    best2 = d2;
                    best = v;
                }
            }
            // Every rest vertex not cached is at least this far from the tool.
            const float clearance = mRadiusMm * (1.0f - kRoundingMargin) - shift;
            if (clearance > 0.0f && best2 < clearance * clearance) return true;
        }
        ++mFullSearches;
        return false;
    }

    /// How often the cache was retaken, and how often no certificate was found (the caller then
    /// runs the full octree search).
    std::size_t refreshes() const { return mRefreshes; }
    std::size_t fullSearches() const { return mFullSearches; }

private:
    /// Retakes the K nearest rest vertices around a centre: the tool, or (offsetCentre) a point
    /// beyond it that makes the bound last (docs/method.md).
    void refresh(const Octree& octree, const glm::vec3& tool, const glm::vec3& toolStepMm, bool offsetCentre);

    glm::vec3 mCentreMm{0.0f};
    glm::vec3 mRestMm[kCacheSize] = {};  // rest positions of the cached vertices
    glm::vec3 mPreviousToolMm{0.0f};     // the tool at the previous search
    int mCount = 0;
    float mRadiusMm = 0.0f;  // distance of the K-th cached vertex from the centre (infinite if all cached)
    VertexId mIds[kCacheSize] = {};
    float mDistanceMm[kCacheSize] = {};  // from the centre, ascending
    std::size_t mRefreshes = 0;
    std::size_t mFullSearches = 0;
};

}  // namespace palpate
