#pragma once
// The models that have a stability map, by name, each with its cell runner (the real model driven
// by a fixed press: the tool held at a depth below a vertex for a number of ticks) and its derived
// boundary (StabilityBounds.h). docs/stability.md says what each map sweeps and why.

#include "engine/stability/StabilityMap.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace palpate {

/// The scene every map runs on: a small sphere (cells must be cheap), pressed at one vertex.
struct StabilitySceneDef {
    std::size_t sphereVertices = 242;  ///< generated sphere, radius 50 mm
    double pressDepthMm = 0.5;         ///< tool tip below the touched vertex's rest position
    int slopeRingTicks = 3000;         ///< ticks per slope-ring cell
    int massSpringTicks = 2000;        ///< ticks per explicit mass-spring cell
    int implicitTicks = 200;           ///< ticks per backward-Euler cell (no boundary to resolve)
};

/// slope-ring-gain, slope-ring-relaxation, mass-spring-symplectic, mass-spring-symplectic-vertex,
/// mass-spring-rk4, mass-spring-implicit.
std::vector<std::string> stabilityModelNames();
/// The map's definition for a name; nullopt for an unknown one. Builds the scene (not real-time).
std::optional<StabilityMapSpec> stabilityMapSpec(std::string_view name, const StabilitySceneDef& scene = {});

}  // namespace palpate
