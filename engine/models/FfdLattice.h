#pragma once
// A trivariate Bernstein lattice (Sederberg and Parry 1986): control points P_ijk, i, j, k in
// 0..d, start evenly spaced over a box; a point with lattice coordinates (s, t, u) in [0, 1]^3 maps
// to X = sum_ijk B_i(s) B_j(t) B_k(u) P_ijk, B the degree-d Bernstein polynomials. With the
// control points at rest the map is the identity (Bernstein polynomials reproduce linear
// functions), which is why the embedded mesh is unchanged until a control point moves.

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace palpate {

class FfdLattice {
public:
    /// pointsPerAxis (2..64) control points per axis over the box [minMm, maxMm] (max > min on every axis).
    FfdLattice(const glm::dvec3& minMm, const glm::dvec3& maxMm, int pointsPerAxis);

    int pointsPerAxis() const { return mPoints; }
    int degree() const { return mPoints - 1; }
    std::size_t controlPointCount() const { return std::size_t(mPoints) * mPoints * mPoints; }
    /// Index of P_ijk in control-point arrays.
    std::size_t index(int i, int j, int k) const { return (std::size_t(i) * mPoints + j) * mPoints + k; }

    /// (s, t, u) of a point: in [0, 1]^3 inside the box.
    glm::dvec3 latticeCoordinates(const glm::dvec3& pointMm) const;
    /// P_ijk at rest.
    glm::dvec3 restControlPoint(int i, int j, int k) const;
    std::vector<glm::dvec3> restControlPoints() const;
    /// The map X(s, t, u) for the given control points (controlPointCount() of them, index order).
    glm::dvec3 evaluate(const glm::dvec3& stu, std::span<const glm::dvec3> controlPointsMm) const;

    /// B_0..B_degree at s (stable de Casteljau-style recurrence), into out[0..degree].
    static void bernstein(int degree, double s, double* out);

private:
    glm::dvec3 mMinMm;
    glm::dvec3 mSizeMm;
    int mPoints;
};

}  // namespace palpate
