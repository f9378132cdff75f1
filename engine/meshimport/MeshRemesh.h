#pragma once
// Isotropic remeshing to a target edge length with CGAL's Polygon Mesh Processing (docs/meshes.md,
// "Remeshing"): uniform, near-equilateral triangles keep the slope model's rings round.

#include "engine/meshimport/TriangleSurface.h"

#include <functional>
#include <string>
#include <vector>

namespace palpate {

struct MeshRemeshDef {
    double edgeMm = 0.0;   ///< target edge length
    int iterations = 3;
};

/// Remeshes `surface` in place (borders kept where they are). Returns "" or the problem (a target so
/// small that the result would exceed the mesh limits, "cancelled"). `progress(fraction)` is called
/// after each iteration; it returns false to cancel. One line per change goes to `changes`.
std::string remeshIsotropic(TriangleSurface& surface, const MeshRemeshDef& def,
                            const std::function<bool(double fraction)>& progress, std::vector<std::string>& changes);

/// The number of triangles a surface of `areaMm2` has when remeshed at `edgeMm` (equilateral).
double remeshedTriangleEstimate(double areaMm2, double edgeMm);

}  // namespace palpate
