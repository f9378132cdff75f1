#pragma once
// Two octree queries every model in this folder needs, over the octree's public nodes (tight boxes
// of rest positions): the exact nearest vertex when no vertex is farther than a known bound from
// its rest position, and the rest vertices within a radius of a point. Fixed stacks: no allocation.

#include "engine/core/Octree.h"
#include "engine/core/TissueMesh.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>

namespace palpate {

/// Exact nearest vertex to `pointMm` over the current `positionsMm` (the mesh's vertex order),
/// given that every vertex is at most `maxDisplacementMm` from its rest position. Depth-first,
/// nearest box first; a node is skipped when its rest box is farther than best + bound. Why that
/// is exact: a vertex v in a skipped node has |p_v - x| >= |rest_v - x| - U >= box distance - U > best.
/// `hint` (e.g. last tick's answer, or kNoVertex) seeds the best distance. Ties go to the lower
/// index, as Octree::nearestExact and nearestLinear. Allocation-free.
VertexId nearestWithBoundedDisplacement(const Octree& octree, const glm::vec3& pointMm,
                                        std::span<const glm::vec3> positionsMm, float maxDisplacementMm,
                                        VertexId hint = kNoVertex);

/// Writes the vertices whose rest position is within `radiusMm` of `centreMm` to `out` (capacity
/// `capacity`, e.g. the vertex count) and returns how many there are (more than `capacity` means
/// the list was cut). Order: octree (Morton) order. Allocation-free.
std::size_t restVerticesWithinRadius(const Octree& octree, std::span<const glm::vec3> restMm, const glm::vec3& centreMm,
                                     float radiusMm, VertexId* out, std::size_t capacity);

}  // namespace palpate
