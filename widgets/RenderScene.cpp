#include "widgets/RenderScene.h"

#include "widgets/SceneStyle.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace palpate {

void RenderScene::setMesh(const TissueMesh& mesh) {
    mIndices.clear();
    mIndices.reserve(3 * mesh.triangleCount());
    for (const auto& t : mesh.triangles()) mIndices.insert(mIndices.end(), t.begin(), t.end());
    mRestMm = mesh.restPositionsMm();
    mPositionsMm = mRestMm;
    mPressedWeights.assign(mRestMm.size(), 0.0f);
    mBoundsMinMm = mesh.boundsMinMm();
    mBoundsMaxMm = mesh.boundsMaxMm();
    mTouched = kNoVertex;
    mContact = false;
    mHasTool = false;
    mToolTipMm = glm::vec3(0.0f);
    mForceN = glm::vec3(0.0f);
}

void RenderScene::clear() { *this = RenderScene(); }

void RenderScene::setSnapshot(const SceneSnapshot& snapshot) {
    if (snapshot.positionsMm.size() == mRestMm.size()) {
        mPositionsMm = snapshot.positionsMm;
        for (std::size_t v = 0; v < mRestMm.size(); ++v) {
            const float displacementMm = glm::length(mPositionsMm[v] - mRestMm[v]);
            mPressedWeights[v] = std::min(displacementMm / style::kFullTintDisplacementMm, 1.0f);
        }
    }
    mTouched = snapshot.touched < mRestMm.size() ? snapshot.touched : kNoVertex;
    mContact = snapshot.contact && mTouched != kNoVertex;
    mHasTool = snapshot.hasTool;
    mToolTipMm = snapshot.toolTipMm;
    mForceN = snapshot.forceN;
}

void RenderScene::computeVertexNormals(std::vector<glm::vec3>& normals) const {
    normals.assign(mPositionsMm.size(), glm::vec3(0.0f));
    for (std::size_t i = 0; i + 2 < mIndices.size(); i += 3) {
        const std::uint32_t a = mIndices[i], b = mIndices[i + 1], c = mIndices[i + 2];
        // The cross product's length is twice the area: larger triangles weigh more, for free.
        const glm::vec3 n = glm::cross(mPositionsMm[b] - mPositionsMm[a], mPositionsMm[c] - mPositionsMm[a]);
        normals[a] += n;
        normals[b] += n;
        normals[c] += n;
    }
    for (auto& n : normals) {
        const float length = glm::length(n);
        n = length > 0.0f ? n / length : glm::vec3(0.0f, 0.0f, 1.0f);
    }
}

float RenderScene::diagonalMm() const { return glm::length(mBoundsMaxMm - mBoundsMinMm); }

}  // namespace palpate
