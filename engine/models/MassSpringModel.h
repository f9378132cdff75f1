#pragma once
// The mass-spring model, the paper's physics-based family (docs/models.md): a mass per vertex,
// springs along the mesh edges and to rest positions, a penalty contact on the touched vertex,
// integrated by symplectic Euler, RK4 or backward Euler (Baraff-Witkin, solved by our own
// conjugate gradients on preallocated vectors). The whole-model variant simulates every vertex
// every tick (O(n), its point on the chart); the local variant only the touched vertex's rings and
// the vertices still moving, with everything else pinned at rest. Both share every formula.

#include "engine/models/DeformationModel.h"
#include "engine/core/Octree.h"
#include "engine/core/Rings.h"
#include "engine/models/MassSpringParams.h"

#include <vector>

namespace palpate {

enum class MassSpringScope {
    Whole,  ///< every vertex, every tick
    Local,  ///< the touched vertex's rings (MassSpringParams::localRingCount) and what still moves
};

class MassSpringModel final : public DeformationModel {
public:
    /// `mesh` and `octree` must outlive the model. Throws std::invalid_argument on bad params.
    MassSpringModel(const TissueMesh& mesh, const Octree& octree, const MassSpringParams& params,
                    MassSpringIntegrator integrator, MassSpringScope scope);

    TickResult step(const glm::vec3& toolTipMm, double dtS) override;
    std::span<const glm::vec3> positionsMm() const override { return mPositions; }
    void reset() override;
    std::string name() const override;
    std::size_t copyDisplaced(VertexId* ids, glm::vec3* positionsMm, std::uint8_t* rings,
                              std::size_t capacity) const override;

    const MassSpringParams& params() const { return mParams; }
    MassSpringIntegrator integrator() const { return mIntegrator; }
    MassSpringScope scope() const { return mScope; }

    /// Kinetic energy plus the anchor and edge springs' energy, mJ (N mm); the contact penalty is
    /// not included. For the integrators' tests.
    double energyMilliJ() const;
    /// Puts a vertex at rest + displacement with a velocity (tests, scripted perturbations). Not real-time.
    void setVertexState(VertexId v, const glm::vec3& displacementMm, const glm::vec3& velocityMmPerS);
    /// Displacement from rest (mm) and velocity (mm/s) of every vertex.
    std::span<const glm::vec3> displacementsMm() const { return mU; }
    std::span<const glm::vec3> velocitiesMmPerS() const { return mW; }
    /// Upper bound of the highest angular frequency (Gershgorin, contact included), rad/s.
    double omegaMaxBoundRadPerS() const { return mOmegaMaxBound; }
    /// Sub-steps a tick of dtS takes (1 for backward Euler).
    int substepsFor(double dtS) const;
    /// Vertices simulated in the last tick (n for the whole model).
    std::size_t simulatedCount() const { return mSetCount; }
    /// Conjugate-gradient iterations of the last backward-Euler solve, and whether it met the tolerance.
    int lastCgIterations() const { return mLastCgIterations; }
    bool lastCgConverged() const { return mLastCgConverged; }
    /// Largest |position - rest| over the mesh after the last tick, mm (the touched-vertex search's bound).
    float maxDisplacementMm() const { return mMaxDisplacementMm; }
    float contactForceN() const { return mContactForceN; }

private:
    struct Contact {
        bool valid = false;  // a touched vertex and a finite tool
        VertexId vertex = kNoVertex;
        glm::vec3 normal{0.0f};
        float depthMm = 0.0f;  // tool below the touched vertex's rest position, along its normal
    };
    glm::vec3 force(const glm::vec3* u, VertexId v, const Contact& contact) const;
    void stepSymplectic(float h, const Contact& contact);
    void stepRk4(float h, const Contact& contact);
    void stepBackwardEuler(float h, const Contact& contact);
    void addToSet(VertexId v);
    void removeFromSetAt(std::size_t slot);
    void updateRings(VertexId touched);

    const TissueMesh& mMesh;
    const Octree& mOctree;
    MassSpringParams mParams;
    MassSpringIntegrator mIntegrator;
    MassSpringScope mScope;

    // Constants of the equations of motion: a = mAccelPerN * f - mGamma * w (mm/s^2, f in N).
    float mAccelPerN = 0.0f;  // 1000 / m
    float mAnchor = 0.0f, mEdge = 0.0f, mContactK = 0.0f, mGamma = 0.0f;
    double mOmegaMaxBound = 0.0;
    std::vector<std::uint32_t> mDegree;

    // State: displacement from rest (mm) and velocity (mm/s) per vertex; zero outside the set.
    std::vector<glm::vec3> mU, mW;
    std::vector<glm::vec3> mPositions;
    // The simulated set (all vertices for the whole model) with each vertex's slot in it.
    std::vector<VertexId> mSet;
    std::vector<std::uint32_t> mSlot;
    std::size_t mSetCount = 0;
    // Work arrays, zero outside the set: RK4 stages (A, B: displacement and velocity; Acc: the
    // weighted sum of slopes) or conjugate gradients (R residual, P direction, Ap = A P).
    std::vector<glm::vec3> mUa, mWa, mUb, mWb, mAccU, mAccW;
    std::vector<glm::vec3> mR, mP, mAp;
    std::vector<float> mInverseDiagonal;  // Jacobi preconditioner for step mInverseDiagonalH
    float mInverseDiagonalH = -1.0f;

    // Local variant: the touched vertex's rings.
    RingFinder mRingFinder;
    RingSet mRings;
    VertexId mRingCentre = kNoVertex;
    std::vector<std::uint8_t> mRingOf;

    VertexId mTouched = kNoVertex;
    bool mContact = false;
    float mContactForceN = 0.0f;
    float mMaxDisplacementMm = 0.0f;
    int mLastCgIterations = 0;
    bool mLastCgConverged = true;
};

}  // namespace palpate
