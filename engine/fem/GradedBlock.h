#pragma once
// The reference FEM's graded structured block: a quarter of the half-space under a contact at the
// origin, [0, L] x [0, L] x [-L, 0], top surface z = 0, symmetry planes x = 0 and y = 0.
// Spacing h near the contact, growing geometrically outward; every hex is split into 6 tets along
// its main diagonal (Kuhn), the same way in every cell, so neighbouring faces conform. The lateral
// grid may be bent into circular rings near the contact (ContactEdgeNodes), the same at all depths.

#include "base/params/Problem.h"

#include "engine/fem/TetMesh.h"

#include <cstddef>
#include <vector>

namespace palpate {

/// How the surface nodes meet the contact edge r = a (the punch edge is singular, so it matters).
enum class ContactEdgeNodes {
    Grid,         ///< the plain grid: the nodes with r <= a form a staircase inside the circle
    OnCircle,     ///< the grid bent so the ring of nodes max(i, j) h = a lies on r = a
    /// Bent so that the last ring inside is at r = a - h/2 and the next at r = a + h/2: the nodes
    /// inside then carry exactly the contact area (each node stands for the area halfway to its
    /// neighbours), like the staircase does on average, but with a smooth edge.
    HalfSpacing,
};

struct GradedBlockDef {
    double contactRadiusMm = 1.0;     ///< a: the length everything else is measured in
    int contactRadiusOverSpacing = 8;  ///< a/h, integer so that nodes sit at r = a on both axes
    double fineLateralFactor = 2.0;   ///< uniform spacing h for x, y <= 2a (the contact and its edge)
    double fineDepthFactor = 1.0;     ///< uniform spacing h for depth <= a
    double blockSizeFactor = 16.0;    ///< L = 16 a: Boussinesq far field is then within ~(a/L)^2
    /// Ratio of neighbouring cell sizes outside the fine zone; 0 = automatic, 1 + 2h/a (at most
    /// 1.5): cells at distance d then measure about h (1 + 2d/a), so refining h refines the whole
    /// block, not only the contact (see docs/accuracy.md for why that matters at nu = 0.45).
    double growthRatio = 0.0;
    ContactEdgeNodes contactEdge = ContactEdgeNodes::HalfSpacing;
};

/// "" when usable, else a message naming the field.
Problems validateGradedBlockOptions(const GradedBlockDef& o);

/// Node coordinates 0 = c0 < c1 < ... = totalMm: spacing `spacingMm` up to `fineExtentMm`, then
/// cells growing by `growthRatio` (uniformly rescaled so the last node lands on totalMm).
std::vector<double> gradedCoordinatesMm(double spacingMm, double fineExtentMm, double totalMm, double growthRatio);

struct GradedBlock {
    TetMesh mesh;
    std::vector<double> lateralMm;  ///< node x (and y) coordinates, ascending from 0 to L
    std::vector<double> depthMm;    ///< node depths, ascending from 0 (z = 0) to L (z = -L)
    double sizeMm = 0.0;            ///< L
    double spacingMm = 0.0;         ///< h

    std::size_t nx() const { return lateralMm.size(); }
    std::size_t nz() const { return depthMm.size(); }
    /// Node index of lateral indices (i, j) and depth index k (k = 0 is the top surface).
    TetNodeId node(std::size_t i, std::size_t j, std::size_t k) const { return TetNodeId((k * nx() + j) * nx() + i); }
};

/// The growth ratio used: options.growthRatio, or the automatic one when it is 0.
double effectiveGrowthRatio(const GradedBlockDef& options);

/// Throws std::invalid_argument on bad options.
GradedBlock makeGradedBlock(const GradedBlockDef& options);

}  // namespace palpate
