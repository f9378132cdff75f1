#pragma once
// Reference linear-elastic FEM (docs/accuracy.md): 4-node tets, isotropic (E, nu), small strain, static,
// with constant strain per tet or with the volume change averaged at the nodes (locking-free as nu -> 0.5).
// K is assembled from triplets; Dirichlet conditions by partition into free and fixed DOFs (never
// penalty); a direct LDLT or a preconditioned conjugate-gradient solve. Units: mm, N, N/mm^2.
// DOF numbering: node i owns DOFs 3i (x), 3i+1 (y), 3i+2 (z).

#include "engine/fem/ClosedForms.h"
#include "engine/fem/TetMesh.h"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace palpate {

enum class FemSolverKind {
    Auto,               ///< direct up to FemSolverDef::directMaxFreeDofs, CG above
    DirectLdlt,         ///< Eigen SimplicialLDLT (AMD ordering)
    ConjugateGradient,  ///< Eigen ConjugateGradient with the preconditioner below
};

enum class FemPreconditioner {
    IncompleteCholesky,  ///< Eigen IncompleteCholesky (AMD): half the iterations, each ~5x dearer (measured)
    Diagonal,            ///< Jacobi: the faster of the two on the block and the filler (measured)
    NodeBlockJacobi,     ///< Jacobi with each node's 3x3 block inverted (~12 % fewer iterations than Diagonal)
};

/// How a tet's volume change is taken (docs/accuracy.md, "Element").
enum class TetElement {
    /// Constant strain per tet: locks as nu -> 0.5 (too stiff: 4-node tets cannot keep the volume).
    ConstantStrain,
    /// Average nodal pressure (after Bonet & Burton 1998): the mu term per tet, the lambda term of
    /// the volume change averaged over each node's tets, so one volume constraint per node instead
    /// of per tet.
    NodalPressure,
};

std::string_view tetElementName(TetElement element);
/// "constant-strain" or "nodal-pressure"; nullopt otherwise.
std::optional<TetElement> parseTetElement(std::string_view name);

struct FemSolverDef {
    /// The element K is assembled from (StiffnessMatrix); read where K is built from a mesh. The
    /// tissue presets' nu (0.45-0.49) needs the locking-free one.
    TetElement element = TetElement::NodalPressure;
    FemSolverKind kind = FemSolverKind::Auto;
    /// Auto picks LDLT at or below this many free DOFs. Measured on the graded block: LDLT and CG
    /// both ~0.03 s at 1.4k DOFs, LDLT 10x slower at 5k (3D fill); see docs/accuracy.md.
    std::size_t directMaxFreeDofs = 3000;
    FemPreconditioner preconditioner = FemPreconditioner::Diagonal;
    /// |K_ff u_f - b_f| / |b_f| at which CG stops. Measured: displacements then lie within ~3 tol
    /// (relative to the largest) of a 1e-11 solve, so 1e-6 is far below the errors we measure.
    double cgRelativeTolerance = 1e-6;
    int cgMaxIterations = 20000;
    int threads = 0;  ///< for the CG product; 0 = one per core
};

/// What one solve did: for reports and the CLI.
struct FemSolveStats {
    std::string solver;            ///< "ldlt", "cg+ic", "cg+diag" or "cg+block"
    std::size_t freeDofs = 0;
    std::size_t fixedDofs = 0;
    int iterations = 0;            ///< CG iterations (0 for LDLT)
    double relativeResidual = 0;   ///< |K_ff u_f - b_f| / |b_f|, recomputed after the solve
    bool converged = true;
    double assemblySeconds = 0;    ///< K (once per StiffnessMatrix)
    double factorSeconds = 0;      ///< partition + factorization / preconditioner (once)
    double solveSeconds = 0;       ///< this solve
};

struct FemSolution {
    std::vector<glm::dvec3> displacementMm;  ///< per node
    /// Per node: (K_full u) at fixed DOFs = the force the constraint applies to the body; 0 at free DOFs.
    std::vector<glm::dvec3> reactionN;
    FemSolveStats stats;
};

/// Lame constants (lambda, mu) in N/mm^2.
std::array<double, 2> lameConstantsNPerMm2(const ElasticMaterial& m);

/// 12x12 stiffness of one tet (row-major, DOF order n0x n0y n0z n1x ...). Throws on a flat tet.
std::array<double, 144> tetStiffness(const std::array<glm::dvec3, 4>& nodesMm, const ElasticMaterial& m);

/// Constant stress of a tet (N/mm^2) in Voigt order xx, yy, zz, yz, xz, xy.
std::array<double, 6> tetStressNPerMm2(const std::array<glm::dvec3, 4>& nodesMm,
                                       const std::array<glm::dvec3, 4>& displacementMm, const ElasticMaterial& m);

/// K of one mesh and material, assembled once from triplets; shared (not copied) by the systems
/// built on it, so several partitions or frames reuse one assembly.
class StiffnessMatrix {
public:
    /// Throws std::invalid_argument on a bad mesh (missing nodes, non-finite, flat or inverted tets)
    /// or material.
    StiffnessMatrix(const TetMesh& mesh, const ElasticMaterial& material, TetElement element);
    /// The same K in a rotated frame, u' = R u at every node (R K_ab R^T per node block), as if
    /// the rotated mesh had been assembled. For new axes e1, e2, e3: R = transpose(dmat3(e1, e2, e3)).
    StiffnessMatrix rotated(const glm::dmat3& rotation) const;

    std::size_t nodeCount() const;
    std::size_t tetCount() const;
    double assemblySeconds() const;

private:
    struct Data;
    std::shared_ptr<const Data> mData;
    friend class LinearElasticFem;
};

/// The assembled system of one mesh, material and set of fixed DOFs: assembled and factorized once,
/// solved for any prescribed values (the same partition) as often as needed.
class LinearElasticFem {
public:
    /// `fixedDofs[d]` != 0 marks DOF d as prescribed (size 3 * nodes). Throws std::invalid_argument
    /// on a bad mesh, material or mask, std::runtime_error if the factorization fails.
    LinearElasticFem(const TetMesh& mesh, const ElasticMaterial& material, std::vector<std::uint8_t> fixedDofs,
                     const FemSolverDef& options = {});
    /// The same on an already assembled K.
    LinearElasticFem(const StiffnessMatrix& stiffness, std::vector<std::uint8_t> fixedDofs,
                     const FemSolverDef& options = {});
    ~LinearElasticFem();
    LinearElasticFem(const LinearElasticFem&) = delete;
    LinearElasticFem& operator=(const LinearElasticFem&) = delete;

    /// Static solve: `prescribedMm` has one value per DOF (read only at fixed DOFs).
    FemSolution solve(const std::vector<double>& prescribedMm) const;
    /// Several load cases of the same partition, solved concurrently (the cores shared among them).
    std::vector<FemSolution> solveMany(const std::vector<std::vector<double>>& prescribedMm) const;

    std::size_t nodeCount() const;
    std::size_t tetCount() const;
    std::size_t freeDofCount() const;
    std::size_t fixedDofCount() const;
    const std::string& solverName() const;

private:
    FemSolution solveWithThreads(const std::vector<double>& prescribedMm, int threads) const;
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

}  // namespace palpate
