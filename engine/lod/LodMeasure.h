#pragma once
// Fills the planner's table on this machine: for every level and ring count, the slope-ring model
// with slopes calibrated from the flat punch (Calibration.h) is pressed and measured against the
// punch (ModelError.h, the sweep's metric) and timed over the press-and-stroke path (TickTimer.h,
// the sweep's and Table 1's timer). The error that counts is the one the user sees: the level's
// deformation carried to the source surface (MeshLevels::toFine) and compared there, so that a
// coarse level is not judged only at its own few vertices.

#include "base/params/Problem.h"

#include "engine/models/slopering/SlopeRingParams.h"
#include "engine/models/TickTimer.h"
#include "engine/core/ToolPath.h"
#include "engine/accuracy/Calibration.h"
#include "engine/accuracy/ModelError.h"
#include "engine/lod/LodPlanner.h"
#include "engine/lod/MeshLevels.h"

#include <atomic>
#include <string>
#include <vector>

namespace palpate {

struct LodMeasureDef {
    ToolContact contact;                     ///< tissue and tool the slopes are calibrated for
    PressDef press;                          ///< the accuracy press (depth, settle ticks, region)
    SlopeRingParams base;                    ///< damping, k_c, ...; slopes and spring k are calibrated
    std::vector<int> ringCounts{1, 2, 3, 4, 6};
    TickTimingDef timing{5, 20.0};            ///< Table 1's defaults: median of 5, each at least 20 ms
    ToolPathDef path;                        ///< the timed tool path (per level: makePressAndStrokePath)
};

/// "" when usable, else a message naming the field.
Problems validateLodMeasureDef(const LodMeasureDef& def);

struct LodMeasurement {
    std::vector<LodCandidate> candidates;  ///< level by level, ring counts ascending
    bool cancelled = false;
};

/// Fewer source vertices than this in the loaded region (5 tool radii) and the error says nothing:
/// with the touched vertex alone it is 0 by construction. Such a candidate gets a NaN error and a
/// note (the mesh is too coarse for the tool), so it is never chosen.
inline constexpr int kMinVerticesCompared = 7;

/// Measures every level of `levels` with every ring count. A configuration that cannot be measured
/// (e.g. more rings than the level has) gets NaN error and tick and a note, and the rest go on.
/// Throws std::invalid_argument for a bad definition.
LodMeasurement measureLodCandidates(const MeshLevels& levels, const LodMeasureDef& def, const LodProgressFn& progress = {},
                                    const std::atomic<bool>* cancel = nullptr);

}  // namespace palpate
