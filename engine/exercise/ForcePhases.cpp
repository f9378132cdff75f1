#include "engine/exercise/ForcePhases.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace palpate {

namespace {

double percentile(const std::vector<double>& sorted, double q) {
    const double at = q * double(sorted.size() - 1);
    const std::size_t below = std::size_t(std::floor(at));
    const std::size_t above = std::min(below + 1, sorted.size() - 1);
    return sorted[below] + (at - double(below)) * (sorted[above] - sorted[below]);
}

std::optional<ForcePercentiles> percentilesOf(std::vector<double> forces) {
    if (forces.empty()) return std::nullopt;
    std::sort(forces.begin(), forces.end());
    ForcePercentiles p;
    p.samples = forces.size();
    p.p10N = percentile(forces, 0.10);
    p.p50N = percentile(forces, 0.50);
    p.p90N = percentile(forces, 0.90);
    p.maxN = forces.back();
    return p;
}

}  // namespace

SurfaceSpeed::SurfaceSpeed(double windowS, double periodS) : mWindowS(windowS) {
    // A window of ticks and one more (its start); at least two points.
    const double ticks = periodS > 0.0 && windowS > 0.0 ? std::ceil(windowS / periodS) : 1.0;
    mRing.resize(std::size_t(std::clamp(ticks, 1.0, 1e6)) + 1);
}

void SurfaceSpeed::reset() {
    mOldest = mCount = 0;
    mTimeS = 0.0;
}

std::optional<double> SurfaceSpeed::add(double dtS, const glm::dvec3& pointMm, const glm::dvec3& normal) {
    if (mCount > 0) mTimeS += std::max(0.0, dtS);
    // Points older than the window leave, but one stays: the window's start (ticks of uneven
    // length make it a little longer than the window, never shorter).
    while (mCount > 1 && mTimeS - mRing[(mOldest + 1) % mRing.size()].timeS >= mWindowS) {
        mOldest = (mOldest + 1) % mRing.size();
        --mCount;
    }
    if (mCount == mRing.size()) {  // full (ticks shorter than the period): the oldest goes
        mOldest = (mOldest + 1) % mRing.size();
        --mCount;
    }
    mRing[(mOldest + mCount) % mRing.size()] = {mTimeS, pointMm};
    ++mCount;
    const Timed& start = mRing[mOldest];
    const double elapsedS = mTimeS - start.timeS;
    if (mCount < 2 || !(elapsedS > 0.0)) return std::nullopt;
    glm::dvec3 moved = pointMm - start.pointMm;
    moved -= glm::dot(moved, normal) * normal;
    return glm::length(moved) / elapsedS;
}

ForceByPhase forceByPhase(const std::vector<ForceMotionSample>& samples, const ForcePhaseDef& def) {
    std::vector<double> search, palpation;
    for (const ForceMotionSample& s : samples) {
        if (!(s.forceN >= def.minForceN)) continue;
        (s.tangentialSpeedMmPerS <= def.palpationMaxSpeedMmPerS ? palpation : search).push_back(s.forceN);
    }
    ForceByPhase out;
    out.search = percentilesOf(std::move(search));
    out.palpation = percentilesOf(std::move(palpation));
    if (out.search && out.palpation && out.search->p50N > 0.0) out.palpationOverSearch = out.palpation->p50N / out.search->p50N;
    return out;
}

}  // namespace palpate
