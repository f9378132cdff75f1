#pragma once
// The slope-ring model: the touched vertex and its rings move by p = p_rest + m_r F (the paper's
// Eq. (1)-(3), m_r < 0), return springs tie them to rest, and the touched vertex's spring
// reaction is the force rendered. One class runs the paper's three configurations and ours, so
// that they share every formula and differ only in search and in how much work a tick does.

#include "engine/models/DeformationModel.h"
#include "engine/core/Octree.h"
#include "engine/core/Rings.h"
#include "engine/models/slopering/SlopeRingMethod.h"
#include "engine/models/slopering/SlopeRingParams.h"

#include <memory>
#include <vector>

namespace palpate {

class SlopeRingDeformer final : public DeformationModel {
public:
    /// `mesh` and `octree` must outlive the deformer. Throws std::invalid_argument on bad params.
    /// `eagerPositions` (Palpate only) writes the active rings' positions every tick instead of
    /// when they are read; the benchmark reports both.
    SlopeRingDeformer(const TissueMesh& mesh, const Octree& octree, const SlopeRingParams& params,
                      SlopeRingMethod method = SlopeRingMethod::Palpate, bool eagerPositions = false);

    TickResult step(const glm::vec3& toolTipMm, double dtS) override;
    /// Current positions. For Palpate the active rings are written here, on demand (not real-time:
    /// call from the thread that steps, at display rate).
    std::span<const glm::vec3> positionsMm() const override;
    void reset() override;
    std::string name() const override;

    /// Replaces the parameters (validated first; throws std::invalid_argument listing every problem).
    /// Not real-time: may precompute rings.
    void setParams(const SlopeRingParams& params);
    std::size_t copyDisplaced(VertexId* ids, glm::vec3* positionsMm, std::uint8_t* rings,
                              std::size_t capacity) const override;
    /// Runs this method's search for the last tool position (a read-only pass over the search's
    /// and the active set's memory).
    void warm(const glm::vec3& lastToolTipMm) const override;
    /// Real-time: true for Palpate, and for the paper's methods while the ring count is unchanged.
    bool applySlopeRingParams(const SlopeRingParams& params) override;
    const SlopeRingParams& params() const { return mParams; }
    SlopeRingMethod method() const { return mMethod; }

    /// The touched vertex this method's search would report now, without changing the deformation
    /// (kNoVertex where the paper's searchNode finds nothing).
    VertexId findTouched(const glm::vec3& toolTipMm) const;
    VertexId touchedVertex() const { return mTouched; }
    /// Contact force magnitude of the slope model (N), before the spring rendering.
    float contactForceN() const { return mForceN; }
    /// Palpate: every vertex that may be away from rest (the active rings and those relaxing).
    /// Other methods: empty. Not real-time.
    std::span<const VertexId> displacedVertices() const;
    /// A stiffer inclusion (engine/scoring's find-the-lump exercises): one factor per vertex in
    /// (0, 1] that scales every ring slope while that vertex is the touched one, with the return
    /// spring of the touched vertex stiffened by its inverse, so the rendered force for a given
    /// depth grows (docs/scoring.md). Empty clears it. Palpate only (the paper's methods stay as
    /// published). Not real-time; throws std::invalid_argument naming the problem.
    void setCompliance(std::vector<float> factors);
    std::span<const float> compliance() const { return mCompliance; }
    /// Palpate search statistics: how often the candidate cache was retaken, and how often the
    /// full octree search was needed.
    std::size_t cacheRefreshes() const { return mCacheRefreshes; }
    std::size_t fullSearches() const { return mFullSearches; }

private:
    void applyParams();
    void precomputeRingLists();
    VertexId searchPalpate(const glm::vec3& tool) const;
    void searchActive(const glm::vec3& tool, VertexId& best, float& best2) const;
    void refreshCandidateCache(const glm::vec3& tool, const glm::vec3& toolStepMm, bool offsetCentre) const;
    void writeActivePositions() const;
    void changeActiveSet(VertexId touched, bool contact);
    void releaseActiveSet();
    void stepPalpate(VertexId touched, bool contact);
    void stepWholeModel(VertexId touched, bool contact);
    void stepProposed(VertexId touched, bool contact);
    void relaxVertex(VertexId v);
    void addRelaxing(VertexId v);
    void removeRelaxing(VertexId v);

    const TissueMesh& mMesh;
    const Octree& mOctree;
    SlopeRingParams mParams;
    SlopeRingMethod mMethod;
    bool mEagerPositions;

    // Hot-loop constants derived from the parameters.
    float mSignedSlope[kMaxRings + 1] = {};  // -|m_r|, mm/N
    int mRingCount = 2;
    float mAlpha = 1.0f;
    float mContactStiffness = 1.0f;
    float mSpringStiffness = 1.0f;
    float mOmega2 = 0.0f;        // return-spring omega^2, 1/s^2
    float mTwoZetaOmega = 0.0f;  // 2 zeta omega, 1/s
    double mRelaxDtS = -1.0;     // dt for which the two factors below hold
    float mRelaxDenominatorInv = 1.0f, mRelaxDt = 0.0f;

    std::vector<float> mCompliance;  // per-vertex slope factor (setCompliance); empty: all 1, skipped

    mutable std::vector<glm::vec3> mPositions;  // mutable: Palpate writes active rings on demand
    std::vector<glm::vec3> mVelocitiesMmPerS;

    // State of the contact.
    VertexId mTouched = kNoVertex;
    float mForceN = 0.0f;
    bool mContact = false;

    // Palpate: the active set (rings of the touched vertex in contact) with a copy of its rest
    // positions in structure-of-arrays form for the search, and the vertices still relaxing.
    RingFinder mRingFinder;
    RingSet mActive, mNextActive;
    std::vector<float> mActiveRestX, mActiveRestY, mActiveRestZ;
    mutable std::vector<float> mScratchDistance2;
    VertexId mActiveCentre = kNoVertex;
    bool mActiveContact = false;
    glm::vec3 mActiveNormal{0.0f};
    float mActiveForceN = 0.0f;  // the force the active positions follow
    mutable bool mActiveDirty = false;  // active positions not yet written for mForceN
    std::vector<std::uint32_t> mActiveStamp;
    std::uint32_t mActiveGeneration = 1;
    std::vector<VertexId> mRelaxing;
    std::size_t mRelaxingCount = 0;
    std::vector<std::uint32_t> mRelaxingSlot;
    mutable std::vector<VertexId> mDisplacedScratch;
    // The last full scan of the active set: its nearest vertex and the margin to the runner-up.
    // Until the tool and the force have moved more than that margin allows, the nearest active
    // vertex cannot change and one distance replaces the scan.
    mutable bool mActiveScanValid = false;
    mutable glm::vec3 mActiveScanToolMm{0.0f};
    mutable float mActiveScanForceN = 0.0f;
    mutable std::uint32_t mActiveScanBest = 0;     // index into mActive
    mutable int mActiveScanBestRing = 0;
    mutable float mActiveScanSecondMm = 0.0f;      // runner-up distance at the scan

    // Palpate's touched-vertex search: the K rest vertices nearest to a centre. Any other vertex
    // at rest is at least mCacheRadiusMm - |tool - centre| from the tool, which certifies the
    // answer without touching the octree on most ticks (docs/method.md). The centre is placed
    // beyond the tool, away from the surface (kCentreOffset times the tool's distance to it), and
    // ahead along the tool's motion (kLeadTicks ticks sideways, kAxialLeadTicks along the offset
    // direction, at most half the distance): the bound then decays slowly as the tool moves.
    static constexpr int kCacheSize = 16;
    static constexpr float kCentreOffset = 0.5f;
    static constexpr float kLeadTicks = 10.0f;
    static constexpr float kAxialLeadTicks = 60.0f;
    mutable glm::vec3 mCacheCentreMm{0.0f};
    mutable glm::vec3 mCacheRestMm[kCacheSize] = {};  // rest positions of the cached vertices
    mutable glm::vec3 mPreviousToolMm{0.0f};         // the tool at the previous search
    mutable int mCacheCount = 0;
    mutable float mCacheRadiusMm = 0.0f;  // distance of the K-th cached vertex (infinite if all cached)
    mutable VertexId mCacheIds[kCacheSize] = {};
    mutable float mCacheDistanceMm[kCacheSize] = {};
    mutable std::size_t mCacheRefreshes = 0;
    mutable std::size_t mFullSearches = 0;

    // The paper's methods: rings precomputed per vertex (nodes[t].firstRing, .secondRing, ...).
    std::vector<std::vector<std::vector<VertexId>>> mRingLists;  // [vertex][ring-1]
    std::vector<std::uint8_t> mRingOf;                           // whole model: ring index per vertex this tick
    std::vector<VertexId> mPreviousRingVertices;                 // proposed: what to restore next tick
};

}  // namespace palpate
