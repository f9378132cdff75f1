#pragma once
// The speed-vs-accuracy sweep on the organ's own shape (docs/accuracy.md, "The organ's own shape"):
// every model, calibrated from the half-space punch as in the punch sweep, pressed at the stomach's
// thin, thick and curved sites and scored against the FEM of the filled organ there, linear and
// hyperelastic. Beside them the slope-ring model with stiffening knots (calibrated from the
// hyperelastic half-space, not from the organ).

#include "engine/accuracy/AccuracySweep.h"
#include "engine/accuracy/OrganReference.h"

#include <string>
#include <vector>

namespace palpate {

struct OrganSweepDef {
    /// Models, tissue, timing, progress and cancel as in the punch sweep; its shapes and sizes are
    /// ignored and its press depth is set per site (OrganReference::maxDepthMm).
    SweepDef sweep;
    GeneratedShape shape = GeneratedShape::Stomach;
    std::vector<std::size_t> sizes{1442, 3970};
    OrganReferenceDef reference;  ///< its contact is sweep.contact
    bool stiffeningSeries = true; ///< also the slope-ring model (sweep.maxRings rings) with knots
};

/// What the reference was at one site of one mesh.
struct OrganSiteSummary {
    std::size_t vertices = 0;
    OrganSite site;
    double depthMm = 0.0;
    double linearForceN = 0.0;
    double hyperelasticForceN = 0.0;   ///< at the deepest depth reached
    double hyperelasticDepthMm = 0.0;
    bool hyperelasticCompleted = false;
    std::string failure;
    std::size_t nodes = 0, tets = 0;
    double seconds = 0.0;
};

struct OrganSweepResult {
    SweepResult sweep;                   ///< the points (error: against the linear FEM; hyperelastic errors beside)
    std::vector<OrganSiteSummary> sites;
    StiffeningCalibration stiffening;    ///< the knots the stiffening series ran with
};

/// Runs it. Throws std::invalid_argument for a bad definition.
OrganSweepResult runOrganSweep(const OrganSweepDef& def);

/// {"reference": "fem", "sites": [...], "points": [...]} with each point's "site" and
/// "displacement_error_hyperelastic" / "force_error_hyperelastic" (null when not measured).
std::string organSweepToJson(const OrganSweepResult& result, const OrganSweepDef& def);

}  // namespace palpate
