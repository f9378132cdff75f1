#include "device/hid/SpaceMouseControl.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>

namespace palpate {
namespace {

float axis(std::int16_t counts, const SpaceMouseControlDef& def) {
    const double c = counts;
    const double magnitude = std::fabs(c);
    if (magnitude <= def.deadbandCounts) return 0.0f;
    // Rescale so that the output starts from 0 at the deadband edge (no jump) and reaches 1 at
    // full scale; clamp beyond, since units differ in their true range.
    double v = (magnitude - def.deadbandCounts) / (def.fullScaleCounts - def.deadbandCounts);
    if (v > 1.0) v = 1.0;
    return float(c < 0 ? -v : v);
}

bool finitePositive(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

const char* spaceMouseModeName(SpaceMouseMode mode) { return mode == SpaceMouseMode::Rate ? "rate" : "position"; }

Problems validateSpaceMouseControlDef(const SpaceMouseControlDef& def) {
    if (!finitePositive(def.fullScaleCounts))
        return oneProblem("fullScaleCounts", "SpaceMouseControlDef.fullScaleCounts must be finite and > 0");
    if (!std::isfinite(def.deadbandCounts) || def.deadbandCounts < 0.0 || def.deadbandCounts >= def.fullScaleCounts)
        return oneProblem("deadbandCounts", "SpaceMouseControlDef.deadbandCounts must be in [0, fullScaleCounts)");
    if (!finitePositive(def.rateMmPerS))
        return oneProblem("rateMmPerS", "SpaceMouseControlDef.rateMmPerS must be finite and > 0");
    if (!finitePositive(def.positionRangeMm))
        return oneProblem("positionRangeMm", "SpaceMouseControlDef.positionRangeMm must be finite and > 0");
    if (!finitePositive(def.workspaceRadiusMm))
        return oneProblem("workspaceRadiusMm", "SpaceMouseControlDef.workspaceRadiusMm must be finite and > 0");
    if (!std::isfinite(def.homeMm.x) || !std::isfinite(def.homeMm.y) || !std::isfinite(def.homeMm.z))
        return oneProblem("homeMm", "SpaceMouseControlDef.homeMm must be finite");
    return {};
}

glm::vec3 spaceMouseDeflection(const SpaceMouseRaw& raw, const SpaceMouseControlDef& def) {
    return {axis(raw.translation[0], def), -axis(raw.translation[1], def), -axis(raw.translation[2], def)};
}

SpaceMouseControl::SpaceMouseControl(SpaceMouseControlDef def) : mDef(def), mPositionMm(def.homeMm) {
    const std::string problem = joinedMessages(validateSpaceMouseControlDef(def));
    if (!problem.empty()) throw std::invalid_argument(problem);
}

glm::vec3 SpaceMouseControl::update(const SpaceMouseRaw& raw, double dtS) {
    const glm::vec3 deflection = spaceMouseDeflection(raw, mDef);
    if (mDef.mode == SpaceMouseMode::Position) {
        mPositionMm = mDef.homeMm + deflection * float(mDef.positionRangeMm);
        return mPositionMm;
    }
    if (!std::isfinite(dtS) || dtS < 0.0) dtS = 0.0;
    // A long gap (loop paused, device swapped in) must not fling the tool: cap one step at 50 ms.
    if (dtS > 0.05) dtS = 0.05;
    mPositionMm += deflection * float(mDef.rateMmPerS * dtS);
    const glm::vec3 offset = mPositionMm - mDef.homeMm;
    const float distance = glm::length(offset);
    if (distance > float(mDef.workspaceRadiusMm)) mPositionMm = mDef.homeMm + offset * (float(mDef.workspaceRadiusMm) / distance);
    return mPositionMm;
}

}  // namespace palpate
