// docs/stability.md, docs/models.md: the maps of the other models (mass-spring-local, the four slope-ring methods, the
// volumetric rings, radius of influence and FFD against a simulated device), both sides of each
// derived boundary on the real models, the sampled-wall closed form against a direct simulation,
// and every registry model covered by a map.
#include "engine/stability/DivergenceGuard.h"
#include "engine/stability/StabilityBounds.h"
#include "engine/stability/StabilityModels.h"

#include "engine/core/MeshGenerator.h"
#include "engine/core/Octree.h"
#include "engine/models/ModelRegistry.h"
#include "engine/models/VolumetricFill.h"
#include "engine/models/VolumetricRingsModel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace palpate;

namespace {

/// Short runs: 3 % either side of each boundary, not the map's resolution.
StabilitySceneDef testScene() {
    StabilitySceneDef def;
    def.slopeRingTicks = 1500;
    def.massSpringTicks = 800;
    def.deviceTicks = 4000;
    return def;
}

void expectBothSides(const std::string& name, std::initializer_list<double> xs) {
    const auto spec = stabilityMapSpec(name, testScene());
    ASSERT_TRUE(spec) << name;
    for (double x : xs) {
        const double y = spec->derivedBoundaryY(x);
        ASSERT_TRUE(std::isfinite(y)) << name;
        const CellOutcome inside = spec->runCell(x, 0.97 * y), outside = spec->runCell(x, 1.03 * y);
        EXPECT_TRUE(inside.bounded) << name << " inside at x = " << x << ", y = " << 0.97 * y << ", growth " << inside.growth;
        EXPECT_FALSE(outside.bounded) << name << " outside at x = " << x << ", y = " << 1.03 * y << ", growth "
                                      << outside.growth;
    }
}

/// The sampled wall stepped directly (many sub-steps of the continuous device between samples).
bool sampledWallBounded(double m, double b, double T, double kNPerM) {
    double x = 1e-3, v = 0.0;
    const int sub = 200;
    const double h = T / sub;
    double first = 0.0, last = 0.0;
    const int ticks = 20000;
    for (int t = 0; t < ticks; ++t) {
        const double f = -kNPerM * x;  // held over the period
        if (t < 2000) first = std::max(first, std::abs(x));
        if (t >= ticks - 2000) last = std::max(last, std::abs(x));
        for (int s = 0; s < sub; ++s) {  // semi-implicit in the damping, fine steps: the continuous device
            v = (v + h * f / m) / (1.0 + h * b / m);
            x += h * v;
        }
    }
    return last < first;
}

}  // namespace

TEST(StabilityModels, VolumetricRingsGainBothSides) { expectBothSides("volumetric-rings", {0.3, 3.0}); }
TEST(StabilityModels, EverySlopeRingMethodGainBothSides) {
    for (const char* method : {"coherent", "proposed", "hybrid", "previous"}) expectBothSides(method, {1.0});
}
TEST(StabilityModels, MassSpringLocalBothSides) { expectBothSides("mass-spring-local", {0.1, 2.0}); }
TEST(StabilityModels, RadiusOfInfluenceAgainstTheDeviceBothSides) { expectBothSides("radius-of-influence", {500.0, 2000.0}); }
TEST(StabilityModels, FfdAgainstTheDeviceBothSides) { expectBothSides("ffd", {500.0, 2000.0}); }

TEST(StabilityModels, LocalBoundIsWiderThanTheWholeMeshs) {
    // Pinning the vertices beyond two rings removes the mesh's highest modes: a larger step.
    const auto local = stabilityMapSpec("mass-spring-local", testScene());
    const auto whole = stabilityMapSpec("mass-spring-symplectic", testScene());
    ASSERT_TRUE(local && whole);
    EXPECT_GT(local->derivedBoundaryY(1.0), whole->derivedBoundaryY(1.0));
    EXPECT_LT(local->derivedBoundaryY(1.0), 1.2 * whole->derivedBoundaryY(1.0));
}

TEST(StabilityBounds, SampledWallExactLimitAgainstColgateAndADirectSimulation) {
    const double m = 0.05, b = 0.5;
    for (double T : {1.0 / 200.0, 1.0 / 1000.0, 1e-4}) {
        const double colgate = passiveMaxStiffnessNPerMm(b / 1000.0, T);
        const double exact = sampledWallMaxStiffnessNPerMm(m, b, T);
        const double e = b * T / m;
        // Above Colgate's passivity limit by about e / 6 (no hand: passivity is sufficient, not necessary).
        EXPECT_GT(exact, colgate);
        EXPECT_NEAR(exact / colgate - 1.0, e / 6.0, 0.1 * e / 6.0 + 1e-9) << T;
        if (T > 5e-4) {  // the direct simulation is slow at 10 kHz; two rates suffice
            EXPECT_TRUE(sampledWallBounded(m, b, T, 0.98 * exact * 1000.0)) << T;
            EXPECT_FALSE(sampledWallBounded(m, b, T, 1.02 * exact * 1000.0)) << T;
        }
    }
}

TEST(StabilityModels, EveryRegistryModelHasAMapAndEveryMapRunsARegistryModel) {
    std::vector<std::string> covered;
    for (const auto& map : stabilityModelNames()) {
        const auto models = stabilityMapModels(map);
        EXPECT_FALSE(models.empty()) << map;
        for (const auto& m : models) {
            EXPECT_TRUE(modelDefForName(m)) << map << " runs " << m;
            covered.push_back(m);
        }
    }
    for (const auto& name : modelNames())
        EXPECT_NE(std::find(covered.begin(), covered.end(), name), covered.end()) << name << " has no stability map";
    EXPECT_TRUE(stabilityMapModels("no-such-map").empty());
}

TEST(StabilityModels, QuickMapsOfTheNewModelsAreWithinFivePercent) {
    StabilityMapDef def;
    def.columns = 2;
    def.rows = 2;
    def.bisections = 9;
    for (const std::string name : {"volumetric-rings", "radius-of-influence", "mass-spring-local"}) {
        const auto spec = stabilityMapSpec(name, testScene());
        ASSERT_TRUE(spec);
        const StabilityMap map = runStabilityMap(*spec, def);
        EXPECT_TRUE(map.hasDerivedBoundary) << name;
        EXPECT_LT(map.relativeGap, 0.05) << name;
    }
}

TEST(DivergenceGuard, VolumetricRingsBeyondTheGainBoundIsCaughtAndInsideIsNot) {
    auto generated = generateMesh(GeneratedShape::Sphere, 242);
    ASSERT_TRUE(generated.mesh);
    const TissueMesh& mesh = *generated.mesh;
    const Octree octree(mesh, OctreeDef{});
    const TetMesh tets = fillSurfaceWithTets(mesh);
    VertexId v = 0;
    for (VertexId i = 1; i < mesh.vertexCount(); ++i)
        if (mesh.restPositionsMm()[i].x > mesh.restPositionsMm()[v].x) v = i;
    const glm::vec3 tool = mesh.restPositionsMm()[v] - 0.5f * mesh.restNormals()[v];
    for (double factor : {0.95, 1.05}) {
        VolumetricRingsModel model(mesh, octree, tets, VolumetricRingsParams{});
        SlopeRingParams p;
        p.forceRelaxation = 1.0;  // bound: gain < 1
        p.slopeLimitMmPerN = 100.0;
        p.contactStiffnessNPerMm = factor / p.slopeMagnitudeMmPerN[0];
        ModelDef def;
        def.kind = ModelKind::VolumetricRings;
        def.slopeRing = p;
        ASSERT_TRUE(model.applyModelParams(def));
        DivergenceGuard guard;
        DivergenceKind seen = DivergenceKind::None;
        for (int t = 0; t < 3000 && seen == DivergenceKind::None; ++t)
            seen = guard.check(mesh, model.positionsMm(), model.step(tool, 1e-3)).kind;
        EXPECT_EQ(seen, factor > 1.0 ? DivergenceKind::Oscillation : DivergenceKind::None) << factor;
    }
}
