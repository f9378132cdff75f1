#pragma once
// The mapping between two levels of a mesh: every vertex of one surface is tied to its nearest
// triangle of the other by barycentric coordinates in that triangle's plane and an offset along
// the triangle's normal. Rebuilding the point from the triangle's (deformed) corners and normal
// carries a deformation from one level to the other: the display can stay fine while the haptic
// model is coarse, or the reverse. The coordinates are those of the point's projection onto the
// triangle's plane (not clamped to the triangle), so the rest positions round-trip exactly.

#include "engine/core/TissueMesh.h"

#include <glm/vec3.hpp>

#include <array>
#include <atomic>
#include <cstdint>
#include <span>
#include <vector>

namespace palpate {

struct EmbeddedPoint {
    std::uint32_t triangle = 0;          ///< in the surface it is embedded in
    std::array<float, 3> barycentric{};  ///< weights of the triangle's corners, summing to 1
    float normalOffsetMm = 0.0f;         ///< along the triangle's unit normal (outward: positive)
};

/// Each of `pointsMm` tied to its nearest triangle of `onto` (rest positions). Returns an empty
/// vector when `cancel` was set before the end.
std::vector<EmbeddedPoint> embedPoints(std::span<const glm::vec3> pointsMm, const TissueMesh& onto,
                                       const std::atomic<bool>* cancel = nullptr);

/// The embedded points rebuilt on `onto` with its corners at `ontoPositionsMm` (its rest positions,
/// or a deformed state in its vertex order): corners weighted, plus the offset along the deformed
/// triangle's normal. Writes points.size() positions to `outMm`.
void placeEmbeddedPoints(std::span<const EmbeddedPoint> points, const TissueMesh& onto,
                         std::span<const glm::vec3> ontoPositionsMm, std::span<glm::vec3> outMm);

/// A displacement field on `onto`'s vertices interpolated at the embedded points (no normal term:
/// for scalar or vector fields that are not positions).
void interpolateAtEmbeddedPoints(std::span<const EmbeddedPoint> points, const TissueMesh& onto,
                                 std::span<const glm::vec3> ontoField, std::span<glm::vec3> out);

}  // namespace palpate
