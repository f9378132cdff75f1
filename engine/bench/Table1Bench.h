#pragma once
// The paper's Table 1, measured: time of one haptic tick for the paper's previous, hybrid and
// proposed methods and ours, over a press-and-stroke tool path. The headline is the tick as the
// haptic loop runs it: the model's step (search + deformation + force), the divergence guard and
// the copy of the displaced vertices into the loop's snapshot; the step alone stands beside it.

#include "engine/core/MeshGenerator.h"
#include "engine/models/ContactDef.h"
#include "engine/models/slopering/SlopeRingMethod.h"
#include "engine/models/slopering/SlopeRingParams.h"

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

struct MethodMeasurement {
    double tickUs = 0.0;        ///< median over repeats of the mean tick as the loop runs it
    double stepUs = 0.0;        ///< the same for the model's step alone
    /// Ticks whose touched vertex is not the true nearest (NaN for ours: its contact lies on a
    /// triangle and it reports that triangle's corner with the largest weight, not a nearest vertex).
    double wrongPct = 0.0;
    double maxOffMm = 0.0;      ///< worst extra distance of a wrong touched vertex (when one was found)
};

struct Table1Row {
    GeneratedShape shape = GeneratedShape::Sphere;
    std::size_t vertices = 0;
    std::size_t triangles = 0;
    std::size_t ticks = 0;
    std::array<std::optional<MethodMeasurement>, 4> methods;  ///< indexed by SlopeRingMethod
    /// Ours with the active rings' positions written every tick by the model itself (as the
    /// paper's methods do), for an honest comparison of what the lazy writing saves.
    std::optional<MethodMeasurement> coherentEager;
};

struct Table1Def {
    std::vector<std::size_t> paperSizes{1442, 3970, 5762, 8664};
    std::vector<std::size_t> largeSphereSizes{100'000, 1'000'000};  ///< proposed and ours only
    int repeats = 5;
    double minMeasureMs = 20.0;  ///< each repeat runs the path as often as needed to last this long
    SlopeRingParams params{};
    /// Ours's tool (the paper's methods touch with a point): its path is the same press with the
    /// sphere's centre this radius further out.
    ContactDef contact{};
    std::function<void(const std::string&)> progress;  ///< optional, called with a line per step
};

std::vector<Table1Row> runTable1(const Table1Def& options);

}  // namespace palpate
