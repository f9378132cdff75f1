#include "engine/stability/StabilityModels.h"

#include "engine/core/MeshGenerator.h"
#include "engine/core/Octree.h"
#include "engine/core/Rings.h"
#include "engine/models/MassSpringModel.h"
#include "engine/models/ModelRegistry.h"
#include "engine/models/VolumetricFill.h"
#include "engine/models/VolumetricRingsModel.h"
#include "engine/models/slopering/SlopeRingModel.h"
#include "engine/stability/RenderedStiffness.h"
#include "engine/stability/StabilityBounds.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
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
    TetMesh tets;  // filled only for the volumetric map

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
/// The slope-ring parameters of a cell: the default slopes scaled so that ring 0's is |m1|.
SlopeRingParams slopeRingCellParams(double slope1MmPerN, double contactNPerMm, double alpha) {
    SlopeRingParams p;
    p.slopeLimitMmPerN = 100.0;
    const double scale = slope1MmPerN / p.slopeMagnitudeMmPerN[0];
    for (double& m : p.slopeMagnitudeMmPerN) m *= scale;
    p.contactStiffnessNPerMm = contactNPerMm;
    p.forceRelaxation = alpha;
    return p;
}

/// Passivity of a slope-ring set rendered at 1 kHz (the slope-ring maps' tick) to the simulated
/// device: K_eq / (2 b / T), K_eq in closed form (RenderedStiffness.h; the sweep gives the same).
double slopeRingPassivityRatio(const SlopeRingParams& p, const StabilityDeviceDef& device = {}) {
    return slopeRingPassiveEquivalentNPerMm(p) / passiveMaxStiffnessNPerMm(device.dampingNsPerM / 1000.0, 1e-3);
}

constexpr const char* kSlopeRingPassivityFormula =
    "K_eq = k_s |m1| k_c / (1 + g) x (1 + |lambda|) / (1 - |lambda|), lambda = 1 - alpha (1 + g), above the "
    "device's passive 2 b / T = 1 N/mm at 1 kHz (k_s = 1.5 N/mm)";

/// Runs `ticks` presses of a model whose contact force is `force()` and classifies the tail.
template <class Model>
CellOutcome settles(const PressScene& scene, Model& model, double slope1MmPerN, double contactNPerMm, int ticks) {
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

CellOutcome runSlopeRingCell(const PressScene& scene, double slope1MmPerN, double contactNPerMm, double alpha,
                             int ticks, SlopeRingMethod method = SlopeRingMethod::Coherent) {
    SlopeRingParams valid;  // defaults: the constructor validates, the real-time apply does not
    const auto model = makeSlopeRing(scene.mesh, scene.octree, valid, method);
    model->applyModelParams(slopeRingModelDef(slopeRingCellParams(slope1MmPerN, contactNPerMm, alpha), method));
    return settles(scene, *model, slope1MmPerN, contactNPerMm, ticks);
}

/// The same update on the tet graph's rings (VolumetricRingsModel).
CellOutcome runVolumetricRingsCell(const PressScene& scene, double slope1MmPerN, double contactNPerMm, double alpha,
                                   int ticks) {
    VolumetricRingsModel model(scene.mesh, scene.octree, scene.tets, VolumetricRingsParams{});
    ModelDef def;
    def.kind = ModelKind::VolumetricRings;
    def.slopeRing = slopeRingCellParams(slope1MmPerN, contactNPerMm, alpha);
    model.applyModelParams(def);
    return settles(scene, model, slope1MmPerN, contactNPerMm, ticks);
}

/// A geometric model (radius of influence, FFD) rendering to the simulated device of
/// StabilityDeviceDef at `rateHz`: each tick the tool is the device's position along the touched
/// vertex's normal, the model's force is held over the period (zero-order hold) and the device
/// moves by the exact solution of m x'' + b x' = F_hand - F_model for a constant force. The hand's
/// force holds the device d* deep at equilibrium (F_hand = k_s d*, whatever k_s: the loop is linear,
/// only the ratio matters). Energy growth: divergent when the largest deviation from d* over the
/// last tenth of the run exceeds the deviation it started with (perturbation d*, at rest: a peak of
/// the oscillation), or the device leaves the sphere. growth = that ratio. (Beyond the bound the
/// oscillation grows until the device leaves the surface and bounces, a limit cycle at least d*
/// from d*; inside it decays as |lambda|^t.)
/// `stiffnessNPerMm` is the model's static rendered stiffness (k_s for the geometric models, K_r for
/// the slope ring), which sets the hand's force.
CellOutcome runDeviceCell(const PressScene& scene, const ModelDef& def, double stiffnessNPerMm, double rateHz,
                          int ticks, const StabilityDeviceDef& device) {
    const auto model = makeModel(def, scene.mesh, scene.octree);
    const double stiffness = stiffnessNPerMm;
    const glm::vec3 rest = scene.mesh.restPositionsMm()[scene.touched];
    const glm::vec3 n = scene.mesh.restNormals()[scene.touched];
    const double periodS = 1.0 / rateHz;
    const double b = device.dampingNsPerM, tau = device.massKg / b;
    const double oneMinusDelta = -std::expm1(-periodS / tau), delta = 1.0 - oneMinusDelta;
    const double a = tau * oneMinusDelta;  // x advance per unit velocity over a period
    const double equilibriumM = device.equilibriumMm * 1e-3;
    const double handN = stiffness * device.equilibriumMm;
    double x = equilibriumM * (1.0 + device.perturbation), v = 0.0;  // m, m/s, positive inward
    const double first = std::abs(x - equilibriumM);
    double last = 0.0;
    const int window = std::max(10, ticks / 10);
    for (int t = 0; t < ticks; ++t) {
        const double deviation = std::abs(x - equilibriumM);
        if (t >= ticks - window) last = std::max(last, deviation);
        if (!(std::abs(x) < 0.05)) return {false, kNoBound};  // 50 mm: through the sphere or gone
        const glm::vec3 tool = rest - float(x * 1e3) * n;
        const TickResult r = model->step(tool, periodS);
        const double modelN = double(glm::dot(r.forceN, n));  // outward: against the press
        if (!std::isfinite(modelN)) return {false, kNoBound};
        const double f = handN - modelN;
        const double xNext = x + a * v + (f / b) * (periodS - a);
        v = delta * v + oneMinusDelta * f / b;
        x = xNext;
    }
    const double growth = last / first;
    return {growth < 1.0, growth};
}

/// Mass-spring: energy growth. The press can give the undamped tissue at most about the contact
/// spring's energy at the start, E_ref = k_c d^2 / 2 (the total energy, penalty included, is
/// conserved by the exact flow; symplectic Euler keeps a nearby one within (1 + h w/2) / (1 - h w/2),
/// some hundreds just inside its bound). Divergent when the tissue's energy passes 1e5 E_ref, or a
/// value is not finite, within the run; the growth reported is max E / E_ref.
CellOutcome runMassSpringCell(const PressScene& scene, const MassSpringParams& params, MassSpringIntegrator integrator,
                              double dtS, int ticks, MassSpringScope scope = MassSpringScope::Whole) {
    MassSpringModel model(scene.mesh, scene.octree, params, integrator, scope);
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

/// mass-spring-local: symplectic Euler on the touched vertex's rings, everything else pinned. The
/// derived boundary is 2 / omega_max of the simulated block (pinned neighbours still pull).
StabilityMapSpec massSpringLocalSpec(const std::string& name, std::shared_ptr<PressScene> scene,
                                     const StabilitySceneDef& def) {
    StabilityMapSpec spec;
    spec.model = name;
    spec.x = {"k", "N/mm", 0.01, 10.0, true};
    spec.y = {"dt", "s", 1e-5, 1e-1, true};
    const int rings = def.localRingCount;
    RingFinder finder(scene->mesh);
    RingSet set = finder.makeRingSet();
    finder.find(scene->touched, rings, set);
    std::vector<std::uint8_t> simulated(scene->mesh.vertexCount(), 0);
    for (std::size_t i = 0; i < set.size(); ++i) simulated[set.vertices[i]] = 1;
    const int ticks = def.massSpringTicks;
    spec.description = "symplectic-euler, local (" + std::to_string(rings) + " rings, " + std::to_string(set.size()) +
                       " vertices simulated, the rest pinned), " + std::to_string(scene->mesh.vertexCount()) +
                       "-vertex sphere, m = 1 g, anchor k, edges 5 k, contact k, undamped, 1 step/tick, press " +
                       std::to_string(def.pressDepthMm).substr(0, 4) + " mm, " + std::to_string(ticks) + " ticks";
    spec.criterion = "energy: divergent when the tissue energy passes 1e5 k_c d^2 / 2 or a value is not finite";
    spec.derivedFormula = "dt = 2 / omega_max of the simulated rings (pinned neighbours' springs kept; power iteration)";
    auto unit = massSpringCellParams(1.0, true);
    const double omegaAtUnitK = massSpringOmegaMaxRadPerS(scene->mesh, unit, scene->touched, simulated);
    spec.derivedBoundaryY = [omegaAtUnitK](double k) { return symplecticEulerMaxStepS(omegaAtUnitK * std::sqrt(k)); };
    spec.runCell = [scene, ticks, rings](double k, double dt) {
        MassSpringParams p = massSpringCellParams(k, true);
        p.localRingCount = rings;
        p.localIntegrator = MassSpringIntegrator::SymplecticEuler;
        return runMassSpringCell(*scene, p, MassSpringIntegrator::SymplecticEuler, dt, ticks, MassSpringScope::Local);
    };
    return spec;
}

/// The gain map (k_c, |m1|) at alpha = 0.5 for a slope-ring method or the volumetric rings.
StabilityMapSpec slopeGainSpec(const std::string& name, const std::string& what, std::shared_ptr<PressScene> scene,
                               const StabilitySceneDef& def, std::function<CellOutcome(double, double)> cell) {
    constexpr double kAlpha = 0.5;
    StabilityMapSpec spec;
    spec.model = name;
    spec.description = what + ", forceRelaxation alpha = 0.5 held, press " +
                       std::to_string(def.pressDepthMm).substr(0, 4) + " mm, " + std::to_string(def.slopeRingTicks) +
                       " ticks";
    spec.criterion = "contact force settles: swing over the last tenth < 1 % of k_c d / (1 + g)";
    spec.derivedFormula = "|m1| = (2 / alpha - 1) / k_c  (alpha (1 + |m1| k_c) = 2)";
    spec.x = {"k_c", "N/mm", 0.2, 5.0, true};
    spec.y = {"|m1|", "mm/N", 0.1, 100.0, true};
    spec.derivedBoundaryY = [](double kc) { return slopeRingMaxGain(kAlpha) / kc; };
    spec.runCell = [scene, cell](double kc, double m1) { return cell(kc, m1); };
    spec.passivityRatio = [](double kc, double m1) {
        return slopeRingPassivityRatio(slopeRingCellParams(m1, kc, kAlpha));
    };
    spec.passivityFormula = kSlopeRingPassivityFormula;
    (void)scene;
    return spec;
}

/// A geometric model against the simulated device: loop rate against the rendered stiffness k_s.
StabilityMapSpec deviceSpec(const std::string& name, ModelKind kind, std::shared_ptr<PressScene> scene,
                            const StabilitySceneDef& def, const StabilityDeviceDef& device = {}) {
    StabilityMapSpec spec;
    spec.model = name;
    const int ticks = def.deviceTicks;
    char text[400];
    std::snprintf(text, sizeof text,
                  "%s on a %zu-vertex sphere rendering k_s d to a 1-DOF device (m = %.3g kg, b = %.3g N s/m, "
                  "zero-order hold, no hand stiffness), hand force holding d* = %.2g mm, started %.0f %% deeper, "
                  "%d ticks",
                  name.c_str(), scene->mesh.vertexCount(), device.massKg, device.dampingNsPerM, device.equilibriumMm,
                  100.0 * device.perturbation, ticks);
    spec.description = text;
    spec.criterion = "energy growth: divergent when the largest deviation from d* over the last tenth exceeds the "
                     "initial one";
    spec.derivedFormula = "k_s = 2 b / T = 2 b rate (Colgate and Brown: b > K T / 2 + |B|, B = 0)";
    spec.x = {"rate", "Hz", 200.0, 10000.0, true};
    spec.y = {"k_s", "N/mm", 0.01, 100.0, true};
    const double b = device.dampingNsPerM;
    spec.derivedBoundaryY = [b](double rate) { return passiveMaxStiffnessNPerMm(b / 1000.0, 1.0 / rate); };
    // A pure spring: K_eq = k_s, so passivity is the derived boundary itself.
    spec.passivityRatio = [b](double rate, double ks) {
        return ks / passiveMaxStiffnessNPerMm(b / 1000.0, 1.0 / rate);
    };
    spec.passivityFormula = "K_eq = k_s (a pure spring) above the device's passive 2 b / T";
    spec.runCell = [scene, kind, ticks, device](double rate, double ks) {
        ModelDef model;
        model.kind = kind;
        model.radiusOfInfluence.stiffnessNPerMm = ks;
        model.ffd.stiffnessNPerMm = ks;
        return runDeviceCell(*scene, model, ks, rate, ticks, device);
    };
    return spec;
}

/// The slope ring's rendered force against the simulated device: relaxation alpha against the
/// return-spring stiffness k_s, the default slopes and k_c = 1 N/mm held (g = 0.6), at 1 kHz. The
/// derived boundary is the exact stability limit of the linearised loop (device, zero-order hold,
/// H(z) with the relaxation pole); the passivity boundary is drawn over it.
StabilityMapSpec slopeRingPassivitySpec(const std::string& name, std::shared_ptr<PressScene> scene,
                                        const StabilitySceneDef& def, const StabilityDeviceDef& device = {}) {
    constexpr double kPeriodS = 1e-3;
    const SlopeRingParams held;  // |m1| = 0.6 mm/N, k_c = 1 N/mm
    const double gain = held.loopGain();
    const double perSpring = held.slopeMagnitudeMmPerN[0] * held.contactStiffnessNPerMm / (1.0 + gain);  // K_r / k_s
    const auto params = [held](double alpha, double ks) {
        SlopeRingParams p = held;
        p.forceRelaxation = alpha;
        p.springStiffnessNPerMm = ks;
        return p;
    };
    StabilityMapSpec spec;
    spec.model = name;
    const int ticks = def.deviceTicks;
    char text[400];
    std::snprintf(text, sizeof text,
                  "coherent slope ring (|m1| = %.2g mm/N, k_c = %.2g N/mm, g = %.2g) on a %zu-vertex sphere rendering "
                  "to a 1-DOF device (m = %.3g kg, b = %.3g N s/m, zero-order hold, 1 kHz), hand force holding d* = "
                  "%.2g mm, started %.0f %% deeper, %d ticks",
                  held.slopeMagnitudeMmPerN[0], held.contactStiffnessNPerMm, gain, scene->mesh.vertexCount(),
                  device.massKg, device.dampingNsPerM, device.equilibriumMm, 100.0 * device.perturbation, ticks);
    spec.description = text;
    spec.criterion =
        "energy growth: divergent when the largest deviation from d* over the last tenth exceeds the "
        "initial one";
    spec.derivedFormula =
        "k_s at the stability limit of device + H(z) = K_r (1 - lambda) / (1 - lambda z^-1) "
        "(Jury's test on the 3 x 3 loop)";
    spec.x = {"alpha (forceRelaxation)", "", 0.05, 1.0, false};
    spec.y = {"k_s", "N/mm", 0.02, 50.0, true};
    const double m = device.massKg, b = device.dampingNsPerM;
    spec.derivedBoundaryY = [params, perSpring, m, b](double alpha) {
        const double lambda = slopeRingRelaxationPole(params(alpha, 1.0));
        return slopeRingDeviceLoopMaxStiffnessNPerMm(lambda, m, b, kPeriodS) / perSpring;
    };
    spec.passivityRatio = [params, device](double alpha, double ks) {
        return slopeRingPassivityRatio(params(alpha, ks), device);
    };
    spec.passivityFormula = "K_eq = K_r (1 + |lambda|) / (1 - |lambda|) above the device's passive 2 b / T = 1 N/mm";
    spec.runCell = [scene, params, perSpring, ticks, device](double alpha, double ks) {
        const ModelDef model = slopeRingModelDef(params(alpha, ks));
        return runDeviceCell(*scene, model, perSpring * ks, 1.0 / kPeriodS, ticks, device);
    };
    return spec;
}

}  // namespace

std::vector<std::string> stabilityModelNames() {
    return {"slope-ring-gain",
            "slope-ring-relaxation",
            "mass-spring-symplectic",
            "mass-spring-symplectic-vertex",
            "mass-spring-rk4",
            "mass-spring-implicit",
            "mass-spring-local",
            "coherent",
            "proposed",
            "hybrid",
            "previous",
            "volumetric-rings",
            "radius-of-influence",
            "ffd",
            "slope-ring-passivity"};
}

std::vector<std::string> stabilityMapModels(std::string_view map) {
    if (map == "slope-ring-gain" || map == "slope-ring-relaxation" || map == "slope-ring-passivity")
        return {"coherent"};
    if (map == "mass-spring-symplectic" || map == "mass-spring-symplectic-vertex") return {"mass-spring-symplectic"};
    const auto names = stabilityModelNames();
    if (std::find(names.begin(), names.end(), map) == names.end()) return {};
    return {std::string(map)};  // the other maps are named after the registry model they run
}

std::optional<StabilityMapSpec> stabilityMapSpec(std::string_view nameGiven, const StabilitySceneDef& def) {
    // A slope-ring method by its current name (parseMethod also reads "palpate", the former name of coherent).
    const auto named = parseMethod(nameGiven);
    const std::string_view name = named ? methodName(*named) : nameGiven;
    const auto names = stabilityModelNames();
    if (std::find(names.begin(), names.end(), name) == names.end()) return std::nullopt;
    auto scene = makeScene(def);
    const int ticks = def.slopeRingTicks;
    if (const auto method = parseMethod(name); method && name != "slope-ring-gain") {
        const std::string what = std::string(name) + " slope-ring tick";
        const SlopeRingMethod m = *method;
        return slopeGainSpec(std::string(name), what, scene, def, [scene, ticks, m](double kc, double m1) {
            return runSlopeRingCell(*scene, m1, kc, 0.5, ticks, m);
        });
    }
    if (name == "volumetric-rings") {
        scene->tets = fillSurfaceWithTets(scene->mesh);
        const std::string what = "volumetric-rings tick on " + std::to_string(scene->tets.nodeCount()) +
                                 " tet nodes (" + std::to_string(scene->tets.tetCount()) + " tets)";
        return slopeGainSpec(std::string(name), what, scene, def, [scene, ticks](double kc, double m1) {
            return runVolumetricRingsCell(*scene, m1, kc, 0.5, ticks);
        });
    }
    if (name == "radius-of-influence") return deviceSpec(std::string(name), ModelKind::RadiusOfInfluence, scene, def);
    if (name == "ffd") return deviceSpec(std::string(name), ModelKind::Ffd, scene, def);
    if (name == "mass-spring-local") return massSpringLocalSpec(std::string(name), scene, def);
    if (name == "slope-ring-passivity") return slopeRingPassivitySpec(std::string(name), scene, def);
    if (name == "slope-ring-gain") {
        constexpr double kAlpha = 0.5;
        StabilityMapSpec spec;
        spec.model = std::string(name);
        spec.description = "coherent slope-ring tick, forceRelaxation alpha = 0.5 held, press " +
                           std::to_string(def.pressDepthMm).substr(0, 4) + " mm, " + std::to_string(ticks) + " ticks";
        spec.criterion = "contact force settles: swing over the last tenth < 1 % of k_c d / (1 + g)";
        spec.derivedFormula = "|m1| = (2 / alpha - 1) / k_c  (alpha (1 + |m1| k_c) = 2)";
        spec.x = {"k_c", "N/mm", 0.2, 5.0, true};
        spec.y = {"|m1|", "mm/N", 0.1, 100.0, true};
        spec.derivedBoundaryY = [](double kc) { return slopeRingMaxGain(kAlpha) / kc; };
        spec.runCell = [scene, ticks](double kc, double m1) { return runSlopeRingCell(*scene, m1, kc, kAlpha, ticks); };
        spec.passivityRatio = [](double kc, double m1) {
            return slopeRingPassivityRatio(slopeRingCellParams(m1, kc, kAlpha));
        };
        spec.passivityFormula = kSlopeRingPassivityFormula;
        return spec;
    }
    if (name == "slope-ring-relaxation") {
        constexpr double kContact = 1.0;
        StabilityMapSpec spec;
        spec.model = std::string(name);
        spec.description = "coherent slope-ring tick, k_c = 1 N/mm held, gain swept through |m1|, press " +
                           std::to_string(def.pressDepthMm).substr(0, 4) + " mm, " + std::to_string(ticks) + " ticks";
        spec.criterion = "contact force settles: swing over the last tenth < 1 % of k_c d / (1 + g)";
        spec.derivedFormula = "g = 2 / alpha - 1";
        spec.x = {"alpha (forceRelaxation)", "", 0.05, 1.0, false};
        spec.y = {"g = |m1| k_c", "", 0.1, 100.0, true};
        spec.derivedBoundaryY = [](double alpha) { return slopeRingMaxGain(alpha); };
        spec.runCell = [scene, ticks](double alpha, double gain) {
            return runSlopeRingCell(*scene, gain / kContact, kContact, alpha, ticks);
        };
        spec.passivityRatio = [](double alpha, double gain) {
            return slopeRingPassivityRatio(slopeRingCellParams(gain / kContact, kContact, alpha));
        };
        spec.passivityFormula = kSlopeRingPassivityFormula;
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
