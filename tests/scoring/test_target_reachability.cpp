// Whether press targets can be reached with the mouse (engine/scoring/TargetReachability.h): the
// force probed at each touch depth is the force the loop renders to a mouse device held there, it
// grows with depth and with the tissue's stiffness, and a target's window is judged against it
// (reachable at a depth, beyond the deepest press, or between two wheel steps).
#include "engine/scoring/TargetReachability.h"

#include "engine/scoring/ExerciseReachCheck.h"

#include "device/MouseDevice.h"
#include "engine/loop/HapticLoop.h"
#include "tests/scoring/ScoringTestRig.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace palpate {
namespace {

/// Depths of the test's own choosing (the mouse's are the viewport's, tested with the widgets).
const TouchReach kTouch{6.0, 1.0};

ExerciseAssets exampleAssets(const std::string& name, const std::string& preset = "") {
    Exercise e = test::loadExampleExercise(name);
    if (!preset.empty()) e.tissuePresetPath = "presets/tissues/" + preset + ".json";
    std::vector<std::string> errors;
    auto assets = loadExerciseAssets(e, test::testResourceFinder(), errors);
    EXPECT_TRUE(assets) << (errors.empty() ? "" : errors.front());
    return std::move(*assets);
}

TEST(TargetReachability, TheDepthsRunFromZeroToTheMaximumInSteps) {
    EXPECT_EQ((TouchReach{2.0, 0.5}.depthsMm()), (std::vector<double>{0.0, 0.5, 1.0, 1.5, 2.0}));
    EXPECT_EQ((TouchReach{1.2, 0.5}.depthsMm()), (std::vector<double>{0.0, 0.5, 1.0, 1.2}));
    EXPECT_EQ((TouchReach{3.0, 0.0}.depthsMm()), (std::vector<double>{3.0}));
    EXPECT_TRUE((TouchReach{-1.0, 0.5}.depthsMm().empty()));
}

TEST(TargetReachability, TheProbedForceIsWhatALoopRendersToAMouseHeldAtThatDepth) {
    const ExerciseAssets a = exampleAssets("press_targets");
    std::string error;
    auto probe = TouchForceProbe::create(*a.mesh, a.preset, a.geometry.get(), kTouch, error);
    ASSERT_TRUE(probe) << error;
    const ResolvedTarget& target = a.geometry->targets().front();
    const std::vector<double> probed = probe->forcesN(target.vertex);
    ASSERT_EQ(probed.size(), kTouch.depthsMm().size());

    // An independent run: a fresh loop, the tool placed at the deepest press at once and held
    // for two seconds, as a click at that depth does.
    auto scene = createExerciseScene(a, error);
    ASSERT_TRUE(scene) << error;
    const auto& mesh = scene->mesh();
    const float radiusMm = scene->model().toolRadiusMm();
    auto device = std::make_unique<MouseDevice>();
    ASSERT_TRUE(device->open());
    MouseDevice* mouse = device.get();
    HapticLoopDef def;
    def.rateHz = a.preset.hapticRateHz;
    HapticLoop loop(def, std::move(scene), std::move(device));
    const glm::vec3 rest = mesh.restPositionsMm()[target.vertex], normal = mesh.restNormals()[target.vertex];
    mouse->setTargetMm(rest + 30.0f * normal);
    for (int i = 0; i < 200; ++i) loop.stepOnce();
    mouse->setTargetMm(rest + (radiusMm - float(kTouch.maxDepthMm)) * normal);
    for (int i = 0; i < int(2.0 * def.rateHz); ++i) loop.stepOnce();
    const double heldN = double(glm::length(mouse->lastForceN()));
    std::printf("[ figures  ] press_targets target 1, %s: %.4f N probed, %.4f N held at %.1f mm\n",
                a.preset.name.c_str(), probed.back(), heldN, kTouch.maxDepthMm);
    EXPECT_GT(heldN, 0.0);
    EXPECT_NEAR(probed.back(), heldN, 0.01 * heldN);
}

TEST(TargetReachability, TheForceGrowsWithDepthAndWithTheTissuesStiffness) {
    std::vector<double> deepest;
    for (const char* preset : {"stomach_wall", "skin"}) {
        const ExerciseAssets a = exampleAssets("press_targets", preset);
        std::string error;
        auto probe = TouchForceProbe::create(*a.mesh, a.preset, a.geometry.get(), kTouch, error);
        ASSERT_TRUE(probe) << error;
        const std::vector<double> f = probe->forcesN(a.geometry->targets().front().vertex);
        ASSERT_FALSE(f.empty());
        std::printf("[ figures  ] %s:", preset);
        for (std::size_t i = 0; i < f.size(); ++i) std::printf(" %.3g N at %.3g mm;", f[i], kTouch.depthsMm()[i]);
        std::printf("\n");
        EXPECT_LT(f.front(), 0.01) << preset << ": touching without pressing";
        for (std::size_t i = 1; i < f.size(); ++i) EXPECT_GT(f[i], f[i - 1]) << preset << " at depth " << i;
        deepest.push_back(f.back());
    }
    // The stomach wall is the softer tissue (its slopes are the larger, docs/models.md).
    EXPECT_LT(deepest[0], deepest[1]);
}

TEST(TargetReachability, AWindowIsJudgedAgainstTheForcesOfTheDepths) {
    const TouchReach touch{3.0, 1.0};  // depths 0, 1, 2, 3 mm
    const std::vector<double> forces{0.0, 0.4, 0.9, 1.5};
    PressTarget t;
    t.forceMinN = 0.8;
    t.forceMaxN = 1.0;
    TargetReach r = judgeTarget(t, forces, touch);
    EXPECT_TRUE(r.reachable);
    ASSERT_TRUE(r.depthMm);
    EXPECT_EQ(*r.depthMm, 2.0);
    EXPECT_EQ(r.maxForceN, 1.5);
    EXPECT_EQ(reachAdvice(t, r), "");

    // Beyond the deepest press: not reachable, and the advice names the most it gets.
    t.forceMinN = 2.0;
    t.forceMaxN = 3.0;
    r = judgeTarget(t, forces, touch);
    EXPECT_FALSE(r.reachable);
    EXPECT_FALSE(r.belowForceN);
    EXPECT_EQ(r.maxDepthMm, 3.0);
    const std::string advice = reachAdvice(t, r);
    EXPECT_NE(advice.find("at most 1.5 N"), std::string::npos) << advice;
    EXPECT_NE(advice.find("stiffer tissue"), std::string::npos) << advice;

    // Between two steps of the wheel: 0.9 N at 2 mm, 1.5 N at 3 mm.
    t.forceMinN = 1.0;
    t.forceMaxN = 1.2;
    r = judgeTarget(t, forces, touch);
    EXPECT_FALSE(r.reachable);
    ASSERT_TRUE(r.belowForceN && r.aboveForceN);
    EXPECT_EQ(*r.belowForceN, 0.9);
    EXPECT_EQ(*r.aboveDepthMm, 3.0);
    EXPECT_NE(reachAdvice(t, r).find("widen"), std::string::npos);
}

TEST(TargetReachability, AComfortableWindowIsMetBetweenAThirdAndTwoThirdsOfTheDeepestTouch) {
    const TouchReach touch{6.0, 0.5, 1.0};  // the default press (1 mm) two steps short of a third
    for (const char* preset : {"stomach_wall", "phantom_gel", "skin"}) {
        const ExerciseAssets a = exampleAssets("press_targets", preset);
        std::string error;
        auto probe = TouchForceProbe::create(*a.mesh, a.preset, nullptr, touch, error);
        ASSERT_TRUE(probe) << error;
        const std::vector<double> f = probe->forcesN(a.geometry->targets().front().vertex);
        const auto window = comfortableWindow(f, touch);
        ASSERT_TRUE(window) << preset;
        std::printf("[ figures  ] %s: comfortable window %.3g to %.3g N\n", preset, window->minN, window->maxN);
        // Inside the forces at 2 mm and 4 mm (a third and two thirds of 6 mm: probed depths).
        const auto depths = touch.depthsMm();
        const auto at = [&](double d) { return f[std::size_t(std::find(depths.begin(), depths.end(), d) - depths.begin())]; };
        EXPECT_GE(window->minN, at(2.0));
        EXPECT_LE(window->maxN, at(4.0));
        EXPECT_LT(window->minN, window->maxN);
        PressTarget t;
        t.forceMinN = window->minN;
        t.forceMaxN = window->maxN;
        EXPECT_TRUE(judgeTarget(t, f, touch).reachable) << preset;
    }
    // A tissue that gives nothing gets no window.
    EXPECT_FALSE(comfortableWindow(std::vector<double>(13, 0.0), touch));
}

// A window a touch meets at its default press, or one step deeper, is no exercise: the window
// starts two wheel steps past the default press (and stays two steps wide), wherever the
// default sits against a third of the deepest touch.
TEST(TargetReachability, AComfortableWindowStartsTwoStepsDeeperThanTheDefaultPress) {
    const ExerciseAssets a = exampleAssets("press_targets", "stomach_wall");
    const TouchReach touch{10.0, 0.5, 3.0};  // touch mode's own depths
    std::string error;
    auto probe = TouchForceProbe::create(*a.mesh, a.preset, nullptr, touch, error);
    ASSERT_TRUE(probe) << error;
    const std::vector<double> f = probe->forcesN(a.geometry->targets().front().vertex);
    const auto depths = touch.depthsMm();
    const auto at = [&](double d) {
        return f[std::size_t(std::find(depths.begin(), depths.end(), d) - depths.begin())];
    };
    const auto window = comfortableWindow(f, touch);
    ASSERT_TRUE(window);
    std::printf(
        "[ figures  ] stomach wall: the default press gives %.3g N, one step deeper %.3g N; window %.3g to %.3g N\n",
        at(3.0), at(3.5), window->minN, window->maxN);
    EXPECT_GT(window->minN, at(3.5));
    EXPECT_GE(window->minN, at(4.0));
    EXPECT_LE(window->maxN, at(7.0));  // up to two thirds of the deepest press (6.7 mm)
    // A default deep in the range pushes the window deeper still, never past the deepest press.
    const TouchReach deepDefault{10.0, 0.5, 7.0};
    const auto deeper = comfortableWindow(f, deepDefault);
    ASSERT_TRUE(deeper);
    EXPECT_GE(deeper->minN, at(8.0));
    EXPECT_LE(deeper->maxN, at(10.0));
    // No room for a window past the default: none.
    EXPECT_FALSE(comfortableWindow(f, TouchReach{10.0, 0.5, 9.5}));
}

TEST(TargetReachability, EveryTargetOfAnExerciseIsJudged) {
    ExerciseAssets a = exampleAssets("press_targets", "stomach_wall");
    std::string error;
    const auto soft = checkTargetReachability(a, kTouch, error);
    ASSERT_EQ(error, "");
    ASSERT_EQ(soft.size(), a.geometry->targets().size());
    // The stomach wall at a few millimetres gives a fraction of a newton: 1 N is out of reach.
    for (const TargetReach& r : soft) {
        EXPECT_FALSE(r.reachable);
        EXPECT_LT(r.maxForceN, 1.0);
    }
    // A window just under the most it reaches is reachable.
    Exercise lowered = a.exercise;
    for (std::size_t i = 0; i < lowered.pressTargets.targets.size(); ++i) {
        lowered.pressTargets.targets[i].forceMinN = 0.5 * soft[i].maxForceN;
        lowered.pressTargets.targets[i].forceMaxN = soft[i].maxForceN;
    }
    a.geometry = ExerciseGeometry::build(lowered, *a.mesh, error);
    ASSERT_TRUE(a.geometry) << error;
    for (const TargetReach& r : checkTargetReachability(a, kTouch, error)) EXPECT_TRUE(r.reachable);
}

// The editor's check (engine/scoring/ExerciseReachCheck.h) finds what checkTargetReachability
// judges, with a window the tissue does meet; a preset that cannot be read makes the reach unknown,
// saying why, and nothing is judged on it.
TEST(ExerciseReachCheck, NamesEachUnreachableTargetWithAWindowThatIsMet) {
    const ExerciseAssets a = exampleAssets("press_targets", "stomach_wall");
    std::string error;
    const auto judged = checkTargetReachability(a, kTouch, error);
    ASSERT_EQ(error, "");
    ExerciseReachCheck check(kTouch);
    const std::vector<ReachFinding> findings = check.check(*a.geometry, a.meshPath, a.presetPath, *a.mesh);
    ASSERT_EQ(findings.size(), judged.size());
    for (std::size_t i = 0; i < findings.size(); ++i) {
        const ReachFinding& f = findings[i];
        EXPECT_EQ(f.kind, ReachFinding::Kind::TargetTooSoft);
        EXPECT_EQ(f.item, i);
        EXPECT_DOUBLE_EQ(f.target.maxForceN, judged[i].maxForceN);
        ASSERT_TRUE(f.suggested);
        EXPECT_LE(f.suggested->maxN, f.target.maxForceN);
        // The window it suggests is met at one of the depths.
        PressTarget met = a.geometry->targets()[i].def;
        met.forceMinN = f.suggested->minN;
        met.forceMaxN = f.suggested->maxN;
        const TouchPresses* presses = check.presses(a.meshPath, a.presetPath, *a.mesh, a.geometry->targets()[i].vertex);
        ASSERT_NE(presses, nullptr);
        EXPECT_TRUE(judgeTarget(met, presses->forcesN, kTouch).reachable);
    }

    const std::vector<ReachFinding> unknown = check.check(*a.geometry, a.meshPath, a.presetPath + ".missing", *a.mesh);
    ASSERT_EQ(unknown.size(), 1u);
    EXPECT_EQ(unknown[0].kind, ReachFinding::Kind::Unknown);
    EXPECT_EQ(unknown[0].subject, ReachFinding::Subject::Targets);
    EXPECT_NE(unknown[0].why.find(".missing"), std::string::npos) << unknown[0].why;
    EXPECT_EQ(check.presses(a.meshPath, "", *a.mesh, 0), nullptr);  // no preset named: nothing to probe
}

TEST(TargetReachability, ALumpIsFeltAWheelStepPastThePressThatSinksTheSurfaceToItsTop) {
    const TouchReach touch{3.0, 0.5};  // depths 0, 0.5, ... 3 mm
    // A tissue whose surface sinks 0.8 mm a millimetre pressed (the rest is the contact's give).
    TouchPresses p;
    for (const double d : touch.depthsMm()) {
        p.sinksMm.push_back(0.8 * d);
        p.forcesN.push_back(0.1 * d);
    }
    LumpDef lump;
    lump.depthMm = 1.2;  // the surface sinks 1.2 mm under a 1.5 mm press
    LumpReach r = judgeLump(lump, p, touch);
    EXPECT_NEAR(r.engageDepthMm, 1.5, 1e-9);
    EXPECT_NEAR(r.feelDepthMm, 2.0, 1e-9);
    EXPECT_TRUE(r.mouseFeels);
    ASSERT_TRUE(r.forceN);
    EXPECT_NEAR(*r.forceN, 0.2, 1e-9);
    EXPECT_NEAR(r.deepestFeltMm, 0.8 * 2.5, 1e-9);  // the deepest press less a step

    lump.depthMm = 2.4;  // engaged at 3 mm, the deepest: felt only a step beyond the mouse
    r = judgeLump(lump, p, touch);
    EXPECT_NEAR(r.engageDepthMm, 3.0, 1e-9);
    EXPECT_FALSE(r.mouseFeels);
    ASSERT_TRUE(r.forceN);
    EXPECT_NEAR(*r.forceN, 0.35, 1e-9) << "extrapolated from the deepest two presses";

    // A surface that does not sink never brings a buried lump within reach.
    std::fill(p.sinksMm.begin(), p.sinksMm.end(), 0.0);
    r = judgeLump(lump, p, touch);
    EXPECT_FALSE(r.mouseFeels);
    EXPECT_FALSE(std::isfinite(r.engageDepthMm));
    EXPECT_FALSE(r.forceN);
    // A lump at the surface is felt a step in, whatever the tissue.
    lump.depthMm = 0.0;
    r = judgeLump(lump, p, touch);
    EXPECT_NEAR(r.feelDepthMm, 0.5, 1e-9);
    EXPECT_TRUE(r.mouseFeels);
}

TEST(TargetReachability, TheJudgedFeelDepthIsWhereTheLumpRaisesTheForceTheLoopRenders) {
    // The shipped detection exercise (lumps 2, 4 and 8 mm deep in muscle), pressed by the loop with
    // its lumps and without them: no difference before the judged engaging press, a clear one from
    // a wheel step past it.
    const ExerciseAssets a = exampleAssets("detect_lumps");
    const TouchReach touch{12.0, 0.5};
    std::string error;
    auto tissue = TouchForceProbe::create(*a.mesh, a.preset, nullptr, touch, error);
    ASSERT_TRUE(tissue) << error;
    auto withLumps = TouchForceProbe::create(*a.mesh, a.preset, a.geometry.get(), touch, error);
    ASSERT_TRUE(withLumps) << error;
    const std::vector<double> depths = touch.depthsMm();
    ASSERT_EQ(a.geometry->lumps().size(), 3u);
    for (const ResolvedLump& lump : a.geometry->lumps()) {
        const TouchPresses plain = tissue->presses(lump.vertex);
        ASSERT_EQ(plain.sinksMm.size(), depths.size());
        for (std::size_t i = 1; i < depths.size(); ++i) {
            EXPECT_GT(plain.sinksMm[i], plain.sinksMm[i - 1]) << "the surface sinks deeper the deeper the press";
            EXPECT_LT(plain.sinksMm[i], depths[i]) << "less than the press: the contact gives too";
        }
        const LumpReach reach = judgeLump(lump.def, plain, touch);
        ASSERT_TRUE(reach.mouseFeels) << "lump " << lump.def.depthMm << " mm deep within 12 mm";
        const std::vector<double> felt = withLumps->forcesN(lump.vertex);
        ASSERT_EQ(felt.size(), depths.size());
        std::printf("[ figures  ] lump %.0f mm deep: surface there at %.2f mm, felt from %.2f mm;", lump.def.depthMm,
                    reach.engageDepthMm, reach.feelDepthMm);
        for (std::size_t i = 0; i < depths.size(); ++i) {
            if (depths[i] < reach.engageDepthMm - 1e-6)
                EXPECT_NEAR(felt[i], plain.forcesN[i], 0.01 * plain.forcesN[i] + 1e-6)
                    << "before the lump, at " << depths[i];
            if (depths[i] >= reach.feelDepthMm - 1e-6 && depths[i] < reach.feelDepthMm + 0.5) {
                std::printf(" %.3f N against %.3f N at %.1f mm", felt[i], plain.forcesN[i], depths[i]);
                EXPECT_GT(felt[i], 1.1 * plain.forcesN[i]) << "a step past, at " << depths[i];
            }
        }
        std::printf("\n");
    }
}

TEST(TargetReachability, TheExaminingForceIsTheMiddleOverPointsSpreadOverTheSurface) {
    // A box's corners and centre: the six extremes are corners, without repeats.
    const std::vector<glm::vec3> rest{{0, 0, 0}, {-5, 0, 0}, {5, 1, 0}, {0, -7, 0}, {0, 7, 2}, {0, 0, -9}, {1, 1, 9}};
    EXPECT_EQ(examinePoints(rest), (std::vector<VertexId>{1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(examinePoints({{1, 1, 1}}), (std::vector<VertexId>{0}));
    EXPECT_TRUE(examinePoints({}).empty());

    const TouchReach touch{3.0, 1.0};  // depths 0, 1, 2, 3 mm; the default press 1 mm deep
    const std::vector<std::vector<double>> forces{
        {0.0, 0.123, 0.3, 0.5}, {0.0, 0.2, 0.5, 0.9}, {0.0, 0.01, 0.02, 0.03}, {}};
    const auto reach = judgeExamining(forces, touch, 1.0);
    ASSERT_TRUE(reach);
    EXPECT_NEAR(reach->deepestN, 0.5, 1e-12);       // the middle of 0.03, 0.5, 0.9 (a point without forces is left out)
    EXPECT_NEAR(reach->defaultPressN, 0.12, 1e-12);  // the middle of 0.01, 0.123, 0.2, rounded down to two digits
    EXPECT_FALSE(judgeExamining({{0.0, 0.0}}, TouchReach{1.0, 1.0}, 1.0));  // a tissue that gives nothing
    EXPECT_FALSE(judgeExamining({}, touch, 1.0));
}

}  // namespace
}  // namespace palpate
