#include "engine/exercise/ExerciseChecker.h"

#include <cmath>
#include <sstream>

namespace palpate {

std::string ExerciseChecker::text(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

void ExerciseChecker::error(const std::string& key, const std::string& problem) {
    mProblems.push_back({key, -1, -1, key + ": " + problem});
}

bool ExerciseChecker::range(const std::string& key, double v, double lo, double hi, bool openLow) {
    const bool ok = std::isfinite(v) && (openLow ? v > lo : v >= lo) && v <= hi;
    if (!ok) error(key, text(v) + " is out of range " + (openLow ? "(" : "[") + text(lo) + ", " + text(hi) + "]");
    return ok;
}

void ExerciseChecker::point(const std::string& key, const SurfacePoint& p) {
    if (p.vertex) return;
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(p.pointMm[i]) || std::fabs(p.pointMm[i]) > 1e6f) {
            error(key + ".point_mm", "must be three finite coordinates in mm");
            return;
        }
}

void ExerciseChecker::window(const std::string& key, double minN, double maxN, const char* minKey, const char* maxKey) {
    const bool a = range(key + "." + minKey, minN, 0.0, 1000.0);
    const bool b = range(key + "." + maxKey, maxN, 0.0, 1000.0, true);
    if (a && b && !(maxN > minN)) error(key + "." + maxKey, text(maxN) + " must be greater than " + minKey + " " + text(minN));
}

}  // namespace palpate
