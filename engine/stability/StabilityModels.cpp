#include "engine/stability/StabilityModels.h"

#include "engine/MeshGenerator.h"
#include "engine/Octree.h"
#include "engine/SlopeRingDeformer.h"
#include "engine/models/MassSpringModel.h"
#include "engine/stability/StabilityBounds.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace palpate {

namespace {

/// The mesh, its octree and the pressed vertex, shared by every cell of a map.
struct PressScene {
    TissueMesh mesh;
    Octree octree;
    VertexId touched = 0;
    glm::vec3 toolMm{0.0f};
    double depthMm = 0.5;

    PressScene(TissueMesh m, double depth) : mesh(std::move(m)), octree(mesh, OctreeDef{}), depthMm(depth) {
        // The vertex farthest along +x: on the equator, away from the poles' high valence.
        const auto& rest = mesh.restPositionsMm();
        for (VertexId v = 1; v < rest.size(); ++v)
            if (rest[v].x > rest[touched].x) touched = v;
        toolMm = rest[touched] - float(depth) * mesh.restNormals()[touched];
    }
};

std::shared_ptr<PressScene> makeScene(const StabilitySceneDef& def) {
    auto generated = generateMesh(GeneratedShape::Sphere, def.sphereVertices);
    if (!generated.mesh) throw std::invalid_argument("stability scene: " + generated.error());
    return std::make_shared<PressScene>(std::move(*generated.mesh), def.pressDepthMm);
}

/// Slope ring: the contact force must settle. The projected iteration cannot grow without bound
/// (beyond alpha (1 + g) = 2 it locks into the two-cycle 0 <-> alpha k_c d, a buzz), so "divergent"
/// here means the force still swings by more than 1 % of its equilibrium over the last tenth.
CellOutcome runSlopeRingCell(const PressScene& scene, double slope1MmPerN, double contactNPerMm, double alpha,
                             int ticks) {
    SlopeRingParams valid;  // defaults: the constructor validates, the real-time apply does not
    SlopeRingDeformer model(scene.mesh, scene.octree, valid, SlopeRingMethod::Palpate);
    SlopeRingParams p = valid;
    p.slopeLimitMmPerN = 100.0;
    const double scale = slope1MmPerN / valid.slopeMagnitudeMmPerN[0];
    for (double& m : p.slopeMagnitudeMmPerN) m *= scale;
    p.contactStiffnessNPerMm = contactNPerMm;
    p.forceRelaxation = alpha;
    model.applySlopeRingParams(p);
    const double gain = slope1MmPerN * contactNPerMm;
    const double equilibriumN = contactNPerMm * scene.depthMm / (1.0 + gain);
    float lo = INFINITY, hi = -INFINITY;
    const int tail = std::max(10, ticks / 10);
    for (int t = 0; t < ticks; ++t) {
        model.step(scene.toolMm, 1e-3);
        const float f = model.contactForceN();
        if (!std::isfinite(f)) return {false, kNoBound};
        if (t >= ticks - tail) {
            lo = std::min(lo, f);
            hi = std::max(hi, f);
        }
    }
    const double swing = double(hi - lo) / equilibriumN;
    return {swing < 0.01, swing};
}

/// Mass-spring: energy growth. The press can give the undamped tissue at most about the contact
/// spring's energy at the start, E_ref = k_c d^2 / 2 (the total energy, penalty included, is
/// conserved by the exact flow; symplectic Euler keeps a nearby one within (1 + h w/2) / (1 - h w/2),
/// some hundreds just inside its bound). Divergent when the tissue's energy passes 1e5 E_ref, or a
/// value is not finite, within the run; the growth reported is max E / E_ref.
CellOutcome runMassSpringCell(const PressScene& scene, const MassSpringParams& params, MassSpringIntegrator integrator,
                              double dtS, int ticks) {
    MassSpringModel model(scene.mesh, scene.octree, params, integrator, MassSpringScope::Whole);
    const double reference = 0.5 * params.contactStiffnessNPerMm * scene.depthMm * scene.depthMm;
    double peak = 0.0;
    for (int t = 0; t < ticks; ++t) {
        model.step(scene.toolMm, dtS);
        const double e = model.energyMilliJ();
        if (!std::isfinite(e)) return {false, kNoBound};
        peak = std::max(peak, e);
        if (peak > 1e5 * reference) return {false, peak / reference};
    }
    return {true, peak / reference};
}

/// Mass-spring parameters for a map cell, undamped, one step per tick. Coupled mesh: anchor k,
/// edges 5 k (the default ratio), contact k (soft against the tissue's ~18 k point stiffness, so
/// the contact stays closed through the press's transient and the system stays linear). Per
/// vertex: no edges, contact 0.01 k (likewise).
MassSpringParams massSpringCellParams(double anchorNPerMm, bool edges) {
    MassSpringParams p;
    p.anchorStiffnessNPerMm = anchorNPerMm;
    p.edgeStiffnessNPerMm = edges ? 5.0 * anchorNPerMm : 0.0;
    p.contactStiffnessNPerMm = edges ? anchorNPerMm : 0.01 * anchorNPerMm;
    p.dampingRatio = 0.0;
    p.substeps = 1;
    return p;
}

StabilityMapSpec massSpringSpec(const std::string& name, MassSpringIntegrator integrator, bool edges,
                                std::shared_ptr<PressScene> scene, const StabilitySceneDef& def) {
    StabilityMapSpec spec;
    spec.model = name;
    spec.x = {"k", "N/mm", 0.01, 10.0, true};
    spec.y = {"dt", "s", 1e-5, 1e-1, true};
    const int ticks = integrator == MassSpringIntegrator::BackwardEuler ? def.implicitTicks : def.massSpringTicks;
    spec.description = std::string(integratorName(integrator)) + ", whole, " +
                       std::to_string(scene->mesh.vertexCount()) + "-vertex sphere, m = 1 g, anchor k, " +
                       (edges ? "edges 5 k, contact k" : "no edges, contact 0.01 k") +
                       ", undamped, 1 step/tick, press " + std::to_string(def.pressDepthMm).substr(0, 4) +
                       " mm, " + std::to_string(ticks) + " ticks";
    spec.criterion = "energy: divergent when the tissue energy passes 1e5 k_c d^2 / 2 or a value is not finite";
    // omega_max scales as sqrt(k): compute it once at k = 1.
    const double omegaAtUnitK = massSpringOmegaMaxRadPerS(scene->mesh, massSpringCellParams(1.0, edges), scene->touched);
    const auto omega = [omegaAtUnitK](double k) { return omegaAtUnitK * std::sqrt(k); };
    switch (integrator) {
        case MassSpringIntegrator::SymplecticEuler:
            spec.derivedFormula = edges ? "dt = 2 / omega_max, omega_max^2 = 1000 lambda_max(K) / m (power iteration)"
                                        : "dt = 2 sqrt(m / k_total), k_total = k + k_c = 1.01 k";
            spec.derivedBoundaryY = [omega](double k) { return symplecticEulerMaxStepS(omega(k)); };
            break;
        case MassSpringIntegrator::Rk4:
            spec.derivedFormula = "dt = 2 sqrt(2) / omega_max";
            spec.derivedBoundaryY = [omega](double k) { return rk4MaxStepS(omega(k)); };
            break;
        case MassSpringIntegrator::BackwardEuler:
            spec.derivedFormula = "none: backward Euler is stable at every dt";
            spec.derivedBoundaryY = [](double) { return kNoBound; };
            break;
    }
    spec.runCell = [scene, integrator, edges, ticks](double k, double dt) {
        return runMassSpringCell(*scene, massSpringCellParams(k, edges), integrator, dt, ticks);
    };
    return spec;
}

}  // namespace

std::vector<std::string> stabilityModelNames() {
    return {"slope-ring-gain",          "slope-ring-relaxation", "mass-spring-symplectic",
            "mass-spring-symplectic-vertex", "mass-spring-rk4",  "mass-spring-implicit"};
}

std::optional<StabilityMapSpec> stabilityMapSpec(std::string_view name, const StabilitySceneDef& def) {
    const auto names = stabilityModelNames();
    if (std::find(names.begin(), names.end(), name) == names.end()) return std::nullopt;
    auto scene = makeScene(def);
    const int ticks = def.slopeRingTicks;
    if (name == "slope-ring-gain") {
        constexpr double kAlpha = 0.5;
        StabilityMapSpec spec;
        spec.model = std::string(name);
        spec.description = "palpate slope-ring tick, forceRelaxation alpha = 0.5 held, press " +
                           std::to_string(def.pressDepthMm).substr(0, 4) + " mm, " + std::to_string(ticks) + " ticks";
        spec.criterion = "contact force settles: swing over the last tenth < 1 % of k_c d / (1 + g)";
        spec.derivedFormula = "|m1| = (2 / alpha - 1) / k_c  (alpha (1 + |m1| k_c) = 2)";
        spec.x = {"k_c", "N/mm", 0.2, 5.0, true};
        spec.y = {"|m1|", "mm/N", 0.1, 100.0, true};
        spec.derivedBoundaryY = [](double kc) { return slopeRingMaxGain(kAlpha) / kc; };
        spec.runCell = [scene, ticks](double kc, double m1) { return runSlopeRingCell(*scene, m1, kc, kAlpha, ticks); };
        return spec;
    }
    if (name == "slope-ring-relaxation") {
        constexpr double kContact = 1.0;
        StabilityMapSpec spec;
        spec.model = std::string(name);
        spec.description = "palpate slope-ring tick, k_c = 1 N/mm held, gain swept through |m1|, press " +
                           std::to_string(def.pressDepthMm).substr(0, 4) + " mm, " + std::to_string(ticks) + " ticks";
        spec.criterion = "contact force settles: swing over the last tenth < 1 % of k_c d / (1 + g)";
        spec.derivedFormula = "g = 2 / alpha - 1";
        spec.x = {"alpha (forceRelaxation)", "", 0.05, 1.0, false};
        spec.y = {"g = |m1| k_c", "", 0.1, 100.0, true};
        spec.derivedBoundaryY = [](double alpha) { return slopeRingMaxGain(alpha); };
        spec.runCell = [scene, ticks](double alpha, double gain) {
            return runSlopeRingCell(*scene, gain / kContact, kContact, alpha, ticks);
        };
        return spec;
    }
    if (name == "mass-spring-symplectic")
        return massSpringSpec(std::string(name), MassSpringIntegrator::SymplecticEuler, true, scene, def);
    if (name == "mass-spring-symplectic-vertex")
        return massSpringSpec(std::string(name), MassSpringIntegrator::SymplecticEuler, false, scene, def);
    if (name == "mass-spring-rk4") return massSpringSpec(std::string(name), MassSpringIntegrator::Rk4, true, scene, def);
    return massSpringSpec(std::string(name), MassSpringIntegrator::BackwardEuler, true, scene, def);
}

}  // namespace palpate
