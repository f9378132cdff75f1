#pragma once
// The feel bench's tool path (docs/bench/README.md, "Feel"): the tool slides across the rest surface
// at a constant depth and speed, as a trainee strokes tissue. The path follows the surface's section
// by the plane through the default target vertex, its normal and the +y tangent (a straight stroke
// seen from above), on the rest triangles (each point the exact nearest point of the surface),
// at constant arc length per tick; the normal there is the vertex normals interpolated with the
// point's barycentric weights. The tool sits at surface + n (toolRadius - depth): a point
// tool's tip is `depth` below the surface, a sphere tool's centre is placed so that the sphere
// penetrates `depth`. Before the slide the tool comes down from above onto the first point and
// settles; after it, it lifts off the last one.

#include "engine/core/TissueMesh.h"
#include "base/params/Problem.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace palpate {

struct SlideDef {
    double depthMm = 1.0;       ///< how far the tool penetrates the rest surface
    double speedMmPerS = 25.0;  ///< along the surface (a trainee's stroke: 20-30 mm/s)
    double slideS = 1.6;        ///< time sliding
    double approachS = 0.2;     ///< from approachHeightMm above the first point down to the depth
    double settleS = 0.1;       ///< held at the first point before sliding
    double breakawayS = 0.1;    ///< first part of the slide left out of the statistics (static friction breaks away)
    double liftS = 0.1;         ///< from the depth at the last point up to approachHeightMm
    double approachHeightMm = 2.0;  ///< above the surface (of the tool's surface, for a sphere)
    double rateHz = 1000.0;         ///< one path point per tick
};

/// Every problem of the definition, each naming the field; empty when valid.
Problems validateSlideDef(const SlideDef& def);

struct SlidePath {
    std::vector<glm::vec3> toolMm;     ///< the position step() is given, one per tick
    std::vector<glm::vec3> surfaceMm;  ///< the rest surface point under the tool at each tick
    std::vector<glm::vec3> normal;     ///< the interpolated unit normal there
    std::size_t slideBegin = 0;        ///< first tick of the slide
    std::size_t statsBegin = 0;        ///< first tick of the statistics (slideBegin + breakaway)
    std::size_t slideEnd = 0;          ///< one past the last tick of the slide (then the lift)
    double toolRadiusMm = 0.0;
    double depthMm = 0.0;
    double lengthMm = 0.0;  ///< arc length of the slide along the surface
    double rateHz = 1000.0;
    double durationS() const { return double(toolMm.size()) / rateHz; }
};

/// The slide over `mesh` for a tool of `toolRadiusMm` (0: a point tool; the position is its tip).
/// Throws std::invalid_argument on an invalid definition, a negative radius or an empty mesh.
SlidePath makeSlidePath(const TissueMesh& mesh, double toolRadiusMm, const SlideDef& def = {});

}  // namespace palpate
