// The measured table: one candidate per level and ring count, all measured (finite, positive), the
// error on the source level equal to the sweep's metric, more rings never much worse than one, and
// a cancel that stops early. No timing is asserted beyond "positive".
#include "engine/core/Octree.h"
#include "engine/core/SceneTarget.h"
#include "engine/lod/LodMeasure.h"
#include "engine/models/ModelRegistry.h"
#include "tests/lod/LodTestMeshes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace palpate {
namespace {

LodMeasureDef quickDef() {
    LodMeasureDef def;
    def.contact.material = {4.34e-3, 0.45};
    def.contact.toolRadiusMm = 5.0;
    def.ringCounts = {1, 2, 4};
    def.timing = {1, 0.0};
    def.path.approachTicks = 20;
    def.path.pressTicks = 30;
    def.path.holdTicks = 20;
    def.path.strokeTicks = 100;
    def.path.releaseTicks = 30;
    def.press.settleTicks = 200;
    return def;
}

TEST(LodMeasure, OneMeasuredCandidatePerLevelAndRingCount) {
    const MeshLevels& levels = test::levelsOf(GeneratedShape::Sphere, 1442);
    ASSERT_GE(levels.levels.size(), 3u);
    const LodMeasureDef def = quickDef();
    const LodMeasurement m = measureLodCandidates(levels, def);
    EXPECT_FALSE(m.cancelled);
    ASSERT_EQ(m.candidates.size(), levels.levels.size() * def.ringCounts.size());
    for (std::size_t i = 0; i < m.candidates.size(); ++i) {
        const LodCandidate& c = m.candidates[i];
        SCOPED_TRACE(describeCandidate(c));
        EXPECT_EQ(c.note, "");
        EXPECT_EQ(c.level, i / def.ringCounts.size());
        EXPECT_EQ(c.rings, def.ringCounts[i % def.ringCounts.size()]);
        EXPECT_EQ(c.vertices, levels.levels[c.level].mesh.vertexCount());
        EXPECT_EQ(c.model, "coherent");
        EXPECT_TRUE(std::isfinite(c.errorFraction) && c.errorFraction > 0.0 && c.errorFraction < 1.0);
        EXPECT_TRUE(std::isfinite(c.levelErrorFraction) && c.levelErrorFraction > 0.0);
        EXPECT_TRUE(std::isfinite(c.tickUs) && c.tickUs > 0.0);
        EXPECT_GE(c.verticesCompared, kMinVerticesCompared);
    }
}

TEST(LodMeasure, OnTheSourceLevelTheErrorIsTheSweepsMetric) {
    // Level 0 maps onto itself, so the error shown on the source surface is the one
    // measureModelError reports, as the sweep (AccuracySweep) computes it for this mesh.
    const MeshLevels& levels = test::levelsOf(GeneratedShape::Stomach, 1442);
    const LodMeasureDef def = quickDef();
    const LodMeasurement m = measureLodCandidates(levels, def);
    const TissueMesh& mesh = levels.levels[0].mesh;
    const VertexId touched = defaultTargetVertex(mesh);
    const Octree octree(mesh, OctreeDef{});
    for (const LodCandidate& c : m.candidates) {
        if (c.level != 0) continue;
        EXPECT_NEAR(c.errorFraction, c.levelErrorFraction, 1e-6 * c.levelErrorFraction);
        SlopeRingParams base = def.base;
        base.ringCount = c.rings;
        ModelDef modelDef;
        modelDef.slopeRing = calibrateSlopesFromPunch(mesh, touched, def.contact, base).params;
        const auto model = makeModel(modelDef, mesh, octree);
        const ModelError direct = measureModelError(*model, mesh, touched, def.contact, def.press);
        EXPECT_NEAR(c.levelErrorFraction, direct.displacementError, 1e-9) << c.rings << " rings";
    }
}

TEST(LodMeasure, MoreRingsAreNotWorseThanOne) {
    // The punch's displacement reaches far (2/pi asin(a/r)); one ring leaves all of it out, so on
    // every level the most rings measured must beat a single ring.
    const MeshLevels& levels = test::levelsOf(GeneratedShape::Sphere, 1442);
    const LodMeasurement m = measureLodCandidates(levels, quickDef());
    for (std::size_t L = 0; L < levels.levels.size(); ++L) {
        double one = NAN, most = NAN;
        for (const LodCandidate& c : m.candidates)
            if (c.level == L) (c.rings == 1 ? one : most) = c.errorFraction;
        EXPECT_LT(most, one) << "level " << L;
    }
}

TEST(LodMeasure, AMeshTooCoarseForTheToolIsNotMeasuredAndNeverChosen) {
    // 12 vertices on a 50 mm sphere: within 5 tool radii (25 mm) of the contact there is only the
    // touched vertex, whose error is 0 by construction. That must not pass for accuracy.
    const MeshLevels levels = generateLevels(test::generated(GeneratedShape::Sphere, 12), LevelDef{});
    const LodMeasurement m = measureLodCandidates(levels, quickDef());
    ASSERT_EQ(m.candidates.size(), 3u);
    for (const LodCandidate& c : m.candidates) {
        EXPECT_LT(c.verticesCompared, kMinVerticesCompared);
        EXPECT_TRUE(std::isnan(c.errorFraction));
        EXPECT_NE(c.note.find("too coarse"), std::string::npos) << c.note;
    }
    const LodPlan plan = planLod(m.candidates, LodNeeds{0.5, 1000.0});
    EXPECT_FALSE(plan.feasible);
    EXPECT_FALSE(plan.chosen);
}

TEST(LodMeasure, CancelStopsAndBadDefinitionsAreNamed) {
    const MeshLevels& levels = test::levelsOf(GeneratedShape::Sphere, 1442);
    std::atomic<bool> cancel{false};
    const LodMeasurement m = measureLodCandidates(levels, quickDef(), [&](double, const std::string&) { cancel = true; }, &cancel);
    EXPECT_TRUE(m.cancelled);
    EXPECT_EQ(m.candidates.size(), 1u);

    LodMeasureDef bad = quickDef();
    bad.ringCounts = {0};
    EXPECT_THROW(measureLodCandidates(levels, bad), std::invalid_argument);
    bad = quickDef();
    bad.contact.toolRadiusMm = -1;
    EXPECT_THROW(measureLodCandidates(levels, bad), std::invalid_argument);
    bad = quickDef();
    bad.ringCounts.clear();
    try {
        measureLodCandidates(levels, bad);
        ADD_FAILURE() << "accepted no ring counts";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("ring counts"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace palpate
