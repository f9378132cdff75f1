#include "engine/fem/SurfaceFill.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace palpate {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

/// A tet with 6 V / (longest edge)^3 at or below this counts as inverted (a sliver this flat would
/// only spoil the conditioning of K). A regular tet has 0.71; a prism layer 1/10 of the edge ~0.05.
constexpr double kMinTetShape = 1e-4;

/// Prism vertex relabelling that brings local vertex m to position 0 (Dompierre et al. 1999,
/// "How to subdivide pyramids, prisms and hexahedra into tetrahedra"): rotations of the
/// triangles, and swapping outer and inner triangle with a reversal, which keeps orientation.
constexpr int kPrismRelabel[6][6] = {{0, 1, 2, 3, 4, 5}, {1, 2, 0, 4, 5, 3}, {2, 0, 1, 5, 3, 4},
                                     {3, 5, 4, 0, 2, 1}, {4, 3, 5, 1, 0, 2}, {5, 4, 3, 2, 1, 0}};

/// A right prism in local labels: outer triangle 0, 1, 2 counter-clockwise seen from outside (+z),
/// inner triangle 3, 4, 5 below it. A template tet's sign here is its sign in any unfolded prism.
const glm::dvec3 kCanonicalPrism[6] = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

/// Splits the prism with global node ids g (local labels as above) into 3 tets, returned as
/// local labels, positively oriented for an unfolded prism. Each quad face is cut along the
/// diagonal through its smallest global id, so the prisms sharing a face agree.
std::array<std::array<int, 4>, 3> splitPrism(const std::array<TetNodeId, 6>& g) {
    int m = 0;
    for (int i = 1; i < 6; ++i)
        if (g[std::size_t(i)] < g[std::size_t(m)]) m = i;
    const int* v = kPrismRelabel[m];
    std::array<std::array<int, 4>, 3> tets;
    if (std::min(g[std::size_t(v[1])], g[std::size_t(v[5])]) < std::min(g[std::size_t(v[2])], g[std::size_t(v[4])]))
        tets = {{{v[0], v[1], v[2], v[5]}, {v[0], v[1], v[5], v[4]}, {v[0], v[4], v[5], v[3]}}};
    else
        tets = {{{v[0], v[1], v[2], v[4]}, {v[0], v[4], v[2], v[5]}, {v[0], v[4], v[5], v[3]}}};
    for (auto& t : tets) {
        const auto& c = kCanonicalPrism;
        if (tetSignedVolume6(c[t[0]], c[t[1]], c[t[2]], c[t[3]]) < 0.0) std::swap(t[2], t[3]);
    }
    return tets;
}

struct SurfaceData {
    std::vector<glm::dvec3> restMm;
    std::vector<glm::dvec3> normals;
};

SurfaceData checkedSurface(const TissueMesh& mesh) {
    const std::string name = mesh.report().source.empty() ? "surface" : mesh.report().source;
    if (mesh.vertexCount() < 4 || mesh.triangleCount() < 4)
        throw std::invalid_argument(name + ": too small to fill (needs a closed surface)");
    if (mesh.report().boundaryEdgeCount > 0)
        throw std::invalid_argument(name + ": surface is open (" + std::to_string(mesh.report().boundaryEdgeCount) +
                                    " boundary edges); the filler needs a closed surface");
    SurfaceData s;
    s.restMm.reserve(mesh.vertexCount());
    s.normals.reserve(mesh.vertexCount());
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const glm::dvec3 p(mesh.restPositionsMm()[v]);
        const glm::dvec3 n(mesh.restNormals()[v]);
        if (!finite(p) || !finite(n) || glm::length(n) < 0.5)
            throw std::invalid_argument(name + ": vertex " + std::to_string(v) + " has a non-finite position or normal");
        s.restMm.push_back(p);
        s.normals.push_back(glm::normalize(n));
    }
    double volume6 = 0.0;
    for (const auto& t : mesh.triangles())
        volume6 += glm::dot(s.restMm[t[0]], glm::cross(s.restMm[t[1]], s.restMm[t[2]]));
    if (!(volume6 > 0.0)) throw std::invalid_argument(name + ": surface faces inward (negative enclosed volume)");
    return s;
}

/// How thick the organ is at each vertex: the distance along minus its normal to the nearest other
/// triangle (Moller-Trumbore against every triangle: the meshes filled here have at most some 10^4
/// triangles), or to the nearest vertex facing the other way when that is nearer.
std::vector<double> innerDistancesMm(const SurfaceData& s, const std::vector<std::array<VertexId, 3>>& triangles) {
    std::vector<double> out(s.restMm.size(), std::numeric_limits<double>::infinity());
    for (std::size_t v = 0; v < s.restMm.size(); ++v) {
        const glm::dvec3 o = s.restMm[v], d = -s.normals[v];
        for (const auto& t : triangles) {
            if (t[0] == v || t[1] == v || t[2] == v) continue;
            const glm::dvec3 a = s.restMm[t[0]], e1 = s.restMm[t[1]] - a, e2 = s.restMm[t[2]] - a;
            const glm::dvec3 p = glm::cross(d, e2);
            const double det = glm::dot(e1, p);
            if (std::abs(det) < 1e-14) continue;
            const glm::dvec3 q = o - a;
            const double u = glm::dot(q, p) / det;
            if (u < 0.0 || u > 1.0) continue;
            const glm::dvec3 r = glm::cross(q, e1);
            const double w = glm::dot(d, r) / det;
            if (w < 0.0 || u + w > 1.0) continue;
            const double dist = glm::dot(e2, r) / det;
            if (dist > 1e-9 && dist < out[v]) out[v] = dist;
        }
        // A pointed end sends the ray along the organ's length: the nearest vertex facing the other
        // way (normals more than 120 degrees apart) bounds the thickness too.
        for (std::size_t u = 0; u < s.restMm.size(); ++u)
            if (glm::dot(s.normals[u], s.normals[v]) < -0.5) out[v] = std::min(out[v], glm::length(s.restMm[u] - o));
    }
    return out;
}

/// The largest convex curvature at each vertex over its edges: an edge to u of length l whose far
/// end lies h below v's tangent plane bends by 2 h / l^2 (1 / radius); 0 where nothing bends away.
std::vector<double> convexCurvaturesPerMm(const SurfaceData& s, const std::vector<std::array<VertexId, 3>>& triangles) {
    std::vector<double> out(s.restMm.size(), 0.0);
    for (const auto& tri : triangles)
        for (int e = 0; e < 3; ++e) {
            const VertexId a = tri[std::size_t(e)], b = tri[std::size_t((e + 1) % 3)];
            const glm::dvec3 d = s.restMm[a] - s.restMm[b];
            const double l2 = glm::dot(d, d);
            if (!(l2 > 0.0)) continue;
            out[a] = std::max(out[a], 2.0 * glm::dot(d, s.normals[a]) / l2);
            out[b] = std::max(out[b], -2.0 * glm::dot(d, s.normals[b]) / l2);
        }
    return out;
}

/// Lowers columns until neighbours differ by at most `slope` per mm between them (a deep column
/// next to a shallow one would shear its prisms flat).
void limitThicknessSlope(std::vector<double>& t, const SurfaceData& s, const std::vector<std::array<VertexId, 3>>& triangles,
                         double slope) {
    for (bool changed = true; changed;) {
        changed = false;
        for (const auto& tri : triangles)
            for (int e = 0; e < 3; ++e) {
                const VertexId a = tri[std::size_t(e)], b = tri[std::size_t((e + 1) % 3)];
                const double limit = slope * glm::length(s.restMm[a] - s.restMm[b]);
                if (t[b] > t[a] + limit + 1e-12) t[b] = t[a] + limit, changed = true;
                if (t[a] > t[b] + limit + 1e-12) t[a] = t[b] + limit, changed = true;
            }
    }
}

}  // namespace

FilledSurface fillSurface(const TissueMesh& mesh, const SurfaceFillDef& options) {
    const auto start = std::chrono::steady_clock::now();
    if (options.layers < 1 || options.layers > 32) throw std::invalid_argument("layers must be in 1..32");
    if (!std::isfinite(options.layerGrowth) || options.layerGrowth < 1.0 || options.layerGrowth > 4.0)
        throw std::invalid_argument("layer growth must be in [1, 4]");
    if (options.maxHalvings < 0 || options.maxHalvings > 30) throw std::invalid_argument("max halvings must be in 0..30");
    if (options.thicknessMm && !(std::isfinite(*options.thicknessMm) && *options.thicknessMm > 0.0))
        throw std::invalid_argument("thickness must be a positive number of mm");
    if (!(options.localThicknessFraction >= 0.0 && options.localThicknessFraction <= 0.45))
        throw std::invalid_argument("local thickness fraction must be in [0, 0.45]");
    if (!(options.maxThicknessSlope > 0.0 && options.maxThicknessSlope <= 2.0))
        throw std::invalid_argument("thickness slope must be in (0, 2]");
    const SurfaceData s = checkedSurface(mesh);

    FilledSurface f;
    const std::size_t vertexCount = s.restMm.size();
    f.surfaceVertexCount = vertexCount;
    f.layers = options.layers;
    const glm::dvec3 extent = glm::dvec3(mesh.boundsMaxMm()) - glm::dvec3(mesh.boundsMinMm());
    f.requestedThicknessMm = options.thicknessMm ? *options.thicknessMm : 0.25 * std::min({extent.x, extent.y, extent.z});
    if (!(f.requestedThicknessMm > 0.0)) throw std::invalid_argument("surface is flat: no default thickness");

    // Depth of node layer l as a fraction of T: layer thicknesses grow by layerGrowth inward.
    std::vector<double> depthFraction(std::size_t(options.layers) + 1, 0.0);
    double total = 0.0, t = 1.0;
    for (int l = 0; l < options.layers; ++l, t *= options.layerGrowth) depthFraction[std::size_t(l) + 1] = total += t;
    for (double& d : depthFraction) d /= total;

    // Tets in local labels are the same for every T: split once.
    const auto& triangles = mesh.triangles();
    f.mesh.tets.clear();
    f.mesh.tets.reserve(triangles.size() * std::size_t(options.layers) * 3);
    for (int l = 0; l < options.layers; ++l) {
        for (const auto& tri : triangles) {
            const std::array<TetNodeId, 6> g{f.node(tri[0], l),     f.node(tri[1], l),     f.node(tri[2], l),
                                             f.node(tri[0], l + 1), f.node(tri[1], l + 1), f.node(tri[2], l + 1)};
            for (const auto& local : splitPrism(g))
                f.mesh.tets.push_back({g[std::size_t(local[0])], g[std::size_t(local[1])], g[std::size_t(local[2])],
                                       g[std::size_t(local[3])]});
        }
    }

    f.mesh.nodesMm.resize(vertexCount * (std::size_t(options.layers) + 1));
    std::vector<double> column(vertexCount, f.requestedThicknessMm);
    if (options.localThicknessFraction > 0.0) {
        const std::vector<double> inner = innerDistancesMm(s, triangles);
        const std::vector<double> curvature = convexCurvaturesPerMm(s, triangles);
        for (std::size_t v = 0; v < vertexCount; ++v) {
            column[v] = std::min(f.requestedThicknessMm, options.localThicknessFraction * inner[v]);
            // Columns converge under a convex bend: at most half its radius (a pointed end has none).
            if (curvature[v] > 0.0) column[v] = std::min(column[v], 0.5 / curvature[v]);
        }
        limitThicknessSlope(column, s, triangles, options.maxThicknessSlope);
    }
    double scale = 1.0;
    double thickness = f.requestedThicknessMm;
    for (int attempt = 0;; ++attempt) {
        for (int l = 0; l <= options.layers; ++l)
            for (std::size_t v = 0; v < vertexCount; ++v)
                f.mesh.nodesMm[f.node(VertexId(v), l)] =
                    s.restMm[v] - depthFraction[std::size_t(l)] * scale * column[v] * s.normals[v];
        double minShape = std::numeric_limits<double>::infinity();
        double minVolume6 = std::numeric_limits<double>::infinity();
        for (const auto& tet : f.mesh.tets) {
            const auto& p = f.mesh.nodesMm;
            const double v6 = tetSignedVolume6(p[tet[0]], p[tet[1]], p[tet[2]], p[tet[3]]);
            double longest2 = 0.0;
            for (int i = 0; i < 4; ++i)
                for (int j = i + 1; j < 4; ++j) {
                    const glm::dvec3 e = p[tet[std::size_t(j)]] - p[tet[std::size_t(i)]];
                    longest2 = std::max(longest2, glm::dot(e, e));
                }
            minShape = std::min(minShape, v6 / (longest2 * std::sqrt(longest2)));
            minVolume6 = std::min(minVolume6, v6);
        }
        if (minShape > kMinTetShape) {
            f.vertexThicknessMm.resize(vertexCount);
            for (std::size_t v = 0; v < vertexCount; ++v) f.vertexThicknessMm[v] = scale * column[v];
            f.thicknessMm = *std::max_element(f.vertexThicknessMm.begin(), f.vertexThicknessMm.end());
            f.halvings = attempt;
            f.minTetVolumeMm3 = minVolume6 / 6.0;
            break;
        }
        if (attempt == options.maxHalvings)
            throw std::invalid_argument("cannot fill the surface: tets still invert at thickness " +
                                        std::to_string(thickness) + " mm after " + std::to_string(attempt) +
                                        " halvings (vertex normals disagree with their faces?)");
        thickness *= 0.5;
        scale *= 0.5;
    }
    f.seconds = secondsSince(start);
    return f;
}

namespace {

const ElasticMaterial& checkedMaterial(const ElasticMaterial& m) {
    if (const std::string e = joinedMessages(validateElasticMaterial(m)); !e.empty()) throw std::invalid_argument(e);
    return m;
}

}  // namespace

SurfaceIndenter::SurfaceIndenter(const TissueMesh& mesh, const ElasticMaterial& material, const SurfaceFillDef& fill,
                                 const FemSolverDef& solver)
    : mSolver(solver),
      mFilled(fillSurface(mesh, fill)),
      mStiffness(mFilled.mesh, checkedMaterial(material), solver.element) {
    SurfaceData s = checkedSurface(mesh);
    mRestMm = std::move(s.restMm);
    mNormals = std::move(s.normals);
}

SurfaceIndentation SurfaceIndenter::indent(VertexId touched, double punchRadiusMm, double indentationMm) const {
    const auto start = std::chrono::steady_clock::now();
    const std::size_t vertexCount = mFilled.surfaceVertexCount;
    if (touched >= vertexCount)
        throw std::invalid_argument("touched vertex " + std::to_string(touched) + " is not on the surface (" +
                                    std::to_string(vertexCount) + " vertices)");
    if (!std::isfinite(punchRadiusMm) || punchRadiusMm <= 0.0)
        throw std::invalid_argument("punch radius must be a positive number of mm");
    if (!std::isfinite(indentationMm) || indentationMm <= 0.0)
        throw std::invalid_argument("indentation must be a positive number of mm");

    // Work in a frame whose z axis is the touched vertex's rest normal: the punch then prescribes
    // u_z only and leaves u_x, u_y free (frictionless), a plain DOF partition. K is rotated, not
    // reassembled.
    const glm::dvec3 n = mNormals[touched];
    const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 t1 = glm::normalize(glm::cross(helper, n));
    const glm::dvec3 t2 = glm::cross(n, t1);
    const std::size_t dofs = mFilled.mesh.dofCount();

    std::vector<std::uint8_t> fixed(dofs, 0);
    std::vector<double> prescribed(dofs, 0.0);
    for (std::size_t v = 0; v < vertexCount; ++v) {
        const TetNodeId core = mFilled.node(VertexId(v), mFilled.layers);
        for (int d = 0; d < 3; ++d) fixed[3 * core + std::size_t(d)] = 1;
    }
    std::vector<std::size_t> contact;
    const double limit2 = punchRadiusMm * punchRadiusMm;
    for (std::size_t v = 0; v < vertexCount; ++v) {
        const glm::dvec3 e = mRestMm[v] - mRestMm[touched];
        if (v == touched || glm::dot(e, e) <= limit2) {
            const TetNodeId node = mFilled.node(VertexId(v), 0);
            fixed[3 * node + 2] = 1;
            prescribed[3 * node + 2] = -indentationMm;
            contact.push_back(v);
        }
    }

    LinearElasticFem fem(mStiffness.rotated(glm::transpose(glm::dmat3(t1, t2, n))), std::move(fixed), mSolver);
    const FemSolution solution = fem.solve(prescribed);

    SurfaceIndentation out;
    out.displacementMm.resize(vertexCount);
    for (std::size_t v = 0; v < vertexCount; ++v) {
        const glm::dvec3& u = solution.displacementMm[mFilled.node(VertexId(v), 0)];
        out.displacementMm[v] = u.x * t1 + u.y * t2 + u.z * n;
    }
    for (std::size_t v : contact) out.reactionForceN -= solution.reactionN[mFilled.node(VertexId(v), 0)].z;
    out.prescribedVertexCount = contact.size();
    out.nodes = mFilled.mesh.nodeCount();
    out.tets = mFilled.mesh.tetCount();
    out.dofs = dofs;
    out.freeDofs = fem.freeDofCount();
    out.thicknessMm = mFilled.thicknessMm;
    out.solve = solution.stats;
    out.seconds = secondsSince(start);
    return out;
}

SurfaceIndentation indentSurface(const TissueMesh& mesh, VertexId touched, double punchRadiusMm, double indentationMm,
                                 const ElasticMaterial& material, const SurfaceFillDef& fill) {
    return SurfaceIndenter(mesh, material, fill).indent(touched, punchRadiusMm, indentationMm);
}

}  // namespace palpate
