#pragma once
// The choice (docs/lod.md, section 5): of the measured candidates (one per level and ring count), the coarsest
// level with the fewest rings whose error meets the target and whose tick fits the budget. A pure
// function on a table, so it is tested on synthetic tables and the GUI can replan on an override
// without measuring again. docs/lod.md says why the order is structural, not "lowest tick".

#include "engine/lod/LodNeeds.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

/// One measured configuration: a level of the mesh and a ring count.
struct LodCandidate {
    std::size_t level = 0;           ///< index in MeshLevels::levels (0: the source)
    std::size_t vertices = 0;
    std::size_t triangles = 0;
    int rings = 0;
    std::string model = "coherent";  ///< registry name (engine/models/ModelRegistry.h)
    double errorFraction = 0.0;      ///< displacement error on the display (source) surface
    double levelErrorFraction = 0.0; ///< the same metric on the level's own vertices (the sweep's view)
    double forceErrorFraction = 0.0; ///< |F - F_punch| / F_punch at the model's indentation
    double tickUs = 0.0;             ///< median tick time on this machine
    int verticesCompared = 0;        ///< source vertices in the loaded region the error is over
    std::string note;                ///< "" or why the measurement failed (then error and tick are NaN)
};

/// Whether a candidate meets each target (NaN never does).
bool meetsError(const LodCandidate& c, const LodNeeds& needs);
bool meetsBudget(const LodCandidate& c, const LodNeeds& needs);

/// The order of preference among candidates that meet both targets: fewer vertices (coarser
/// level), then fewer rings, then lower tick, then lower error. True when `a` comes before `b`.
bool cheaperThan(const LodCandidate& a, const LodCandidate& b);

/// How far a candidate misses the targets: the sum of its relative excesses,
/// max(0, error / max_error - 1) + max(0, tick / budget - 1); 0 when it meets both; +inf for NaN.
double shortfall(const LodCandidate& c, const LodNeeds& needs);

struct LodPlan {
    std::string error;                   ///< "" or why no plan was made (bad needs, no candidates)
    bool feasible = false;               ///< some candidate meets both targets
    std::optional<std::size_t> chosen;   ///< index of the choice (set when feasible)
    std::optional<std::size_t> closest;  ///< when infeasible: index of the candidate with the least shortfall
    std::size_t feasibleCount = 0;
    std::string reason;                  ///< one or two sentences for people: what and why
};

/// Chooses. Never throws: invalid needs or an empty table give `error`.
LodPlan planLod(const std::vector<LodCandidate>& candidates, const LodNeeds& needs);

/// A candidate in words: "level 2 (2166 vertices), 3 rings: error 0.081, tick 0.42 us".
std::string describeCandidate(const LodCandidate& c);

}  // namespace palpate
