#include "engine/models/RadiusOfInfluenceModel.h"

#include "engine/models/OctreeQueries.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>

namespace palpate {

RadiusOfInfluenceModel::RadiusOfInfluenceModel(const TissueMesh& mesh, const Octree& octree,
                                               const RadiusOfInfluenceParams& params)
    : mMesh(mesh), mOctree(octree), mParams(params) {
    const auto errors = validateRadiusOfInfluenceParams(params);
    if (!errors.empty()) {
        std::string text = "invalid radius-of-influence parameters:";
        for (const auto& e : errors) text += "\n  " + e.message;
        throw std::invalid_argument(text);
    }
    for (int k = 0; k <= params.degree; ++k) mCoefficients[k] = float(params.coefficients[std::size_t(k)]);
    mRadiusMm = float(params.radiusMm);
    mStiffness = float(params.stiffnessNPerMm);
    mPositions = mesh.restPositionsMm();
    mInfluenced.resize(mesh.vertexCount());
    mProfile.resize(mesh.vertexCount());
}

void RadiusOfInfluenceModel::reset() {
    std::copy(mMesh.restPositionsMm().begin(), mMesh.restPositionsMm().end(), mPositions.begin());
    mInfluencedCount = 0;
    mActive = false;
    mCentre = kNoVertex;
    mTouched = kNoVertex;
    mContact = false;
    mMaxDisplacementMm = 0.0f;
}

void RadiusOfInfluenceModel::release() {
    const auto& rest = mMesh.restPositionsMm();
    if (mActive)
        for (std::size_t i = 0; i < mInfluencedCount; ++i) mPositions[mInfluenced[i]] = rest[mInfluenced[i]];
    mActive = false;
    mMaxDisplacementMm = 0.0f;
}

void RadiusOfInfluenceModel::collect(VertexId touched) {
    // Euclidean distance between rest positions, through the octree: vertices across a fold of the
    // surface are influenced too (the model ignores topology, as Basdogan's).
    const auto& rest = mMesh.restPositionsMm();
    const glm::vec3 centre = rest[touched];
    mInfluencedCount = restVerticesWithinRadius(mOctree, rest, centre, mRadiusMm, mInfluenced.data(), mInfluenced.size());
    const int degree = mParams.degree;
    mMaxAbsProfile = 0.0f;
    for (std::size_t i = 0; i < mInfluencedCount; ++i) {
        const float rho = glm::length(rest[mInfluenced[i]] - centre) / mRadiusMm;
        float phi = 0.0f;
        for (int k = degree; k >= 0; --k) phi = phi * rho + mCoefficients[k];
        mProfile[i] = phi;
        mMaxAbsProfile = std::max(mMaxAbsProfile, std::fabs(phi));
    }
    mCentre = touched;
    mNormal = mMesh.restNormals()[touched];
    mActive = true;
}

TickResult RadiusOfInfluenceModel::step(const glm::vec3& tool, double /*dtS*/) {
    const bool toolValid = std::isfinite(tool.x) && std::isfinite(tool.y) && std::isfinite(tool.z);
    const auto& rest = mMesh.restPositionsMm();
    VertexId touched = mTouched;
    if (toolValid) {
        const VertexId found = nearestWithBoundedDisplacement(mOctree, tool, mPositions, mMaxDisplacementMm, mTouched);
        if (found != kNoVertex) touched = found;
    }
    TickResult result;
    result.touched = touched;
    // Contact: the tool tip below the touched vertex's rest position along its rest normal, by depth d.
    float depth = 0.0f;
    if (toolValid && touched != kNoVertex) {
        const glm::vec3 n = mMesh.restNormals()[touched];
        depth = glm::dot(rest[touched] - tool, n);
        result.penetrationMm = glm::dot(mPositions[touched] - tool, n);
    }
    const bool contact = toolValid && touched != kNoVertex && depth > 0.0f;
    if (contact) {
        if (!mActive || touched != mCentre) {
            release();
            collect(touched);
        }
        // p_v = rest_v - d phi_v n: the touched vertex (phi = 1) lands on the tool's depth.
        for (std::size_t i = 0; i < mInfluencedCount; ++i) {
            const VertexId v = mInfluenced[i];
            mPositions[v] = rest[v] - (depth * mProfile[i]) * mNormal;
        }
        mMaxDisplacementMm = depth * mMaxAbsProfile;
        result.forceN = (mStiffness * depth) * mNormal;  // k_s times the touched vertex's displacement
    } else if (mActive) {
        release();
    }
    mTouched = touched;
    mContact = contact;
    result.contact = contact;
    return result;
}

std::size_t RadiusOfInfluenceModel::copyDisplaced(VertexId* ids, glm::vec3* positionsMm, std::uint8_t* rings,
                                                  std::size_t capacity) const {
    if (!mActive) return 0;
    const auto& rest = mMesh.restPositionsMm();
    std::size_t count = 0;
    for (std::size_t i = 0; i < mInfluencedCount; ++i) {
        const VertexId v = mInfluenced[i];
        if (mPositions[v] == rest[v]) continue;
        if (count < capacity) {
            ids[count] = v;
            positionsMm[count] = mPositions[v];
            rings[count] = v == mCentre ? 0 : 1;  // no rings here: 0 the touched vertex, 1 the rest of the dent
        }
        ++count;
    }
    return count;
}

}  // namespace palpate
