#pragma once
// The closest point of a triangle surface to a moving point, found by walking from the last
// triangle to its neighbours (docs/method.md, "Contact"): the proxy of a tool stays on the surface
// and moves over it, never jumping through it, and a tick costs one to a few closest-point tests.
// The walk stops at a local minimum of the distance: on a convex surface, or a concave one whose
// creases are wider than the tool's distance to them, that is the closest point.

#include "engine/core/TissueMesh.h"
#include "engine/core/TrianglePoint.h"

#include <cstdint>
#include <vector>

namespace palpate {

using TriangleId = std::uint32_t;
inline constexpr TriangleId kNoTriangle = 0xffffffffu;

/// A point on the surface: a triangle and the weights of its corners.
struct SurfaceHit {
    TriangleId triangle = kNoTriangle;
    TrianglePoint at;
};

class SurfaceWalk {
public:
    /// Builds the adjacency of `mesh`'s triangles (not real-time). `mesh` must outlive the walk.
    explicit SurfaceWalk(const TissueMesh& mesh);

    /// The closest point of the rest surface to `pointMm`, walking from `from` (its triangle must
    /// be valid). Gives up after kMaxSteps moves and returns where it got to (`converged` false).
    /// Real-time safe.
    SurfaceHit walk(const glm::vec3& pointMm, TriangleId from, bool* converged = nullptr) const;
    /// The closest point among the triangles around vertex `v`, then walked from there. Real-time safe.
    SurfaceHit fromVertex(const glm::vec3& pointMm, VertexId v, bool* converged = nullptr) const;

    /// The shaded projection of `pointMm`, walking from `from`: the point c of the surface with
    /// pointMm = c + h N(c), N the rest normals interpolated with c's weights (the normal field
    /// the force is shaded with). Unlike the closest point of a faceted surface, which rests on a
    /// vertex while the point moves through that vertex's normal cone, it moves smoothly with the
    /// point, across edges and vertices alike (docs/method.md, "Our contact"). `converged` false
    /// when no triangle solves it within kMaxSteps (the closest point is returned instead).
    /// Real-time safe.
    /// `startWeights` (optional): a first guess on `from` (last tick's weights), which Newton's
    /// method refines in a step or two instead of starting from the plane's foot.
    SurfaceHit project(const glm::vec3& pointMm, TriangleId from, bool* converged = nullptr,
                       const float* startWeights = nullptr) const;

    /// The triangle across the edge opposite corner k of triangle t (kNoTriangle on a boundary).
    TriangleId across(TriangleId t, int k) const { return mAcross[3 * std::size_t(t) + std::size_t(k)]; }
    /// The triangles around vertex v.
    const TriangleId* fanBegin(VertexId v) const { return mMesh.fanTriangles().data() + mMesh.fanStart()[v]; }
    const TriangleId* fanEnd(VertexId v) const { return mMesh.fanTriangles().data() + mMesh.fanStart()[v + 1]; }

    static constexpr int kMaxSteps = 64;

private:
    TrianglePoint closest(const glm::vec3& p, TriangleId t) const;

    const TissueMesh& mMesh;
    std::vector<TriangleId> mAcross;  // 3 per triangle
};

}  // namespace palpate
