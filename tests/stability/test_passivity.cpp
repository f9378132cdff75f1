// docs/stability.md, "Rendered stiffness and passivity": the sampled-data passivity condition
// (Colgate and Schenkel) as a frequency sweep against its closed forms, the rendered transfer of
// every model (closed form, and measured on the real model by the probe), the energy of the
// sampled loop on both sides of each passivity boundary (the direct check of the formula), the
// slope ring's device loop, and the margin that names the parameter.
#include "engine/stability/RenderedStiffness.h"
#include "engine/stability/SampledPassivity.h"
#include "engine/stability/StabilityBounds.h"
#include "engine/stability/StabilityMargin.h"
#include "engine/stability/StabilityModels.h"
#include "engine/stability/TransferProbe.h"

#include "engine/core/MeshGenerator.h"
#include "engine/core/Octree.h"
#include "engine/models/ModelRegistry.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

using namespace palpate;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kPeriodS = 1e-3;

const TissueMesh& sphere242() {
    static const TissueMesh mesh = std::move(*generateMesh(GeneratedShape::Sphere, 242).mesh);
    return mesh;
}
const Octree& octree242() {
    static const Octree octree(sphere242(), OctreeDef{});
    return octree;
}

/// A slope-ring set with the default slopes (|m1| = 0.6 mm/N), k_c = 1 N/mm (g = 0.6) and the
/// relaxation chosen for the pole lambda = 1 - alpha (1 + g).
ModelDef slopeRingWithPole(double lambda, double springNPerMm = 1.5,
                           SlopeRingMethod method = SlopeRingMethod::Coherent) {
    SlopeRingParams p;
    p.forceRelaxation = (1.0 - lambda) / (1.0 + p.loopGain());
    p.springStiffnessNPerMm = springNPerMm;
    return slopeRingModelDef(p, method);
}

/// The energy the device and the environment absorb per tick, on average, while the hand moves
/// the device through the samples x_n = d0 + X cos(theta n) along straight lines between them, the
/// worst motion for given samples (it spends the least in the device's damping: Colgate and
/// Schenkel). The damping takes b (dx)^2 / T over a period, the environment F_n dx_n (its force is
/// held over the period); the mass returns what it takes over whole periods. mJ (N mm) per tick:
/// > 0 dissipating (passive), < 0 generating. The real model, stepped at period T from rest.
double absorbedPerTickMilliJ(const ModelDef& def, double dampingNsPerMm, int ticksPerPeriod, double pressMm = 0.5,
                             double amplitudeMm = 0.05) {
    const TissueMesh& mesh = sphere242();
    const auto model = makeModel(def, mesh, octree242());
    const VertexId v = highestValenceVertex(mesh);
    const glm::vec3 n = mesh.restNormals()[v], rest = mesh.restPositionsMm()[v];
    const double theta = 2.0 * kPi / ticksPerPeriod;
    const int settle = std::max(600, 3 * ticksPerPeriod), measured = 4 * ticksPerPeriod;
    double energy = 0.0;
    double x = pressMm + amplitudeMm;
    for (int t = 0; t < settle + measured; ++t) {
        const TickResult r = model->step(rest - float(x) * n, kPeriodS);
        EXPECT_TRUE(r.contact && r.touched == v) << "the contact must stay closed at the vertex";
        const double force = double(glm::dot(r.forceN, n));
        const double next = pressMm + amplitudeMm * std::cos(theta * (t + 1));
        const double dx = next - x;
        if (t >= settle) energy += dampingNsPerMm * dx * dx / kPeriodS + force * dx;
        x = next;
    }
    return energy / measured;
}

/// The linear loop of slopeRingDeviceLoopStable stepped directly: bounded after 20000 ticks?
bool deviceLoopBounded(double kNPerM, double lambda, double m, double b, double T) {
    const double tau = m / b, oneMinusDelta = -std::expm1(-T / tau), delta = 1.0 - oneMinusDelta;
    const double a = tau * oneMinusDelta, c = kNPerM * (1.0 - lambda);
    double x = 1e-4, v = 0.0, f = 0.0, first = 0.0, last = 0.0;
    const int ticks = 20000;
    for (int t = 0; t < ticks; ++t) {
        f = lambda * f + c * x;
        const double xNext = x + a * v - (f / b) * (T - a);
        v = delta * v - oneMinusDelta * f / b;
        x = xNext;
        if (t < 2000) first = std::max(first, std::abs(x));
        if (t >= ticks - 2000) last = std::max(last, std::abs(x));
    }
    return last < first;
}

}  // namespace

TEST(Passivity, APureSpringNeedsColgateAndBrownsDampingAndAVirtualDamperAddsIts) {
    for (double k : {0.125, 1.0, 37.5}) {
        const RenderedTransfer spring = [k](double) { return std::complex<double>(k, 0.0); };
        EXPECT_NEAR(sweepPassivity(spring).passiveEquivalentNPerMm, k, 1e-12 * k);
        EXPECT_NEAR(requiredDeviceDampingNsPerMm(spring, kPeriodS), k * kPeriodS / 2.0, 1e-15);
        // H = K + B (1 - z^-1) / T: Colgate and Brown's b > K T / 2 + |B|, at Nyquist for B > 0 and at
        // theta -> 0 for B < 0 (a negative damper).
        for (double B : {2e-4, -2e-4}) {
            const RenderedTransfer wall = [k, B](double theta) {
                return k + B * (1.0 - std::polar(1.0, -theta)) / kPeriodS;
            };
            const PassivitySweep sweep = sweepPassivity(wall);
            EXPECT_NEAR(0.5 * kPeriodS * sweep.passiveEquivalentNPerMm, k * kPeriodS / 2.0 + std::abs(B), 1e-9);
            if (B > 0) EXPECT_DOUBLE_EQ(sweep.worstThetaRad, kPi);
            else EXPECT_LT(sweep.worstThetaRad, 1e-6);
        }
    }
    // The device: passive up to 1 N/mm at 1 kHz, 2 N/mm at 2 kHz.
    EXPECT_DOUBLE_EQ(devicePassiveStiffnessNPerMm(1.0, 1e-3), 1.0);
    EXPECT_DOUBLE_EQ(devicePassiveStiffnessNPerMm(1.0, 5e-4), 2.0);
}

TEST(Passivity, TheRelaxationLagAndItsAlternationRaiseTheSlopeRingsPassiveEquivalent) {
    for (double lambda : {0.9, 0.52, 0.1, 0.0, -0.3, -0.6, -0.9}) {
        const SlopeRingParams p = slopeRingWithPole(lambda).slopeRing;
        EXPECT_NEAR(slopeRingRelaxationPole(p), lambda, 1e-12);
        const double kr = p.renderedStiffnessNPerMm();
        EXPECT_NEAR(kr, 1.5 * 0.6 / 1.6, 1e-12);  // K_r = k_s |m1| k_c / (1 + g) whatever alpha
        const PassivitySweep sweep = sweepPassivity(slopeRingTransfer(p));
        const double closed = kr * (1.0 + std::abs(lambda)) / (1.0 - std::abs(lambda));
        EXPECT_NEAR(slopeRingPassiveEquivalentNPerMm(p), closed, 1e-12 * closed);
        EXPECT_NEAR(sweep.passiveEquivalentNPerMm, closed, 1e-6 * closed) << "lambda " << lambda;
        if (lambda == 0.0) {
            EXPECT_NEAR(sweep.passiveEquivalentNPerMm, kr, 1e-12);  // exact in one tick: a pure spring
        } else {
            EXPECT_GT(sweep.passiveEquivalentNPerMm, 1.01 * kr) << "lambda " << lambda;
            // A lag (lambda > 0) is a negative damper, worst towards theta -> 0; an alternation
            // (lambda < 0) is worst at Nyquist.
            if (lambda > 0) EXPECT_LT(sweep.worstThetaRad, 1e-6);
            else EXPECT_DOUBLE_EQ(sweep.worstThetaRad, kPi);
        }
    }
}

TEST(Passivity, TheProbeMeasuresEachModelsClosedForm) {
    // The slope-ring methods and the volumetric rings: the closed form H(z), measured on the model.
    for (double lambda : {0.52, 0.0, -0.6}) {
        for (SlopeRingMethod method : {SlopeRingMethod::Coherent, SlopeRingMethod::Proposed}) {
            const ModelDef def = slopeRingWithPole(lambda, 1.5, method);
            const auto model = makeModel(def, sphere242(), octree242());
            const MeasuredTransfer measured = measureRenderedTransfer(*model, sphere242(),
                                                                      highestValenceVertex(sphere242()), kPeriodS);
            ASSERT_TRUE(measured.ok) << measured.problem;
            const double kr = def.slopeRing.renderedStiffnessNPerMm();
            EXPECT_NEAR(measured.staticNPerMm, kr, 1e-3 * kr) << "lambda " << lambda;
            const double keq = slopeRingPassiveEquivalentNPerMm(def.slopeRing);
            EXPECT_NEAR(sweepPassivity(measured.transfer()).passiveEquivalentNPerMm, keq, 2e-3 * keq)
                << "lambda " << lambda;
        }
        ModelDef volumetric = *modelDefForName("volumetric-rings");
        volumetric.slopeRing = slopeRingWithPole(lambda).slopeRing;
        const auto model = makeModel(volumetric, sphere242(), octree242());
        const MeasuredTransfer measured = measureRenderedTransfer(*model, sphere242(),
                                                                  highestValenceVertex(sphere242()), kPeriodS);
        ASSERT_TRUE(measured.ok) << measured.problem;
        const double keq = slopeRingPassiveEquivalentNPerMm(volumetric.slopeRing);
        EXPECT_NEAR(sweepPassivity(measured.transfer()).passiveEquivalentNPerMm, keq, 2e-3 * keq);
    }
    // The geometric models: a pure spring k_s, no delay.
    for (const char* name : {"radius-of-influence", "ffd"}) {
        const ModelDef def = *modelDefForName(name);
        const auto model = makeModel(def, sphere242(), octree242());
        const MeasuredTransfer measured = measureRenderedTransfer(*model, sphere242(),
                                                                  highestValenceVertex(sphere242()), kPeriodS);
        ASSERT_TRUE(measured.ok) << measured.problem;
        const double ks = renderedStiffness(def, nullptr, kPeriodS)->lines.front().passiveEquivalentNPerMm;
        EXPECT_NEAR(ks, 0.125, 1e-12) << name;
        EXPECT_NEAR(measured.staticNPerMm, ks, 1e-4) << name;
        EXPECT_NEAR(sweepPassivity(measured.transfer()).passiveEquivalentNPerMm, ks, 1e-4) << name;
    }
}

TEST(Passivity, MassSpringIsMeasuredAndAnUndampedExplicitOneHasNoFiniteBound) {
    for (const char* name :
         {"mass-spring-symplectic", "mass-spring-rk4", "mass-spring-implicit", "mass-spring-local"}) {
        const ModelDef def = *modelDefForName(name);
        EXPECT_FALSE(renderedStiffness(def, nullptr, kPeriodS)) << name << ": needs the mesh";
        const RenderedStiffnessLine line = renderedStiffness(def, &sphere242(), kPeriodS)->lines.front();
        // Static: the contact in series with the tissue's point stiffness (docs/stability.md section 3);
        // K_eq: towards k_c = 1 N/mm, where the touched vertex's mass no longer follows the tool.
        EXPECT_GT(line.staticNPerMm, 0.6) << name;
        EXPECT_LT(line.staticNPerMm, 0.7) << name;
        EXPECT_GT(line.passiveEquivalentNPerMm, 1.2 * line.staticNPerMm) << name;
        EXPECT_LT(line.passiveEquivalentNPerMm, 1.0) << name;
        std::printf("%s: static %.4f N/mm, K_eq %.4f N/mm at theta %.3g\n", name, line.staticNPerMm,
                    line.passiveEquivalentNPerMm, line.worstThetaRad);
    }
    ModelDef undamped = *modelDefForName("mass-spring-symplectic");
    undamped.massSpring.dampingRatio = 0.0;
    const RenderedStiffnessLine line = renderedStiffness(undamped, &sphere242(), kPeriodS)->lines.front();
    EXPECT_TRUE(std::isinf(line.passiveEquivalentNPerMm));
    EXPECT_NE(line.why.find("does not settle"), std::string::npos) << line.why;
}

// The direct check of the formula: at the frequency where the sweep finds K_eq, the sampled loop
// with device damping 3 % below b_req generates energy, 3 % above it dissipates, on the real model.
TEST(Passivity, EnergyOfTheSampledLoopChangesSignAtTheBoundary) {
    struct Case {
        const char* what;
        ModelDef def;
        int ticksPerPeriod;  // 400: theta = 0.0157 (a lag's worst is theta -> 0); 2: Nyquist
    };
    const Case cases[] = {
        {"slope ring, lag lambda = 0.52", slopeRingWithPole(0.52), 400},
        {"slope ring, alternation lambda = -0.6", slopeRingWithPole(-0.6), 2},
        {"slope ring, exact lambda = 0", slopeRingWithPole(0.0), 7},
        {"radius of influence (pure spring)", *modelDefForName("radius-of-influence"), 5},
    };
    for (const Case& c : cases) {
        const double keq = renderedStiffness(c.def, nullptr, kPeriodS)->lines.front().passiveEquivalentNPerMm;
        const double b = 0.5 * kPeriodS * keq;
        const double below = absorbedPerTickMilliJ(c.def, 0.97 * b, c.ticksPerPeriod);
        const double above = absorbedPerTickMilliJ(c.def, 1.03 * b, c.ticksPerPeriod);
        std::printf("%s: b_req %.4g N s/m, absorbed per tick %.3g mJ at 0.97 b_req, %.3g at 1.03\n", c.what, 1000.0 * b,
                    below, above);
        EXPECT_LT(below, 0.0) << c.what << ": generates";
        EXPECT_GT(above, 0.0) << c.what << ": dissipates";
        // Above the bound the loop dissipates at every frequency.
        for (int period : {2, 3, 6, 50})
            EXPECT_GT(absorbedPerTickMilliJ(c.def, 1.03 * b, period), 0.0) << c.what << ", period " << period;
    }
    // The lag's K_eq is what makes it: damping for its static stiffness alone is 3.2x too little.
    const ModelDef lag = slopeRingWithPole(0.52);
    EXPECT_LT(absorbedPerTickMilliJ(lag, 1.03 * 0.5 * kPeriodS * lag.slopeRing.renderedStiffnessNPerMm(), 400),
              0.0);

    // Mass-spring, measured: its b_req at the frequency the sweep found (rounded to whole ticks per period).
    for (const char* name : {"mass-spring-implicit", "mass-spring-symplectic"}) {
        const ModelDef def = *modelDefForName(name);
        const auto model = makeModel(def, sphere242(), octree242());
        const MeasuredTransfer measured = measureRenderedTransfer(*model, sphere242(),
                                                                  highestValenceVertex(sphere242()), kPeriodS);
        ASSERT_TRUE(measured.ok) << measured.problem;
        const PassivitySweep sweep = sweepPassivity(measured.transfer());
        const int period = std::max(2, int(std::lround(2.0 * kPi / sweep.worstThetaRad)));
        const double theta = 2.0 * kPi / period;
        const std::complex<double> h = measured.transfer()(theta);
        const double bAtTheta = 0.5 * kPeriodS * (h.real() - h.imag() / std::tan(0.5 * theta));
        EXPECT_GT(bAtTheta, 0.9 * 0.5 * kPeriodS * sweep.passiveEquivalentNPerMm) << name;
        const double below = absorbedPerTickMilliJ(def, 0.97 * bAtTheta, period);
        const double above = absorbedPerTickMilliJ(def, 1.03 * bAtTheta, period);
        std::printf(
            "%s: b_req %.4g N s/m at %d ticks per period (K_eq %.4g N/mm), absorbed per tick %.3g mJ at "
            "0.97 b_req, %.3g at 1.03\n",
            name, 1000.0 * bAtTheta, period, sweep.passiveEquivalentNPerMm, below, above);
        EXPECT_LT(below, 0.0) << name << ": generates";
        EXPECT_GT(above, 0.0) << name << ": dissipates";
    }
}

TEST(Passivity, TheDeviceLoopFollowsPassivityForALagAndNotForAnAlternation) {
    const double m = 0.05, b = 0.5, T = 1e-3;  // the maps' simulated device: passive up to 1 N/mm
    for (double lambda : {0.9, 0.52, 0.0, -0.3, -0.6}) {
        const double stable = slopeRingDeviceLoopMaxStiffnessNPerMm(lambda, m, b, T);
        const double passive = (2.0 * b / T / 1000.0) * (1.0 - std::abs(lambda)) / (1.0 + std::abs(lambda));
        // Jury's test against the loop stepped directly, both sides.
        EXPECT_TRUE(deviceLoopBounded(0.97 * stable * 1000.0, lambda, m, b, T)) << lambda;
        EXPECT_FALSE(deviceLoopBounded(1.03 * stable * 1000.0, lambda, m, b, T)) << lambda;
        // Passivity is sufficient: never above the stability limit. For a lag it is the limit (to
        // the device's b T / m and the lag's low frequency); for an alternation far below it.
        EXPECT_LE(passive, stable) << lambda;
        if (lambda >= 0.0) EXPECT_LT(stable / passive, lambda > 0.6 ? 1.12 : 1.02) << lambda;
        else EXPECT_GT(stable / passive, 3.0) << lambda;
    }
    EXPECT_NEAR(slopeRingDeviceLoopMaxStiffnessNPerMm(0.0, m, b, T), sampledWallMaxStiffnessNPerMm(m, b, T), 1e-9);
}

TEST(Passivity, SlopeRingPassivityMapBothSidesOnTheRealModel) {
    StabilitySceneDef scene;
    scene.deviceTicks = 6000;
    const auto spec = stabilityMapSpec("slope-ring-passivity", scene);
    ASSERT_TRUE(spec);
    for (double alpha : {0.2, 0.5, 0.9}) {
        const double y = spec->derivedBoundaryY(alpha);
        EXPECT_TRUE(spec->runCell(alpha, 0.97 * y).bounded) << alpha;
        EXPECT_FALSE(spec->runCell(alpha, 1.03 * y).bounded) << alpha;
    }
    // Its passivity shading: both sides of K_eq = 1 N/mm at alpha = 0.2 (lambda = 0.68) and 0.9 (-0.44).
    for (double alpha : {0.2, 0.9}) {
        SlopeRingParams p;
        p.forceRelaxation = alpha;
        p.springStiffnessNPerMm = 1.0;
        const double boundary = 1.0 / slopeRingPassiveEquivalentNPerMm(p);  // K_eq is linear in k_s
        EXPECT_LT(spec->passivityRatio(alpha, 0.97 * boundary), 1.0) << alpha;
        EXPECT_GT(spec->passivityRatio(alpha, 1.03 * boundary), 1.0) << alpha;
    }
}

TEST(Passivity, TheSlopeRingMapsShadeThePassivityBoundary) {
    StabilitySceneDef scene;
    scene.slopeRingTicks = 300;
    for (const char* name : {"slope-ring-gain", "coherent", "volumetric-rings", "slope-ring-relaxation"}) {
        const auto spec = stabilityMapSpec(name, scene);
        ASSERT_TRUE(spec && spec->passivityRatio) << name;
        EXPECT_FALSE(spec->passivityFormula.empty());
    }
    // The gain map at alpha = 0.5, k_s = 1.5 N/mm, k_c = 1 N/mm: bisect |m1| for K_eq = 1 N/mm and
    // check 3 % either side with the margin's own computation.
    const auto spec = stabilityMapSpec("slope-ring-gain", scene);
    double lo = 0.1, hi = 10.0;
    for (int i = 0; i < 60; ++i) {
        const double mid = std::sqrt(lo * hi);
        (spec->passivityRatio(1.0, mid) < 1.0 ? lo : hi) = mid;
    }
    for (double f : {0.97, 1.03}) {
        ModelDef def = *modelDefForName("coherent");
        def.slopeRing.slopeLimitMmPerN = 100.0;
        const double scale = f * lo / def.slopeRing.slopeMagnitudeMmPerN[0];
        for (double& s : def.slopeRing.slopeMagnitudeMmPerN) s *= scale;
        def.slopeRing.forceRelaxation = 0.5;
        const StabilityMargin margin = stabilityMargin(def, sphere242(), kPeriodS);
        EXPECT_EQ(margin.passivityMargin > 0.0, f < 1.0) << f;
        EXPECT_EQ(spec->passivityRatio(1.0, f * lo) < 1.0, f < 1.0) << f;
    }
    // The geometric maps: passivity is their derived boundary.
    const auto roi = stabilityMapSpec("radius-of-influence", scene);
    for (double rate : {500.0, 2000.0}) {
        EXPECT_LT(roi->passivityRatio(rate, 0.97 * roi->derivedBoundaryY(rate)), 1.0);
        EXPECT_GT(roi->passivityRatio(rate, 1.03 * roi->derivedBoundaryY(rate)), 1.0);
    }
}

TEST(StabilityMargin, PassivityNamesTheParameterOnBothSides) {
    // The default set: K_r = 0.5625 N/mm of the device's passive 1 N/mm (44 %), below the loop-gain 50 %.
    ModelDef def = *modelDefForName("coherent");
    StabilityMargin m = stabilityMargin(def, sphere242(), kPeriodS);
    EXPECT_NEAR(m.boundMargin, 0.5, 1e-12);
    EXPECT_NEAR(m.passivityMargin, 1.0 - 0.5625, 1e-9);
    EXPECT_NEAR(m.margin, 1.0 - 0.5625, 1e-9);
    EXPECT_NE(m.text.find("passivity margin 44 %"), std::string::npos) << m.text;
    // Both sides of K_eq = K_device (k_s = 1 / 0.375 N/mm), at 1 kHz and, twice as stiff, at 2 kHz.
    for (double rate : {1000.0, 2000.0})
        for (double f : {0.97, 1.03}) {
            def.slopeRing.springStiffnessNPerMm = f * (rate / 1000.0) / 0.375;
            m = stabilityMargin(def, sphere242(), 1.0 / rate);
            EXPECT_EQ(m.margin > 0.0, f < 1.0) << rate << " " << f;
            if (f > 1.0) {
                for (const char* name : {"springStiffness", "k_s", "|m1|", "contactStiffness"})
                    EXPECT_NE(m.text.find(name), std::string::npos) << name << " in " << m.text;
            }
        }
    // k_s = 100 N/mm: 37.5 N/mm rendered, and with the lag of alpha = 0.6 (lambda = 0.04) 40.6.
    def.slopeRing.springStiffnessNPerMm = 100.0;
    m = stabilityMargin(def, sphere242(), kPeriodS);
    EXPECT_NEAR(m.passivityMargin, 1.0 - 37.5, 1e-9);
    EXPECT_NE(m.text.find("rendered stiffness 37.5 N/mm is 37.5x the device's passive 1 N/mm"), std::string::npos)
        << m.text;
    def.slopeRing.forceRelaxation = 0.6;
    m = stabilityMargin(def, sphere242(), kPeriodS);
    EXPECT_NEAR(m.passivityMargin, 1.0 - 37.5 * 1.04 / 0.96, 1e-9);
    EXPECT_NE(m.text.find("passive-equivalent 40.6 N/mm, with the relaxation lag"), std::string::npos) << m.text;
    EXPECT_NE(m.text.find("forceRelaxation"), std::string::npos) << m.text;
    // The coherent method's friction proxy is its own line: a pure spring of K_r.
    def.contact.staticFriction = 0.3;
    m = stabilityMargin(def, sphere242(), kPeriodS);
    EXPECT_NE(m.text.find("proxy (friction, stick): rendered stiffness 37.5 N/mm (passive-equivalent 37.5 N/mm, a "
                          "pure spring) is 37.5x"),
              std::string::npos)
        << m.text;
    def.slopeRingMethod = SlopeRingMethod::Proposed;  // the paper's methods render no friction
    EXPECT_EQ(stabilityMargin(def, sphere242(), kPeriodS).text.find("proxy"), std::string::npos);

    // Mass-spring: beyond with a stiff contact, named; an undamped explicit one cannot be passive.
    ModelDef ms = *modelDefForName("mass-spring-implicit");
    ms.massSpring.contactStiffnessNPerMm = 2.0;
    m = stabilityMargin(ms, sphere242(), kPeriodS);
    EXPECT_EQ(m.boundMargin, 1.0);
    EXPECT_LT(m.margin, 0.0);
    EXPECT_NE(m.text.find("contactStiffness"), std::string::npos) << m.text;
    ms.massSpring.contactStiffnessNPerMm = 1.0;
    EXPECT_GT(stabilityMargin(ms, sphere242(), kPeriodS).margin, 0.0);
    ms.kind = ModelKind::MassSpringSymplectic;
    ms.massSpring.dampingRatio = 0.0;
    m = stabilityMargin(ms, sphere242(), kPeriodS);
    EXPECT_LT(m.margin, 0.0);
    EXPECT_NE(m.text.find("not measured"), std::string::npos) << m.text;
}
