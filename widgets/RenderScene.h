#pragma once
// The scene as the viewports draw it: the mesh's topology and rest shape, copied so that a viewport
// never refers to a mesh that was replaced, plus the latest snapshot and what is derived from it.

#include "widgets/SceneSnapshot.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace palpate {

class RenderScene {
public:
    /// Copies the mesh; the current shape becomes the rest shape and the tool disappears.
    void setMesh(const TissueMesh& mesh);
    void clear();
    /// Takes the snapshot's tool and contact; positions only when their count matches the mesh.
    void setSnapshot(const SceneSnapshot& snapshot);

    bool empty() const { return mIndices.empty(); }
    std::size_t vertexCount() const { return mRestMm.size(); }
    std::size_t triangleCount() const { return mIndices.size() / 3; }
    /// Three vertex indices per triangle.
    std::span<const std::uint32_t> indices() const { return mIndices; }
    std::span<const glm::vec3> positionsMm() const { return mPositionsMm; }
    /// Per vertex in [0, 1]: how pressed it looks (displacement from rest, see style::kFullTintDisplacementMm).
    std::span<const float> pressedWeights() const { return mPressedWeights; }
    /// Area-weighted vertex normals of the current shape (the deformed surface must shade as deformed).
    void computeVertexNormals(std::vector<glm::vec3>& normals) const;

    /// The touched vertex while in contact, else kNoVertex: without contact nothing is highlighted.
    VertexId touched() const { return mContact ? mTouched : kNoVertex; }
    bool contact() const { return mContact; }
    bool hasTool() const { return mHasTool; }
    glm::vec3 toolTipMm() const { return mToolTipMm; }
    glm::vec3 forceN() const { return mForceN; }

    glm::vec3 boundsMinMm() const { return mBoundsMinMm; }
    glm::vec3 boundsMaxMm() const { return mBoundsMaxMm; }
    float diagonalMm() const;

private:
    std::vector<std::uint32_t> mIndices;
    std::vector<glm::vec3> mRestMm;
    std::vector<glm::vec3> mPositionsMm;
    std::vector<float> mPressedWeights;
    glm::vec3 mBoundsMinMm{0.0f};
    glm::vec3 mBoundsMaxMm{0.0f};
    VertexId mTouched = kNoVertex;
    bool mContact = false;
    bool mHasTool = false;
    glm::vec3 mToolTipMm{0.0f};
    glm::vec3 mForceN{0.0f};
};

}  // namespace palpate
