#include "engine/accuracy/OrganReference.h"

#include "engine/fem/HyperelasticFem.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace palpate {

namespace {

/// Mean convex curvature at v from the sagittas of the vertices within two tool radii:
/// h = (p_v - p_u) . n_v over a circle of radius r is r^2 / (2 R), so 1/R = mean(2 h / r^2).
double convexCurvaturePerMm(const TissueMesh& mesh, VertexId v, double toolRadiusMm) {
    const glm::dvec3 p(mesh.restPositionsMm()[v]);
    const glm::dvec3 n = glm::normalize(glm::dvec3(mesh.restNormals()[v]));
    double sum = 0.0;
    int count = 0;
    for (std::size_t u = 0; u < mesh.vertexCount(); ++u) {
        const glm::dvec3 d = p - glm::dvec3(mesh.restPositionsMm()[u]);
        const double h = glm::dot(d, n);
        const double d2 = glm::dot(d, d);
        // Within two tool radii in space (the far side of a thin part is near in the tangent plane).
        if (d2 < 0.09 * toolRadiusMm * toolRadiusMm || d2 > 4.0 * toolRadiusMm * toolRadiusMm) continue;
        const double r2 = d2 - h * h;
        sum += 2.0 * h / r2;
        ++count;
    }
    return count ? sum / count : 0.0;
}

std::string fixed(double v, int digits) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(digits);
    s << v;
    return s.str();
}

}  // namespace

std::vector<OrganSite> chooseOrganSites(const TissueMesh& mesh, const FilledSurface& filled, double toolRadiusMm) {
    const std::size_t n = mesh.vertexCount();
    if (filled.vertexThicknessMm.size() != n) throw std::invalid_argument("organ sites: the fill does not match the mesh");
    if (!(toolRadiusMm > 0.0)) throw std::invalid_argument("organ sites: tool radius must be positive");
    const auto& t = filled.vertexThicknessMm;
    std::vector<double> curvature(n);
    for (std::size_t v = 0; v < n; ++v) curvature[v] = convexCurvaturePerMm(mesh, VertexId(v), toolRadiusMm);
    std::vector<double> sorted = t;
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(n / 2), sorted.end());
    const double median = sorted[n / 2];
    const double maxT = *std::max_element(t.begin(), t.end());

    const VertexId thin = VertexId(std::min_element(t.begin(), t.end()) - t.begin());
    // The thickest: among columns within 1 % of the deepest (the cap makes many equal), the flattest.
    VertexId thick = 0;
    bool haveThick = false;
    for (std::size_t v = 0; v < n; ++v)
        if (t[v] >= 0.99 * maxT && (!haveThick || std::abs(curvature[v]) < std::abs(curvature[thick])))
            thick = VertexId(v), haveThick = true;
    const auto far = [&](VertexId a, VertexId b) {
        return glm::length(glm::dvec3(mesh.restPositionsMm()[a]) - glm::dvec3(mesh.restPositionsMm()[b])) >= 4.0 * toolRadiusMm;
    };
    VertexId curved = 0;
    bool haveCurved = false;
    for (std::size_t v = 0; v < n; ++v)
        if (t[v] >= median && far(VertexId(v), thin) && far(VertexId(v), thick) &&
            (!haveCurved || curvature[v] > curvature[curved]))
            curved = VertexId(v), haveCurved = true;
    if (!haveCurved) throw std::invalid_argument("organ sites: no convex point far enough from the thin and thick ones");

    const auto radius = [&](VertexId v) { return curvature[v] > 1e-9 ? fixed(1.0 / curvature[v], 0) + " mm" : "flat"; };
    std::vector<OrganSite> sites;
    sites.push_back({"thin", thin, t[thin], curvature[thin],
                     "the shallowest tissue layer on the surface (" + fixed(t[thin], 1) + " mm over the core, radius " +
                         radius(thin) + "): where a half-space calibration should fail most, the core being felt"});
    sites.push_back({"thick", thick, t[thick], curvature[thick],
                     "the deepest layer (" + fixed(t[thick], 1) + " mm) and, of those, the flattest (radius " + radius(thick) +
                         "): the nearest the organ comes to the half-space the slopes are calibrated on"});
    sites.push_back({"curved", curved, t[curved], curvature[curved],
                     "the most convex point (radius " + radius(curved) + ", " + fixed(1.0 / std::max(curvature[curved], 1e-9) / toolRadiusMm, 1) +
                         " tool radii) with at least the median layer (" + fixed(t[curved], 1) + " mm >= " + fixed(median, 1) +
                         " mm): curvature without thinness"});
    return sites;
}

struct OrganReferenceSolver::Impl {
    const TissueMesh& mesh;
    OrganReferenceDef def;
    SurfaceIndenter indenter;
};

OrganReferenceSolver::OrganReferenceSolver(const TissueMesh& mesh, const OrganReferenceDef& def) {
    if (const std::string e = joinedMessages(validateToolContact(def.contact)); !e.empty())
        throw std::invalid_argument(e);
    if (!(def.maxDepthMm > 0.0) || !(def.maxDepthOverThickness > 0.0 && def.maxDepthOverThickness < 1.0) ||
        def.hyperelasticSteps < 1 || def.hyperelasticSteps > 100)
        throw std::invalid_argument("organ reference: depth must be positive, its fraction of the layer in (0, 1), steps in 1..100");
    // Constant-strain tets, like the hyperelastic FEM it is compared with at small strain: they lock
    // at the presets' nu (docs/accuracy.md, "Locking, and the element that does not lock") until
    // the hyperelastic laws have the nodal-pressure element too.
    FemSolverDef constantStrain;
    constantStrain.element = TetElement::ConstantStrain;
    mImpl.reset(new Impl{mesh, def, SurfaceIndenter(mesh, def.contact.material, def.fill, constantStrain)});
}

OrganReferenceSolver::~OrganReferenceSolver() = default;

const FilledSurface& OrganReferenceSolver::filled() const { return mImpl->indenter.filled(); }

OrganReference OrganReferenceSolver::solve(const OrganSite& site) const {
    const auto start = std::chrono::steady_clock::now();
    const TissueMesh& mesh = mImpl->mesh;
    const FilledSurface& f = filled();
    const double a = mImpl->def.contact.toolRadiusMm;
    if (site.vertex >= mesh.vertexCount()) throw std::invalid_argument("organ reference: site vertex is not on the surface");
    OrganReference out;
    out.site = site;
    out.maxDepthMm = std::min(mImpl->def.maxDepthMm, mImpl->def.maxDepthOverThickness * f.vertexThicknessMm[site.vertex]);
    out.nodes = f.mesh.nodeCount();
    out.tets = f.mesh.tetCount();

    const glm::dvec3 n = glm::normalize(glm::dvec3(mesh.restNormals()[site.vertex]));
    const auto normalField = [&](const std::vector<glm::dvec3>& surfaceDisplacementMm) {
        std::vector<double> normal(mesh.vertexCount());
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v) normal[v] = -glm::dot(surfaceDisplacementMm[v], n);
        return normal;
    };
    const SurfaceIndentation lin = mImpl->indenter.indent(site.vertex, a, out.maxDepthMm);
    out.linear = {out.maxDepthMm, lin.reactionForceN, normalField(lin.displacementMm)};

    // The hyperelastic FEM in a frame whose z axis is the site's normal: the punch then prescribes
    // u_z of the nodes under it and leaves their sliding free, as the linear indentation does.
    const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 t1 = glm::normalize(glm::cross(helper, n));
    const glm::dvec3 t2 = glm::cross(n, t1);
    const glm::dmat3 toLocal = glm::transpose(glm::dmat3(t1, t2, n));
    TetMesh local = f.mesh;
    for (glm::dvec3& p : local.nodesMm) p = toLocal * p;
    std::vector<std::uint8_t> fixedDofs(local.dofCount(), 0);
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const TetNodeId core = f.node(VertexId(v), f.layers);
        for (int d = 0; d < 3; ++d) fixedDofs[3 * core + std::size_t(d)] = 1;
    }
    std::vector<TetNodeId> punch;
    const glm::dvec3 centre(mesh.restPositionsMm()[site.vertex]);
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const glm::dvec3 e = glm::dvec3(mesh.restPositionsMm()[v]) - centre;
        if (v == site.vertex || glm::dot(e, e) <= a * a) {
            const TetNodeId node = f.node(VertexId(v), 0);
            fixedDofs[3 * node + 2] = 1;
            punch.push_back(node);
        }
    }
    try {
        const HyperelasticFem fem(local, hyperelasticMaterialOf(mImpl->def.contact), fixedDofs);
        auto load = [&](double t) {
            HyperelasticLoad l;
            l.prescribedMm.assign(local.dofCount(), 0.0);
            for (TetNodeId node : punch) l.prescribedMm[3 * node + 2] = -t * out.maxDepthMm;
            return l;
        };
        std::vector<double> factors;
        for (int s = 1; s <= mImpl->def.hyperelasticSteps; ++s) factors.push_back(double(s) / mImpl->def.hyperelasticSteps);
        const LoadPathResult path = fem.solvePath(load, factors, 1.0 / (2.0 * mImpl->def.hyperelasticSteps));
        for (std::size_t k = 0; k < path.states.size(); ++k) {
            const HyperelasticState& st = path.states[k];
            OrganField field;
            field.depthMm = factors[k] * out.maxDepthMm;
            for (TetNodeId node : punch) field.forceN -= st.reactionN[node].z;
            field.normalDisplacementMm.resize(mesh.vertexCount());
            for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
                field.normalDisplacementMm[v] = -st.displacementMm[f.node(VertexId(v), 0)].z;
            out.hyperelastic.push_back(std::move(field));
        }
        out.hyperelasticCompleted = path.completed;
        out.failure = path.failure;
    } catch (const std::exception& e) {
        out.failure = e.what();
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

OrganError errorAgainstLinear(const OrganReference& ref, const TissueMesh& mesh, const std::vector<double>& modelNormalMm,
                              double modelIndentationMm, double modelForceN, double toolRadiusMm) {
    OrganError e;
    if (!(modelIndentationMm > 0.0) || !(ref.linear.depthMm > 0.0)) return e;
    const double scale = modelIndentationMm / ref.linear.depthMm;
    std::vector<double> scaled = ref.linear.normalDisplacementMm;
    for (double& u : scaled) u *= scale;
    e.displacementError = displacementErrorAgainstField(mesh, ref.site.vertex, modelNormalMm, scaled, toolRadiusMm);
    e.referenceForceN = ref.linear.forceN * scale;
    e.forceError = std::abs(modelForceN - e.referenceForceN) / e.referenceForceN;
    e.measured = true;
    return e;
}

OrganError errorAgainstHyperelastic(const OrganReference& ref, const TissueMesh& mesh,
                                    const std::vector<double>& modelNormalMm, double modelIndentationMm,
                                    double modelForceN, double toolRadiusMm) {
    OrganError e;
    e.displacementError = e.forceError = e.referenceForceN = std::nan("");
    // A model pressed to the reference's deepest depth may reach it to within float rounding.
    if (ref.hyperelastic.empty() || !(modelIndentationMm > 0.0) ||
        modelIndentationMm > ref.hyperelastic.back().depthMm * (1.0 + 1e-4))
        return e;
    modelIndentationMm = std::min(modelIndentationMm, ref.hyperelastic.back().depthMm);
    // The two kept depths around the model's (rest, i.e. zero, below the first).
    std::size_t k = 0;
    while (ref.hyperelastic[k].depthMm < modelIndentationMm) ++k;
    const OrganField& hi = ref.hyperelastic[k];
    const double loDepth = k ? ref.hyperelastic[k - 1].depthMm : 0.0;
    const double w = (modelIndentationMm - loDepth) / (hi.depthMm - loDepth);
    std::vector<double> field(hi.normalDisplacementMm.size());
    for (std::size_t v = 0; v < field.size(); ++v)
        field[v] = (k ? (1.0 - w) * ref.hyperelastic[k - 1].normalDisplacementMm[v] : 0.0) + w * hi.normalDisplacementMm[v];
    e.referenceForceN = (k ? (1.0 - w) * ref.hyperelastic[k - 1].forceN : 0.0) + w * hi.forceN;
    e.displacementError = displacementErrorAgainstField(mesh, ref.site.vertex, modelNormalMm, field, toolRadiusMm);
    e.forceError = std::abs(modelForceN - e.referenceForceN) / e.referenceForceN;
    e.measured = true;
    return e;
}

}  // namespace palpate
