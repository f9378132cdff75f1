#pragma once
// The scene as the viewports draw it: the mesh's topology and rest shape, copied so that a viewport
// never refers to a mesh that was replaced, plus the latest snapshot and what is derived from it.
// It also remembers which vertices changed since a renderer last took them (dirtyVertices), so the
// OpenGL viewport can upload only those ranges of its vertex buffer.

#include "widgets/SceneSnapshot.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace palpate {

/// Vertices [first, first + count).
struct VertexRange {
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    bool operator==(const VertexRange&) const = default;
};

/// Sorts `ids` (in place, duplicates allowed) and writes the runs of consecutive ids to `ranges`,
/// merging runs separated by at most `maxGap` ids (re-sending a few unchanged vertices is cheaper
/// than another buffer call). Clears `ranges` first.
void coalesceVertexRanges(std::vector<VertexId>& ids, std::uint32_t maxGap, std::vector<VertexRange>& ranges);

class RenderScene {
public:
    /// Copies the mesh; the current shape becomes the rest shape and the tool disappears.
    void setMesh(const TissueMesh& mesh);
    void clear();
    /// Takes the snapshot's tool and contact; positions and rings only when their count matches
    /// the mesh. When the snapshot is the version after the last one taken, only its `changed`
    /// vertices are read; otherwise all of them.
    void setSnapshot(const SceneSnapshot& snapshot);

    bool empty() const { return mIndices.empty(); }
    std::size_t vertexCount() const { return mRestMm.size(); }
    std::size_t triangleCount() const { return mIndices.size() / 3; }
    /// Three vertex indices per triangle.
    std::span<const std::uint32_t> indices() const { return mIndices; }
    std::span<const glm::vec3> positionsMm() const { return mPositionsMm; }
    std::span<const glm::vec3> restPositionsMm() const { return mRestMm; }
    /// Per vertex in [0, 1]: how pressed it looks (displacement from rest, see style::kFullTintDisplacementMm).
    std::span<const float> pressedWeights() const { return mPressedWeights; }
    /// Per vertex: its ring of the touched vertex (0 = touched), or kNoRing.
    std::span<const std::uint8_t> rings() const { return mRings; }
    /// The ring a triangle is drawn in: the lowest ring among its corners (kNoRing if none).
    std::uint8_t triangleRing(std::size_t triangle) const;
    /// How many vertices are in ring `ring` now (0 = the touched vertex).
    std::uint32_t ringVertexCount(std::uint8_t ring) const { return mRingCounts[ring]; }
    /// The highest ring index (0..8) with a vertex in it, or -1 when no vertex is in a ring.
    int highestRing() const;
    /// The triangles around vertex `v` (each once, increasing).
    std::span<const std::uint32_t> vertexTriangles(VertexId v) const;

    /// Area-weighted vertex normals of the current shape (the deformed surface must shade as deformed).
    void computeVertexNormals(std::vector<glm::vec3>& normals) const;
    /// Recomputes, in `normals` (sized by an earlier computeVertexNormals), the normals that the
    /// dirty vertices can have changed: those of the dirty vertices and of every corner of a
    /// triangle around one. Lists them in `recomputed` (each once; so every dirty vertex is there).
    /// The result equals computeVertexNormals bit for bit. With `normals` of the wrong size, all.
    void updateVertexNormals(std::vector<glm::vec3>& normals, std::vector<VertexId>& recomputed);

    /// Vertices whose position, pressed weight or ring changed since clearDirty(), each once; when
    /// allDirty() the list is not kept (a new mesh, or a snapshot that had to be read whole).
    std::span<const VertexId> dirtyVertices() const { return mDirty; }
    bool allDirty() const { return mAllDirty; }
    void clearDirty();

    /// The nearest triangle hit by the ray (origin, direction), and on it the corner nearest to the
    /// hit point; nullopt when the ray misses the mesh. Uses the current (deformed) positions.
    std::optional<VertexId> pick(const glm::vec3& originMm, const glm::vec3& direction) const;

    /// The touched vertex while in contact, else kNoVertex: without contact nothing is highlighted.
    VertexId touched() const { return mContact ? mTouched : kNoVertex; }
    bool contact() const { return mContact; }
    bool hasTool() const { return mHasTool; }
    glm::vec3 toolTipMm() const { return mToolTipMm; }
    /// The tool's radius (0: a point) and where it is held on the tissue (its proxy).
    float toolRadiusMm() const { return mToolRadiusMm; }
    glm::vec3 proxyMm() const { return mProxyMm; }
    glm::vec3 forceN() const { return mForceN; }

    /// Whether every edge joins exactly two triangles that run it in opposite directions (a closed,
    /// consistently wound surface). Seen from outside, only its front faces can be nearest: the
    /// renderers skip the back faces (half the triangles) on such a mesh.
    bool closedAndConsistent() const { return mOutwardWinding != 0; }
    /// +1 when the triangles wind counter-clockwise seen from outside (positive enclosed volume),
    /// -1 when clockwise, 0 when the mesh is not closedAndConsistent().
    int outwardWinding() const { return mOutwardWinding; }
    /// Whether `eyeMm` is outside the rest and current bounds (with a margin): then back faces are hidden.
    bool outside(const glm::vec3& eyeMm) const;

    glm::vec3 boundsMinMm() const { return mBoundsMinMm; }
    glm::vec3 boundsMaxMm() const { return mBoundsMaxMm; }
    float diagonalMm() const;

private:
    void markDirty(VertexId v);
    void markAllDirty();
    void setRing(VertexId v, std::uint8_t ring);
    glm::vec3 vertexNormal(VertexId v) const;
    int computeOutwardWinding() const;

    std::vector<std::uint32_t> mIndices;
    std::vector<glm::vec3> mRestMm;
    std::vector<glm::vec3> mPositionsMm;
    std::vector<float> mPressedWeights;
    std::vector<std::uint8_t> mRings;
    std::array<std::uint32_t, 256> mRingCounts{};
    // Triangles around each vertex, compressed: those of v are mVertexTriangles[start[v] .. start[v+1]).
    std::vector<std::uint32_t> mVertexTriangleStart;
    std::vector<std::uint32_t> mVertexTriangles;
    int mOutwardWinding = 0;
    glm::vec3 mBoundsMinMm{0.0f};
    glm::vec3 mBoundsMaxMm{0.0f};
    std::uint64_t mVersion = 0;  // of the last snapshot taken; 0: none (read the next one whole)

    std::vector<VertexId> mDirty;
    std::vector<std::uint32_t> mDirtyStamp;  // per vertex: == mDirtyGeneration when in mDirty
    std::uint32_t mDirtyGeneration = 1;
    bool mAllDirty = true;
    std::vector<std::uint32_t> mNormalStamp;  // scratch of updateVertexNormals
    std::uint32_t mNormalGeneration = 0;

    VertexId mTouched = kNoVertex;
    bool mContact = false;
    bool mHasTool = false;
    glm::vec3 mToolTipMm{0.0f};
    float mToolRadiusMm = 0.0f;
    glm::vec3 mProxyMm{0.0f};
    glm::vec3 mForceN{0.0f};
};

}  // namespace palpate
