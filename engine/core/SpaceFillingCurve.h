#pragma once
// Orders points along a Morton (Z-order) curve so that spatial neighbours are memory neighbours.
// The octree is built on the same curve, which makes every octree node a contiguous vertex range.

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace palpate {

/// The cube in which Morton codes are taken (shared by the mesh reordering and the octree).
struct MortonCube {
    glm::vec3 originMm{0.0f};
    float sizeMm = 1.0f;
};

inline constexpr int kMortonBitsPerAxis = 21;

/// Smallest cube around the points, slightly inflated so that no point lies on its far faces.
MortonCube mortonCubeFor(const std::vector<glm::vec3>& pointsMm);

/// 63-bit Morton code of a point inside the cube (points outside are clamped).
std::uint64_t mortonCode(const MortonCube& cube, const glm::vec3& pointMm);

/// Permutation `order` such that points[order[0]], points[order[1]], ... follow the curve.
std::vector<std::uint32_t> mortonOrder(const std::vector<glm::vec3>& pointsMm, const MortonCube& cube);

}  // namespace palpate
