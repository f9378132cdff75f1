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
    int deviceTicks = 10000;           ///< ticks per haptic-device cell (radius-of-influence, ffd)
    int localRingCount = 2;            ///< mass-spring-local: simulated rings (the rest pinned)
};

/// The simulated device of the geometric models' maps (docs/stability.md section 3): one degree of
/// freedom along the touched vertex's normal, mass m and physical damping b, pushed by a hand force
/// that holds it `equilibriumMm` deep at equilibrium, started `perturbation` x that deeper, at rest.
/// b = 0.5 N s/m: the DeviceSpec default's 1 N/mm at 1 kHz is its Colgate-Brown limit, 2 b / T.
struct StabilityDeviceDef {
    double massKg = 0.05;
    double dampingNsPerM = 0.5;
    double equilibriumMm = 0.5;
    double perturbation = 0.2;
};

/// The registry models (ModelRegistry.h modelNames()) each map runs; a model is on the list when
/// some map runs it. Empty for an unknown map.
std::vector<std::string> stabilityMapModels(std::string_view mapName);

/// slope-ring-gain, slope-ring-relaxation, mass-spring-symplectic, mass-spring-symplectic-vertex,
/// mass-spring-rk4, mass-spring-implicit, mass-spring-local, coherent, proposed, hybrid, previous
/// (the gain map on each slope-ring method), volumetric-rings, radius-of-influence, ffd,
/// slope-ring-passivity (the slope ring's rendered force against the simulated device).
std::vector<std::string> stabilityModelNames();
/// The map's definition for a name; nullopt for an unknown one. Builds the scene (not real-time).
std::optional<StabilityMapSpec> stabilityMapSpec(std::string_view name, const StabilitySceneDef& scene = {});

}  // namespace palpate
