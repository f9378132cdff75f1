// The feel metrics (engine/bench/FeelMetrics.h) on force sequences whose answers are known by hand:
// a step of known size, a constant friction ratio, a force without a normal, no force at all, and
// dropouts against their neighbours.
#include "engine/bench/FeelMetrics.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace palpate {
namespace {

const glm::vec3 kUp(0.0f, 0.0f, 1.0f);

std::vector<FeelTick> constant(std::size_t n, glm::vec3 force, glm::vec3 normal = kUp) {
    return std::vector<FeelTick>(n, FeelTick{force, normal});
}

TEST(FeelMetrics, ASteadyForceHasNoStepAndNoRipple) {
    const auto ticks = constant(200, {0.0f, 0.0f, 0.625f});
    const FeelMetrics m = feelMetrics(ticks);
    EXPECT_EQ(m.ticks, 200u);
    EXPECT_NEAR(m.meanForceN, 0.625, 1e-6);
    EXPECT_DOUBLE_EQ(m.maxStepPct, 0.0);
    EXPECT_DOUBLE_EQ(m.maxNormalStepPct, 0.0);
    EXPECT_DOUBLE_EQ(m.ripplePct, 0.0);
    EXPECT_DOUBLE_EQ(m.frictionRatio, 0.0);
}

TEST(FeelMetrics, OneStepOfKnownSize) {
    // 50 ticks at 1.0 N, then 50 at 1.1 N: mean 1.05 N, one step of 0.1 N = 9.524 % of the mean.
    auto ticks = constant(50, {0.0f, 0.0f, 1.0f});
    const auto high = constant(50, {0.0f, 0.0f, 1.1f});
    ticks.insert(ticks.end(), high.begin(), high.end());
    const FeelMetrics m = feelMetrics(ticks);
    EXPECT_NEAR(m.meanForceN, 1.05, 1e-6);
    EXPECT_NEAR(m.maxStepPct, 100.0 * 0.1 / 1.05, 1e-4);
    EXPECT_NEAR(m.maxNormalStepPct, 100.0 * 0.1 / 1.05, 1e-4);
    EXPECT_NEAR(m.ripplePct, 100.0 * 0.1 / 1.05, 1e-4);
}

TEST(FeelMetrics, TheLargestOfSeveralStepsCounts) {
    std::vector<FeelTick> ticks;
    for (float f : {1.0f, 1.01f, 1.0f, 1.03f, 1.0f, 0.98f, 1.0f}) ticks.push_back({{0.0f, 0.0f, f}, kUp});
    const FeelMetrics m = feelMetrics(ticks);
    const double mean = (1.0 + 1.01 + 1.0 + 1.03 + 1.0 + 0.98 + 1.0) / 7.0;
    EXPECT_NEAR(m.maxStepPct, 100.0 * 0.03 / mean, 1e-4);
    EXPECT_NEAR(m.ripplePct, 100.0 * 0.05 / mean, 1e-4);
}

TEST(FeelMetrics, AConstantFrictionRatio) {
    // F = 1 N along the normal plus 0.2 N along the slide: ratio 0.2 whatever the direction of the
    // tangential part, and the normal part has no step although the tangential one turns.
    std::vector<FeelTick> ticks;
    for (int i = 0; i < 100; ++i) {
        const float angle = 0.01f * float(i);
        ticks.push_back({{0.2f * std::cos(angle), 0.2f * std::sin(angle), 1.0f}, kUp});
    }
    const FeelMetrics m = feelMetrics(ticks);
    EXPECT_NEAR(m.frictionRatio, 0.2, 1e-5);
    EXPECT_NEAR(m.meanNormalN, 1.0, 1e-6);
    EXPECT_NEAR(m.meanTangentialN, 0.2, 1e-5);
    EXPECT_LT(m.maxNormalStepPct, 1e-4);
    EXPECT_GT(m.maxStepPct, 0.1);  // the tangential part turns by 0.002 N per tick
}

TEST(FeelMetrics, AForceOnATiltedNormalSplitsAlongIt) {
    const glm::vec3 n = glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f));
    const glm::vec3 t = glm::normalize(glm::vec3(1.0f, 0.0f, -1.0f));
    const auto ticks = constant(10, 2.0f * n + 0.5f * t, n);
    const FeelMetrics m = feelMetrics(ticks);
    EXPECT_NEAR(m.meanNormalN, 2.0, 1e-5);
    EXPECT_NEAR(m.frictionRatio, 0.25, 1e-5);
}

TEST(FeelMetrics, AForceWithoutANormalRendersNoFriction) {
    // TickResult::normal zero while there is force: the model renders no friction, all is normal.
    const auto ticks = constant(20, {0.3f, 0.0f, 0.4f}, glm::vec3(0.0f));
    const FeelMetrics m = feelMetrics(ticks);
    EXPECT_NEAR(m.meanNormalN, 0.5, 1e-6);
    EXPECT_DOUBLE_EQ(m.frictionRatio, 0.0);
}

TEST(FeelMetrics, NoForceGivesNoPercentages) {
    const FeelMetrics none = feelMetrics(constant(10, glm::vec3(0.0f)));
    EXPECT_DOUBLE_EQ(none.meanForceN, 0.0);
    EXPECT_TRUE(std::isnan(none.maxStepPct));
    EXPECT_TRUE(std::isnan(none.ripplePct));
    EXPECT_DOUBLE_EQ(none.frictionRatio, 0.0);
    const FeelMetrics empty = feelMetrics({});
    EXPECT_EQ(empty.ticks, 0u);
    EXPECT_TRUE(std::isnan(empty.maxStepPct));
}

std::vector<FeltTick> steady(std::size_t n, double forceN = 1.0) {
    return std::vector<FeltTick>(n, FeltTick{forceN, true});
}

TEST(FeelDropouts, ATickBelowHalfItsNeighboursIsADropout) {
    auto ticks = steady(40);
    ticks[20].forceN = 0.3;  // below half of 1.0
    ticks[30].forceN = 0.6;  // above half: a dip, not a dropout
    EXPECT_EQ(countDropouts(ticks, 0, ticks.size()), 1u);
    // Two ticks in a row at zero: each is below half of the mean of its six neighbours.
    ticks[10].forceN = ticks[11].forceN = 0.0;
    EXPECT_EQ(countDropouts(ticks, 0, ticks.size()), 3u);
}

TEST(FeelDropouts, OnlyContactTicksInTheRangeCount) {
    auto ticks = steady(40);
    ticks[5].forceN = 0.0;     // outside [10, 40)
    ticks[20] = {0.0, false};  // no contact: the tool left the tissue, not a dropout
    EXPECT_EQ(countDropouts(ticks, 10, ticks.size()), 0u);
    EXPECT_EQ(countDropouts(ticks, 0, ticks.size()), 1u);
    // The range may run past the end; neighbours outside the sequence are left out.
    ticks[39].forceN = 0.1;
    EXPECT_EQ(countDropouts(ticks, 30, 100), 1u);
}

TEST(FeelDropouts, ASteadyOrSlowlyChangingForceHasNone) {
    std::vector<FeltTick> ticks;
    for (int i = 0; i < 500; ++i) ticks.push_back({0.5 + 0.3 * std::sin(0.02 * i), true});
    EXPECT_EQ(countDropouts(ticks, 0, ticks.size()), 0u);
}

}  // namespace
}  // namespace palpate
