#pragma once
// Speed against accuracy for every model (docs/calibration.md): at each Table 1 resolution, each model gets a
// tick cost (over the benchmark's press-and-stroke path) and an error against the flat punch
// (ModelError). Slope-ring models use slopes calibrated from the same material and tool, so the
// error measures the model's structure (rings, resolution), not a badly chosen parameter.

#include "engine/core/MeshGenerator.h"
#include "engine/models/slopering/SlopeRingMethod.h"
#include "engine/accuracy/Calibration.h"
#include "engine/accuracy/ModelError.h"
#include "engine/accuracy/StiffeningCalibration.h"
#include "engine/core/Octree.h"
#include "engine/models/ModelRegistry.h"

#include <atomic>
#include <limits>
#include <functional>
#include <memory>
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
    /// The knots the stiffening series get (engine/accuracy/StiffeningCalibration.h); the organ
    /// sweep fills them from the hyperelastic half-space punch.
    StiffeningCalibration stiffening;
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
    ModelError error;     ///< against the sweep's reference: the punch, or the organ's linear FEM
    bool pareto = false;  ///< on the Pareto front of its shape and site (no point is both faster and more accurate)
    /// The organ sweep only (docs/accuracy.md, "The organ's own shape"): the site pressed and the
    /// error against the hyperelastic FEM there (NaN when the model went deeper than it reached).
    std::string site;
    double hyperelasticDisplacementError = std::numeric_limits<double>::quiet_NaN();
    double hyperelasticForceError = std::numeric_limits<double>::quiet_NaN();
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

/// One configuration the sweep measures (the organ sweep adds stiffening ones).
struct SweepModelDef {
    ModelKind kind;
    SlopeRingMethod method;
    int rings;
    bool stiffening = false;  ///< the slope-ring model with def.stiffening's knots
};
std::vector<SweepModelDef> sweepConfigs(const SweepDef& def);

/// The configuration's model, calibrated from the flat punch of def.contact at `touched`; fills
/// the point's series, model, rings and vertices.
std::unique_ptr<DeformationModel> makeSweepModel(const SweepModelDef& config, const TissueMesh& mesh, const Octree& octree,
                                                 VertexId touched, const SweepDef& def, SweepPoint& point);

/// The benchmark's press-and-stroke path, and one ten times shorter for slow models.
struct SweepPaths {
    std::vector<glm::vec3> full, shortened;
};
SweepPaths makeSweepPaths(const TissueMesh& mesh);
/// The median tick over the path (the short one when the full one would exceed def.maxPathSeconds).
double sweepTickUs(DeformationModel& model, const SweepPaths& paths, const SweepDef& def);

/// Marks, per shape, the points no other point beats in both tick cost and displacement error.
void markParetoFront(std::vector<SweepPoint>& points);

/// The sweep as CSV (header line first) and as JSON {"points": [...]}.
std::string sweepToCsv(const std::vector<SweepPoint>& points);
std::string sweepToJson(const SweepResult& result, const SweepDef& def);

}  // namespace palpate
