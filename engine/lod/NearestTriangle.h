#pragma once
// The triangle of a surface nearest to a point, through a uniform grid of triangle boxes: the level
// mapping asks this once per vertex of every level, so a brute-force scan (V x F) would make a
// million-vertex hierarchy take hours. Exact: the search grows shell by shell until no unvisited
// cell can hold a nearer triangle.

#include "engine/core/TissueMesh.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace palpate {

/// The closest point of triangle (a, b, c) to p (Ericson, Real-Time Collision Detection, 5.1.5).
glm::dvec3 closestPointOnTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

class NearestTriangle {
public:
    /// Indexes the rest positions of `mesh`'s triangles. `mesh` must outlive this object.
    explicit NearestTriangle(const TissueMesh& mesh);

    struct Hit {
        std::uint32_t triangle = 0;
        double distanceMm = 0.0;
    };
    /// The nearest triangle (ties: the lower index). Not thread-safe (it keeps a visit stamp).
    Hit nearest(const glm::dvec3& pointMm);

private:
    const TissueMesh& mMesh;
    glm::dvec3 mOriginMm{0.0};
    double mCellMm = 1.0;
    int mDims[3] = {1, 1, 1};
    std::vector<std::uint32_t> mCellStart;  ///< CSR: triangles of cell c are mCellTriangles[mCellStart[c] .. [c+1])
    std::vector<std::uint32_t> mCellTriangles;
    std::vector<std::uint32_t> mStamp;      ///< per triangle: the query that last tested it
    std::uint32_t mQuery = 0;

    int cellIndex(double coordinateMm, int axis) const;
};

}  // namespace palpate
