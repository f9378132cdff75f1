#pragma once
// Reference hyperelastic FEM (docs/accuracy.md, "Hyperelastic reference"): 4-node tets, total
// Lagrangian (everything on the rest mesh), static equilibrium by Newton's method with a
// backtracking line search on the potential energy, load stepping with step halving on failure.
// Dirichlet conditions by partition, as the linear FEM; a rigid frictionless sphere by a penalty on
// chosen nodes (node-to-sphere). Units: mm, N, N/mm^2; DOF 3i + c is node i's component c.

#include "engine/fem/HyperelasticMaterial.h"
#include "engine/fem/LinearElasticFem.h"
#include "engine/fem/TetMesh.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

/// A rigid frictionless sphere pressed on `nodes`: each node whose deformed position lies inside it
/// by g is pushed out along the normal with kappa g (energy kappa g^2 / 2).
struct SphereContactDef {
    glm::dvec3 centreMm{0.0};
    double radiusMm = 1.0;
    double penaltyNPerMm = 1.0;      ///< kappa
    std::vector<TetNodeId> nodes;    ///< the candidate nodes (e.g. the surface near the contact)
};

struct HyperelasticSolverDef {
    /// The tets (docs/accuracy.md, "Element"): constant strain, or the law's volume term on each
    /// node's volume ratio (nodal pressure, locking-free). Constant strain until the nodal-pressure
    /// hyperelastic FEM is checked against a second solver at large strain.
    TetElement element = TetElement::ConstantStrain;
    FemSolverDef linear;  ///< LDLT or CG for each Newton step (CG tolerance is adapted; its element is not read)
    /// |r_free| <= tol * |internal force| ends the iterations. Rounding leaves ~2e-9 on the graded
    /// block at strains of 1e-4, where the energy's decrease is below its last digit.
    double residualTolerance = 1e-8;
    int maxNewtonIterations = 40;
    int maxLineSearchHalvings = 30;
    int maxStepHalvings = 10;            ///< load stepping: halvings of one step before giving up
};

/// One equilibrium.
struct HyperelasticState {
    std::vector<glm::dvec3> displacementMm;  ///< per node
    std::vector<glm::dvec3> reactionN;       ///< at fixed DOFs: the force the constraint applies (0 elsewhere)
    glm::dvec3 contactForceN{0.0};           ///< the sphere's force on the body
    std::size_t contactNodes = 0;            ///< nodes the sphere pushes
    double maxPenetrationMm = 0.0;           ///< of those nodes into the sphere
    double energyNmm = 0.0;                  ///< stored strain energy + penalty
    int newtonIterations = 0;
    int lineSearchHalvings = 0;
    long linearIterations = 0;               ///< CG iterations summed (0 for LDLT)
    double relativeResidual = 0.0;
    bool converged = false;
    std::string failure;                     ///< "" or why the solve stopped
};

/// What the load applies at load factor t in (0, 1]: prescribed values (read at fixed DOFs) and an
/// optional sphere.
struct HyperelasticLoad {
    std::vector<double> prescribedMm;
    std::optional<SphereContactDef> sphere;
};

struct LoadPathResult {
    std::vector<HyperelasticState> states;  ///< one per requested load factor, in order
    int steps = 0;                          ///< converged load steps taken
    int stepHalvings = 0;
    bool completed = false;                 ///< every requested factor reached
    std::string failure;
    double seconds = 0.0;
};

class HyperelasticFem {
public:
    /// `fixedDofs[d]` != 0 marks DOF d prescribed. Throws std::invalid_argument on a bad mesh
    /// (flat or inverted tet, missing node), material or mask.
    HyperelasticFem(const TetMesh& mesh, const HyperelasticMaterial& material, std::vector<std::uint8_t> fixedDofs,
                    const HyperelasticSolverDef& options = {});
    ~HyperelasticFem();
    HyperelasticFem(const HyperelasticFem&) = delete;
    HyperelasticFem& operator=(const HyperelasticFem&) = delete;

    /// Newton from `initialGuessMm` (per node; its fixed DOFs are replaced by the prescribed values).
    HyperelasticState solve(const HyperelasticLoad& load, const std::vector<glm::dvec3>& initialGuessMm) const;

    /// From rest to each factor in `reportAt` (ascending, in (0, 1]) in steps of at most
    /// `maxStep`; a step that fails is halved (up to maxStepHalvings times). Each step starts from
    /// the previous two states extrapolated.
    /// `onStep` (optional) sees every converged step, e.g. to make the next load follow the force.
    LoadPathResult solvePath(const std::function<HyperelasticLoad(double t)>& load, const std::vector<double>& reportAt,
                             double maxStep,
                             const std::function<void(double t, const HyperelasticState&)>& onStep = {}) const;

    std::size_t nodeCount() const;
    std::size_t tetCount() const;
    std::size_t freeDofCount() const;
    const std::string& solverName() const;

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

}  // namespace palpate
