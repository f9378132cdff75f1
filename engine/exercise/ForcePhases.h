#pragma once
// Search and palpation, told apart from force and motion (docs/scoring.md, "Force by phase"):
// examiners sweep the surface lightly to search and then hold still and press to palpate, and
// successful ones press about 15 % harder in palpation than in search (Laufer, Klatzky and Pugh
// 2024). Each contact sample is one or the other by the tool's speed along the surface.

#include "engine/exercise/PalpationResult.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace palpate {

struct ForcePhaseDef {
    /// Slower than this along the surface is palpation; faster is search.
    double palpationMaxSpeedMmPerS = 10.0;
    /// Below this force there is no examination at all (resting contact).
    double minForceN = 0.1;
};

/// One sample of a session: the force's magnitude and the tool's speed along the surface.
struct ForceMotionSample {
    double forceN = 0.0;
    double tangentialSpeedMmPerS = 0.0;
};

/// Percentiles by linear interpolation between order statistics (the "type 7" definition).
ForceByPhase forceByPhase(const std::vector<ForceMotionSample>& samples, const ForcePhaseDef& def = {});

}  // namespace palpate
