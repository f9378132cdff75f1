#include "engine/models/FfdLattice.h"

#include <stdexcept>
#include <string>

namespace palpate {

FfdLattice::FfdLattice(const glm::dvec3& minMm, const glm::dvec3& maxMm, int pointsPerAxis)
    : mMinMm(minMm), mSizeMm(maxMm - minMm), mPoints(pointsPerAxis) {
    if (pointsPerAxis < 2 || pointsPerAxis > 64)
        throw std::invalid_argument("FFD lattice: needs 2..64 control points per axis, not " + std::to_string(pointsPerAxis));
    if (!(mSizeMm.x > 0.0 && mSizeMm.y > 0.0 && mSizeMm.z > 0.0))
        throw std::invalid_argument("FFD lattice: the box must have a positive size on every axis");
}

glm::dvec3 FfdLattice::latticeCoordinates(const glm::dvec3& p) const { return (p - mMinMm) / mSizeMm; }

glm::dvec3 FfdLattice::restControlPoint(int i, int j, int k) const {
    const double d = double(degree());
    return mMinMm + mSizeMm * glm::dvec3(double(i) / d, double(j) / d, double(k) / d);
}

std::vector<glm::dvec3> FfdLattice::restControlPoints() const {
    std::vector<glm::dvec3> points(controlPointCount());
    for (int i = 0; i < mPoints; ++i)
        for (int j = 0; j < mPoints; ++j)
            for (int k = 0; k < mPoints; ++k) points[index(i, j, k)] = restControlPoint(i, j, k);
    return points;
}

void FfdLattice::bernstein(int degree, double s, double* out) {
    // out[i] after pass j holds B_i^j(s); B_i^j = (1 - s) B_i^(j-1) + s B_(i-1)^(j-1).
    out[0] = 1.0;
    for (int j = 1; j <= degree; ++j) {
        out[j] = s * out[j - 1];
        for (int i = j - 1; i >= 1; --i) out[i] = (1.0 - s) * out[i] + s * out[i - 1];
        out[0] = (1.0 - s) * out[0];
    }
}

glm::dvec3 FfdLattice::evaluate(const glm::dvec3& stu, std::span<const glm::dvec3> controlPoints) const {
    if (controlPoints.size() != controlPointCount()) throw std::invalid_argument("FFD lattice: wrong number of control points");
    double bs[64], bt[64], bu[64];
    bernstein(degree(), stu.x, bs);
    bernstein(degree(), stu.y, bt);
    bernstein(degree(), stu.z, bu);
    glm::dvec3 x(0.0);
    for (int i = 0; i < mPoints; ++i)
        for (int j = 0; j < mPoints; ++j) {
            const double bij = bs[i] * bt[j];
            for (int k = 0; k < mPoints; ++k) x += (bij * bu[k]) * controlPoints[index(i, j, k)];
        }
    return x;
}

}  // namespace palpate
