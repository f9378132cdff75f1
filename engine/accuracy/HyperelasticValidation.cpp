#include "engine/accuracy/HyperelasticValidation.h"

#include "engine/fem/ClosedForms.h"
#include "engine/fem/HyperelasticClosedForms.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace palpate {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

GradedBlock blockFor(double contactRadiusMm, int aOverH, GradedBlockDef options = {}) {
    options.contactRadiusMm = contactRadiusMm;
    options.contactRadiusOverSpacing = aOverH;
    return makeGradedBlock(options);
}

bool onFarFace(const GradedBlock& b, std::size_t i, std::size_t j, std::size_t k) {
    return i + 1 == b.nx() || j + 1 == b.nx() || k + 1 == b.nz();
}

/// The quarter block's constraints: symmetry (u_x = 0 on x = 0, u_y = 0 on y = 0) and every DOF of
/// the far faces fixed. Collects the far faces' nodes and the top surface's other nodes.
std::vector<std::uint8_t> quarterBlockConstraints(const GradedBlock& b, std::vector<TetNodeId>& farNodes,
                                                  std::vector<TetNodeId>& topNodes) {
    std::vector<std::uint8_t> fixed(b.mesh.dofCount(), 0);
    for (std::size_t k = 0; k < b.nz(); ++k)
        for (std::size_t j = 0; j < b.nx(); ++j)
            for (std::size_t i = 0; i < b.nx(); ++i) {
                const TetNodeId n = b.node(i, j, k);
                if (i == 0) fixed[3 * n + 0] = 1;
                if (j == 0) fixed[3 * n + 1] = 1;
                if (onFarFace(b, i, j, k)) {
                    for (int d = 0; d < 3; ++d) fixed[3 * n + std::size_t(d)] = 1;
                    farNodes.push_back(n);
                } else if (k == 0) {
                    topNodes.push_back(n);
                }
            }
    return fixed;
}

}  // namespace

std::string_view hyperelasticReferenceName(HyperelasticReference r) {
    switch (r) {
    case HyperelasticReference::UniaxialNeoHookean: return "uniaxial-neo-hookean";
    case HyperelasticReference::UniaxialExponential: return "uniaxial-exponential";
    case HyperelasticReference::IndentationNeoHookean: return "indentation-neo-hookean";
    }
    return "";
}

std::optional<HyperelasticReference> parseHyperelasticReference(std::string_view name) {
    for (auto r : {HyperelasticReference::UniaxialNeoHookean, HyperelasticReference::UniaxialExponential,
                   HyperelasticReference::IndentationNeoHookean})
        if (name == hyperelasticReferenceName(r)) return r;
    return std::nullopt;
}

// The block [0, L]^2 x [-L, 0] on rollers at x = 0, y = 0 and z = -L, its top z = 0 moved by
// (s - 1) L, its sides free: uniaxial stress along z, homogeneous, which linear tets represent
// exactly on any mesh, so the error is the solver's alone.
UniaxialResult runUniaxialCase(const UniaxialCase& c) {
    const auto start = std::chrono::steady_clock::now();
    if (const std::string e = joinedMessages(validateHyperelasticMaterial(c.material)); !e.empty())
        throw std::invalid_argument(e);
    for (double s : c.stretches)
        if (!(s > 0.0 && s != 1.0 && s < 10.0)) throw std::invalid_argument("stretches must lie in (0, 10), not 1");
    const GradedBlock block = blockFor(1.0, c.aOverH);
    const TetMesh& mesh = block.mesh;
    const double length = block.sizeMm;
    std::vector<std::uint8_t> fixed(mesh.dofCount(), 0);
    std::vector<TetNodeId> top;
    const std::size_t nx = block.nx(), nz = block.nz();
    for (std::size_t k = 0; k < nz; ++k)
        for (std::size_t j = 0; j < nx; ++j)
            for (std::size_t i = 0; i < nx; ++i) {
                const TetNodeId n = block.node(i, j, k);
                if (i == 0) fixed[3 * n + 0] = 1;
                if (j == 0) fixed[3 * n + 1] = 1;
                if (k == 0 || k + 1 == nz) fixed[3 * n + 2] = 1;
                if (k == 0) top.push_back(n);
            }
    const TetNodeId corner = block.node(nx - 1, 0, 0);
    const HyperelasticFem fem(mesh, c.material, fixed, c.solver);

    UniaxialResult out;
    out.nodes = mesh.nodeCount();
    out.tets = mesh.tetCount();
    out.freeDofs = fem.freeDofCount();
    out.completed = true;
    std::vector<double> stretches = c.stretches;
    std::sort(stretches.begin(), stretches.end());
    // Two paths from rest: compression (stretches below 1, nearest first) and tension.
    std::vector<double> compression, tension;
    for (double s : stretches) (s < 1.0 ? compression : tension).push_back(s);
    std::reverse(compression.begin(), compression.end());
    for (const auto* path : {&compression, &tension}) {
        if (path->empty()) continue;
        const double end = path->back();
        auto load = [&](double t) {
            HyperelasticLoad l;
            l.prescribedMm.assign(mesh.dofCount(), 0.0);
            for (TetNodeId n : top) l.prescribedMm[3 * n + 2] = t * (end - 1.0) * length;
            return l;
        };
        std::vector<double> factors;
        for (double s : *path) factors.push_back((s - 1.0) / (end - 1.0));
        const LoadPathResult r = fem.solvePath(load, factors, c.maxStretchStep / std::abs(end - 1.0));
        out.loadSteps += r.steps;
        if (!r.completed) {
            out.completed = false;
            out.failure = r.failure;
        }
        for (std::size_t p = 0; p < r.states.size(); ++p) {
            const HyperelasticState& st = r.states[p];
            UniaxialPoint point;
            point.stretch = (*path)[p];
            double force = 0.0;
            for (TetNodeId n : top) force += st.reactionN[n].z;
            point.nominalFemNPerMm2 = force / (length * length);
            point.lateralFem = 1.0 + st.displacementMm[corner].x / length;
            const UniaxialStress closed = uniaxialStress(c.material, point.stretch);
            point.nominalClosedNPerMm2 = closed.nominalStressNPerMm2;
            point.lateralClosed = closed.lateralStretch;
            point.stressError = std::abs(point.nominalFemNPerMm2 - closed.nominalStressNPerMm2) /
                                std::abs(closed.nominalStressNPerMm2);
            point.lateralError = std::abs(point.lateralFem - closed.lateralStretch) /
                                 std::max(std::abs(closed.lateralStretch - 1.0), 1e-12);
            point.newtonIterations = st.newtonIterations;
            out.worstError = std::max({out.worstError, point.stressError, point.lateralError});
            out.points.push_back(point);
        }
    }
    std::sort(out.points.begin(), out.points.end(), [](auto& a, auto& b) { return a.stretch < b.stretch; });
    out.seconds = secondsSince(start);
    return out;
}

// A flat punch of radius 1 mm pressed by a tiny delta, far faces at rest: the hyperelastic and
// the linear FEM on one mesh and one set of conditions must then agree.
SmallStrainResult runSmallStrainCase(const SmallStrainCase& c) {
    const auto start = std::chrono::steady_clock::now();
    if (const std::string e = joinedMessages(validateHyperelasticMaterial(c.material)); !e.empty())
        throw std::invalid_argument(e);
    const double a = 1.0, delta = c.indentationOverRadius * a;
    const GradedBlock block = blockFor(a, c.aOverH);
    const TetMesh& mesh = block.mesh;
    std::vector<TetNodeId> far, top, contact, surface;
    std::vector<std::uint8_t> fixed = quarterBlockConstraints(block, far, top);
    std::vector<double> prescribed(mesh.dofCount(), 0.0);
    for (TetNodeId n : top) {
        const glm::dvec3& p = mesh.nodesMm[n];
        const double r = std::hypot(p.x, p.y);
        if (r <= a * (1.0 + 1e-9)) {
            fixed[3 * n + 2] = 1;
            prescribed[3 * n + 2] = -delta;
            contact.push_back(n);
        }
        if (r <= 5.0 * a) surface.push_back(n);
    }
    // The hyperelastic FEM's tets have constant strain: so must the linear FEM it is compared with,
    // or the comparison would measure the element, not the material law.
    FemSolverDef constantStrain;
    constantStrain.element = TetElement::ConstantStrain;
    const LinearElasticFem linear(mesh, c.material.smallStrain, fixed, constantStrain);
    const FemSolution lin = linear.solve(prescribed);
    const HyperelasticFem hyper(mesh, c.material, fixed);
    HyperelasticLoad load;
    load.prescribedMm = prescribed;
    const HyperelasticState st = hyper.solve(load, std::vector<glm::dvec3>(mesh.nodeCount(), glm::dvec3(0.0)));
    if (!st.converged) throw std::runtime_error("small-strain hyperelastic solve failed: " + st.failure);
    SmallStrainResult out;
    for (TetNodeId n : contact) {
        out.forceLinearN -= 4.0 * lin.reactionN[n].z;
        out.forceHyperN -= 4.0 * st.reactionN[n].z;
    }
    out.forceDifference = std::abs(out.forceHyperN - out.forceLinearN) / out.forceLinearN;
    double sum = 0.0;
    for (TetNodeId n : surface) {
        const double d = (st.displacementMm[n].z - lin.displacementMm[n].z) / delta;
        sum += d * d;
    }
    out.displacementDifference = std::sqrt(sum / double(surface.size()));
    out.freeDofs = hyper.freeDofCount();
    out.seconds = secondsSince(start);
    return out;
}

// A rigid frictionless sphere on the quarter block (symmetry planes x = 0, y = 0), the far faces at
// the Boussinesq field of the load: the load follows the FEM's own force (extrapolated from the
// last converged steps, and its mismatch reported), never the closed form's.
IndentationResult runIndentationCase(const IndentationCase& c) {
    const auto start = std::chrono::steady_clock::now();
    if (const std::string e = joinedMessages(validateHyperelasticMaterial(c.material)); !e.empty())
        throw std::invalid_argument(e);
    if (c.depthsOverRadius.empty()) throw std::invalid_argument("no indentation depths");
    std::vector<double> depths = c.depthsOverRadius;
    std::sort(depths.begin(), depths.end());
    if (!(depths.front() > 0.0 && depths.back() < 0.9)) throw std::invalid_argument("depths over R must lie in (0, 0.9)");
    const double radius = c.sphereRadiusMm;
    const double deepest = depths.back() * radius;
    const double aMax = sneddonSphereContactRadiusMm(radius, deepest);
    GradedBlockDef blockDef = c.block;
    blockDef.contactEdge = ContactEdgeNodes::Grid;  // the contact radius moves with the depth
    const GradedBlock block = blockFor(aMax, c.aOverH, blockDef);
    const TetMesh& mesh = block.mesh;
    const ElasticMaterial& small = c.material.smallStrain;

    std::vector<TetNodeId> far, top;
    const std::vector<std::uint8_t> fixed = quarterBlockConstraints(block, far, top);
    SphereContactDef sphere;
    sphere.radiusMm = radius;
    sphere.penaltyNPerMm = c.penaltyFactor * small.youngsModulusNPerMm2 * block.spacingMm;
    for (TetNodeId n : top)
        if (std::hypot(mesh.nodesMm[n].x, mesh.nodesMm[n].y) <= 2.0 * aMax) sphere.nodes.push_back(n);
    const HyperelasticFem fem(mesh, c.material, fixed, c.solver);

    // The far field's load: the force of the last converged steps, extrapolated as delta^1.5.
    double lastT = 0.0, lastForce = 0.0, loadUsed = 0.0;
    struct StepRecord {
        double t, loadN;
    };
    std::vector<StepRecord> records;
    auto load = [&](double t) {
        HyperelasticLoad l;
        const double p = lastT > 0.0 ? lastForce * std::pow(t / lastT, 1.5) : 0.0;
        loadUsed = p;
        l.prescribedMm.assign(mesh.dofCount(), 0.0);
        for (TetNodeId n : far) {
            const glm::dvec3 u = boussinesqDisplacementMm(small, p, mesh.nodesMm[n]);
            for (int d = 0; d < 3; ++d) l.prescribedMm[3 * n + std::size_t(d)] = u[d];
        }
        SphereContactDef s = sphere;
        s.centreMm = {0.0, 0.0, radius - t * deepest};
        l.sphere = std::move(s);
        return l;
    };
    auto onStep = [&](double t, const HyperelasticState& st) {
        records.push_back({t, loadUsed});
        lastT = t;
        lastForce = -4.0 * st.contactForceN.z;
    };
    std::vector<double> factors;
    for (double d : depths) factors.push_back(d / depths.back());
    const LoadPathResult path = fem.solvePath(load, factors, c.maxDepthStepOverRadius / depths.back(), onStep);

    IndentationResult out;
    out.aOverH = c.aOverH;
    out.poissonRatio = small.poissonRatio;
    out.nodes = mesh.nodeCount();
    out.tets = mesh.tetCount();
    out.freeDofs = fem.freeDofCount();
    out.solver = fem.solverName();
    out.loadSteps = path.steps;
    out.completed = path.completed;
    out.failure = path.failure;
    for (std::size_t p = 0; p < path.states.size(); ++p) {
        const HyperelasticState& st = path.states[p];
        IndentationPoint point;
        point.depthOverRadius = depths[p];
        const double delta = depths[p] * radius;
        point.forceFemN = -4.0 * st.contactForceN.z;
        point.forceSneddonN = sneddonSphereForceN(small, radius, delta);
        point.forceHertzN = hertzForceN(small, radius, delta);
        point.error = std::abs(point.forceFemN - point.forceSneddonN) / point.forceSneddonN;
        point.contactRadiusSneddonMm = sneddonSphereContactRadiusMm(radius, delta);
        point.penetrationOverDepth = st.maxPenetrationMm / delta;
        point.contactNodes = st.contactNodes;
        const glm::dvec3 centre{0.0, 0.0, radius - delta};
        for (TetNodeId n : sphere.nodes) {
            const glm::dvec3 x = mesh.nodesMm[n] + st.displacementMm[n];
            if (glm::length(x - centre) < radius) point.contactRadiusFemMm = std::max(point.contactRadiusFemMm, std::hypot(x.x, x.y));
        }
        for (const auto& r : records)
            if (std::abs(r.t - factors[p]) < 1e-12) point.farFieldMismatch = std::abs(r.loadN - point.forceFemN) / point.forceFemN;
        out.newtonIterations += st.newtonIterations;
        out.linearIterations += st.linearIterations;
        out.worstError = std::max(out.worstError, point.error);
        out.points.push_back(point);
    }
    out.seconds = secondsSince(start);
    return out;
}

}  // namespace palpate
