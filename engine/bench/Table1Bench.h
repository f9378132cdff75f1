#pragma once
// The paper's Table 1, measured: time of one haptic tick (search + deformation + force) for the
// paper's previous, hybrid and proposed methods and ours, over a press-and-stroke tool path.

#include "engine/core/MeshGenerator.h"
#include "engine/models/slopering/SlopeRingMethod.h"
#include "engine/models/slopering/SlopeRingParams.h"

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

struct MethodMeasurement {
    double tickUs = 0.0;        ///< median over repeats of the mean tick time
    double wrongPct = 0.0;      ///< ticks whose touched vertex is not the true nearest
    double maxOffMm = 0.0;      ///< worst extra distance of a wrong touched vertex (when one was found)
};

struct Table1Row {
    GeneratedShape shape = GeneratedShape::Sphere;
    std::size_t vertices = 0;
    std::size_t triangles = 0;
    std::size_t ticks = 0;
    std::array<std::optional<MethodMeasurement>, 4> methods;  ///< indexed by SlopeRingMethod
    /// Ours with the active rings' positions written every tick (as the paper's methods do), for
    /// an honest comparison of what the lazy writing saves.
    std::optional<MethodMeasurement> coherentEager;
};

struct Table1Def {
    std::vector<std::size_t> paperSizes{1442, 3970, 5762, 8664};
    std::vector<std::size_t> largeSphereSizes{100'000, 1'000'000};  ///< proposed and ours only
    int repeats = 5;
    double minMeasureMs = 20.0;  ///< each repeat runs the path as often as needed to last this long
    SlopeRingParams params{};
    std::function<void(const std::string&)> progress;  ///< optional, called with a line per step
};

std::vector<Table1Row> runTable1(const Table1Def& options);

}  // namespace palpate
