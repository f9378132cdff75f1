#pragma once
// Ours, the coherent method (docs/method.md, "Our contact"): the paper's slope-ring formulas
// (SlopeRingModel) with a continuous contact. A sphere tool of radius a (a point when a = 0) is
// held on the surface by a proxy that walks over the rest triangles (SurfaceWalk) to the point
// closest to the tool; the rings of the contact triangle's three corners are blended with the
// contact's barycentric weights, scaled so that the contact point itself moves by |m1| F as the
// paper's touched vertex does; the force points along the interpolated normal (force shading) and
// Coulomb friction acts on the proxy. Work is incremental: the blended ring set is rebuilt only
// when the contact triangle or the contact changes, its positions are a function of (weights,
// normal, force) written when read, and only the vertices still relaxing are integrated.

#include "engine/core/SurfaceWalk.h"
#include "engine/models/slopering/CandidateCache.h"
#include "engine/models/slopering/ProxyFriction.h"
#include "engine/models/slopering/SlopeRingModel.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace palpate {

class CoherentSlopeRing final : public SlopeRingModel {
public:
    /// `mesh` and `octree` must outlive the model. Throws std::invalid_argument on bad params.
    /// `eagerPositions` writes the active rings' positions every tick instead of when they are
    /// read; the benchmark reports both.
    CoherentSlopeRing(const TissueMesh& mesh, const Octree& octree, const SlopeRingParams& params,
                      bool eagerPositions = false);

    TickResult step(const glm::vec3& toolMm, double dtS) override;
    /// Current positions; the active rings are written here, on demand (not real-time: call from
    /// the thread that steps, at display rate).
    std::span<const glm::vec3> positionsMm() const override;
    void copyPositionsMm(std::span<const VertexId> ids, glm::vec3* out) const override;
    /// Only the active set and the relaxing vertices leave rest (and relax by backward Euler,
    /// unconditionally stable): the rest of the mesh is exactly at rest.
    bool movesOnlyDisplaced() const override { return true; }
    void reset() override;
    std::size_t copyDisplaced(VertexId* ids, glm::vec3* positionsMm, std::uint8_t* rings,
                              std::size_t capacity) const override;
    /// Reads the memory the next tick will touch (the proxy's triangle and the active rings).
    void warm(const glm::vec3& lastToolMm) const override;
    /// The corner of the contact triangle with the largest weight, for the tool at `toolMm`
    /// (kNoVertex if the surface has no triangle), without changing the deformation.
    VertexId findTouched(const glm::vec3& toolMm) const override;
    float toolRadiusMm() const override { return float(mContactDef.toolRadiusMm); }
    void setContact(const ContactDef& contact) override;
    const ContactDef& contact() const { return mContactDef; }

    /// Every vertex that may be away from rest (the active rings and those relaxing). Not real-time.
    std::span<const VertexId> displacedVertices() const override;
    /// A stiffer inclusion (engine/scoring's find-the-lump exercises): one factor per vertex in
    /// (0, 1] that scales every ring slope while that vertex is the touched one, with the return
    /// spring of the touched vertex stiffened by its inverse, so the rendered force for a given
    /// depth grows (docs/scoring.md); blended over the contact triangle's corners like the rings.
    /// Empty clears it. Not real-time; throws std::invalid_argument naming the problem.
    void setCompliance(std::vector<float> factors);
    std::span<const float> compliance() const { return mCompliance; }
    /// Lumps under the surface (engine/scoring's detect-lumps exercises; docs/scoring.md, "Lumps
    /// under the surface"): per vertex the compliance factor c (1 / contrast over a lump, 1
    /// elsewhere) and the depth z at which its lump begins to resist. Pressing there sinks the
    /// surface by |m1| F until the sink reaches z, and by c |m1| per newton beyond: a deeper lump
    /// feels like the tissue around it until it is pressed deeper. Not real-time; throws
    /// std::invalid_argument naming the problem.
    void setLumps(std::vector<float> factors, const std::vector<float>& engageDepthMm);
    /// The contact on the rest surface (its triangle is kNoTriangle before the first tick).
    const SurfaceHit& contactPoint() const { return mContactPoint; }
    /// Search statistics: how often the nearest-vertex cache (used to find the surface while the
    /// tool is not in contact) was retaken, and how often the full octree search was needed.
    std::size_t cacheRefreshes() const { return mCache.refreshes(); }
    std::size_t fullSearches() const { return mCache.fullSearches(); }

protected:
    /// Always real-time: the active set is sized for every ring count.
    bool canTakeParams(const SlopeRingParams&) const override { return true; }
    void paramsReplaced(bool ringsChanged) override;

private:
    SurfaceHit findContactPoint(const glm::vec3& tool, bool walkFromLast) const;
    bool walksFromLast(const glm::vec3& tool) const;
    VertexId nearestRestVertex(const glm::vec3& tool) const;
    glm::vec3 activeDisplacementMm(std::uint32_t i) const;
    void writeActivePositions() const;
    void changeActiveSet(TriangleId triangle, bool contact);
    void releaseActiveSet();
    void stepRings(const SurfaceHit& contact, bool inContact);
    void addRelaxing(VertexId v);
    void removeRelaxing(VertexId v);
    float blendedCompliance(TriangleId t, const float* weight) const;
    float blendedOffsetMm(TriangleId t, const float* weight) const;

    bool mEagerPositions;
    std::vector<float> mCompliance;  // per-vertex slope factor (setCompliance); empty: all 1, skipped
    std::vector<float> mEngageOffsetMm;  // per-vertex b = (1 - c) z of a lump under it (setLumps); empty: 0
    ContactDef mContactDef;
    float mToolRadiusMm = 0.0f;
    SurfaceWalk mWalk;
    ProxyFriction mFriction;

    // The contact: where the proxy stands on the rest surface, and the shaded normal there.
    SurfaceHit mContactPoint;
    glm::vec3 mContactNormal{0.0f};
    // Out of contact the proxy walks while the tool moved less than this per tick and its sphere
    // is nearer the surface than this (walksFromLast).
    static constexpr float kHoverWalkStepMm = 1.0f;
    static constexpr float kHoverWalkClearanceMm = 10.0f;
    glm::vec3 mLastToolMm{0.0f};
    float mLastClearanceMm = std::numeric_limits<float>::infinity();  // sphere to surface, last tick

    // The active set: the union of the rings of the contact triangle's corners, with a copy of
    // each vertex's rest position and its ring from each corner (kBeyondRings when outside).
    static constexpr std::uint8_t kBeyondRings = kMaxRings + 1;
    RingSet mCornerRings;
    std::vector<VertexId> mActive;
    std::uint32_t mActiveCount = 0;
    std::vector<float> mActiveRestX, mActiveRestY, mActiveRestZ;
    std::vector<std::uint8_t> mActiveRing;  // 3 per active vertex
    std::vector<float> mActiveSlope;        // 3 per active vertex: s[ring from each corner]
    std::vector<std::uint8_t> mActiveNearestRing;  // per active vertex: its nearest ring from any corner
    std::vector<std::uint32_t> mActiveStamp;  // == mActiveGeneration: in the active set...
    std::vector<std::uint32_t> mActiveIndex;  // ...at this index
    std::uint32_t mActiveGeneration = 1;
    TriangleId mActiveTriangle = kNoTriangle;
    bool mActiveContact = false;
    // The field the active positions follow: vertex i moves by -(sum_k w_k s[ring_k(i)]) f n.
    float mSlopeByRing[16] = {};  // |m_r| for r <= ringCount, 0 beyond
    float mFieldWeight[3] = {};
    int mFieldTouchedCorner = 0;  // the corner with the largest weight: the touched vertex
    glm::vec3 mFieldNormal{0.0f};
    float mFieldForceN = 0.0f;          // c F N(w): compliance, force, the normalisation
    mutable bool mActiveDirty = false;  // mutable with mPositions: active positions not yet written

    std::vector<VertexId> mRelaxing;
    std::size_t mRelaxingCount = 0;
    std::vector<std::uint32_t> mRelaxingSlot;

    // The nearest rest vertex while not in contact (CandidateCache.h): search state, updated by
    // the const searches (findTouched, warm), hence mutable.
    mutable CandidateCache mCache;
    // displacedVertices()'s list, reserved for every vertex so that it never allocates.
    mutable std::vector<VertexId> mDisplacedScratch;
};

}  // namespace palpate
