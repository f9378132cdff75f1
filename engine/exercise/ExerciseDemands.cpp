#include "engine/exercise/ExerciseDemands.h"

#include "engine/exercise/ExerciseKind.h"

#include <algorithm>

namespace palpate {

std::vector<ExerciseDemand> exerciseDemands(const Exercise& exercise) { return exerciseKind(exercise.type).demands(exercise); }

double deepestDemandMm(const std::vector<ExerciseDemand>& demands, double firstSlopeMmPerN, double atLeastMm) {
    double deepest = atLeastMm;
    for (const ExerciseDemand& d : demands)
        deepest = std::max(deepest, d.depthMm > 0.0 ? d.depthMm : d.forceN * firstSlopeMmPerN);
    return deepest;
}

}  // namespace palpate
