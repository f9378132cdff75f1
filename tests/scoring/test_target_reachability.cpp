// Whether press targets can be reached with the mouse (engine/scoring/TargetReachability.h): the
// force probed at each touch depth is the force the loop renders to a mouse device held there, it
// grows with depth and with the tissue's stiffness, and a target's window is judged against it
// (reachable at a depth, beyond the deepest press, or between two wheel steps).
#include "engine/scoring/TargetReachability.h"

#include "device/MouseDevice.h"
#include "engine/loop/HapticLoop.h"
#include "tests/scoring/ScoringTestRig.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
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
    const TouchReach touch{6.0, 0.5};
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

}  // namespace
}  // namespace palpate
