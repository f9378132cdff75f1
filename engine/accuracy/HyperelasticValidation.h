#pragma once
// Validation of the hyperelastic reference FEM (docs/accuracy.md, "Hyperelastic reference"):
// homogeneous uniaxial stress against its closed form; the small-strain limit against the linear
// FEM on the same mesh; a rigid sphere pressed into a neo-Hookean half-space (the graded block)
// against Sneddon's exact-sphere solution up to delta/R = 0.3, with Hertz beside it; mesh
// convergence over levels.

#include "engine/fem/GradedBlock.h"
#include "engine/fem/HyperelasticFem.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace palpate {

enum class HyperelasticReference { UniaxialNeoHookean, UniaxialExponential, IndentationNeoHookean };

std::string_view hyperelasticReferenceName(HyperelasticReference r);
/// "uniaxial-neo-hookean", "uniaxial-exponential" or "indentation-neo-hookean"; nullopt otherwise.
std::optional<HyperelasticReference> parseHyperelasticReference(std::string_view name);

// ---- uniaxial stress -------------------------------------------------------------------------

struct UniaxialCase {
    HyperelasticMaterial material;
    std::vector<double> stretches{0.7, 0.85, 1.15, 1.3, 1.5};
    int aOverH = 2;                 ///< the graded block the cube is cut from (any mesh must do)
    double maxStretchStep = 0.05;   ///< load step, in stretch
    HyperelasticSolverDef solver;
};

struct UniaxialPoint {
    double stretch = 1.0;
    double nominalFemNPerMm2 = 0.0, nominalClosedNPerMm2 = 0.0;
    double lateralFem = 1.0, lateralClosed = 1.0;
    double stressError = 0.0;   ///< |P_fem - P_closed| / |P_closed|
    double lateralError = 0.0;  ///< |t_fem - t_closed| / |t_closed - 1| (relative to the lateral strain)
    int newtonIterations = 0;
};

struct UniaxialResult {
    std::vector<UniaxialPoint> points;
    double worstError = 0.0;    ///< max of the stress and lateral errors
    std::size_t nodes = 0, tets = 0, freeDofs = 0;
    int loadSteps = 0;
    bool completed = false;
    std::string failure;
    double seconds = 0.0;
};

UniaxialResult runUniaxialCase(const UniaxialCase& c);

// ---- small-strain limit ----------------------------------------------------------------------

struct SmallStrainCase {
    HyperelasticMaterial material;
    int aOverH = 4;
    double indentationOverRadius = 1e-4;  ///< flat punch of radius 1 mm, far faces at rest
};

struct SmallStrainResult {
    double forceHyperN = 0.0, forceLinearN = 0.0;
    double forceDifference = 0.0;         ///< |F_hyper - F_linear| / F_linear
    double displacementDifference = 0.0;  ///< RMS over the surface within 5a of (u_hyper - u_linear) / delta
    std::size_t freeDofs = 0;
    double seconds = 0.0;
};

SmallStrainResult runSmallStrainCase(const SmallStrainCase& c);

// ---- spherical indentation -------------------------------------------------------------------

struct IndentationCase {
    HyperelasticMaterial material;
    std::vector<double> depthsOverRadius{0.1, 0.2, 0.3};
    /// Cells across the contact radius at the deepest point (Sneddon's a there); the block's fine
    /// zone is sized for it, so shallower points have proportionally fewer.
    int aOverH = 12;
    double sphereRadiusMm = 1.0;
    double maxDepthStepOverRadius = 0.025;
    /// kappa = this * E * h: the penetration is then ~1e-3 h, far below every error measured.
    double penaltyFactor = 1000.0;
    GradedBlockDef block;           ///< contactRadiusMm and contactRadiusOverSpacing are overwritten
    HyperelasticSolverDef solver;
};

struct IndentationPoint {
    double depthOverRadius = 0.0;
    double forceFemN = 0.0;       ///< whole (4 x the quarter)
    double forceSneddonN = 0.0;
    double forceHertzN = 0.0;
    double error = 0.0;           ///< |F_fem - F_sneddon| / F_sneddon
    double contactRadiusFemMm = 0.0;  ///< the outermost node the sphere pushes
    double contactRadiusSneddonMm = 0.0;
    double penetrationOverDepth = 0.0;  ///< the penalty's deepest penetration / delta
    double farFieldMismatch = 0.0;      ///< |P - F| / F of the Boussinesq far field's load
    std::size_t contactNodes = 0;
};

struct IndentationResult {
    int aOverH = 0;
    double poissonRatio = 0.0;
    std::vector<IndentationPoint> points;
    double worstError = 0.0;
    std::size_t nodes = 0, tets = 0, freeDofs = 0;
    std::string solver;
    int loadSteps = 0, newtonIterations = 0;
    long linearIterations = 0;
    bool completed = false;
    std::string failure;
    double seconds = 0.0;
};

IndentationResult runIndentationCase(const IndentationCase& c);

}  // namespace palpate
