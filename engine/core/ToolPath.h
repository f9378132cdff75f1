#pragma once
// A realistic tool path over a mesh for benchmarks and tests: approach, press, hold, a stroke
// across the surface at constant depth, release. Deterministic for a given mesh.

#include "engine/core/TissueMesh.h"

#include <glm/vec3.hpp>

#include <vector>

namespace palpate {

struct ToolPathDef {
    int approachTicks = 200;   ///< from 2 mm above the surface down to contact
    int pressTicks = 300;      ///< from contact to full depth
    int holdTicks = 200;
    int strokeTicks = 3000;    ///< across the surface at full depth
    int releaseTicks = 300;    ///< back up to 2 mm above
    double depthMm = 3.0;
    double strokeLengthMm = 40.0;
};

/// Tool-tip positions, one per tick. Starts at the vertex with the largest x (a side of the shape,
/// away from the generators' poles) and strokes along the surface by a greedy walk towards a point
/// `strokeLengthMm` away along the +y tangent direction.
std::vector<glm::vec3> makePressAndStrokePath(const TissueMesh& mesh, const ToolPathDef& def = {});

/// The same phases at the same stroke speed, ten times shorter (for models too slow to time on the
/// whole path, and for quick runs).
inline ToolPathDef shortenedTenTimes(ToolPathDef def = {}) {
    def.approachTicks /= 10;
    def.pressTicks /= 10;
    def.holdTicks /= 10;
    def.strokeTicks /= 10;
    def.releaseTicks /= 10;
    def.strokeLengthMm /= 10.0;
    return def;
}

}  // namespace palpate
