#pragma once
// Range checks for an exercise's values that name the key as the file writes it
// ("press_targets.targets[1].force_max_n: 0 is out of range (0, 1000]"); the common checks and each
// kind's (ExerciseKind::validate) share them.

#include "base/params/Problem.h"
#include "engine/exercise/Exercise.h"

#include <string>
#include <vector>

namespace palpate {

class ExerciseChecker {
public:
    explicit ExerciseChecker(Problems& problems) : mProblems(problems) {}

    /// A problem of `key`, its message "key: problem".
    void error(const std::string& key, const std::string& problem);
    /// lo < v <= hi (openLow) or lo <= v <= hi.
    bool range(const std::string& key, double v, double lo, double hi, bool openLow = false);
    /// A point in the mesh's frame has three finite coordinates (a vertex is checked on the mesh).
    void point(const std::string& key, const SurfacePoint& p);
    /// A force window [minN, maxN] with 0 <= minN < maxN <= 1000.
    void window(const std::string& key, double minN, double maxN, const char* minKey, const char* maxKey);

    /// The number as messages print it.
    static std::string text(double v);

private:
    Problems& mProblems;
};

}  // namespace palpate
