#pragma once
// The paper's three configurations of the slope-ring model, as published (docs/method.md):
// previous (linear nearest-vertex search, whole model processed every tick), hybrid (the paper's
// octree searchNode, whole model) and proposed (searchNode, only the rings processed). Rings are
// precomputed per vertex (nodes[t].firstRing, .secondRing, ...). The formulas are the shared ones
// of SlopeRingModel; only the search and the work per tick are the paper's.

#include "engine/models/slopering/SlopeRingModel.h"

#include <cstdint>
#include <vector>

namespace palpate {

class PaperSlopeRing final : public SlopeRingModel {
public:
    /// `mesh` and `octree` must outlive the model. `method` is previous, hybrid or proposed.
    /// Throws std::invalid_argument on bad params or another method.
    PaperSlopeRing(const TissueMesh& mesh, const Octree& octree, const SlopeRingParams& params, SlopeRingMethod method);

    TickResult step(const glm::vec3& toolTipMm, double dtS) override;
    void reset() override;
    std::size_t copyDisplaced(VertexId* ids, glm::vec3* positionsMm, std::uint8_t* rings,
                              std::size_t capacity) const override;
    VertexId findTouched(const glm::vec3& toolTipMm) const override;

protected:
    /// Real-time only while the ring count is unchanged (the precomputed rings would be rebuilt).
    bool canTakeParams(const SlopeRingParams& params) const override { return params.ringCount == mParams.ringCount; }
    void paramsReplaced(bool ringsChanged) override;

private:
    void precomputeRingLists();
    void stepWholeModel(VertexId touched, bool contact);
    void stepProposed(VertexId touched, bool contact);

    std::vector<std::vector<std::vector<VertexId>>> mRingLists;  // [vertex][ring-1]
    std::vector<std::uint8_t> mRingOf;                           // whole model: ring index per vertex this tick
    std::vector<VertexId> mPreviousRingVertices;                 // proposed: what to restore next tick
};

}  // namespace palpate
