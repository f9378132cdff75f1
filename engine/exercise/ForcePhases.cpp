#include "engine/exercise/ForcePhases.h"

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
