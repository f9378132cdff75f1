#pragma once
// The radius-of-influence model (Basdogan et al. 1998): while the tool presses, the touched vertex
// follows it along its rest normal by the depth, and every vertex whose rest position is within
// the radius of the touched vertex's moves the same way by phi(distance / radius) times that depth
// (RadiusOfInfluenceParams). Independent of the mesh's edges. Geometric, not dynamic: the dent is a
// function of the contact and disappears with it. Work per tick: the vertices in the radius.

#include "engine/models/DeformationModel.h"
#include "engine/core/Octree.h"
#include "engine/models/RadiusOfInfluenceParams.h"

#include <vector>

namespace palpate {

class RadiusOfInfluenceModel final : public DeformationModel {
public:
    /// `mesh` and `octree` must outlive the model. Throws std::invalid_argument on bad params.
    RadiusOfInfluenceModel(const TissueMesh& mesh, const Octree& octree, const RadiusOfInfluenceParams& params);

    TickResult step(const glm::vec3& toolTipMm, double dtS) override;
    std::span<const glm::vec3> positionsMm() const override { return mPositions; }
    void reset() override;
    std::string name() const override { return "radius-of-influence"; }
    std::size_t copyDisplaced(VertexId* ids, glm::vec3* positionsMm, std::uint8_t* rings,
                              std::size_t capacity) const override;

    const RadiusOfInfluenceParams& params() const { return mParams; }
    /// The vertices the current contact moves (empty without contact).
    std::span<const VertexId> influencedVertices() const { return {mInfluenced.data(), mActive ? mInfluencedCount : 0}; }
    /// The profile value of each influenced vertex, in the same order.
    std::span<const float> influencedProfile() const { return {mProfile.data(), mActive ? mInfluencedCount : 0}; }

private:
    void release();
    void collect(VertexId touched);

    const TissueMesh& mMesh;
    const Octree& mOctree;
    RadiusOfInfluenceParams mParams;
    float mCoefficients[kMaxProfileDegree + 1] = {};
    float mRadiusMm = 0.0f;
    float mStiffness = 0.0f;

    std::vector<glm::vec3> mPositions;
    std::vector<VertexId> mInfluenced;  // capacity: every vertex
    std::vector<float> mProfile;
    std::size_t mInfluencedCount = 0;
    float mMaxAbsProfile = 0.0f;
    bool mActive = false;  // the influenced set is displaced
    VertexId mCentre = kNoVertex;
    glm::vec3 mNormal{0.0f};

    VertexId mTouched = kNoVertex;
    bool mContact = false;
    float mMaxDisplacementMm = 0.0f;
};

}  // namespace palpate
