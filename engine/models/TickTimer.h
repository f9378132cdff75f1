#pragma once
// Times one haptic tick of a model over a tool path: the same measurement for Table 1 and for the
// speed-vs-accuracy sweep, so their x axes agree.

#include "engine/models/DeformationModel.h"

#include <glm/vec3.hpp>

#include <vector>

namespace palpate {

struct TickTimingDef {
    int repeats = 5;             ///< the median over this many repeats is reported
    double minMeasureMs = 20.0;  ///< each repeat runs the path as often as needed to last this long
};

/// Median over repeats of the mean time of one step() along `path` (µs); the model is reset before
/// each pass so every pass does the same work.
double medianTickUs(DeformationModel& model, const std::vector<glm::vec3>& path, const TickTimingDef& def = {});

}  // namespace palpate
