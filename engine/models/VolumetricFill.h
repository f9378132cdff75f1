#pragma once
// The tetrahedral mesh the volumetric slope-ring model runs on. Its first nodes are the surface's
// vertices in the TissueMesh's order, so the display and the error measurement work unchanged.

#include "engine/core/TissueMesh.h"
#include "engine/fem/TetMesh.h"

namespace palpate {

/// Fills a closed surface with tetrahedra for the volumetric model: the lead team's filler
/// (engine/fem/SurfaceFill.h: prism layers extruded inward along the normals, default
/// options), renumbered so that the surface vertices come first in the mesh's order and each
/// vertex's inner nodes follow, layer by layer. Throws std::invalid_argument naming the problem
/// when the surface cannot be filled. Not real-time.
TetMesh fillSurfaceWithTets(const TissueMesh& mesh);

/// Our earlier filler, kept for tests (it fills to the centroid, not to a core): surfaces that are star-shaped about their vertex centroid (the generated
/// sphere, not the stomach): `innerShells` copies of the surface scaled towards the centroid, each
/// triangle's prism between neighbouring shells split into 3 tets (diagonals chosen by vertex
/// index, so neighbouring prisms share faces), and a fan to the centroid inside the last shell.
/// Throws std::invalid_argument when a triangle does not face away from the centroid.
TetMesh fillStarShapedSurface(const TissueMesh& mesh, int innerShells);

}  // namespace palpate
