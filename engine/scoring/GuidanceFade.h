#pragma once
// Fading guidance (docs/scoring.md, "Fading guidance"): continuous visual force feedback breeds
// dependence unless it fades, so the trainee's force gauge fades over their sessions of an
// exercise as they do well, and comes back when they do not.

#include <vector>

namespace palpate {

struct GuidanceFadeDef {
    bool enabled = true;
    int sessionsToFade = 5;   ///< good sessions from a full gauge to the floor, >= 1
    double goodScore = 80.0;  ///< a session at or above this score counts as good
    double floorLevel = 0.0;  ///< the faintest the gauge gets, [0, 1]
};

/// The gauge's level for the next session, 1 (fully shown) down to the floor: starting at 1, each
/// previous scored session (oldest first) at or above the good score lowers it by 1 / N, each
/// below raises it by 1 / N. 1 when disabled.
double forceGaugeLevel(const std::vector<double>& previousScores, const GuidanceFadeDef& def);

}  // namespace palpate
