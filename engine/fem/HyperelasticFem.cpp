#include "engine/fem/HyperelasticFem.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <variant>

namespace palpate {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Ldlt = Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>>;
using Cg = Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, Eigen::DiagonalPreconditioner<double>>;

constexpr int kNoFree = -1;

/// Rest-mesh gradients of the four shape functions and the rest volume.
struct RestTet {
    std::array<glm::dvec3, 4> grad;
    double volumeMm3;
};

RestTet restTet(const std::array<glm::dvec3, 4>& p, std::size_t index) {
    const glm::dvec3 e1 = p[1] - p[0], e2 = p[2] - p[0], e3 = p[3] - p[0];
    const double det = tetSignedVolume6(p[0], p[1], p[2], p[3]);
    const double scale = std::max({glm::dot(e1, e1), glm::dot(e2, e2), glm::dot(e3, e3)});
    if (!(det > 1e-12 * scale * std::sqrt(scale)))
        throw std::invalid_argument("tet " + std::to_string(index) + " has non-positive volume");
    RestTet t;
    t.grad[1] = glm::cross(e2, e3) / det;
    t.grad[2] = glm::cross(e3, e1) / det;
    t.grad[3] = glm::cross(e1, e2) / det;
    t.grad[0] = -(t.grad[1] + t.grad[2] + t.grad[3]);
    t.volumeMm3 = det / 6.0;
    return t;
}

double norm(const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x * x;
    return std::sqrt(s);
}

}  // namespace

struct HyperelasticFem::Impl {
    std::vector<glm::dvec3> restMm;
    std::vector<std::array<TetNodeId, 4>> tets;
    std::vector<RestTet> rest;
    HyperelasticLawEvaluator law;  ///< per tet: the whole law, or without its volume term (nodal)
    HyperelasticSolverDef options;
    std::vector<std::uint8_t> fixed;
    std::vector<int> freeIndex;   // per DOF: index among the free DOFs, or kNoFree
    std::vector<std::size_t> freeDof;  // per free index: its DOF
    std::size_t freeCount = 0;
    /// The nodal-pressure element (docs/accuracy.md, "Element"): the law's volume term
    /// lambda/2 (ln J_a)^2 is taken on each node's volume ratio J_a = (sum of J_e V_e / 4) / V_a.
    bool nodal = false;
    double lambda = 0.0;
    std::vector<double> nodeVolume;          ///< V_a: a quarter of each of the node's tets
    std::vector<std::uint32_t> tetsOfStart;  ///< the node's tets: tetsOf[tetsOfStart[a] .. [a + 1])
    std::vector<std::uint32_t> tetsOf;
    SparseMatrix pattern;         // K_ff's sparsity (both triangles), values rewritten per iteration
    std::vector<int> slot;        // per tet, 144 entries: position in pattern's values, or -1
    bool direct = true;
    std::string solverName;

    Impl(const TetMesh& mesh, const HyperelasticMaterial& m, std::vector<std::uint8_t> mask,
         const HyperelasticSolverDef& o)
        : restMm(mesh.nodesMm),
          tets(mesh.tets),
          law(o.element == TetElement::NodalPressure ? HyperelasticLawEvaluator(m).withoutVolumeTerm()
                                                     : HyperelasticLawEvaluator(m)),
          options(o),
          fixed(std::move(mask)),
          nodal(o.element == TetElement::NodalPressure),
          lambda(HyperelasticLawEvaluator(m).lambdaNPerMm2()) {}

    /// The nodes' volumes and tets (after `rest` is set).
    void buildNodePatches() {
        const std::size_t nodes = restMm.size();
        nodeVolume.assign(nodes, 0.0);
        tetsOfStart.assign(nodes + 1, 0);
        for (std::size_t e = 0; e < tets.size(); ++e)
            for (TetNodeId n : tets[e]) {
                nodeVolume[n] += rest[e].volumeMm3 / 4.0;
                ++tetsOfStart[n + 1];
            }
        for (std::size_t n = 0; n < nodes; ++n) tetsOfStart[n + 1] += tetsOfStart[n];
        tetsOf.assign(tetsOfStart.back(), 0);
        std::vector<std::uint32_t> fill(tetsOfStart.begin(), tetsOfStart.end() - 1);
        for (std::size_t e = 0; e < tets.size(); ++e)
            for (TetNodeId n : tets[e]) tetsOf[fill[n]++] = std::uint32_t(e);
    }

    /// The nodes of a's patch (its tets' nodes), each once.
    void patchOf(std::size_t a, std::vector<TetNodeId>& patch) const {
        patch.clear();
        for (std::uint32_t i = tetsOfStart[a]; i < tetsOfStart[a + 1]; ++i)
            for (TetNodeId n : tets[tetsOf[i]])
                if (std::find(patch.begin(), patch.end(), n) == patch.end()) patch.push_back(n);
    }

    /// Each node's volume ratio J_a from the tets' J_e; false when one is not positive.
    bool nodeVolumeRatios(const std::vector<double>& tetJ, std::vector<double>& nodeJ) const {
        nodeJ.assign(restMm.size(), 0.0);
        for (std::size_t e = 0; e < tets.size(); ++e)
            for (TetNodeId n : tets[e]) nodeJ[n] += tetJ[e] * rest[e].volumeMm3 / 4.0;
        for (std::size_t a = 0; a < nodeJ.size(); ++a) {
            if (nodeVolume[a] <= 0.0) continue;
            nodeJ[a] /= nodeVolume[a];
            if (!(nodeJ[a] > 0.0)) return false;
        }
        return true;
    }

    /// Free DOFs whose entry of K_ff may be nonzero: the tets' couplings and each node's own 3x3
    /// block (the sphere's penalty).
    void buildPattern() {
        std::vector<Eigen::Triplet<double>> triplets;
        triplets.reserve(tets.size() * 144 / 2);
        for (const auto& t : tets)
            for (int a = 0; a < 4; ++a)
                for (int b = 0; b < 4; ++b)
                    for (int i = 0; i < 3; ++i)
                        for (int k = 0; k < 3; ++k) {
                            const int r = freeIndex[3 * t[a] + i], c = freeIndex[3 * t[b] + k];
                            if (r != kNoFree && c != kNoFree) triplets.emplace_back(r, c, 0.0);
                        }
        for (std::size_t n = 0; n < restMm.size(); ++n)
            for (int i = 0; i < 3; ++i)
                for (int k = 0; k < 3; ++k) {
                    const int r = freeIndex[3 * n + i], c = freeIndex[3 * n + k];
                    if (r != kNoFree && c != kNoFree) triplets.emplace_back(r, c, 0.0);
                }
        // The nodal volume term couples every pair of nodes of a node's patch.
        std::vector<TetNodeId> patch;
        if (nodal)
            for (std::size_t a = 0; a < restMm.size(); ++a) {
                patchOf(a, patch);
                for (TetNodeId n : patch)
                    for (TetNodeId m : patch)
                        for (int i = 0; i < 3; ++i)
                            for (int k = 0; k < 3; ++k) {
                                const int r = freeIndex[3 * n + std::size_t(i)], c = freeIndex[3 * m + std::size_t(k)];
                                if (r != kNoFree && c != kNoFree) triplets.emplace_back(r, c, 0.0);
                            }
            }
        pattern.resize(Eigen::Index(freeCount), Eigen::Index(freeCount));
        pattern.setFromTriplets(triplets.begin(), triplets.end());
        pattern.makeCompressed();
        slot.assign(tets.size() * 144, -1);
        for (std::size_t e = 0; e < tets.size(); ++e)
            for (int a = 0; a < 4; ++a)
                for (int i = 0; i < 3; ++i)
                    for (int b = 0; b < 4; ++b)
                        for (int k = 0; k < 3; ++k) {
                            const int r = freeIndex[3 * tets[e][std::size_t(a)] + std::size_t(i)];
                            const int c = freeIndex[3 * tets[e][std::size_t(b)] + std::size_t(k)];
                            if (r == kNoFree || c == kNoFree) continue;
                            slot[e * 144 + std::size_t((3 * a + i) * 12 + 3 * b + k)] = positionOf(r, c);
                        }
    }

    int positionOf(int row, int col) const {
        const int* inner = pattern.innerIndexPtr();
        const int begin = pattern.outerIndexPtr()[col], end = pattern.outerIndexPtr()[col + 1];
        const int* found = std::lower_bound(inner + begin, inner + end, row);
        return int(found - inner);
    }

    glm::dmat3 deformationGradient(std::size_t e, const std::vector<double>& u) const {
        glm::dmat3 f(1.0);
        for (int a = 0; a < 4; ++a) {
            const std::size_t n = tets[e][std::size_t(a)];
            const glm::dvec3& g = rest[e].grad[std::size_t(a)];
            for (int col = 0; col < 3; ++col)
                for (int row = 0; row < 3; ++row) f[col][row] += u[3 * n + std::size_t(row)] * g[col];
        }
        return f;
    }

    /// Sphere penalty at node n for displacement u: penetration g, outward normal.
    static bool penetration(const SphereContactDef& s, const glm::dvec3& x, double& gap, glm::dvec3& normal) {
        const glm::dvec3 d = x - s.centreMm;
        const double len = glm::length(d);
        gap = s.radiusMm - len;
        if (!(gap > 0.0) || len == 0.0) return false;
        normal = d / len;
        return true;
    }

    /// Potential energy of `u`; +inf when a tet inverts.
    double energy(const std::vector<double>& u, const SphereContactDef* sphere) const {
        double total = 0.0;
        std::vector<double> tetJ(nodal ? tets.size() : 0);
        for (std::size_t e = 0; e < tets.size(); ++e) {
            const glm::dmat3 f = deformationGradient(e, u);
            const HyperelasticPoint p = law.evaluate(f);
            if (!p.valid) return std::numeric_limits<double>::infinity();
            total += rest[e].volumeMm3 * p.energyNPerMm2;
            if (nodal) tetJ[e] = glm::determinant(f);
        }
        if (nodal) {
            std::vector<double> nodeJ;
            if (!nodeVolumeRatios(tetJ, nodeJ)) return std::numeric_limits<double>::infinity();
            for (std::size_t a = 0; a < nodeJ.size(); ++a)
                if (nodeVolume[a] > 0.0) {
                    const double lnJ = std::log(nodeJ[a]);
                    total += nodeVolume[a] * 0.5 * lambda * lnJ * lnJ;
                }
        }
        if (sphere)
            for (TetNodeId n : sphere->nodes) {
                double gap;
                glm::dvec3 normal;
                const glm::dvec3 x = restMm[n] + glm::dvec3(u[3 * n], u[3 * n + 1], u[3 * n + 2]);
                if (penetration(*sphere, x, gap, normal)) total += 0.5 * sphere->penaltyNPerMm * gap * gap;
            }
        return total;
    }

    /// Gradient of the potential (internal + penalty force) at every DOF and, when `tangent`,
    /// K_ff into pattern's values. False when a tet inverts.
    /// `fixedIncrement` (optional, with `tangent`): a motion of the fixed DOFs still to be applied;
    /// K_fp times it is added to `predictor` (the free DOFs' linearized response to it).
    bool assemble(const std::vector<double>& u, const SphereContactDef* sphere, std::vector<double>& gradient,
                  std::vector<double>* internalOnly, bool tangent, const std::vector<double>* fixedIncrement = nullptr,
                  std::vector<double>* predictor = nullptr) const {
        gradient.assign(u.size(), 0.0);
        if (predictor) predictor->assign(u.size(), 0.0);
        double* values = const_cast<SparseMatrix&>(pattern).valuePtr();
        if (tangent) std::fill(values, values + pattern.nonZeros(), 0.0);
        std::array<double, 81> a{};
        for (std::size_t e = 0; e < tets.size(); ++e) {
            const glm::dmat3 f = deformationGradient(e, u);
            const HyperelasticPoint p = law.evaluate(f);
            if (!p.valid) return false;
            const RestTet& rt = rest[e];
            for (int n = 0; n < 4; ++n) {
                const std::size_t node = tets[e][std::size_t(n)];
                const glm::dvec3& g = rt.grad[std::size_t(n)];
                for (int i = 0; i < 3; ++i) {
                    double v = 0.0;
                    for (int jj = 0; jj < 3; ++jj) v += p.stress[jj][i] * g[jj];
                    gradient[3 * node + std::size_t(i)] += rt.volumeMm3 * v;
                }
            }
            if (!tangent) continue;
            if (!law.tangent(f, a)) return false;
            const int* s = slot.data() + e * 144;
            for (int na = 0; na < 4; ++na) {
                const glm::dvec3& ga = rt.grad[std::size_t(na)];
                for (int nb = 0; nb < 4; ++nb) {
                    const glm::dvec3& gb = rt.grad[std::size_t(nb)];
                    for (int i = 0; i < 3; ++i)
                        for (int k = 0; k < 3; ++k) {
                            const int at = s[(3 * na + i) * 12 + 3 * nb + k];
                            const std::size_t rowDof = 3 * tets[e][std::size_t(na)] + std::size_t(i);
                            const std::size_t colDof = 3 * tets[e][std::size_t(nb)] + std::size_t(k);
                            const bool pushesFree = at < 0 && predictor && freeIndex[rowDof] != kNoFree &&
                                                    freeIndex[colDof] == kNoFree && (*fixedIncrement)[colDof] != 0.0;
                            if (at < 0 && !pushesFree) continue;
                            double v = 0.0;
                            for (int jj = 0; jj < 3; ++jj)
                                for (int l = 0; l < 3; ++l) v += a[std::size_t((3 * i + jj) * 9 + 3 * k + l)] * ga[jj] * gb[l];
                            if (at >= 0) values[at] += rt.volumeMm3 * v;
                            else (*predictor)[rowDof] += rt.volumeMm3 * v * (*fixedIncrement)[colDof];
                        }
                }
            }
        }
        if (nodal && !assembleNodalVolumeTerm(u, gradient, tangent, fixedIncrement, predictor)) return false;
        if (internalOnly) *internalOnly = gradient;
        if (sphere)
            for (TetNodeId n : sphere->nodes) {
                double gap;
                glm::dvec3 normal;
                const glm::dvec3 x = restMm[n] + glm::dvec3(u[3 * n], u[3 * n + 1], u[3 * n + 2]);
                if (!penetration(*sphere, x, gap, normal)) continue;
                const double kappa = sphere->penaltyNPerMm;
                for (int i = 0; i < 3; ++i) gradient[3 * n + std::size_t(i)] -= kappa * gap * normal[i];
                if (!tangent) continue;
                // Gauss-Newton: kappa n n^T (the curvature term -kappa g / |x - c| (I - n n^T) is
                // dropped; it is O(g / R) of the kept one and would make K indefinite).
                for (int i = 0; i < 3; ++i)
                    for (int k = 0; k < 3; ++k) {
                        const int r = freeIndex[3 * n + std::size_t(i)], c = freeIndex[3 * n + std::size_t(k)];
                        if (r != kNoFree && c != kNoFree) values[positionOf(r, c)] += kappa * normal[i] * normal[k];
                    }
            }
        return true;
    }

    /// Adds K entry (row DOF, column DOF) of the free block, or its push on the free DOFs when the
    /// column is a fixed DOF still to move.
    void addEntry(std::size_t rowDof, std::size_t colDof, double v, double* values,
                  const std::vector<double>* fixedIncrement, std::vector<double>* predictor) const {
        const int r = freeIndex[rowDof], c = freeIndex[colDof];
        if (r == kNoFree) return;
        if (c != kNoFree) values[positionOf(r, c)] += v;
        else if (predictor && (*fixedIncrement)[colDof] != 0.0) (*predictor)[rowDof] += v * (*fixedIncrement)[colDof];
    }

    /// The nodal volume term of the nodal-pressure element: its force sum_e pbar_e V_e cof(F_e) g_n
    /// (pbar_e the mean of p_a = lambda ln J_a / J_a over the tet's nodes) and, with `tangent`, its
    /// stiffness: per node V_a U''(J_a) dJ_a dJ_a^T, per tet pbar_e V_e d2J_e. False when a node's
    /// volume ratio is not positive.
    bool assembleNodalVolumeTerm(const std::vector<double>& u, std::vector<double>& gradient, bool tangent,
                                 const std::vector<double>* fixedIncrement, std::vector<double>* predictor) const {
        double* values = const_cast<SparseMatrix&>(pattern).valuePtr();
        std::vector<double> tetJ(tets.size());
        std::vector<std::array<glm::dvec3, 4>> h(tets.size());  // F_e^-T g_n: J_e h_n = cof(F_e) g_n
        for (std::size_t e = 0; e < tets.size(); ++e) {
            const glm::dmat3 f = deformationGradient(e, u);
            tetJ[e] = glm::determinant(f);
            if (!(tetJ[e] > 0.0)) return false;
            const glm::dmat3 inverseTranspose = glm::transpose(glm::inverse(f));
            for (int n = 0; n < 4; ++n) h[e][std::size_t(n)] = inverseTranspose * rest[e].grad[std::size_t(n)];
        }
        std::vector<double> nodeJ;
        if (!nodeVolumeRatios(tetJ, nodeJ)) return false;
        std::vector<double> pressure(nodeJ.size(), 0.0);
        for (std::size_t a = 0; a < nodeJ.size(); ++a)
            if (nodeVolume[a] > 0.0) pressure[a] = lambda * std::log(nodeJ[a]) / nodeJ[a];
        for (std::size_t e = 0; e < tets.size(); ++e) {
            double mean = 0.0;
            for (TetNodeId n : tets[e]) mean += 0.25 * pressure[n];
            const double scale = mean * rest[e].volumeMm3 * tetJ[e];
            for (int n = 0; n < 4; ++n)
                for (int i = 0; i < 3; ++i)
                    gradient[3 * tets[e][std::size_t(n)] + std::size_t(i)] += scale * h[e][std::size_t(n)][i];
            if (!tangent) continue;
            // d2 J / dx_n,i dx_m,k = J (h_n,i h_m,k - h_m,i h_n,k)
            const int* at = slot.data() + e * 144;
            for (int n = 0; n < 4; ++n)
                for (int m = 0; m < 4; ++m) {
                    const glm::dvec3& hn = h[e][std::size_t(n)];
                    const glm::dvec3& hm = h[e][std::size_t(m)];
                    for (int i = 0; i < 3; ++i)
                        for (int k = 0; k < 3; ++k) {
                            const double v = scale * (hn[i] * hm[k] - hm[i] * hn[k]);
                            const int position = at[(3 * n + i) * 12 + 3 * m + k];
                            if (position >= 0) values[position] += v;
                            else
                                addEntry(3 * tets[e][std::size_t(n)] + std::size_t(i),
                                         3 * tets[e][std::size_t(m)] + std::size_t(k), v, values, fixedIncrement,
                                         predictor);
                        }
                }
        }
        if (!tangent) return true;
        // Per node, the row dJ_a/dx of D (free DOFs) and its product with the fixed DOFs' motion
        // still to come; the stiffness is D^T diag(k) D, added into the pattern column by column.
        std::vector<Eigen::Triplet<double>> rows;
        std::vector<double> k(nodeJ.size(), 0.0), pushed(nodeJ.size(), 0.0);
        std::vector<TetNodeId> patch;
        std::vector<glm::dvec3> d;
        for (std::size_t a = 0; a < nodeJ.size(); ++a) {
            if (nodeVolume[a] <= 0.0) continue;
            patch.clear();
            d.clear();
            for (std::uint32_t t = tetsOfStart[a]; t < tetsOfStart[a + 1]; ++t) {
                const std::uint32_t e = tetsOf[t];
                const double weight = rest[e].volumeMm3 / 4.0 * tetJ[e] / nodeVolume[a];
                for (int n = 0; n < 4; ++n) {
                    const TetNodeId node = tets[e][std::size_t(n)];
                    const auto at = std::find(patch.begin(), patch.end(), node);
                    if (at == patch.end()) {
                        patch.push_back(node);
                        d.push_back(weight * h[e][std::size_t(n)]);
                    } else {
                        d[std::size_t(at - patch.begin())] += weight * h[e][std::size_t(n)];
                    }
                }
            }
            const double lnJ = std::log(nodeJ[a]);
            k[a] = nodeVolume[a] * lambda * (1.0 - lnJ) / (nodeJ[a] * nodeJ[a]);
            for (std::size_t p = 0; p < patch.size(); ++p)
                for (int i = 0; i < 3; ++i) {
                    const std::size_t dof = 3 * patch[p] + std::size_t(i);
                    if (freeIndex[dof] != kNoFree) rows.emplace_back(int(a), freeIndex[dof], d[p][i]);
                    else if (predictor) pushed[a] += d[p][i] * (*fixedIncrement)[dof];
                }
        }
        SparseMatrix dFree(Eigen::Index(nodeJ.size()), Eigen::Index(freeCount));
        dFree.setFromTriplets(rows.begin(), rows.end());
        const Eigen::Map<const Eigen::VectorXd> kMap(k.data(), Eigen::Index(k.size()));
        const SparseMatrix kd = kMap.asDiagonal() * dFree;
        const SparseMatrix nodalK = SparseMatrix(dFree.transpose()) * kd;
        for (Eigen::Index col = 0; col < nodalK.outerSize(); ++col) {
            int position = pattern.outerIndexPtr()[col];
            const int* inner = pattern.innerIndexPtr();
            const int end = pattern.outerIndexPtr()[col + 1];
            for (SparseMatrix::InnerIterator it(nodalK, col); it; ++it) {
                while (position < end && inner[position] < it.row()) ++position;  // it holds every patch pair
                if (position < end && inner[position] == it.row()) values[position] += it.value();
            }
        }
        if (predictor) {
            // K_fp times the motion: D_f^T diag(k) (D_p motion)
            for (Eigen::Index col = 0; col < dFree.outerSize(); ++col)
                for (SparseMatrix::InnerIterator it(dFree, col); it; ++it) {
                    const std::size_t node = std::size_t(it.row());
                    if (pushed[node] == 0.0) continue;
                    (*predictor)[freeDof[std::size_t(col)]] += it.value() * k[node] * pushed[node];
                }
        }
        return true;
    }
};

HyperelasticFem::HyperelasticFem(const TetMesh& mesh, const HyperelasticMaterial& material,
                                 std::vector<std::uint8_t> fixedDofs, const HyperelasticSolverDef& options) {
    if (const std::string e = joinedMessages(validateHyperelasticMaterial(material)); !e.empty())
        throw std::invalid_argument(e);
    if (fixedDofs.size() != mesh.dofCount())
        throw std::invalid_argument("fixed-DOF mask has " + std::to_string(fixedDofs.size()) + " entries for " +
                                    std::to_string(mesh.dofCount()) + " DOFs");
    mImpl = std::make_unique<Impl>(mesh, material, std::move(fixedDofs), options);
    Impl& s = *mImpl;
    for (const auto& p : s.restMm)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::invalid_argument("mesh has a node that is not finite");
    s.rest.reserve(s.tets.size());
    for (std::size_t e = 0; e < s.tets.size(); ++e) {
        std::array<glm::dvec3, 4> p;
        for (int a = 0; a < 4; ++a) {
            const TetNodeId n = s.tets[e][std::size_t(a)];
            if (n >= s.restMm.size()) throw std::invalid_argument("tet " + std::to_string(e) + " names a missing node");
            p[std::size_t(a)] = s.restMm[n];
        }
        s.rest.push_back(restTet(p, e));
    }
    s.freeIndex.assign(s.fixed.size(), kNoFree);
    for (std::size_t d = 0; d < s.fixed.size(); ++d)
        if (!s.fixed[d]) {
            s.freeIndex[d] = int(s.freeCount++);
            s.freeDof.push_back(d);
        }
    if (s.freeCount == 0) throw std::invalid_argument("every DOF is fixed: nothing to solve");
    if (s.nodal) s.buildNodePatches();
    s.buildPattern();
    const FemSolverKind kind = options.linear.kind;
    s.direct = kind == FemSolverKind::DirectLdlt ||
               (kind == FemSolverKind::Auto && s.freeCount <= options.linear.directMaxFreeDofs);
    s.solverName = s.direct ? "ldlt" : "cg+diag";
}

HyperelasticFem::~HyperelasticFem() = default;

HyperelasticState HyperelasticFem::solve(const HyperelasticLoad& load, const std::vector<glm::dvec3>& guess) const {
    const Impl& s = *mImpl;
    const std::size_t dofs = s.fixed.size();
    if (load.prescribedMm.size() != dofs || guess.size() * 3 != dofs)
        throw std::invalid_argument("prescribed values or initial guess do not match the mesh");
    const SphereContactDef* sphere = load.sphere ? &*load.sphere : nullptr;
    // The fixed DOFs start where the guess has them and move to their prescribed values with the
    // first Newton step, whose right-hand side carries K_fp times that motion: the free DOFs then
    // follow it at once (a linear predictor) instead of a layer of tets taking it all.
    std::vector<double> u(dofs), increment(dofs, 0.0), predictor;
    for (std::size_t d = 0; d < dofs; ++d) {
        u[d] = guess[d / 3][int(d % 3)];
        if (s.fixed[d]) increment[d] = load.prescribedMm[d] - u[d];
    }
    bool moving = std::any_of(increment.begin(), increment.end(), [](double v) { return v != 0.0; });

    HyperelasticState out;
    std::vector<double> gradient, internal, trial(dofs);
    Eigen::VectorXd rhs(Eigen::Index(s.freeCount)), step;
    Ldlt ldlt;
    bool analysed = false;
    double energy = s.energy(u, sphere);
    if (!std::isfinite(energy)) {
        out.failure = "the starting guess inverts a tet";
        return out;
    }
    for (int iteration = 0;; ++iteration) {
        if (!s.assemble(u, sphere, gradient, &internal, true, moving ? &increment : nullptr,
                        moving ? &predictor : nullptr)) {
            out.failure = "a tet inverted";
            return out;
        }
        double freeNorm2 = 0.0;
        for (std::size_t d = 0; d < dofs; ++d)
            if (s.freeIndex[d] != kNoFree) {
                rhs[s.freeIndex[d]] = -gradient[d] - (moving ? predictor[d] : 0.0);
                freeNorm2 += gradient[d] * gradient[d];
            }
        const double scale = std::max(norm(internal), 1e-300);
        out.relativeResidual = std::sqrt(freeNorm2) / scale;
        out.newtonIterations = iteration;
        if (!moving && out.relativeResidual <= s.options.residualTolerance) {
            out.converged = true;
            break;
        }
        if (iteration >= s.options.maxNewtonIterations) {
            out.failure = "Newton did not converge in " + std::to_string(iteration) + " iterations (residual " +
                          std::to_string(out.relativeResidual) + ")";
            return out;
        }
        if (s.direct) {
            if (!analysed) ldlt.analyzePattern(s.pattern), analysed = true;
            ldlt.factorize(s.pattern);
            if (ldlt.info() != Eigen::Success) {
                out.failure = "the tangent stiffness is singular";
                return out;
            }
            step = ldlt.solve(rhs);
        } else {
            Cg cg;
            cg.setMaxIterations(s.options.linear.cgMaxIterations);
            // Inexact Newton: solve only as accurately as the nonlinear residual needs.
            cg.setTolerance(std::clamp(0.01 * out.relativeResidual, 1e-10, 1e-4));
            cg.compute(s.pattern);
            step = cg.solve(rhs);
            out.linearIterations += long(cg.iterations());
        }
        // Backtracking on the potential energy (Armijo), through inverted tets too. While the fixed
        // DOFs move, the constraint does work and the energy may rise: any step without an inverted
        // tet is then taken.
        const double slopeAlong = -rhs.dot(step);
        double alpha = 1.0;
        bool accepted = false;
        for (int h = 0; h <= s.options.maxLineSearchHalvings; ++h, alpha *= 0.5) {
            trial = u;
            for (std::size_t d = 0; d < dofs; ++d)
                trial[d] += alpha * (s.freeIndex[d] != kNoFree ? step[s.freeIndex[d]] : increment[d]);
            const double e = s.energy(trial, sphere);
            if (std::isfinite(e) &&
                (moving || e <= energy + 1e-4 * alpha * slopeAlong + 1e-12 * std::abs(energy))) {
                accepted = true;
                energy = e;
                break;
            }
            ++out.lineSearchHalvings;
        }
        if (accepted && moving) {
            for (std::size_t d = 0; d < dofs; ++d) increment[d] *= 1.0 - alpha;
            if (alpha == 1.0) {
                std::fill(increment.begin(), increment.end(), 0.0);
                moving = false;
            }
        }
        if (!accepted && moving) {
            out.failure = "every step towards the prescribed values inverts a tet";
            return out;
        }
        if (!accepted) {
            // Near the solution the energy's decrease (~ |r|^2 / K) drowns in its rounding; the
            // full step is then taken if it lowers the residual instead.
            trial = u;
            for (std::size_t d = 0; d < dofs; ++d)
                if (s.freeIndex[d] != kNoFree) trial[d] += step[s.freeIndex[d]];
            std::vector<double> trialGradient;
            double trialNorm2 = 0.0;
            if (s.assemble(trial, sphere, trialGradient, nullptr, false))
                for (std::size_t d = 0; d < dofs; ++d)
                    if (s.freeIndex[d] != kNoFree) trialNorm2 += trialGradient[d] * trialGradient[d];
            if (!(trialNorm2 < 0.25 * freeNorm2)) {
                out.failure = "the line search found no step that lowers the energy";
                return out;
            }
            energy = s.energy(trial, sphere);
        }
        u.swap(trial);
    }

    out.energyNmm = energy;
    out.displacementMm.resize(dofs / 3);
    out.reactionN.assign(dofs / 3, glm::dvec3(0.0));
    for (std::size_t n = 0; n < dofs / 3; ++n) {
        out.displacementMm[n] = {u[3 * n], u[3 * n + 1], u[3 * n + 2]};
        for (int c = 0; c < 3; ++c)
            if (s.fixed[3 * n + std::size_t(c)]) out.reactionN[n][c] = internal[3 * n + std::size_t(c)];
    }
    if (sphere)
        for (TetNodeId n : sphere->nodes) {
            double gap;
            glm::dvec3 normal;
            if (!Impl::penetration(*sphere, s.restMm[n] + out.displacementMm[n], gap, normal)) continue;
            out.contactForceN += sphere->penaltyNPerMm * gap * normal;
            ++out.contactNodes;
            out.maxPenetrationMm = std::max(out.maxPenetrationMm, gap);
        }
    return out;
}

LoadPathResult HyperelasticFem::solvePath(const std::function<HyperelasticLoad(double t)>& load,
                                          const std::vector<double>& reportAt, double maxStep,
                                          const std::function<void(double, const HyperelasticState&)>& onStep) const {
    const auto start = std::chrono::steady_clock::now();
    LoadPathResult out;
    if (!(maxStep > 0.0)) throw std::invalid_argument("load step must be positive");
    const std::size_t nodes = mImpl->restMm.size();
    std::vector<glm::dvec3> previous(nodes, glm::dvec3(0.0)), beforePrevious = previous;
    double tPrevious = 0.0, tBeforePrevious = 0.0;
    HyperelasticState reached;
    for (double target : reportAt) {
        if (!(target > 0.0 && target > tPrevious - 1e-15 && target <= 1.0 + 1e-12))
            throw std::invalid_argument("load factors must ascend within (0, 1]");
        while (tPrevious < target - 1e-12) {
            double step = std::min(maxStep, target - tPrevious);
            int halvings = 0;
            for (;;) {
                const double t = tPrevious + step;
                std::vector<glm::dvec3> guess = previous;
                if (tPrevious > tBeforePrevious) {
                    const double ratio = step / (tPrevious - tBeforePrevious);
                    for (std::size_t n = 0; n < nodes; ++n) guess[n] += ratio * (previous[n] - beforePrevious[n]);
                }
                HyperelasticState state = solve(load(t), guess);
                if (!state.converged && tPrevious > tBeforePrevious) state = solve(load(t), previous);
                if (state.converged) {
                    beforePrevious.swap(previous);
                    previous = state.displacementMm;
                    tBeforePrevious = tPrevious;
                    tPrevious = t;
                    ++out.steps;
                    if (onStep) onStep(t, state);
                    reached = std::move(state);
                    break;
                }
                if (++halvings > mImpl->options.maxStepHalvings) {
                    out.failure = "load factor " + std::to_string(t) + ": " + state.failure;
                    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                    return out;
                }
                ++out.stepHalvings;
                step *= 0.5;
            }
        }
        out.states.push_back(reached);
    }
    out.completed = true;
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

std::size_t HyperelasticFem::nodeCount() const { return mImpl->restMm.size(); }
std::size_t HyperelasticFem::tetCount() const { return mImpl->tets.size(); }
std::size_t HyperelasticFem::freeDofCount() const { return mImpl->freeCount; }
const std::string& HyperelasticFem::solverName() const { return mImpl->solverName; }

}  // namespace palpate
