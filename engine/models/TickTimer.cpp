#include "engine/models/TickTimer.h"

#include <algorithm>
#include <chrono>

namespace palpate {

double medianTickUs(DeformationModel& model, const std::vector<glm::vec3>& path, const TickTimingDef& def) {
    if (path.empty()) return 0.0;
    std::vector<double> perTickUs;
    for (int r = 0; r < std::max(def.repeats, 1); ++r) {
        double elapsedUs = 0.0;
        std::size_t ticks = 0;
        while (elapsedUs < def.minMeasureMs * 1000.0 || ticks == 0) {
            model.reset();
            const auto start = std::chrono::steady_clock::now();
            for (const glm::vec3& tool : path) model.step(tool, 0.001);
            const auto stop = std::chrono::steady_clock::now();
            elapsedUs += std::chrono::duration<double, std::micro>(stop - start).count();
            ticks += path.size();
        }
        perTickUs.push_back(elapsedUs / double(ticks));
    }
    std::sort(perTickUs.begin(), perTickUs.end());
    return perTickUs[perTickUs.size() / 2];
}

}  // namespace palpate
