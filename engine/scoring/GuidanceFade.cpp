#include "engine/scoring/GuidanceFade.h"

#include <algorithm>

namespace palpate {

double forceGaugeLevel(const std::vector<double>& previousScores, const GuidanceFadeDef& def) {
    if (!def.enabled) return 1.0;
    const double step = 1.0 / double(std::max(1, def.sessionsToFade));
    const double floor = std::clamp(def.floorLevel, 0.0, 1.0);
    double level = 1.0;
    for (double score : previousScores) level = std::clamp(level + (score >= def.goodScore ? -step : step), floor, 1.0);
    return level;
}

}  // namespace palpate
