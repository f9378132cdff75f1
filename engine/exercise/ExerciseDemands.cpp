#include "engine/exercise/ExerciseDemands.h"

#include <algorithm>
#include <sstream>

namespace palpate {

namespace {

std::string number(double v) {
    std::ostringstream s;
    s.precision(3);
    s << v;
    return s.str();
}

}  // namespace

std::vector<ExerciseDemand> exerciseDemands(const Exercise& exercise) {
    std::vector<ExerciseDemand> out;
    switch (exercise.type) {
    case ExerciseType::PressTargets:
        for (std::size_t i = 0; i < exercise.pressTargets.targets.size(); ++i) {
            const double f = exercise.pressTargets.targets[i].forceMaxN;
            out.push_back({"press target " + std::to_string(i + 1) + " (up to " + number(f) + " N)", f, 0.0});
        }
        break;
    case ExerciseType::Trace:
        out.push_back({"the trace's band (up to " + number(exercise.trace.forceMaxN) + " N)", exercise.trace.forceMaxN, 0.0});
        break;
    case ExerciseType::FindLump:
        out.push_back({"the firmest press allowed (" + number(exercise.excessiveForceN) + " N)", exercise.excessiveForceN, 0.0});
        break;
    case ExerciseType::DetectLumps: {
        double deepest = 0.0;
        for (const LumpDef& lump : exercise.detectLumps.lumps) deepest = std::max(deepest, lump.depthMm);
        if (deepest > 0.0) out.push_back({"the deepest lump (" + number(deepest) + " mm down)", 0.0, deepest});
        else out.push_back({"the firmest press allowed (" + number(exercise.excessiveForceN) + " N)", exercise.excessiveForceN, 0.0});
        break;
    }
    }
    return out;
}

double deepestDemandMm(const std::vector<ExerciseDemand>& demands, double firstSlopeMmPerN, double atLeastMm) {
    double deepest = atLeastMm;
    for (const ExerciseDemand& d : demands)
        deepest = std::max(deepest, d.depthMm > 0.0 ? d.depthMm : d.forceN * firstSlopeMmPerN);
    return deepest;
}

}  // namespace palpate
