#pragma once
// Linear or stiffening tissue (docs/lod.md, "Linear or nonlinear"): the slope-ring model with no
// knots is the cheapest and is enough while the tissue's own stiffening at the scene's depths stays
// within the accuracy target; beyond that the knots calibrated from the hyperelastic reference are
// needed. A pure function on the reference curve (engine/accuracy/StiffeningCalibration.h), so it
// is tested on synthetic curves and the GUI can re-decide without solving again.

#include "engine/accuracy/StiffeningCalibration.h"
#include "engine/lod/LodNeeds.h"

#include <string>
#include <vector>

namespace palpate {

/// A depth the scene presses to, and why ("press target 2 up to 2.5 N", "the plan's press").
struct SceneDepth {
    std::string what;
    double depthMm = 0.0;
};

/// How deep (over the tool radius) to press the reference for a scene whose deepest press is
/// `deepestMm`: 5 % beyond it, within what the reference solves (0.6 to 1.5 radii).
double stiffeningReferenceDepthOverRadius(double deepestMm, double toolRadiusMm);

/// The reference depth at which the tissue carries `forceN` (the curve inverted; beyond its last
/// point its last segment goes on). Non-positive force: 0.
double curveDepthAtForceMm(const std::vector<StiffeningCurvePoint>& curve, double forceN, double firstSlopeMmPerN);

struct StiffeningChoice {
    std::string error;             ///< "" or why no choice was made (no curve, bad needs, no depths)
    bool nonlinear = false;        ///< the knots are needed
    bool feasible = false;         ///< the chosen model meets the target at every depth
    int knots = 0;                 ///< of the chosen model (0 when linear)
    double linearErrorFraction = 0.0;     ///< worst over the depths: |F_linear - F_ref| / F_ref
    double nonlinearErrorFraction = 0.0;  ///< worst over the depths, with the knots
    std::string worstDepthWhat;    ///< the depth where the linear model is worst
    double worstDepthMm = 0.0;
    std::string reason;            ///< for people: what and why
};

/// Chooses for `needs.maxErrorFraction` (the force error allowed, the same fraction as the
/// displacement target) at every depth of `depths` (a depth beyond the reference's deepest point is
/// judged at that point, and the reason says so). `knotted` holds the calibrated knots and |m1|.
StiffeningChoice chooseStiffening(const StiffeningCalibration& reference, const SlopeRingParams& knotted,
                                  const std::vector<SceneDepth>& depths, const LodNeeds& needs);

}  // namespace palpate
