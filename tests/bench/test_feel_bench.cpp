// The feel bench (engine/bench/FeelBench.h): models built from the preset with its tool and friction,
// which models render friction, the goals' verdicts on rows with known figures, a small stepped run
// and a short threaded one. No timed assertions: the tick costs are only reported.
#include "engine/bench/FeelBench.h"

#include <gtest/gtest.h>

#include <cmath>

namespace palpate {
namespace {

TEST(FeelBench, ModelsAreBuiltFromThePresetWithItsToolAndFriction) {
    const TissuePreset preset;  // no tissue: TissueProperties' defaults (5 mm tool, mu 0.3 / 0.2)
    const ModelDef coherent = feelModelDef(preset, "coherent");
    EXPECT_EQ(coherent.kind, ModelKind::SlopeRing);
    EXPECT_EQ(coherent.slopeRingMethod, SlopeRingMethod::Coherent);
    EXPECT_DOUBLE_EQ(coherent.contact.toolRadiusMm, TissueProperties{}.toolRadiusMm);
    EXPECT_DOUBLE_EQ(coherent.contact.dynamicFriction, TissueProperties{}.dynamicFriction);
    EXPECT_EQ(feelModelDef(preset, "previous").slopeRingMethod, SlopeRingMethod::Previous);
    EXPECT_EQ(feelModelDef(preset, "mass-spring-local").kind, ModelKind::MassSpringLocal);
    EXPECT_THROW(feelModelDef(preset, "no-such-model"), std::invalid_argument);

    TissuePreset stiff;
    stiff.tissue = TissueProperties{};
    stiff.tissue->dynamicFriction = 0.15;
    stiff.model.slopeRing.contactStiffnessNPerMm = 1.25;
    const ModelDef own = feelModelDef(stiff, "coherent");
    EXPECT_DOUBLE_EQ(own.contact.dynamicFriction, 0.15);
    EXPECT_DOUBLE_EQ(own.slopeRing.contactStiffnessNPerMm, 1.25);
}

TEST(FeelBench, OnlyTheCoherentMethodRendersFriction) {
    const TissuePreset preset;
    EXPECT_EQ(renderedFriction(feelModelDef(preset, "coherent")), TissueProperties{}.dynamicFriction);
    for (const char* name :
         {"previous", "hybrid", "proposed", "mass-spring-implicit", "radius-of-influence", "ffd", "volumetric-rings"})
        EXPECT_FALSE(renderedFriction(feelModelDef(preset, name))) << name;
    TissuePreset frictionless;
    frictionless.tissue = TissueProperties{};
    frictionless.tissue->staticFriction = frictionless.tissue->dynamicFriction = 0.0;
    EXPECT_FALSE(renderedFriction(feelModelDef(frictionless, "coherent")));
}

FeelRow rowWith(double stepPct) {
    FeelRow r;
    r.model = "coherent";
    r.vertices = 1442;
    r.metrics.ticks = 100;
    r.metrics.maxStepPct = stepPct;
    r.tickNs = 40.0;
    r.previousTickNs = 10'000.0;
    return r;
}

TEST(FeelBench, GoalVerdicts) {
    EXPECT_EQ(stepGoal(rowWith(0.9)), GoalVerdict::Pass);
    EXPECT_EQ(stepGoal(rowWith(1.0)), GoalVerdict::Pass);
    EXPECT_EQ(stepGoal(rowWith(4.2)), GoalVerdict::Fail);
    EXPECT_EQ(stepGoal(rowWith(std::nan(""))), GoalVerdict::Fail);  // no force felt

    FeelRow r = rowWith(0.5);
    EXPECT_DOUBLE_EQ(r.speedupVsPrevious(), 250.0);
    EXPECT_EQ(speedGoal(r), GoalVerdict::NotApplicable);  // only at 8664 vertices
    r.vertices = kFeelSpeedGoalVertices;
    EXPECT_EQ(speedGoal(r), GoalVerdict::Pass);
    r.previousTickNs = 7'000.0;  // 175x
    EXPECT_EQ(speedGoal(r), GoalVerdict::Fail);
    r.model = "proposed";
    EXPECT_EQ(speedGoal(r), GoalVerdict::NotApplicable);

    EXPECT_EQ(dropoutGoal(r), GoalVerdict::NotApplicable);
    r.loaded = LoopFeel{};
    r.loaded->contactTicks = 1000;
    EXPECT_EQ(dropoutGoal(r), GoalVerdict::Pass);
    r.loaded->dropouts = 1;
    EXPECT_EQ(dropoutGoal(r), GoalVerdict::Fail);

    EXPECT_EQ(frictionGoal(r), GoalVerdict::NotApplicable);
    r.dynamicFriction = 0.2;
    r.metrics.frictionRatio = 0.205;  // 2.5 % above
    EXPECT_NEAR(*r.frictionDeviationPct(), 2.5, 1e-9);
    EXPECT_EQ(frictionGoal(r), GoalVerdict::Pass);
    r.metrics.frictionRatio = 0.0;  // no friction rendered: -100 %
    EXPECT_NEAR(*r.frictionDeviationPct(), -100.0, 1e-9);
    EXPECT_EQ(frictionGoal(r), GoalVerdict::Fail);
    EXPECT_STREQ(goalVerdictName(GoalVerdict::NotApplicable), "-");
}

FeelBenchDef smallDef() {
    FeelBenchDef def;
    def.shapes = {GeneratedShape::Sphere};
    def.sizes = {1442};
    def.models = {"coherent", "previous", "mass-spring-local"};
    def.slide.slideS = 0.3;
    def.timingRepeats = 1;
    def.loopModels.clear();
    return def;
}

TEST(FeelBench, ASmallSteppedRunMeasuresEveryModel) {
    const auto rows = runFeelBench(smallDef());
    ASSERT_EQ(rows.size(), 3u);
    const std::size_t statsTicks = 300 - 100;  // 0.3 s of sliding less the 0.1 s breakaway
    for (const FeelRow& r : rows) {
        SCOPED_TRACE(r.model);
        EXPECT_TRUE(r.note.empty()) << r.note;
        EXPECT_EQ(r.metrics.ticks, statsTicks);
        EXPECT_EQ(r.contactTicks, statsTicks);  // 1 mm deep all along
        EXPECT_GT(r.metrics.meanForceN, 0.0);
        EXPECT_TRUE(std::isfinite(r.metrics.maxStepPct));
        EXPECT_GE(r.toolRadiusMm, 0.0);
        EXPECT_GT(r.tickNs, 0.0);
        EXPECT_GT(r.previousTickNs, 0.0);
        EXPECT_FALSE(r.quiet);
        EXPECT_FALSE(r.loaded);
        EXPECT_NEAR(r.depthMm, 1.0, 1e-12);
    }
    EXPECT_EQ(rows[0].dynamicFriction, TissueProperties{}.dynamicFriction);
    EXPECT_FALSE(rows[1].dynamicFriction);
    EXPECT_DOUBLE_EQ(rows[1].speedupVsPrevious(), 1.0);  // the baseline is previous itself
}

TEST(FeelBench, InvalidDefinitionsAreRefused) {
    FeelBenchDef def = smallDef();
    def.models = {"coherent", "nope"};
    def.sizes = {4};
    const Problems problems = validateFeelBenchDef(def);
    EXPECT_TRUE(hasProblem(problems, "models", 1));
    EXPECT_TRUE(hasProblem(problems, "sizes", 0));
    EXPECT_THROW(runFeelBench(def), std::invalid_argument);
}

TEST(FeelBench, AThreadedRunUnderNormalSchedulingCountsItsWindow) {
    auto generated = generateMesh(GeneratedShape::Sphere, 1442);
    ASSERT_TRUE(generated.mesh);
    const ModelDef model = feelModelDef(TissuePreset{}, "coherent");
    SlideDef slide;
    slide.slideS = 0.3;
    const Octree octree(*generated.mesh, OctreeDef{});
    const SlidePath path = makeSlidePath(*generated.mesh, makeModel(model, *generated.mesh, octree)->toolRadiusMm(),
                                         slide);
    LoopFeelDef def;
    def.passes = 2;
    const LoopFeel feel = measureLoopFeel(*generated.mesh, model, path, def, 0);
    EXPECT_FALSE(feel.schedFifo);
    EXPECT_GT(feel.ticks, 0u);
    EXPECT_GT(feel.windowTicks, 0u);
    EXPECT_LE(feel.windowTicks, 2u * (path.slideEnd - path.statsBegin));  // two passes at most
    EXPECT_GT(feel.contactTicks, 0u);
    EXPECT_LE(feel.dropouts, feel.contactTicks);
    EXPECT_TRUE(std::isfinite(feel.maxStepPct));
}

}  // namespace
}  // namespace palpate
