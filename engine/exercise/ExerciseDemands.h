#pragma once
// How hard and how deep an exercise asks the trainee to press (docs/lod.md, "Linear or
// nonlinear"): the forces and depths its own numbers name. The level-of-detail plan turns the
// forces into depths on the tissue's reference curve and judges the linear model there.

#include "engine/exercise/Exercise.h"

#include <string>
#include <vector>

namespace palpate {

struct ExerciseDemand {
    std::string what;       ///< "press target 2 (up to 2.5 N)"
    double forceN = 0.0;    ///< > 0: the press is given as a force
    double depthMm = 0.0;   ///< > 0: the press is given as a depth of tissue
};

/// Press targets: each target's upper force; trace: the band's upper force; find the lump: the
/// excessive force (the firmest press allowed); detect lumps: the deepest lump's top (the tissue
/// must sink that far for the lump to be felt). Never empty for a valid exercise of these types.
std::vector<ExerciseDemand> exerciseDemands(const Exercise& exercise);

/// The deepest of `demands` and `atLeastMm`, a force taken at its linear depth F |m1| (which
/// bounds the depth of tissue that stiffens).
double deepestDemandMm(const std::vector<ExerciseDemand>& demands, double firstSlopeMmPerN, double atLeastMm);

}  // namespace palpate
