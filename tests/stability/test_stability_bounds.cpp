// Both sides of every derived boundary, on the real models (the maps' cell runners), the closed
// forms against direct simulation of one mode, and the map runner's measured-vs-derived gap.
#include "engine/stability/StabilityBounds.h"
#include "engine/stability/StabilityMargin.h"
#include "engine/stability/StabilityModels.h"

#include "engine/core/MeshGenerator.h"
#include "engine/models/slopering/SlopeRingParams.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace palpate;

namespace {

/// Short runs: the tests resolve 3 % either side of each boundary, not the map's 0.2 %.
StabilitySceneDef testScene() {
    StabilitySceneDef def;
    def.slopeRingTicks = 1500;
    def.massSpringTicks = 800;
    def.implicitTicks = 100;
    return def;
}

/// Just inside (0.97 x) stays bounded, just outside (1.03 x) is detected, at two x values.
void expectBothSides(const std::string& name, std::initializer_list<double> xs) {
    const auto spec = stabilityMapSpec(name, testScene());
    ASSERT_TRUE(spec) << name;
    for (double x : xs) {
        const double y = spec->derivedBoundaryY(x);
        ASSERT_TRUE(std::isfinite(y)) << name;
        EXPECT_TRUE(spec->runCell(x, 0.97 * y).bounded) << name << " inside at x = " << x << ", y = " << 0.97 * y;
        EXPECT_FALSE(spec->runCell(x, 1.03 * y).bounded) << name << " outside at x = " << x << ", y = " << 1.03 * y;
    }
}

/// One undamped-or-damped mode u'' = -w^2 u - g u', stepped n times; true when it stays bounded.
template <class Step>
bool modeBounded(Step step, int n = 20000) {
    double u = 1.0, v = 0.0;
    for (int i = 0; i < n; ++i) {
        step(u, v);
        if (!(std::abs(u) + std::abs(v) < 1e6)) return false;
    }
    return true;
}

}  // namespace

TEST(StabilityBounds, ClosedForms) {
    EXPECT_DOUBLE_EQ(slopeRingMaxGain(1.0), 1.0);
    EXPECT_DOUBLE_EQ(slopeRingMaxGain(0.5), 3.0);
    EXPECT_DOUBLE_EQ(slopeRingMaxRelaxation(3.0), 0.5);
    EXPECT_GT(slopeRingMargin(0.5, 2.9), 0.0);
    EXPECT_LT(slopeRingMargin(0.5, 3.1), 0.0);
    EXPECT_DOUBLE_EQ(symplecticEulerMaxStepS(100.0), 0.02);
    EXPECT_NEAR(rk4MaxStepS(100.0), 0.028284271, 1e-9);
    EXPECT_TRUE(std::isinf(backwardEulerMaxStepS(1e6)));
    // Forward Euler, underdamped: h < gamma / omega^2 = c / k.
    EXPECT_DOUBLE_EQ(forwardEulerMaxStepS(100.0, 20.0), 20.0 / 1e4);
    EXPECT_DOUBLE_EQ(forwardEulerMaxStepS(100.0, 0.0), 0.0);
    // Colgate and Brown: K < 2 (b - |B|) / T.
    EXPECT_DOUBLE_EQ(passiveMaxStiffnessNPerMm(0.005, 0.001, 0.001), 8.0);
    EXPECT_DOUBLE_EQ(passiveMaxStiffnessNPerMm(0.001, 0.001, 0.002), 0.0);
    EXPECT_DOUBLE_EQ(inversionMaxTangentialForceN(0.6, 0.35, 2.5), 10.0);
}

TEST(StabilityBounds, OneModeIntegratorsAgreeWithTheirBounds) {
    const double w = 200.0, g = 30.0;
    for (double f : {0.97, 1.03}) {
        const bool inside = f < 1.0;
        const double hs = f * symplecticEulerMaxStepS(w, g);  // damping taken implicitly, as the model does
        EXPECT_EQ(modeBounded([&](double& u, double& v) { v = (v - hs * w * w * u) / (1 + hs * g); u += hs * v; }), inside);
        const double hf = f * forwardEulerMaxStepS(w, g);
        EXPECT_EQ(modeBounded([&](double& u, double& v) {
                      const double a = -w * w * u - g * v;
                      u += hf * v;
                      v += hf * a;
                  }, 200000),
                  inside);
        const double hr = f * rk4MaxStepS(w);
        EXPECT_EQ(modeBounded([&](double& u, double& v) {
                      auto acc = [&](double uu) { return -w * w * uu; };
                      const double k1u = v, k1v = acc(u);
                      const double k2u = v + hr / 2 * k1v, k2v = acc(u + hr / 2 * k1u);
                      const double k3u = v + hr / 2 * k2v, k3v = acc(u + hr / 2 * k2u);
                      const double k4u = v + hr * k3v, k4v = acc(u + hr * k3u);
                      u += hr / 6 * (k1u + 2 * k2u + 2 * k3u + k4u);
                      v += hr / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
                  }, 200000),
                  inside);
    }
    // Backward Euler: bounded at any step.
    const double hb = 100.0 / w;
    EXPECT_TRUE(modeBounded([&](double& u, double& v) {
        const double d = 1 + hb * g + hb * hb * w * w;
        const double vn = (v - hb * w * w * u) / d;
        u += hb * vn;
        v = vn;
    }));
}

TEST(StabilityBounds, SlopeRingLoopGainBothSides) { expectBothSides("slope-ring-gain", {0.3, 3.0}); }
TEST(StabilityBounds, SlopeRingRelaxationBothSides) { expectBothSides("slope-ring-relaxation", {0.1, 0.9}); }
TEST(StabilityBounds, MassSpringSymplecticCoupledMeshBothSides) { expectBothSides("mass-spring-symplectic", {0.02, 2.0}); }
TEST(StabilityBounds, MassSpringSymplecticPerVertexBothSides) {
    expectBothSides("mass-spring-symplectic-vertex", {0.05, 5.0});
}
TEST(StabilityBounds, MassSpringRk4BothSides) { expectBothSides("mass-spring-rk4", {0.1, 1.0}); }

TEST(StabilityBounds, MassSpringImplicitHasNoBoundary) {
    const auto spec = stabilityMapSpec("mass-spring-implicit", testScene());
    ASSERT_TRUE(spec);
    EXPECT_TRUE(std::isinf(spec->derivedBoundaryY(10.0)));
    EXPECT_TRUE(spec->runCell(10.0, spec->y.maxValue).bounded);
    EXPECT_TRUE(spec->runCell(spec->x.minValue, spec->y.maxValue).bounded);
}

TEST(StabilityBounds, OmegaMaxIsBelowGershgorinAndSetsTheCoupledBound) {
    auto mesh = generateMesh(GeneratedShape::Sphere, 242);
    ASSERT_TRUE(mesh.mesh);
    MassSpringParams p;  // defaults: 0.1 / 0.5 / 1 N/mm, 1 g
    const double exact = massSpringOmegaMaxRadPerS(*mesh.mesh, p, 0);
    const double gershgorin = massSpringOmegaGershgorinRadPerS(*mesh.mesh, p);
    std::printf("omega exact %.3f gershgorin %.3f ratio %.4f\n", exact, gershgorin, exact / gershgorin);
    EXPECT_LT(exact, gershgorin);
    EXPECT_GT(exact, 0.7 * gershgorin);
}

TEST(StabilityMap, MeasuredBoundaryWithinFivePercentOfDerived) {
    StabilityMapDef def;
    def.columns = 2;
    def.rows = 2;
    def.bisections = 9;
    for (const std::string name : {"slope-ring-gain", "slope-ring-relaxation", "mass-spring-symplectic"}) {
        const auto spec = stabilityMapSpec(name, testScene());
        ASSERT_TRUE(spec);
        const StabilityMap map = runStabilityMap(*spec, def);
        EXPECT_EQ(map.cells.size(), 4u);
        ASSERT_EQ(map.boundary.size(), 2u);
        EXPECT_TRUE(map.hasDerivedBoundary);
        EXPECT_LT(map.relativeGap, 0.05) << name;
        EXPECT_FALSE(map.derivedCurve.empty());
    }
}

TEST(StabilityMap, ListsEveryModelAndRejectsUnknownOnes) {
    const auto names = stabilityModelNames();
    EXPECT_GE(names.size(), 5u);
    EXPECT_FALSE(stabilityMapSpec("no-such-model"));
}

TEST(StabilityBounds, HeightOverOppositeEdgeOfAHandBuiltPatch) {
    // A square pyramid's apex over a unit square: its height over each base edge is known by hand.
    std::vector<glm::vec3> positions{{0, 0, 1}, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    std::vector<std::array<VertexId, 3>> triangles{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}, {1, 3, 2}, {1, 4, 3}};
    auto loaded = TissueMesh::fromTriangles(positions, triangles, "pyramid", false);
    ASSERT_TRUE(loaded.mesh) << loaded.error();
    EXPECT_NEAR(minHeightOverOppositeEdgeMm(*loaded.mesh, 0), std::sqrt(2.0), 1e-6);
}

TEST(StabilityBounds, DefaultSlopesCannotInvertTheGeneratedSphereWithinTheDeviceForce) {
    // Each ring moves along the touched vertex's normal, so only the normal's tilt against a face
    // can fold it: on the smooth generated sphere that needs far more than the device's 3.3 N.
    auto mesh = generateMesh(GeneratedShape::Sphere, 1442);
    ASSERT_TRUE(mesh.mesh);
    const SlopeRingParams p;
    double smallest = kNoBound;
    for (VertexId v = 0; v < mesh.mesh->vertexCount(); ++v)
        smallest = std::min(smallest, inversionMaxForceAlongNormalN(*mesh.mesh, v, p.slopeMagnitudeMmPerN[0],
                                                                     p.slopeMagnitudeMmPerN[1]));
    std::printf("smallest inversion force on the 1442-vertex sphere: %.1f N\n", smallest);
    EXPECT_GT(smallest, 10.0 * 3.3);
}

TEST(StabilityMargin, NamesTheLimitingParameterOnBothSides) {
    auto mesh = generateMesh(GeneratedShape::Sphere, 242);
    ASSERT_TRUE(mesh.mesh);
    ModelDef def = *modelDefForName("coherent");
    // Automatic alpha: alpha (1 + g) = 1, half the bound; passivity (K_r = 0.5625 N/mm of 1) is closer.
    EXPECT_NEAR(stabilityMargin(def, *mesh.mesh, 1e-3).boundMargin, 0.5, 1e-12);
    EXPECT_NEAR(stabilityMargin(def, *mesh.mesh, 1e-3).margin, 0.4375, 1e-9);
    def.slopeRing.forceRelaxation = 1.0;
    def.slopeRing.contactStiffnessNPerMm = 2.0;  // g = 1.2 > 1
    const StabilityMargin beyond = stabilityMargin(def, *mesh.mesh, 1e-3);
    EXPECT_LT(beyond.margin, 0.0);
    EXPECT_NE(beyond.text.find("forceRelaxation"), std::string::npos);

    ModelDef ms = *modelDefForName("mass-spring-symplectic");
    EXPECT_GT(stabilityMargin(ms, *mesh.mesh, 1e-3).margin, 0.09);  // automatic sub-steps: 0.9 x the bound
    ms.massSpring.substeps = 1;
    ms.massSpring.edgeStiffnessNPerMm = 5.0;
    const StabilityMargin explicitBeyond = stabilityMargin(ms, *mesh.mesh, 1e-3);
    EXPECT_LT(explicitBeyond.margin, 0.0);
    EXPECT_NE(explicitBeyond.text.find("substeps"), std::string::npos);
    EXPECT_EQ(stabilityMargin(*modelDefForName("mass-spring-implicit"), *mesh.mesh, 1.0).boundMargin, 1.0);
    // The geometric models: the rendered stiffness against the device's passive one (Colgate and
    // Brown; 1 N/mm at 1 kHz by default): k_s = 0.125 N/mm leaves 87.5 %, and twice the rate doubles it.
    EXPECT_NEAR(stabilityMargin(*modelDefForName("ffd"), *mesh.mesh, 1e-3).margin, 0.875, 1e-12);
    EXPECT_NEAR(stabilityMargin(*modelDefForName("radius-of-influence"), *mesh.mesh, 5e-4).margin, 0.9375, 1e-12);
    ModelDef roi = *modelDefForName("radius-of-influence");
    roi.radiusOfInfluence.stiffnessNPerMm = 1.5;
    const StabilityMargin roiBeyond = stabilityMargin(roi, *mesh.mesh, 1e-3);
    EXPECT_NEAR(roiBeyond.margin, -0.5, 1e-12);
    EXPECT_NE(roiBeyond.text.find("stiffness"), std::string::npos);
    EXPECT_NEAR(stabilityMargin(roi, *mesh.mesh, 1e-3, 3.0).margin, 0.5, 1e-12);  // a stiffer device
    EXPECT_FALSE(stabilityMarginNeedsMesh(*modelDefForName("ffd")));
    EXPECT_TRUE(stabilityMarginNeedsMesh(*modelDefForName("mass-spring-local")));
}
