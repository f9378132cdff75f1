// Force by phase (engine/exercise/ForcePhases.h) on synthetic sessions whose percentiles are
// worked out by hand.

#include "engine/exercise/ForcePhases.h"

#include <gtest/gtest.h>

namespace palpate {
namespace {

TEST(ForcePhases, SweepsAreSearchAndStillPressesArePalpation) {
    // Search: 1.0 .. 2.0 N in 11 steps at 30 mm/s; palpation: 2.0 .. 3.0 N in 11 steps at 2 mm/s;
    // a resting contact at 0.05 N and a lift-off at 0 N count for neither.
    std::vector<ForceMotionSample> s;
    for (int i = 0; i <= 10; ++i) s.push_back({1.0 + 0.1 * i, 30.0});
    for (int i = 0; i <= 10; ++i) s.push_back({2.0 + 0.1 * i, 2.0});
    s.push_back({0.05, 0.0});
    s.push_back({0.0, 50.0});
    const ForceByPhase r = forceByPhase(s);
    ASSERT_TRUE(r.search && r.palpation);
    EXPECT_EQ(r.search->samples, 11u);
    EXPECT_EQ(r.palpation->samples, 11u);
    // Type-7 percentiles of 11 evenly spaced values: the 10th is the 2nd value, the median the 6th.
    EXPECT_NEAR(r.search->p10N, 1.1, 1e-12);
    EXPECT_NEAR(r.search->p50N, 1.5, 1e-12);
    EXPECT_NEAR(r.search->p90N, 1.9, 1e-12);
    EXPECT_NEAR(r.search->maxN, 2.0, 1e-12);
    EXPECT_NEAR(r.palpation->p50N, 2.5, 1e-12);
    EXPECT_NEAR(*r.palpationOverSearch, 2.5 / 1.5, 1e-12);
}

TEST(ForcePhases, PercentilesInterpolateBetweenSamples) {
    // 4 palpation samples 1, 2, 3, 4 N: p10 at rank 0.3 -> 1.3, p50 at 1.5 -> 2.5, p90 at 2.7 -> 3.7.
    const ForceByPhase r = forceByPhase({{4.0, 0.0}, {1.0, 0.0}, {3.0, 1.0}, {2.0, 5.0}});
    ASSERT_TRUE(r.palpation);
    EXPECT_FALSE(r.search);
    EXPECT_FALSE(r.palpationOverSearch);
    EXPECT_NEAR(r.palpation->p10N, 1.3, 1e-12);
    EXPECT_NEAR(r.palpation->p50N, 2.5, 1e-12);
    EXPECT_NEAR(r.palpation->p90N, 3.7, 1e-12);
}

TEST(ForcePhases, TheSpeedThresholdDecidesThePhase) {
    const std::vector<ForceMotionSample> s{{1.0, 9.0}, {2.0, 11.0}};
    const ForceByPhase r = forceByPhase(s, {10.0, 0.1});
    ASSERT_TRUE(r.search && r.palpation);
    EXPECT_DOUBLE_EQ(r.palpation->p50N, 1.0);
    EXPECT_DOUBLE_EQ(r.search->p50N, 2.0);
    const ForceByPhase slow = forceByPhase(s, {12.0, 0.1});
    EXPECT_FALSE(slow.search);
    EXPECT_EQ(slow.palpation->samples, 2u);
}

TEST(ForcePhases, NoExaminationGivesNoPhases) {
    const ForceByPhase r = forceByPhase({{0.0, 0.0}, {0.05, 20.0}});
    EXPECT_FALSE(r.search);
    EXPECT_FALSE(r.palpation);
}

}  // namespace
}  // namespace palpate
