#pragma once
// Slopes and spring stiffness from elasticity (docs/calibration.md): the slope model is linear in the force,
// like a flat rigid punch on a half-space, so the punch solution gives every ring's compliance:
// |m1| = 1 / (2 a E*), |m_k| = |m1| (2/pi) asin(a / r_k), with r_k the mean distance of ring k from
// the touched vertex; and k = 1 / |m1| makes the rendered spring force equal the punch force at the
// same indentation. See docs/accuracy.md.

#include "base/params/Problem.h"

#include "engine/models/slopering/SlopeRingParams.h"
#include "engine/core/TissueMesh.h"
#include "engine/fem/ClosedForms.h"
#include "engine/fem/HyperelasticMaterial.h"

#include <string>
#include <vector>

namespace palpate {

/// The tissue and the tool that presses it.
struct ToolContact {
    ElasticMaterial material;
    double toolRadiusMm = 5.0;  ///< a: radius of the probe's flat tip
    /// b of the hyperelastic reference's exponential law (0: neo-Hookean), from the preset's tissue.
    double stiffeningExponent = 0.0;
};

/// Every value the same (exact): a reference solved for one still holds for the other.
bool sameToolContact(const ToolContact& a, const ToolContact& b);

/// The hyperelastic law of the tissue at large strain: exponential with b > 0, else neo-Hookean,
/// with the contact's E and nu as its small-strain limit.
HyperelasticMaterial hyperelasticMaterialOf(const ToolContact& contact);

/// "" when usable, else a message naming the field.
Problems validateToolContact(const ToolContact& contact);

/// The smallest slope calibration sets (a ring the punch leaves still is set to it).
inline constexpr double kMinCalibratedSlopeMmPerN = 1e-9;

/// The first ring's slope the flat punch gives: |m1| = 1 / (2 a E*), in mm/N.
double punchFirstSlopeMmPerN(const ToolContact& contact);

/// "" when the punch calibration of `contact` gives slopes a slope-ring can render, else why not,
/// naming the Young's modulus and tool radius and the range that would work for them: |m1| must
/// lie between kMinCalibratedSlopeMmPerN and the slope limit's maximum (a contact far too stiff,
/// 1e308 kPa, or far too soft).
std::string calibrationRangeProblem(const ToolContact& contact);

/// Mean distance of each ring 1..ringCount from `touched`, measured in the touched vertex's tangent
/// plane (the half-space's surface). Element 0 is ring 1.
std::vector<double> ringMeanRadiiMm(const TissueMesh& mesh, VertexId touched, int ringCount);

struct SlopeCalibration {
    SlopeRingParams params;              ///< the base parameters with slopes, slope limit and spring k replaced
    std::vector<double> ringRadiiMm;     ///< ring 1..N mean radius
    std::vector<std::string> notes;      ///< what the user should know (rings inside the tool, paper's range)
    bool outsidePaperRange = false;      ///< |m1| >= 1 mm/N
};

/// Calibrated slopes for `base.ringCount` rings around `touched` from the flat-punch solution.
/// Throws std::invalid_argument (naming the field) for a bad contact or vertex.
SlopeCalibration calibrateSlopesFromPunch(const TissueMesh& mesh, VertexId touched, const ToolContact& contact,
                                          const SlopeRingParams& base);

/// Least-squares slopes from per-vertex displacements of a reference solution (e.g. the FEM): for
/// each ring, the slope that best fits u_v = |m_r| F over the ring's vertices (the mean normal
/// displacement divided by F). `normalDisplacementMm[v]` is positive into the tissue. Strict
/// decrease is enforced (noted) so the result passes validation.
SlopeCalibration calibrateSlopesFromDisplacements(const TissueMesh& mesh, VertexId touched,
                                                  const std::vector<double>& normalDisplacementMm, double forceN,
                                                  const SlopeRingParams& base);

/// Per mesh from the reference FEM (docs/calibration.md, docs/accuracy.md): the mesh filled with tetrahedra
/// (engine/fem/SurfaceFill.h: tissue over a rigid core), the tool's footprint pressed by
/// `indentationMm` at `touched`, then calibrateSlopesFromDisplacements on the FEM's surface.
/// `referenceNormalDisplacementMm` (optional) receives the FEM field for error measurement.
SlopeCalibration calibrateSlopesFromFem(const TissueMesh& mesh, VertexId touched, const ToolContact& contact,
                                        const SlopeRingParams& base, double indentationMm = 1.0,
                                        std::vector<double>* referenceNormalDisplacementMm = nullptr);

}  // namespace palpate
