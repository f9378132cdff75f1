#pragma once
// The paper's three configurations and ours, side by side.

#include <optional>
#include <string>
#include <string_view>

namespace palpate {

enum class SlopeRingMethod {
    Previous,  ///< linear nearest-vertex search + whole model processed every tick (paper, Table 1)
    Hybrid,    ///< the paper's octree searchNode + whole model processed every tick
    Proposed,  ///< the paper's octree searchNode + only the rings processed (faithful to the paper)
    Palpate,   ///< ours: exact warm-started search, incremental ring work, curve-ordered memory
};

std::string_view methodName(SlopeRingMethod method);
std::optional<SlopeRingMethod> parseMethod(std::string_view name);

}  // namespace palpate
