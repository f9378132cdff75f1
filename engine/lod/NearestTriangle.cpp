#include "engine/lod/NearestTriangle.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace palpate {

glm::dvec3 closestPointOnTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return a;
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denom = 1.0 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

NearestTriangle::NearestTriangle(const TissueMesh& mesh) : mMesh(mesh) {
    const auto& rest = mesh.restPositionsMm();
    const auto& tris = mesh.triangles();
    const glm::dvec3 lo(mesh.boundsMinMm()), hi(mesh.boundsMaxMm());
    // About two triangles per cell along an edge keeps both the lists and the shells short.
    mCellMm = std::max(2.0 * mesh.meanEdgeLengthMm(), glm::length(hi - lo) * 1e-3);
    mOriginMm = lo - glm::dvec3(0.5 * mCellMm);
    for (int a = 0; a < 3; ++a) mDims[a] = std::clamp(int(std::ceil((hi[a] - mOriginMm[a]) / mCellMm)) + 1, 1, 1024);
    const std::size_t cells = std::size_t(mDims[0]) * mDims[1] * mDims[2];

    auto forCells = [&](std::uint32_t t, auto&& visit) {
        glm::dvec3 tlo(rest[tris[t][0]]), thi = tlo;
        for (int k = 1; k < 3; ++k) {
            tlo = glm::min(tlo, glm::dvec3(rest[tris[t][k]]));
            thi = glm::max(thi, glm::dvec3(rest[tris[t][k]]));
        }
        int c0[3], c1[3];
        for (int a = 0; a < 3; ++a) {
            c0[a] = cellIndex(tlo[a], a);
            c1[a] = cellIndex(thi[a], a);
        }
        for (int z = c0[2]; z <= c1[2]; ++z)
            for (int y = c0[1]; y <= c1[1]; ++y)
                for (int x = c0[0]; x <= c1[0]; ++x) visit((std::size_t(z) * mDims[1] + y) * mDims[0] + x);
    };
    mCellStart.assign(cells + 1, 0);
    for (std::uint32_t t = 0; t < tris.size(); ++t) forCells(t, [&](std::size_t c) { ++mCellStart[c + 1]; });
    for (std::size_t c = 0; c < cells; ++c) mCellStart[c + 1] += mCellStart[c];
    mCellTriangles.resize(mCellStart.back());
    std::vector<std::uint32_t> fill(mCellStart.begin(), mCellStart.end() - 1);
    for (std::uint32_t t = 0; t < tris.size(); ++t) forCells(t, [&](std::size_t c) { mCellTriangles[fill[c]++] = t; });
    mStamp.assign(tris.size(), 0);
}

int NearestTriangle::cellIndex(double coordinateMm, int axis) const {
    return std::clamp(int(std::floor((coordinateMm - mOriginMm[axis]) / mCellMm)), 0, mDims[axis] - 1);
}

NearestTriangle::Hit NearestTriangle::nearest(const glm::dvec3& p) {
    const auto& rest = mMesh.restPositionsMm();
    const auto& tris = mMesh.triangles();
    if (++mQuery == 0) {  // the stamp wrapped: clear it once every 4 billion queries
        std::fill(mStamp.begin(), mStamp.end(), 0u);
        mQuery = 1;
    }
    int centre[3];
    for (int a = 0; a < 3; ++a) centre[a] = cellIndex(p[a], a);
    Hit best{0, std::numeric_limits<double>::infinity()};
    const int maxShell = std::max({mDims[0], mDims[1], mDims[2]});
    for (int k = 0; k <= maxShell; ++k) {
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::max(centre[a] - k, 0);
            hi[a] = std::min(centre[a] + k, mDims[a] - 1);
        }
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int x = lo[0]; x <= hi[0]; ++x) {
                    // Only the shell's surface: the inside was searched in earlier shells.
                    if (std::abs(x - centre[0]) != k && std::abs(y - centre[1]) != k && std::abs(z - centre[2]) != k) continue;
                    const std::size_t c = (std::size_t(z) * mDims[1] + y) * mDims[0] + x;
                    for (std::uint32_t i = mCellStart[c]; i < mCellStart[c + 1]; ++i) {
                        const std::uint32_t t = mCellTriangles[i];
                        if (mStamp[t] == mQuery) continue;
                        mStamp[t] = mQuery;
                        const glm::dvec3 q = closestPointOnTriangle(p, glm::dvec3(rest[tris[t][0]]), glm::dvec3(rest[tris[t][1]]),
                                                                    glm::dvec3(rest[tris[t][2]]));
                        const double d = glm::length(p - q);
                        if (d < best.distanceMm || (d == best.distanceMm && t < best.triangle)) best = {t, d};
                    }
                }
        // Every triangle not yet visited lies wholly outside the searched box of cells, so it is at
        // least as far as the nearest face of that box (faces at the grid's edge bound nothing).
        double bound = std::numeric_limits<double>::infinity();
        bool coversAll = true;
        for (int a = 0; a < 3; ++a) {
            if (lo[a] > 0) {
                bound = std::min(bound, p[a] - (mOriginMm[a] + lo[a] * mCellMm));
                coversAll = false;
            }
            if (hi[a] < mDims[a] - 1) {
                bound = std::min(bound, mOriginMm[a] + (hi[a] + 1) * mCellMm - p[a]);
                coversAll = false;
            }
        }
        if (coversAll || best.distanceMm <= bound) break;
    }
    return best;
}

}  // namespace palpate
