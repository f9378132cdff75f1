#pragma once
// The slope-ring model: the touched vertex and its rings move by p = p_rest + m_r F (the paper's
// Eq. (1)-(3), m_r < 0), return springs tie them to rest, and the touched vertex's spring
// reaction is the force rendered. One class runs the paper's three configurations and ours, so
// that they share every formula and differ only in search and in how much work a tick does.

#include "engine/DeformationModel.h"
#include "engine/Octree.h"
#include "engine/Rings.h"
#include "engine/SlopeRingMethod.h"
#include "engine/SlopeRingParams.h"

#include <memory>
#include <vector>

namespace palpate {

class SlopeRingDeformer final : public DeformationModel {
public:
    /// `mesh` and `octree` must outlive the deformer. Throws std::invalid_argument on bad params.
    SlopeRingDeformer(const TissueMesh& mesh, const Octree& octree, const SlopeRingParams& params,
                      SlopeRingMethod method = SlopeRingMethod::Palpate);

    TickResult step(const glm::vec3& toolTipMm, double dtS) override;
    std::span<const glm::vec3> positionsMm() const override { return mPositions; }
    void reset() override;
    std::string name() const override;

    /// Replaces the parameters (validated first; throws std::invalid_argument listing every problem).
    /// Not real-time: may precompute rings.
    void setParams(const SlopeRingParams& params);
    const SlopeRingParams& params() const { return mParams; }
    SlopeRingMethod method() const { return mMethod; }

    /// The touched vertex this method's search would report now, without changing state
    /// (kNoVertex where the paper's searchNode finds nothing).
    VertexId findTouched(const glm::vec3& toolTipMm) const;
    VertexId touchedVertex() const { return mTouched; }

    /// Contact force magnitude of the slope model (N), before the spring rendering.
    float contactForceN() const { return mForceN; }
    /// Vertices currently away from rest (the active rings and those still relaxing).
    std::span<const VertexId> displacedVertices() const { return {mDisplaced.data(), mDisplacedCount}; }

private:
    void applyParams();
    VertexId searchPalpate(const glm::vec3& tool) const;
    void stepPalpate(const glm::vec3& tool, VertexId touched, bool contact);
    void stepWholeModel(VertexId touched, bool contact);
    void stepProposed(VertexId touched, bool contact);
    void relaxVertex(VertexId v);
    void addDisplaced(VertexId v);
    void precomputeRingLists();

    const TissueMesh& mMesh;
    const Octree& mOctree;
    SlopeRingParams mParams;
    SlopeRingMethod mMethod;

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

    std::vector<glm::vec3> mPositions;
    std::vector<glm::vec3> mVelocitiesMmPerS;

    // State of the contact.
    VertexId mTouched = kNoVertex;
    float mForceN = 0.0f;
    bool mContact = false;

    // Palpate: the active ring set and the list of displaced vertices (active or relaxing).
    RingFinder mRingFinder;
    RingSet mActive;
    VertexId mActiveCentre = kNoVertex;
    bool mActiveContact = false;
    float mWrittenForceN = -1.0f;
    std::vector<std::uint32_t> mActiveStamp;
    std::uint32_t mActiveGeneration = 1;
    std::vector<VertexId> mDisplaced;
    std::size_t mDisplacedCount = 0;
    std::vector<std::uint32_t> mDisplacedSlot;

    // The paper's methods: rings precomputed per vertex (nodes[t].firstRing, .secondRing, ...).
    std::vector<std::vector<std::vector<VertexId>>> mRingLists;  // [vertex][ring-1]
    std::vector<std::uint8_t> mRingOf;                           // whole model: ring index per vertex this tick
    std::vector<VertexId> mPreviousRingVertices;                 // proposed: what to restore next tick
};

}  // namespace palpate
