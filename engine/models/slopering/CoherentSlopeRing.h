#pragma once
// Ours, the coherent method (temporal coherence, docs/method.md): the paper's slope-ring formulas
// (SlopeRingModel) with an exact, warm-started touched-vertex search (CandidateCache certifies the
// nearest rest vertex; the displaced ones are scanned) and incremental ring work: the active set
// is rebuilt only when the touched vertex or the contact changes, its positions are a function of
// the force (written when read), and only the vertices still relaxing are integrated.

#include "engine/models/slopering/CandidateCache.h"
#include "engine/models/slopering/SlopeRingModel.h"

#include <cstdint>
#include <vector>

namespace palpate {

class CoherentSlopeRing final : public SlopeRingModel {
public:
    /// `mesh` and `octree` must outlive the model. Throws std::invalid_argument on bad params.
    /// `eagerPositions` writes the active rings' positions every tick instead of when they are
    /// read; the benchmark reports both.
    CoherentSlopeRing(const TissueMesh& mesh, const Octree& octree, const SlopeRingParams& params,
                      bool eagerPositions = false);

    TickResult step(const glm::vec3& toolTipMm, double dtS) override;
    /// Current positions; the active rings are written here, on demand (not real-time: call from
    /// the thread that steps, at display rate).
    std::span<const glm::vec3> positionsMm() const override;
    void reset() override;
    std::size_t copyDisplaced(VertexId* ids, glm::vec3* positionsMm, std::uint8_t* rings,
                              std::size_t capacity) const override;
    /// Runs the search for the last tool position (a read-only pass over the search's and the
    /// active set's memory; only the search's caches change).
    void warm(const glm::vec3& lastToolTipMm) const override;
    VertexId findTouched(const glm::vec3& toolTipMm) const override;

    /// Every vertex that may be away from rest (the active rings and those relaxing). Not real-time.
    std::span<const VertexId> displacedVertices() const override;
    /// A stiffer inclusion (engine/scoring's find-the-lump exercises): one factor per vertex in
    /// (0, 1] that scales every ring slope while that vertex is the touched one, with the return
    /// spring of the touched vertex stiffened by its inverse, so the rendered force for a given
    /// depth grows (docs/scoring.md). Empty clears it. Not real-time; throws std::invalid_argument
    /// naming the problem.
    void setCompliance(std::vector<float> factors);
    std::span<const float> compliance() const { return mCompliance; }
    /// Search statistics: how often the candidate cache was retaken, and how often the full octree
    /// search was needed.
    std::size_t cacheRefreshes() const { return mCache.refreshes(); }
    std::size_t fullSearches() const { return mCache.fullSearches(); }

protected:
    /// Always real-time: the active set is sized for every ring count.
    bool canTakeParams(const SlopeRingParams&) const override { return true; }
    void paramsReplaced(bool ringsChanged) override;

private:
    VertexId search(const glm::vec3& tool) const;
    void searchActive(const glm::vec3& tool, VertexId& best, float& best2) const;
    void writeActivePositions() const;
    void changeActiveSet(VertexId touched, bool contact);
    void releaseActiveSet();
    void stepRings(VertexId touched, bool contact);
    void addRelaxing(VertexId v);
    void removeRelaxing(VertexId v);

    bool mEagerPositions;
    std::vector<float> mCompliance;  // per-vertex slope factor (setCompliance); empty: all 1, skipped

    // The active set (rings of the touched vertex in contact) with a copy of its rest positions in
    // structure-of-arrays form for the search, and the vertices still relaxing.
    RingSet mActive, mNextActive;
    std::vector<float> mActiveRestX, mActiveRestY, mActiveRestZ;
    VertexId mActiveCentre = kNoVertex;
    bool mActiveContact = false;
    glm::vec3 mActiveNormal{0.0f};
    float mActiveForceN = 0.0f;         // the force the active positions follow
    mutable bool mActiveDirty = false;  // mutable with mPositions: active positions not yet written for the force
    std::vector<std::uint32_t> mActiveStamp;
    std::uint32_t mActiveGeneration = 1;
    std::vector<VertexId> mRelaxing;
    std::size_t mRelaxingCount = 0;
    std::vector<std::uint32_t> mRelaxingSlot;

    // The search's memory of the last full scan of the active set: its nearest vertex and the
    // margin to the runner-up. Until the tool and the force have moved more than that margin
    // allows, the nearest active vertex cannot change and one distance replaces the scan. Search
    // state, updated by the const searches (findTouched, warm): hence mutable, as mCache.
    struct ActiveScan {
        bool valid = false;
        glm::vec3 toolMm{0.0f};
        float forceN = 0.0f;
        std::uint32_t best = 0;  // index into mActive
        int bestRing = 0;
        float secondMm = 0.0f;            // runner-up distance at the scan
        std::vector<float> distance2Mm2;  // scratch of the full scan, one per active vertex
    };
    mutable ActiveScan mActiveScan;
    // The candidate cache of the rest vertices (CandidateCache.h): search state, see above.
    mutable CandidateCache mCache;
    // The full-search fallback's list of displaced vertices (displacedVertices() const), reserved
    // for every vertex so that it never allocates in the tick.
    mutable std::vector<VertexId> mDisplacedScratch;
};

}  // namespace palpate
