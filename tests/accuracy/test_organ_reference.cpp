// The reference on the organ's own shape (docs/accuracy.md, "The organ's own shape"): the filler's
// local thickness, the sites, the linear and hyperelastic FEM there, and the organ sweep.

#include "engine/accuracy/OrganReference.h"
#include "engine/accuracy/OrganSweep.h"
#include "engine/core/MeshGenerator.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace palpate {
namespace {

const TissueMesh& stomach() {
    static const TissueMesh mesh = *generateMesh(GeneratedShape::Stomach, 1442).mesh;
    return mesh;
}

TEST(LocalThickness, FollowsTheOrganAndStaysValid) {
    SurfaceFillDef def;
    const FilledSurface uniform = fillSurface(stomach(), def);
    def.localThicknessFraction = 0.25;
    const FilledSurface local = fillSurface(stomach(), def);
    EXPECT_EQ(local.halvings, 0);
    ASSERT_EQ(local.vertexThicknessMm.size(), stomach().vertexCount());
    const auto [lo, hi] = std::minmax_element(local.vertexThicknessMm.begin(), local.vertexThicknessMm.end());
    // The tapered ends get a thin layer and the body keeps the requested one, where a uniform
    // fill had to thin everything to what the ends allow.
    EXPECT_LT(*lo, 0.5 * *hi);
    EXPECT_LE(*hi, local.requestedThicknessMm);
    EXPECT_GT(*hi, 2.0 * uniform.thicknessMm);
    for (double t : uniform.vertexThicknessMm) EXPECT_DOUBLE_EQ(t, uniform.thicknessMm);
    EXPECT_GT(local.minTetVolumeMm3, 0.0);
    for (const auto& tri : stomach().triangles())
        for (int e = 0; e < 3; ++e) {
            const VertexId a = tri[std::size_t(e)], b = tri[std::size_t((e + 1) % 3)];
            const double len = glm::length(glm::dvec3(stomach().restPositionsMm()[a]) - glm::dvec3(stomach().restPositionsMm()[b]));
            EXPECT_LE(std::abs(local.vertexThicknessMm[a] - local.vertexThicknessMm[b]), def.maxThicknessSlope * len + 1e-9);
        }
    def.localThicknessFraction = 0.6;
    EXPECT_THROW(fillSurface(stomach(), def), std::invalid_argument);
}

TEST(OrganSites, ThinThickAndCurvedAreDistinctAndSaid) {
    SurfaceFillDef def;
    def.localThicknessFraction = 0.25;
    const FilledSurface filled = fillSurface(stomach(), def);
    const auto sites = chooseOrganSites(stomach(), filled, 5.0);
    ASSERT_EQ(sites.size(), 3u);
    EXPECT_EQ(sites[0].name, "thin");
    EXPECT_EQ(sites[1].name, "thick");
    EXPECT_EQ(sites[2].name, "curved");
    const auto& t = filled.vertexThicknessMm;
    EXPECT_DOUBLE_EQ(sites[0].thicknessMm, *std::min_element(t.begin(), t.end()));
    EXPECT_GE(sites[1].thicknessMm, 0.99 * *std::max_element(t.begin(), t.end()));
    EXPECT_GT(sites[2].curvaturePerMm, std::abs(sites[1].curvaturePerMm));
    for (const OrganSite& s : sites) EXPECT_FALSE(s.reason.empty());
    const auto at = [&](VertexId v) { return glm::dvec3(stomach().restPositionsMm()[v]); };
    EXPECT_GE(glm::length(at(sites[2].vertex) - at(sites[0].vertex)), 20.0);
    EXPECT_GE(glm::length(at(sites[2].vertex) - at(sites[1].vertex)), 20.0);
}

// A press of 1 % of the layer: the hyperelastic FEM is the linear one (same mesh, same conditions).
TEST(OrganReferenceTest, AtSmallStrainTheHyperelasticFemIsTheLinearOne) {
    OrganReferenceDef def;
    def.contact.material = {4.34e-3, 0.45};
    def.contact.toolRadiusMm = 5.0;
    def.maxDepthMm = 0.02;
    def.hyperelasticSteps = 2;
    const OrganReferenceSolver solver(stomach(), def);
    const auto sites = chooseOrganSites(stomach(), solver.filled(), 5.0);
    const OrganReference ref = solver.solve(sites[1]);
    ASSERT_TRUE(ref.hyperelasticCompleted) << ref.failure;
    ASSERT_EQ(ref.hyperelastic.size(), 2u);
    EXPECT_DOUBLE_EQ(ref.hyperelastic.back().depthMm, ref.maxDepthMm);
    EXPECT_NEAR(ref.hyperelastic.back().forceN, ref.linear.forceN, 0.01 * ref.linear.forceN);
    const double peak = ref.linear.normalDisplacementMm[sites[1].vertex];
    EXPECT_NEAR(peak, ref.maxDepthMm, 1e-12);
    for (std::size_t v = 0; v < stomach().vertexCount(); ++v)
        EXPECT_NEAR(ref.hyperelastic.back().normalDisplacementMm[v], ref.linear.normalDisplacementMm[v], 0.01 * peak);

    // The linear FEM itself scores 0 against itself; a field twice as deep against the
    // hyperelastic one is beyond what it reached.
    const OrganError self = errorAgainstLinear(ref, stomach(), ref.linear.normalDisplacementMm, ref.maxDepthMm,
                                               ref.linear.forceN, 5.0);
    EXPECT_TRUE(self.measured);
    EXPECT_NEAR(self.displacementError, 0.0, 1e-12);
    EXPECT_NEAR(self.forceError, 0.0, 1e-12);
    const OrganError deeper = errorAgainstHyperelastic(ref, stomach(), ref.linear.normalDisplacementMm,
                                                       2.0 * ref.maxDepthMm, ref.linear.forceN, 5.0);
    EXPECT_FALSE(deeper.measured);
    EXPECT_TRUE(std::isnan(deeper.displacementError));
    const OrganError half = errorAgainstHyperelastic(ref, stomach(), ref.linear.normalDisplacementMm, 0.5 * ref.maxDepthMm,
                                                     0.5 * ref.linear.forceN, 5.0);
    EXPECT_TRUE(half.measured);
    EXPECT_LT(half.forceError, 0.02);
}

TEST(OrganSweepTest, ScoresEveryModelAtEverySiteAgainstBothReferences) {
    OrganSweepDef def;
    def.sweep.contact.material = {4.34e-3, 0.45};
    def.sweep.contact.stiffeningExponent = 3.0;
    def.sweep.maxRings = 1;
    def.sweep.paperMethods = false;
    def.sweep.otherModels = false;
    def.sweep.timingRepeats = 1;
    def.sweep.minMeasureMs = 0.5;
    def.sizes = {1442};
    def.reference.maxDepthMm = 1.0;
    def.reference.hyperelasticSteps = 3;
    const OrganSweepResult r = runOrganSweep(def);
    ASSERT_EQ(r.sites.size(), 3u);
    ASSERT_EQ(r.sweep.points.size(), 6u);  // 1 ring, and 1 ring with knots, at 3 sites
    EXPECT_GT(r.stiffening.knots, 0);
    for (const SweepPoint& p : r.sweep.points) {
        EXPECT_FALSE(p.site.empty());
        EXPECT_TRUE(std::isfinite(p.error.displacementError)) << p.series;
        EXPECT_TRUE(std::isfinite(p.hyperelasticDisplacementError)) << p.series << " at " << p.site;
        EXPECT_GT(p.error.indentationMm, 0.0);
    }
    EXPECT_NE(r.sweep.points.back().series.find("(stiffening)"), std::string::npos);
    for (const SweepPoint& p : r.sweep.points) EXPECT_EQ(p.series.find(','), std::string::npos) << p.series;  // CSV-safe
    for (const OrganSiteSummary& s : r.sites) {
        EXPECT_TRUE(s.hyperelasticCompleted) << s.failure;
        // The exponential law stiffens: more force than the linear FEM at the same depth.
        EXPECT_GT(s.hyperelasticForceN, s.linearForceN) << s.site.name;
    }
    const auto j = nlohmann::json::parse(organSweepToJson(r, def));
    EXPECT_EQ(j["reference"], "fem");
    EXPECT_EQ(j["sites"].size(), 3u);
    for (const auto& p : j["points"])
        for (const char* key : {"site", "displacement_error", "displacement_error_hyperelastic", "force_error_hyperelastic"})
            EXPECT_TRUE(p.contains(key)) << key;
}

}  // namespace
}  // namespace palpate
