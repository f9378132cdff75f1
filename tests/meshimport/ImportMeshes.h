#pragma once
// Generated meshes for the import tests: a box of n x n quads per side (shared corners), optionally
// with uneven grid lines (slivers), and writers for OBJ with quads (docs/meshes.md). Computed from
// coordinates here, never by the engine code under test.

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace palpate::test {

struct QuadBox {
    std::vector<glm::dvec3> positions;
    std::vector<std::vector<std::uint32_t>> quads;  ///< counter-clockwise seen from outside
};

/// An axis-aligned box of side `sideMm` centred at the origin, each face split into n x n quads.
/// `unevenness` 0 gives equal spacing; towards 1 the grid lines crowd to one end (geometric), so
/// that the cells become slivers of very different sizes.
QuadBox quadBox(int n, double sideMm, double unevenness = 0.0);

/// Quads split into two triangles each (along the 0-2 diagonal).
std::vector<std::array<std::uint32_t, 3>> trianglesOf(const QuadBox& box);

/// OBJ text with `v` lines scaled by `scale` and `f` lines as written (1-based, "i/i/i" corners
/// when `withTextureAndNormal`).
std::string objText(const QuadBox& box, double scale, bool withTextureAndNormal);

}  // namespace palpate::test
