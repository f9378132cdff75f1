#include "engine/fem/GradedBlock.h"

#include <glm/vec2.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace palpate {

Problems validateGradedBlockOptions(const GradedBlockDef& o) {
    if (!std::isfinite(o.contactRadiusMm) || o.contactRadiusMm <= 0.0)
        return oneProblem("contactRadiusMm", "contact radius must be positive");
    if (o.contactRadiusOverSpacing < 1 || o.contactRadiusOverSpacing > 256)
        return oneProblem("contactRadiusOverSpacing", "a/h must be in 1..256");
    if (!std::isfinite(o.fineLateralFactor) || o.fineLateralFactor < 1.0)
        return oneProblem("fineLateralFactor", "fine lateral zone must be >= a");
    if (o.contactEdge != ContactEdgeNodes::Grid &&
        (o.contactRadiusOverSpacing < 2 || o.fineLateralFactor * o.contactRadiusOverSpacing < o.contactRadiusOverSpacing + 2))
        return oneProblem("fineLateralFactor",
                          "a bent contact edge needs a/h >= 2 and the fine lateral zone >= a + 2h");
    if (!std::isfinite(o.fineDepthFactor) || o.fineDepthFactor <= 0.0)
        return oneProblem("fineDepthFactor", "fine depth zone must be positive");
    if (!std::isfinite(o.blockSizeFactor) || o.blockSizeFactor <= o.fineLateralFactor ||
        o.blockSizeFactor <= o.fineDepthFactor)
        return oneProblem("blockSizeFactor", "block size must exceed the fine zones");
    if (!std::isfinite(o.growthRatio) || (o.growthRatio != 0.0 && (o.growthRatio < 1.0 || o.growthRatio > 3.0)))
        return oneProblem("growthRatio", "growth ratio must be 0 (automatic) or in [1, 3]");
    return {};
}

std::vector<double> gradedCoordinatesMm(double spacingMm, double fineExtentMm, double totalMm, double growthRatio) {
    std::vector<double> c;
    const int fineCells = std::max(1, int(std::lround(fineExtentMm / spacingMm)));
    for (int i = 0; i <= fineCells; ++i) c.push_back(i * spacingMm);
    const double fineEnd = c.back();
    const double remaining = totalMm - fineEnd;
    if (remaining <= 1e-12 * totalMm) {
        c.back() = totalMm;
        return c;
    }
    // Smallest n with h (q + q^2 + ... + q^n) >= remaining, then scale those n cells to fit exactly.
    std::vector<double> cells;
    double sum = 0.0, size = spacingMm;
    while (sum < remaining) {
        size *= growthRatio;
        cells.push_back(size);
        sum += size;
    }
    const double scale = remaining / sum;
    double x = fineEnd;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        x += cells[i] * scale;
        c.push_back(i + 1 == cells.size() ? totalMm : x);
    }
    return c;
}

namespace {

/// Bends the lateral grid near the contact: the square ring max(x, y) = s goes to the circle of
/// radius t(s) for s <= a + h, blended linearly back to the square ring s at s = fineEnd.
/// t(s) = s (OnCircle) or shifts the ring s = a to a - h/2 and s = a + h to a + h/2 (HalfSpacing).
/// Along a ray the new radius grows monotonically with s, so no cell folds.
glm::dvec2 bendTowardsContactCircle(const glm::dvec2& p, ContactEdgeNodes edge, double a, double h, double fineEnd) {
    const double s = std::max(p.x, p.y);
    const double r = std::hypot(p.x, p.y);
    if (edge == ContactEdgeNodes::Grid || r == 0.0 || s >= fineEnd) return p;
    const double shift = edge == ContactEdgeNodes::HalfSpacing ? 0.5 * h : 0.0;
    const double outer = a + h;
    const double blend = s <= outer ? 1.0 : (fineEnd - s) / (fineEnd - outer);  // 1 -> 0
    const double t = s <= a ? s * (a - shift) / a : s - shift * blend;
    // Radius on the ray: circle t for blend = 1, square ring t (radius t r / s) for blend = 0.
    const double radius = t * (blend + (1.0 - blend) * r / s);
    return p * (radius / r);
}

}  // namespace

double effectiveGrowthRatio(const GradedBlockDef& o) {
    if (o.growthRatio != 0.0) return o.growthRatio;
    return std::min(1.5, 1.0 + 2.0 / std::max(1, o.contactRadiusOverSpacing));
}

GradedBlock makeGradedBlock(const GradedBlockDef& o) {
    if (const std::string e = joinedMessages(validateGradedBlockOptions(o)); !e.empty()) throw std::invalid_argument(e);
    GradedBlock b;
    const double a = o.contactRadiusMm;
    b.spacingMm = a / o.contactRadiusOverSpacing;
    b.sizeMm = o.blockSizeFactor * a;
    const double growth = effectiveGrowthRatio(o);
    b.lateralMm = gradedCoordinatesMm(b.spacingMm, o.fineLateralFactor * a, b.sizeMm, growth);
    b.depthMm = gradedCoordinatesMm(b.spacingMm, o.fineDepthFactor * a, b.sizeMm, growth);
    const std::size_t nx = b.nx(), nz = b.nz();

    b.mesh.nodesMm.resize(nx * nx * nz);
    const double fineEndMm = o.fineLateralFactor * a;
    for (std::size_t k = 0; k < nz; ++k)
        for (std::size_t j = 0; j < nx; ++j)
            for (std::size_t i = 0; i < nx; ++i) {
                glm::dvec2 p{b.lateralMm[i], b.lateralMm[j]};
                p = bendTowardsContactCircle(p, o.contactEdge, a, b.spacingMm, fineEndMm);
                b.mesh.nodesMm[b.node(i, j, k)] = {p.x, p.y, -b.depthMm[k]};
            }

    // Kuhn split: one tet per path from corner (0,0,0) to (1,1,1) of the cell (in index space)
    // stepping along the axes in each of the 6 orders. Every cell face is then cut along the
    // diagonal through its lowest-index corner, so the two cells sharing it agree.
    static constexpr std::array<std::array<int, 3>, 6> kOrders = {
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    b.mesh.tets.reserve((nx - 1) * (nx - 1) * (nz - 1) * 6);
    for (std::size_t k = 0; k + 1 < nz; ++k)
        for (std::size_t j = 0; j + 1 < nx; ++j)
            for (std::size_t i = 0; i + 1 < nx; ++i)
                for (const auto& order : kOrders) {
                    std::array<std::size_t, 3> at{i, j, k};
                    std::array<TetNodeId, 4> tet{};
                    tet[0] = b.node(at[0], at[1], at[2]);
                    for (int s = 0; s < 3; ++s) {
                        ++at[std::size_t(order[std::size_t(s)])];
                        tet[std::size_t(s) + 1] = b.node(at[0], at[1], at[2]);
                    }
                    const auto& p = b.mesh.nodesMm;
                    if (tetSignedVolume6(p[tet[0]], p[tet[1]], p[tet[2]], p[tet[3]]) < 0.0) std::swap(tet[2], tet[3]);
                    b.mesh.tets.push_back(tet);
                }
    return b;
}

}  // namespace palpate
