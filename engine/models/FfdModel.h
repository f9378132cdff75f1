#pragma once
// Free-form deformation (Sederberg and Parry 1986) as a haptic model: the mesh is embedded in a
// Bernstein lattice (FfdLattice); while the tool presses, the block of control points nearest the
// contact moves by the least-norm displacement that puts the touched vertex on the tool's depth
// along its rest normal, and every vertex follows the lattice. Geometric, not dynamic: the dent is
// a function of the contact. Bernstein functions reach the whole lattice, so a tick is O(n).

#include "engine/models/DeformationModel.h"
#include "engine/core/Octree.h"
#include "engine/models/FfdLattice.h"
#include "engine/models/FfdParams.h"

#include <vector>

namespace palpate {

class FfdModel final : public DeformationModel {
public:
    /// `mesh` and `octree` must outlive the model. Throws std::invalid_argument on bad params.
    FfdModel(const TissueMesh& mesh, const Octree& octree, const FfdParams& params);

    TickResult step(const glm::vec3& toolTipMm, double dtS) override;
    std::span<const glm::vec3> positionsMm() const override { return mPositions; }
    void reset() override;
    std::string name() const override { return "ffd"; }
    std::size_t copyDisplaced(VertexId* ids, glm::vec3* positionsMm, std::uint8_t* rings,
                              std::size_t capacity) const override;

    const FfdParams& params() const { return mParams; }
    const FfdLattice& lattice() const { return mLattice; }
    /// Each control point's displacement now (lattice index order), mm. Not real-time.
    std::vector<glm::dvec3> controlPointDisplacementsMm() const;
    /// The touched vertex's lattice coordinates (s, t, u) in [0, 1]^3.
    glm::dvec3 latticeCoordinatesOf(VertexId v) const;

private:
    void shapeFor(VertexId touched);
    void release();

    const TissueMesh& mMesh;
    const Octree& mOctree;
    FfdParams mParams;
    FfdLattice mLattice;
    int mPoints = 0;
    int mMoved = 0;

    // Per vertex, the Bernstein values along each axis: [v][axis][i], float.
    std::vector<float> mBasis;
    // Per vertex, how far it moves per mm of the touched vertex's displacement, for the current
    // touched vertex: s_v = prod_axis (sum_a B_a(v) B_a(t)) / prod_axis (sum_a B_a(t)^2), a over the moved block.
    std::vector<float> mShape;
    float mMaxAbsShape = 0.0f;
    int mBlockStart[3] = {0, 0, 0};
    double mBlockScale = 0.0;  // 1 / sum over the block of w^2

    std::vector<glm::vec3> mPositions;
    bool mActive = false;  // positions are displaced
    VertexId mCentre = kNoVertex;
    glm::vec3 mDisplacementMm{0.0f};  // the touched vertex's displacement D

    VertexId mTouched = kNoVertex;
    bool mContact = false;
    float mMaxDisplacementMm = 0.0f;
};

}  // namespace palpate
