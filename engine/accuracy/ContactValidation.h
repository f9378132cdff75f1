#pragma once
// Validation of the reference FEM against the closed forms (docs/accuracy.md): a flat punch or a Hertz
// sphere pressed into the graded block, with the Boussinesq field of the self-consistent load on
// the far faces; errors as docs/accuracy.md defines them, and the observed convergence rate.

#include "engine/fem/GradedBlock.h"
#include "engine/fem/LinearElasticFem.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace palpate {

enum class ContactReference { Punch, Hertz };

std::string_view contactReferenceName(ContactReference r);
/// "punch" or "hertz"; nullopt otherwise.
std::optional<ContactReference> parseContactReference(std::string_view name);

struct ContactCase {
    ContactReference reference = ContactReference::Punch;
    int aOverH = 8;                      ///< contact radius over the fine spacing
    ElasticMaterial material{0.01, 0.3};
    double contactRadiusMm = 1.0;        ///< a (punch radius, or Hertz contact radius)
    /// Punch: delta = 0.1 a. Hertz: R = a / 0.1, delta = a^2 / R. (Linear FEM: relative errors do not depend on it.)
    double indentationOverRadius = 0.1;
    GradedBlockDef block;            ///< contactRadiusMm and contactRadiusOverSpacing are overwritten
    FemSolverDef solver;
    double loadTolerance = 1e-8;         ///< stop the load iteration when |P_k+1 - P_k| <= tol P
    int maxLoadIterations = 30;
};

struct ContactCaseResult {
    ContactReference reference = ContactReference::Punch;
    int aOverH = 0;
    double poissonRatio = 0.0;
    double displacementError = 0.0;  ///< RMS over surface nodes with r <= 5a of (u_fem - u_closed) / delta
    double forceError = 0.0;         ///< |F_fem - F_closed| / F_closed
    double forceFemN = 0.0;          ///< whole (not quarter) contact force, pushing in
    double forceClosedN = 0.0;
    double indentationMm = 0.0;
    double contactRadiusMm = 0.0;
    double sphereRadiusMm = 0.0;     ///< Hertz only
    std::size_t contactNodes = 0;    ///< surface nodes with prescribed u_z (quarter model)
    std::size_t errorNodes = 0;      ///< surface nodes with r <= 5a (quarter model)
    std::size_t nodes = 0, tets = 0, freeDofs = 0;
    int loadIterations = 0;          ///< P <- F iterations run (until the change was below tolerance)
    double loadFirstChange = 0.0;    ///< |P_1 - P_0| / P_1 (P_0 = reaction with the far faces held at 0)
    double loadLastChange = 0.0;     ///< |P_k - P_k-1| / P_k at the last iteration
    double loadContraction = 0.0;    ///< dF/dP: the factor the iteration contracts by per step
    bool loadSolvedDirectly = false; ///< |dF/dP| too large to iterate: P = F0 / (1 - dF/dP) taken instead
    FemSolveStats solve;             ///< the contact solve (the unit far-field solve is alike)
    double seconds = 0.0;            ///< wall time of the whole case (mesh, assembly, solves)
};

/// Runs one case. Throws std::invalid_argument on bad input.
ContactCaseResult runContactCase(const ContactCase& c);

/// Least-squares slope of log(y) against log(x) (points with y <= 0 are skipped); NaN if < 2 points.
double logLogSlope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace palpate
