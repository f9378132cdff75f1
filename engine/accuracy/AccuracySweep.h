#pragma once
// Speed against accuracy for every model (docs/calibration.md): at each Table 1 resolution, each model gets a
// tick cost (over the benchmark's press-and-stroke path) and an error against the flat punch
// (ModelError). Slope-ring models use slopes calibrated from the same material and tool, so the
// error measures the model's structure (rings, resolution), not a badly chosen parameter.

#include "engine/core/MeshGenerator.h"
#include "engine/models/slopering/SlopeRingMethod.h"
#include "engine/accuracy/Calibration.h"
#include "engine/accuracy/ModelError.h"

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace palpate {

struct SweepDef {
    ToolContact contact;                               ///< tissue and tool the slopes are calibrated for
    std::vector<GeneratedShape> shapes{GeneratedShape::Sphere, GeneratedShape::Stomach};
    std::vector<std::size_t> sizes{1442, 3970, 5762, 8664};
    int maxRings = 8;                                  ///< slope-ring series for 1..maxRings rings
    bool paperMethods = true;                          ///< also previous, hybrid and proposed (2 rings)
    /// Also the other models (engine/models: mass-spring, radius of influence, FFD, volumetric
    /// rings). Where a model has a stiffness with a punch counterpart it is set to 2 a E* (and the
    /// radius of influence to 5a); mass-spring has no closed-form calibration and keeps its defaults.
    bool otherModels = true;
    /// A model whose tick would make the timed path last longer than this is timed on a path ten
    /// times shorter (same stroke speed), so the sweep stays minutes, not hours.
    double maxPathSeconds = 0.5;
    PressDef press;
    int timingRepeats = 3;
    double minMeasureMs = 10.0;
    SlopeRingParams base;                              ///< damping, k_c, mass...; slopes and k are calibrated
    /// Called after each point with the fraction done and a line saying what was measured.
    std::function<void(double fraction, const std::string& line)> progress;
    /// Set (from any thread) to stop early; the points measured so far are returned.
    const std::atomic<bool>* cancel = nullptr;
};

struct SweepPoint {
    std::string series;   ///< chart series: "slope-ring 3 rings", "proposed (paper)", ...
    std::string model;    ///< the registry name: coherent, proposed, hybrid, previous, mass-spring-rk4, ffd, ...
    int rings = 0;
    GeneratedShape shape = GeneratedShape::Sphere;
    std::size_t vertices = 0;
    double tickUs = 0.0;
    ModelError error;
    bool pareto = false;  ///< on the Pareto front of its shape (no point is both faster and more accurate)
};

struct SweepResult {
    std::vector<SweepPoint> points;
    bool cancelled = false;
};

/// The chart series a configuration belongs to: "slope-ring 3 rings", "proposed (paper)"; "" for
/// a configuration the sweep does not measure (the paper's methods with other than 2 rings).
std::string sweepSeriesName(SlopeRingMethod method, int rings);

/// Runs the sweep. Throws std::invalid_argument for a bad definition (naming the field).
SweepResult runSweep(const SweepDef& def);

/// Marks, per shape, the points no other point beats in both tick cost and displacement error.
void markParetoFront(std::vector<SweepPoint>& points);

/// The sweep as CSV (header line first) and as JSON {"points": [...]}.
std::string sweepToCsv(const std::vector<SweepPoint>& points);
std::string sweepToJson(const SweepResult& result, const SweepDef& def);

}  // namespace palpate
