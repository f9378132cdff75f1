#pragma once
// What a scene needs from its model (docs/lod.md): an accuracy target and a haptic time budget. An
// exercise or a tissue preset may carry them as "needs": {"max_error": E, "budget_us": T}; the
// planner (LodPlanner.h) picks the cheapest level and ring count that meets both.

#include "base/params/Problem.h"

#include <string>
#include <vector>

namespace palpate {

/// Limits of the values a file may state; outside them the request is absurd, not strict.
inline constexpr double kMaxLodErrorFraction = 10.0;  ///< 1000 % of the peak displacement
inline constexpr double kMaxLodBudgetUs = 1.0e6;      ///< one second per tick

struct LodNeeds {
    /// Displacement error allowed: RMS over the loaded region / peak displacement (ModelError.h's
    /// displacementError, measured on the display surface). 0.1 = 10 %.
    double maxErrorFraction = 0.1;
    /// Time one haptic tick may take on this machine (µs); a 1 kHz loop has 1000 µs per tick.
    double budgetUs = 100.0;
};

/// Every problem, each naming the key as `keyPrefix` + "max_error" / "budget_us" (e.g. "needs.");
/// empty when usable. Catches negative, zero, NaN and absurdly large values.
Problems validateLodNeeds(const LodNeeds& needs, const std::string& keyPrefix = "needs.");

}  // namespace palpate
