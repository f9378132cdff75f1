#pragma once
// Stiffening knots from the hyperelastic reference (docs/calibration.md, "Knots from the hyperelastic
// reference"): a rigid flat punch of the tool's radius pressed into a hyperelastic half-space (the
// graded block, frictionless) gives F(delta); divided by the same mesh's force at a depth where the
// response is linear, it is the stiffening ratio rho(delta) = F / (2 a E* delta), free of the mesh's
// small-strain error. The slope-ring model's sink |m1| E(F) then follows the reference when
// E(F(delta)) = 2 a E* delta: knots at the reference's forces, compliances from its segments.

#include "base/params/Problem.h"

#include "engine/fem/HyperelasticMaterial.h"
#include "engine/models/slopering/SlopeRingParams.h"

#include <string>
#include <vector>

namespace palpate {

struct StiffeningCalibrationDef {
    HyperelasticMaterial material;          ///< the law, b, and E, nu of the small-strain limit
    double toolRadiusMm = 5.0;              ///< a: the flat punch the linear slopes are calibrated for
    /// Depths of the reference curve over a, ascending; knots are placed at all but the last, the
    /// last piece's compliance comes from the last two. The first must be small enough to be linear.
    std::vector<double> depthsOverRadius{0.01, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
    /// Extra depths where the curve is evaluated but no knot is placed (the knots' interpolation
    /// error is measured there).
    std::vector<double> checkDepthsOverRadius{0.05, 0.15, 0.25, 0.35, 0.45, 0.55};
    int aOverH = 4;                         ///< cells across the punch radius (the ratio cancels most mesh error)
    double maxStepOverRadius = 0.025;       ///< load step
};

/// Knot depths evenly spaced up to `deepestOverRadius` (after a linear first depth of 0.01), with a
/// check depth halfway between each pair: the definition for pressing that deep.
void setStiffeningDepths(StiffeningCalibrationDef& def, double deepestOverRadius, int knots = 6);

/// "" when usable, else a message naming the field.
Problems validateStiffeningCalibrationDef(const StiffeningCalibrationDef& def);

/// One depth of the reference force-indentation curve.
struct StiffeningCurvePoint {
    double depthMm = 0.0;
    double forceN = 0.0;        ///< 2 a E* delta rho: the reference with the mesh's linear error removed
    double ratio = 1.0;         ///< rho = F / (2 a E* delta)
    bool knot = false;          ///< the knots are fitted through this depth (the others only check them)
};

struct StiffeningCalibration {
    std::vector<StiffeningCurvePoint> curve;  ///< every depth reached, ascending
    int knots = 0;
    std::vector<double> knotForceN;           ///< F_1 < ... < F_K
    std::vector<double> knotCompliance;       ///< q_1 >= ... >= q_K, in (0, 1]
    /// The knots' largest force error against the curve, |F_knots(delta) - F(delta)| / F(delta)
    /// over every depth of the curve (the check depths are between knots).
    double worstKnotErrorFraction = 0.0;
    std::vector<std::string> notes;
    bool completed = false;                   ///< every depth reached
    std::string failure;
    std::size_t freeDofs = 0;
    double seconds = 0.0;
};

/// Runs the punch on the hyperelastic half-space and derives the knots. Throws std::invalid_argument
/// for a bad definition. A load path that stops early keeps the depths reached (completed = false).
StiffeningCalibration calibrateStiffening(const StiffeningCalibrationDef& def);

/// Knots for a curve of (depth, ratio) pairs (ascending depth, first ratio 1): the pure part of
/// calibrateStiffening, for tests and stored curves. `firstSlopeMmPerN` is |m1| = 1 / (2 a E*).
StiffeningCalibration knotsFromCurve(std::vector<StiffeningCurvePoint> curve, double firstSlopeMmPerN);

/// Writes the knots into `params` (stiffeningKnots, stiffeningForceN, stiffeningCompliance).
void applyStiffening(const StiffeningCalibration& calibration, SlopeRingParams& params);

/// The force the knots give at depth `depthMm` of tissue sink: E^-1(depth / |m1|).
double knotForceAtDepthN(const SlopeRingParams& params, double depthMm);

/// The curve's force at `depthMm`, linear between its points; beyond the last its last segment goes
/// on (as the knots' last piece does, so the two agree there by construction: unmeasured).
double curveForceAtDepthN(const std::vector<StiffeningCurvePoint>& curve, double depthMm, double firstSlopeMmPerN);

}  // namespace palpate
