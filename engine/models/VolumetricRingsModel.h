#pragma once
// The slope-ring model on a tetrahedral mesh (the paper's future work): the touched surface vertex's
// rings are taken in the tet mesh's edge graph, so a ring reaches through the interior; every node
// of ring r moves by m_r F along the touched vertex's rest normal, exactly as on the surface
// (docs/method.md: the same contact-force update, return springs and rendered spring reaction).
// The tet mesh's first nodes are the surface vertices in the TissueMesh's order, so the surface
// shown, searched and measured is those nodes' positions.

#include "engine/models/DeformationModel.h"
#include "engine/core/Octree.h"
#include "engine/fem/TetMesh.h"
#include "engine/models/VolumetricRingsParams.h"

#include <vector>

namespace palpate {

class VolumetricRingsModel final : public DeformationModel {
public:
    /// `mesh` and `octree` must outlive the model; `tets` is copied. Its nodes 0..n-1 must be the
    /// mesh's vertices (within 1e-3 mm). Throws std::invalid_argument on bad params or a tet mesh
    /// that does not fit the surface.
    VolumetricRingsModel(const TissueMesh& mesh, const Octree& octree, const TetMesh& tets,
                         const VolumetricRingsParams& params);

    TickResult step(const glm::vec3& toolTipMm, double dtS) override;
    /// The surface: the first n nodes.
    std::span<const glm::vec3> positionsMm() const override { return {mNodePositions.data(), mSurfaceCount}; }
    void reset() override;
    std::string name() const override { return "volumetric-rings"; }
    std::size_t copyDisplaced(VertexId* ids, glm::vec3* positionsMm, std::uint8_t* rings,
                              std::size_t capacity) const override;
    /// Real-time: the rings are found into buffers sized for the whole tet mesh, so any ring count fits.
    /// Real-time: takes a volumetric-rings definition (any ring count: the active set is sized for all).
    bool applyModelParams(const ModelDef& def) override;

    const VolumetricRingsParams& params() const { return mParams; }
    /// Every node (surface first, then interior), mm.
    std::span<const glm::vec3> nodePositionsMm() const { return mNodePositions; }
    std::size_t nodeCount() const { return mNodePositions.size(); }
    /// Edge-graph neighbours of a tet node.
    std::span<const std::uint32_t> nodeNeighbours(std::uint32_t node) const {
        return {mNeighbours.data() + mNeighbourStart[node], mNeighbours.data() + mNeighbourStart[node + 1]};
    }
    /// The active rings' nodes, ring r being [ringStart(r), ringStart(r + 1)).
    std::span<const std::uint32_t> activeNodes() const { return {mActive.data(), mActiveContact ? mActiveCount : 0}; }
    std::uint32_t activeRingStart(int r) const { return mActiveRingStart[r]; }
    int activeRingCount() const { return mActiveRingCount; }
    float contactForceN() const { return mForceN; }

private:
    void applyParams();
    void findRings(std::uint32_t centre, int ringCount);
    void changeActiveSet(VertexId touched, bool contact);
    void addRelaxing(std::uint32_t node);
    void removeRelaxing(std::uint32_t node);

    const TissueMesh& mMesh;
    const Octree& mOctree;
    VolumetricRingsParams mParams;
    std::size_t mSurfaceCount = 0;

    // The tet mesh's edge graph, compressed.
    std::vector<std::uint32_t> mNeighbourStart;
    std::vector<std::uint32_t> mNeighbours;
    std::vector<glm::vec3> mNodeRest;
    std::vector<glm::vec3> mNodePositions;
    std::vector<glm::vec3> mNodeVelocities;

    // Hot constants (as SlopeRingModel's).
    SlopeRingConstants mHot;  // what the tick reads, derived from mParams.slopeRing

    // The active rings (breadth-first in the tet graph), generation-stamped membership.
    std::vector<std::uint32_t> mActive;
    std::uint32_t mActiveRingStart[kMaxRings + 2] = {};
    int mActiveRingCount = 0;
    std::size_t mActiveCount = 0;
    std::vector<std::uint32_t> mStamp;
    std::uint32_t mGeneration = 1;
    VertexId mActiveCentre = kNoVertex;
    bool mActiveContact = false;
    glm::vec3 mActiveNormal{0.0f};
    // Scratch for the breadth-first walk and for nodes leaving the active set.
    std::vector<std::uint32_t> mPrevious;
    std::size_t mPreviousCount = 0;
    std::vector<std::uint32_t> mRelaxing;
    std::size_t mRelaxingCount = 0;
    std::vector<std::uint32_t> mRelaxingSlot;

    VertexId mTouched = kNoVertex;
    float mForceN = 0.0f;
    bool mContact = false;
    float mMaxSurfaceDisplacementMm = 0.0f;
};

}  // namespace palpate
