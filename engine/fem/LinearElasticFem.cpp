#include "engine/fem/LinearElasticFem.h"

#include <glm/geometric.hpp>

#include <Eigen/Dense>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <chrono>
#include <exception>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>
#include <variant>

namespace palpate {
class ParallelSymmetricMatrix;
}

// Eigen's matrix-free hook (its documented "matrix replacement" pattern): lets Eigen's CG loop
// multiply by K_ff with several threads.
namespace Eigen::internal {
template <>
struct traits<palpate::ParallelSymmetricMatrix> : public traits<SparseMatrix<double>> {};
}  // namespace Eigen::internal

namespace palpate {

/// A symmetric column-major sparse matrix whose product with a vector runs on `threads` threads:
/// column i of a symmetric matrix is also its row i, so each thread gathers its own rows.
class ParallelSymmetricMatrix : public Eigen::EigenBase<ParallelSymmetricMatrix> {
public:
    using Scalar = double;
    using RealScalar = double;
    using StorageIndex = int;
    enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic, IsRowMajor = false };

    ParallelSymmetricMatrix(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& m, int threads)
        : mMatrix(m), mThreads(std::max(1, threads)) {
        // Split the rows so that each thread gets about the same number of nonzeros.
        const int* outer = m.outerIndexPtr();
        mSplit.push_back(0);
        for (int t = 1; t < mThreads; ++t) {
            const long target = long(m.nonZeros()) * t / mThreads;
            mSplit.push_back(int(std::lower_bound(outer, outer + m.outerSize(), target) - outer));
        }
        mSplit.push_back(int(m.outerSize()));
    }
    Eigen::Index rows() const { return mMatrix.rows(); }
    Eigen::Index cols() const { return mMatrix.cols(); }

    template <typename Rhs>
    Eigen::Product<ParallelSymmetricMatrix, Rhs, Eigen::AliasFreeProduct> operator*(const Eigen::MatrixBase<Rhs>& x) const {
        return Eigen::Product<ParallelSymmetricMatrix, Rhs, Eigen::AliasFreeProduct>(*this, x.derived());
    }

    /// dst += alpha * M x
    template <typename Dest, typename Rhs>
    void addProductTo(Dest& dst, const Rhs& x, double alpha) const {
        const int* outer = mMatrix.outerIndexPtr();
        const int* inner = mMatrix.innerIndexPtr();
        const double* value = mMatrix.valuePtr();
        auto rowsOf = [&](int part) {
            for (int i = mSplit[std::size_t(part)]; i < mSplit[std::size_t(part) + 1]; ++i) {
                double sum = 0.0;
                for (int k = outer[i]; k < outer[i + 1]; ++k) sum += value[k] * x[inner[k]];
                dst[i] += alpha * sum;
            }
        };
        std::vector<std::thread> pool;
        for (int t = 1; t < mThreads; ++t) pool.emplace_back(rowsOf, t);
        rowsOf(0);
        for (auto& t : pool) t.join();
    }

private:
    const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& mMatrix;
    int mThreads;
    std::vector<int> mSplit;
};

}  // namespace palpate

namespace Eigen::internal {
template <typename Rhs>
struct generic_product_impl<palpate::ParallelSymmetricMatrix, Rhs, SparseShape, DenseShape, GemvProduct>
    : generic_product_impl_base<palpate::ParallelSymmetricMatrix, Rhs,
                                generic_product_impl<palpate::ParallelSymmetricMatrix, Rhs>> {
    template <typename Dest>
    static void scaleAndAddTo(Dest& dst, const palpate::ParallelSymmetricMatrix& lhs, const Rhs& rhs, const double& alpha) {
        lhs.addProductTo(dst, rhs, alpha);
    }
};
}  // namespace Eigen::internal

namespace palpate {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Triplet = Eigen::Triplet<double, int>;
using Vector = Eigen::VectorXd;
using Ldlt = Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>>;
using IcPreconditioner = Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>>;
using DiagPreconditioner = Eigen::DiagonalPreconditioner<double>;

/// Jacobi on the free DOFs of each node (1x1 to 3x3 blocks of K_ff, inverted): couples a node's
/// x, y and z, which plain Jacobi does not. Interface as Eigen's preconditioners for its CG loop.
class NodeBlockJacobi {
public:
    /// `groupStart[g] .. groupStart[g+1]` are the free DOFs of one node (consecutive).
    void compute(const SparseMatrix& k, std::vector<int> groupStart) {
        mStart = std::move(groupStart);
        mInverse.assign(9 * (mStart.size() - 1), 0.0);
        for (std::size_t g = 0; g + 1 < mStart.size(); ++g) {
            const int first = mStart[g], size = mStart[g + 1] - first;
            Eigen::Matrix3d block = Eigen::Matrix3d::Identity();
            for (int c = 0; c < size; ++c)
                for (SparseMatrix::InnerIterator it(k, first + c); it; ++it)
                    if (it.row() >= first && it.row() < first + size) block(it.row() - first, c) = it.value();
            const Eigen::Matrix3d inverse = block.inverse();
            for (int i = 0; i < 9; ++i) mInverse[9 * g + std::size_t(i)] = inverse(i % 3, i / 3);
        }
    }
    Vector solve(const Vector& r) const {
        Vector z(r.size());
        for (std::size_t g = 0; g + 1 < mStart.size(); ++g) {
            const int first = mStart[g], size = mStart[g + 1] - first;
            const double* inv = &mInverse[9 * g];
            for (int i = 0; i < size; ++i) {
                double sum = 0.0;
                for (int j = 0; j < size; ++j) sum += inv[i + 3 * j] * r[first + j];
                z[first + i] = sum;
            }
        }
        return z;
    }

private:
    std::vector<int> mStart;
    std::vector<double> mInverse;  ///< 3x3 column-major per node (upper-left size x size used)
};

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Gradients of the four linear shape functions and the volume; throws on a flat or inverted tet.
struct TetGradients {
    std::array<glm::dvec3, 4> grad;
    double volumeMm3;
};

TetGradients tetGradients(const std::array<glm::dvec3, 4>& p) {
    const glm::dvec3 e1 = p[1] - p[0], e2 = p[2] - p[0], e3 = p[3] - p[0];
    const double det = tetSignedVolume6(p[0], p[1], p[2], p[3]);
    const double scale = std::max({glm::dot(e1, e1), glm::dot(e2, e2), glm::dot(e3, e3)});
    if (!(det > 1e-12 * scale * std::sqrt(scale)))
        throw std::invalid_argument("tet with non-positive volume (" + std::to_string(det / 6.0) + " mm^3)");
    // Rows of the inverse Jacobian are the gradients of N1..N3 (cross products / det).
    TetGradients g;
    g.grad[1] = glm::cross(e2, e3) / det;
    g.grad[2] = glm::cross(e3, e1) / det;
    g.grad[3] = glm::cross(e1, e2) / det;
    g.grad[0] = -(g.grad[1] + g.grad[2] + g.grad[3]);
    g.volumeMm3 = det / 6.0;
    return g;
}

/// K_ab(i,j) = V (lambda g_a,i g_b,j + mu g_a,j g_b,i + mu delta_ij g_a.g_b).
void tetStiffnessInto(const std::array<glm::dvec3, 4>& p, double lambda, double mu, double* k) {
    const TetGradients g = tetGradients(p);
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
            const glm::dvec3& ga = g.grad[a];
            const glm::dvec3& gb = g.grad[b];
            const double dotAb = glm::dot(ga, gb);
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) {
                    const double v = lambda * ga[i] * gb[j] + mu * ga[j] * gb[i] + (i == j ? mu * dotAb : 0.0);
                    k[(3 * a + i) * 12 + 3 * b + j] = g.volumeMm3 * v;
                }
        }
}

/// Adds the nodal-averaged volumetric stiffness to `k` (docs/accuracy.md, "Element"): node a owns
/// the volume V_a = sum of V_e / 4 over its tets and the volume change theta_a = sum over its tets of
/// (V_e / 4) div u_e / V_a = sum over nodes n of g_an . u_n; the energy is lambda V_a theta_a^2 / 2,
/// so K gets lambda V_a g_an g_am^T for every pair (n, m) of a's patch (whole 3x3 blocks).
void addNodalVolumetricStiffness(const TetMesh& mesh, double lambdaNPerMm2, SparseMatrix& k) {
    const std::size_t nodes = mesh.nodeCount();
    std::vector<TetGradients> grads;
    grads.reserve(mesh.tetCount());
    std::vector<double> nodeVolume(nodes, 0.0);
    std::vector<std::uint32_t> tetsOfStart(nodes + 1, 0);
    for (const auto& tet : mesh.tets) {
        grads.push_back(tetGradients({mesh.nodesMm[tet[0]], mesh.nodesMm[tet[1]], mesh.nodesMm[tet[2]],
                                      mesh.nodesMm[tet[3]]}));
        for (TetNodeId n : tet) {
            nodeVolume[n] += grads.back().volumeMm3 / 4.0;
            ++tetsOfStart[n + 1];
        }
    }
    for (std::size_t n = 0; n < nodes; ++n) tetsOfStart[n + 1] += tetsOfStart[n];
    std::vector<std::uint32_t> tetsOf(tetsOfStart.back());
    {
        std::vector<std::uint32_t> fill(tetsOfStart.begin(), tetsOfStart.end() - 1);
        for (std::size_t t = 0; t < mesh.tetCount(); ++t)
            for (TetNodeId n : mesh.tets[t]) tetsOf[fill[n]++] = std::uint32_t(t);
    }
    // Triplets per chunk of nodes (a node's patch of ~15 nodes gives ~2000 entries).
    constexpr std::size_t kChunkNodes = 1u << 13;
    const int dofs = int(k.rows());
    std::vector<Triplet> triplets;
    std::vector<TetNodeId> patch;
    std::vector<glm::dvec3> g;
    for (std::size_t first = 0; first < nodes; first += kChunkNodes) {
        const std::size_t last = std::min(nodes, first + kChunkNodes);
        triplets.clear();
        for (std::size_t a = first; a < last; ++a) {
            if (!(nodeVolume[a] > 0.0)) continue;  // a node in no tet has no volume to keep
            patch.clear();
            g.clear();
            for (std::uint32_t i = tetsOfStart[a]; i < tetsOfStart[a + 1]; ++i) {
                const std::uint32_t t = tetsOf[i];
                const double weight = grads[t].volumeMm3 / 4.0 / nodeVolume[a];
                for (int b = 0; b < 4; ++b) {
                    const TetNodeId n = mesh.tets[t][std::size_t(b)];
                    const auto at = std::find(patch.begin(), patch.end(), n);
                    if (at == patch.end()) {
                        patch.push_back(n);
                        g.push_back(weight * grads[t].grad[std::size_t(b)]);
                    } else {
                        g[std::size_t(at - patch.begin())] += weight * grads[t].grad[std::size_t(b)];
                    }
                }
            }
            const double scale = lambdaNPerMm2 * nodeVolume[a];
            for (std::size_t p = 0; p < patch.size(); ++p)
                for (std::size_t q = 0; q < patch.size(); ++q)
                    for (int i = 0; i < 3; ++i)
                        for (int j = 0; j < 3; ++j)
                            triplets.emplace_back(int(3 * patch[p]) + i, int(3 * patch[q]) + j,
                                                  scale * g[p][i] * g[q][j]);
        }
        SparseMatrix chunk(dofs, dofs);
        chunk.setFromTriplets(triplets.begin(), triplets.end());
        k += chunk;
    }
}

}  // namespace

std::string_view tetElementName(TetElement element) {
    switch (element) {
        case TetElement::ConstantStrain: return "constant-strain";
        case TetElement::NodalPressure: return "nodal-pressure";
    }
    return "constant-strain";
}

std::optional<TetElement> parseTetElement(std::string_view name) {
    for (const TetElement e : {TetElement::ConstantStrain, TetElement::NodalPressure})
        if (name == tetElementName(e)) return e;
    return std::nullopt;
}

std::array<double, 2> lameConstantsNPerMm2(const ElasticMaterial& m) {
    const double e = m.youngsModulusNPerMm2, nu = m.poissonRatio;
    return {e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), e / (2.0 * (1.0 + nu))};
}

std::array<double, 144> tetStiffness(const std::array<glm::dvec3, 4>& nodesMm, const ElasticMaterial& m) {
    const auto [lambda, mu] = lameConstantsNPerMm2(m);
    std::array<double, 144> k{};
    tetStiffnessInto(nodesMm, lambda, mu, k.data());
    return k;
}

std::array<double, 6> tetStressNPerMm2(const std::array<glm::dvec3, 4>& nodesMm,
                                       const std::array<glm::dvec3, 4>& displacementMm, const ElasticMaterial& m) {
    const TetGradients g = tetGradients(nodesMm);
    double h[3][3] = {};  // displacement gradient du_i/dx_j
    for (int a = 0; a < 4; ++a)
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) h[i][j] += displacementMm[a][i] * g.grad[a][j];
    const auto [lambda, mu] = lameConstantsNPerMm2(m);
    const double trace = h[0][0] + h[1][1] + h[2][2];
    return {lambda * trace + 2 * mu * h[0][0], lambda * trace + 2 * mu * h[1][1], lambda * trace + 2 * mu * h[2][2],
            mu * (h[1][2] + h[2][1]),         mu * (h[0][2] + h[2][0]),         mu * (h[0][1] + h[1][0])};
}

struct StiffnessMatrix::Data {
    std::size_t nodes = 0;
    std::size_t tets = 0;
    SparseMatrix k;  ///< full symmetric K (both triangles), global numbering, complete 3x3 node blocks
    double assemblySeconds = 0;
};

StiffnessMatrix::StiffnessMatrix(const TetMesh& mesh, const ElasticMaterial& material, TetElement element) {
    if (const std::string e = joinedMessages(validateElasticMaterial(material)); !e.empty())
        throw std::invalid_argument(e);
    if (mesh.nodesMm.empty() || mesh.tets.empty()) throw std::invalid_argument("empty tet mesh");
    for (const auto& p : mesh.nodesMm)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::invalid_argument("non-finite node position");
    for (const auto& t : mesh.tets)
        for (TetNodeId n : t)
            if (n >= mesh.nodeCount()) throw std::invalid_argument("tet refers to a missing node");

    auto data = std::make_shared<Data>();
    data->nodes = mesh.nodeCount();
    data->tets = mesh.tetCount();
    const int dofs = int(mesh.dofCount());

    // Assembly: triplets per chunk of tets, summed into K (bounds the triplet memory on big meshes).
    // All 144 entries of every tet go in, zeros too, so every node pair's 3x3 block is stored whole.
    const auto start = std::chrono::steady_clock::now();
    const auto [lameLambda, mu] = lameConstantsNPerMm2(material);
    // The nodal-pressure element keeps the mu term per tet (lambda -> 0) and takes the lambda term,
    // the one that locks, at the nodes below: the same split the hyperelastic laws' energies have
    // (mu/2 psi per tet, lambda/2 (ln J)^2 of the volume change).
    const bool nodalPressure = element == TetElement::NodalPressure;
    const double lambda = nodalPressure ? 0.0 : lameLambda;
    constexpr std::size_t kChunkTets = 1u << 16;
    SparseMatrix& k = data->k;
    k.resize(dofs, dofs);
    std::vector<Triplet> triplets;
    triplets.reserve(std::min(mesh.tetCount(), kChunkTets) * 144);
    double ke[144];
    for (std::size_t first = 0; first < mesh.tetCount(); first += kChunkTets) {
        const std::size_t last = std::min(mesh.tetCount(), first + kChunkTets);
        triplets.clear();
        for (std::size_t t = first; t < last; ++t) {
            const auto& tet = mesh.tets[t];
            const std::array<glm::dvec3, 4> p{mesh.nodesMm[tet[0]], mesh.nodesMm[tet[1]], mesh.nodesMm[tet[2]],
                                              mesh.nodesMm[tet[3]]};
            try {
                tetStiffnessInto(p, lambda, mu, ke);
            } catch (const std::invalid_argument& e) {
                throw std::invalid_argument("tet " + std::to_string(t) + ": " + e.what());
            }
            for (int a = 0; a < 4; ++a)
                for (int i = 0; i < 3; ++i)
                    for (int b = 0; b < 4; ++b)
                        for (int j = 0; j < 3; ++j)
                            triplets.emplace_back(int(3 * tet[a]) + i, int(3 * tet[b]) + j, ke[(3 * a + i) * 12 + 3 * b + j]);
        }
        SparseMatrix chunk(dofs, dofs);
        chunk.setFromTriplets(triplets.begin(), triplets.end());
        if (first == 0)
            k = std::move(chunk);
        else
            k += chunk;
    }
    if (nodalPressure) addNodalVolumetricStiffness(mesh, lameLambda, k);
    k.makeCompressed();
    data->assemblySeconds = secondsSince(start);
    mData = std::move(data);
}

StiffnessMatrix StiffnessMatrix::rotated(const glm::dmat3& rotation) const {
    // K'_ab = R K_ab R^T for every stored 3x3 node block, R's rows being the new axes.
    double r[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[i][j] = rotation[j][i];  // glm is column-major: m[col][row]
    auto data = std::make_shared<Data>(*mData);
    SparseMatrix& k = data->k;
    const int* outer = k.outerIndexPtr();
    const int* inner = k.innerIndexPtr();
    double* value = k.valuePtr();
    for (Eigen::Index node = 0; node < Eigen::Index(data->nodes); ++node) {
        const int c0 = int(3 * node);
        const int length = outer[c0 + 1] - outer[c0];
        if (length % 3 != 0 || outer[c0 + 2] - outer[c0 + 1] != length || outer[c0 + 3] - outer[c0 + 2] != length)
            throw std::logic_error("stiffness matrix lost its 3x3 block structure");
        for (int g = 0; g < length; g += 3) {
            double m[3][3], rm[3][3];
            for (int j = 0; j < 3; ++j)
                for (int i = 0; i < 3; ++i) m[i][j] = value[outer[c0 + j] + g + i];
            if (inner[outer[c0] + g] % 3 != 0 || inner[outer[c0 + 2] + g + 2] != inner[outer[c0] + g] + 2)
                throw std::logic_error("stiffness matrix lost its 3x3 block structure");
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) rm[i][j] = r[i][0] * m[0][j] + r[i][1] * m[1][j] + r[i][2] * m[2][j];
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    value[outer[c0 + j] + g + i] = rm[i][0] * r[j][0] + rm[i][1] * r[j][1] + rm[i][2] * r[j][2];
        }
    }
    StiffnessMatrix out = *this;
    out.mData = std::move(data);
    return out;
}

std::size_t StiffnessMatrix::nodeCount() const { return mData->nodes; }
std::size_t StiffnessMatrix::tetCount() const { return mData->tets; }
double StiffnessMatrix::assemblySeconds() const { return mData->assemblySeconds; }

struct LinearElasticFem::Impl {
    std::size_t nodes = 0;
    std::size_t tets = 0;
    std::vector<std::uint8_t> fixed;
    std::vector<int> freeIndex;  ///< global DOF -> index among free DOFs, or -1
    std::size_t freeCount = 0;
    std::shared_ptr<const StiffnessMatrix::Data> stiffness;
    const SparseMatrix* kp = nullptr;  ///< &stiffness->k
    SparseMatrix kFree;          ///< K_ff
    /// LDLT factors, or the CG preconditioner (shared read-only by concurrent solves).
    std::variant<std::monostate, Ldlt, IcPreconditioner, DiagPreconditioner, NodeBlockJacobi> solver;
    FemSolverDef options;
    std::string solverName;
    double assemblySeconds = 0;
    double factorSeconds = 0;
};

LinearElasticFem::LinearElasticFem(const TetMesh& mesh, const ElasticMaterial& material,
                                   std::vector<std::uint8_t> fixedDofs, const FemSolverDef& options)
    : LinearElasticFem(StiffnessMatrix(mesh, material, options.element), std::move(fixedDofs), options) {}

LinearElasticFem::LinearElasticFem(const StiffnessMatrix& stiffness, std::vector<std::uint8_t> fixedDofs,
                                   const FemSolverDef& options)
    : mImpl(std::make_unique<Impl>()) {
    Impl& s = *mImpl;
    s.stiffness = stiffness.mData;
    s.kp = &s.stiffness->k;
    s.nodes = s.stiffness->nodes;
    s.tets = s.stiffness->tets;
    s.assemblySeconds = s.stiffness->assemblySeconds;
    const int dofs = int(3 * s.nodes);
    if (fixedDofs.size() != std::size_t(dofs))
        throw std::invalid_argument("fixed-DOF mask has " + std::to_string(fixedDofs.size()) + " entries, mesh has " +
                                    std::to_string(dofs) + " DOFs");
    s.fixed = std::move(fixedDofs);
    s.options = options;
    const SparseMatrix& k = *s.kp;
    auto start = std::chrono::steady_clock::now();

    // Partition: K_ff keeps the global order of the free DOFs.
    s.freeIndex.assign(std::size_t(dofs), -1);
    for (int d = 0; d < dofs; ++d)
        if (!s.fixed[std::size_t(d)]) s.freeIndex[std::size_t(d)] = int(s.freeCount++);
    if (s.freeCount == 0) throw std::invalid_argument("every DOF is fixed: nothing to solve");
    {
        std::vector<Triplet> freeTriplets;
        freeTriplets.reserve(std::size_t(k.nonZeros()));
        for (int col = 0; col < dofs; ++col) {
            const int fc = s.freeIndex[std::size_t(col)];
            if (fc < 0) continue;
            for (SparseMatrix::InnerIterator it(k, col); it; ++it) {
                const int fr = s.freeIndex[std::size_t(it.row())];
                if (fr >= 0) freeTriplets.emplace_back(fr, fc, it.value());
            }
        }
        s.kFree.resize(int(s.freeCount), int(s.freeCount));
        s.kFree.setFromTriplets(freeTriplets.begin(), freeTriplets.end());
        s.kFree.makeCompressed();
    }

    FemSolverKind kind = options.kind;
    if (kind == FemSolverKind::Auto)
        kind = s.freeCount <= options.directMaxFreeDofs ? FemSolverKind::DirectLdlt : FemSolverKind::ConjugateGradient;
    if (kind == FemSolverKind::DirectLdlt) {
        auto& ldlt = s.solver.emplace<Ldlt>();
        ldlt.compute(s.kFree);
        if (ldlt.info() != Eigen::Success)
            throw std::runtime_error("LDLT factorization failed (is the body held against rigid motion?)");
        s.solverName = "ldlt";
    } else if (options.preconditioner == FemPreconditioner::IncompleteCholesky) {
        auto& ic = s.solver.emplace<IcPreconditioner>();
        ic.compute(s.kFree);
        if (ic.info() != Eigen::Success) throw std::runtime_error("incomplete Cholesky preconditioner failed");
        s.solverName = "cg+ic";
    } else if (options.preconditioner == FemPreconditioner::Diagonal) {
        s.solver.emplace<DiagPreconditioner>().compute(s.kFree);
        s.solverName = "cg+diag";
    } else {
        std::vector<int> groupStart;
        for (std::size_t n = 0; n < s.nodes; ++n)
            for (int i = 0; i < 3; ++i)
                if (const int f = s.freeIndex[3 * n + std::size_t(i)]; f >= 0) {
                    groupStart.push_back(f);  // the node's first free DOF opens its group
                    break;
                }
        groupStart.push_back(int(s.freeCount));
        s.solver.emplace<NodeBlockJacobi>().compute(s.kFree, std::move(groupStart));
        s.solverName = "cg+block";
    }
    s.factorSeconds = secondsSince(start);
}

LinearElasticFem::~LinearElasticFem() = default;

FemSolution LinearElasticFem::solve(const std::vector<double>& prescribedMm) const {
    return solveWithThreads(prescribedMm, mImpl->options.threads > 0 ? mImpl->options.threads
                                                                      : int(std::max(1u, std::thread::hardware_concurrency())));
}

FemSolution LinearElasticFem::solveWithThreads(const std::vector<double>& prescribedMm, int threads) const {
    const Impl& s = *mImpl;
    const std::size_t dofs = 3 * s.nodes;
    if (prescribedMm.size() != dofs)
        throw std::invalid_argument("prescribed values: " + std::to_string(prescribedMm.size()) + " entries, expected " +
                                    std::to_string(dofs));
    const auto start = std::chrono::steady_clock::now();
    Vector full = Vector::Zero(Eigen::Index(dofs));
    for (std::size_t d = 0; d < dofs; ++d)
        if (s.fixed[d]) {
            if (!std::isfinite(prescribedMm[d])) throw std::invalid_argument("non-finite prescribed displacement");
            full[Eigen::Index(d)] = prescribedMm[d];
        }
    // b_f = -K_fp u_p: K times the prescribed-only vector, read at the free DOFs.
    const Vector kUp = *s.kp * full;
    Vector b(Eigen::Index(s.freeCount));
    for (std::size_t d = 0; d < dofs; ++d)
        if (s.freeIndex[d] >= 0) b[s.freeIndex[d]] = -kUp[Eigen::Index(d)];

    FemSolution out;
    out.stats.solver = s.solverName;
    out.stats.freeDofs = s.freeCount;
    out.stats.fixedDofs = dofs - s.freeCount;
    out.stats.assemblySeconds = s.assemblySeconds;
    out.stats.factorSeconds = s.factorSeconds;
    Vector uFree;
    const double bNorm = b.norm();
    if (bNorm == 0.0) {
        uFree = Vector::Zero(b.size());
    } else if (const auto* ldlt = std::get_if<Ldlt>(&s.solver)) {
        uFree = ldlt->solve(b);
    } else {
        // Eigen's ConjugateGradient loop, called directly so that concurrent solves share K_ff and
        // the preconditioner (the solver object itself keeps per-solve state).
        uFree = Vector::Zero(b.size());
        Eigen::Index iterations = s.options.cgMaxIterations;
        double tolerance = s.options.cgRelativeTolerance;
        const ParallelSymmetricMatrix k(s.kFree, threads);
        if (const auto* ic = std::get_if<IcPreconditioner>(&s.solver))
            Eigen::internal::conjugate_gradient(k, b, uFree, *ic, iterations, tolerance);
        else if (const auto* diag = std::get_if<DiagPreconditioner>(&s.solver))
            Eigen::internal::conjugate_gradient(k, b, uFree, *diag, iterations, tolerance);
        else
            Eigen::internal::conjugate_gradient(k, b, uFree, std::get<NodeBlockJacobi>(s.solver), iterations,
                                                tolerance);
        out.stats.iterations = int(iterations);
        out.stats.converged = tolerance <= s.options.cgRelativeTolerance;
    }
    out.stats.relativeResidual = bNorm > 0.0 ? (s.kFree * uFree - b).norm() / bNorm : 0.0;

    for (std::size_t d = 0; d < dofs; ++d)
        if (s.freeIndex[d] >= 0) full[Eigen::Index(d)] = uFree[s.freeIndex[d]];
    const Vector reaction = *s.kp * full;
    out.displacementMm.resize(s.nodes);
    out.reactionN.assign(s.nodes, glm::dvec3(0.0));
    for (std::size_t n = 0; n < s.nodes; ++n)
        for (int i = 0; i < 3; ++i) {
            const std::size_t d = 3 * n + std::size_t(i);
            out.displacementMm[n][i] = full[Eigen::Index(d)];
            if (s.fixed[d]) out.reactionN[n][i] = reaction[Eigen::Index(d)];
        }
    out.stats.solveSeconds = secondsSince(start);
    return out;
}

std::vector<FemSolution> LinearElasticFem::solveMany(const std::vector<std::vector<double>>& prescribedMm) const {
    std::vector<FemSolution> out(prescribedMm.size());
    std::vector<std::exception_ptr> errors(prescribedMm.size());
    if (prescribedMm.empty()) return out;
    const int cores = mImpl->options.threads > 0 ? mImpl->options.threads
                                                 : int(std::max(1u, std::thread::hardware_concurrency()));
    const std::size_t threads = std::clamp<std::size_t>(std::size_t(cores), 1, prescribedMm.size());
    const int threadsPerSolve = std::max(1, cores / int(threads));
    auto work = [&](std::size_t first) {
        for (std::size_t i = first; i < prescribedMm.size(); i += threads) {
            try {
                out[i] = solveWithThreads(prescribedMm[i], threadsPerSolve);
            } catch (...) {
                errors[i] = std::current_exception();
            }
        }
    };
    std::vector<std::thread> pool;
    for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work, t);
    work(0);
    for (auto& t : pool) t.join();
    for (auto& e : errors)
        if (e) std::rethrow_exception(e);
    return out;
}

std::size_t LinearElasticFem::nodeCount() const { return mImpl->nodes; }
std::size_t LinearElasticFem::tetCount() const { return mImpl->tets; }
std::size_t LinearElasticFem::freeDofCount() const { return mImpl->freeCount; }
std::size_t LinearElasticFem::fixedDofCount() const { return 3 * mImpl->nodes - mImpl->freeCount; }
const std::string& LinearElasticFem::solverName() const { return mImpl->solverName; }

}  // namespace palpate
