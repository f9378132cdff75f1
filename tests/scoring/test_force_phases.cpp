// Force by phase (engine/exercise/ForcePhases.h) on synthetic sessions whose percentiles are
// worked out by hand.

#include "engine/exercise/ForcePhases.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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

namespace {

/// A trainee's motion: 22 s of sweeping back and forth along x over 80 mm at 60 mm/s at 0.7 N,
/// then 9 s held still at 1.0 N; the contact point as a device reports it every 1 ms tick
/// (`eventsPerS` 0) or as a mouse moves it, at its event rate (held between events).
ForceByPhase phasesOf(double eventsPerS, double windowS) {
    constexpr double kTickS = 0.001, kSweepS = 22.0, kHoldS = 9.0, kSpeedMmPerS = 60.0, kLengthMm = 80.0;
    const auto position = [&](double tS) {
        const double travelled = kSpeedMmPerS * std::min(tS, kSweepS);
        const double along = std::fmod(travelled, 2.0 * kLengthMm);
        return glm::dvec3(along <= kLengthMm ? along : 2.0 * kLengthMm - along, 0.0, 0.0);
    };
    SurfaceSpeed speed(windowS, kTickS);
    std::vector<ForceMotionSample> samples;
    const int ticks = int(std::lround((kSweepS + kHoldS) / kTickS));
    for (int i = 1; i <= ticks; ++i) {
        const double tS = i * kTickS;
        const double seenS = eventsPerS > 0.0 ? std::floor(tS * eventsPerS) / eventsPerS : tS;
        const auto v = speed.add(kTickS, position(seenS), glm::dvec3(0.0, 0.0, 1.0));
        if (v) samples.push_back({tS <= kSweepS ? 0.7 : 1.0, *v});
    }
    return forceByPhase(samples);
}

}  // namespace

// The same motion, from a mouse at 60 or 125 events a second and from a device at 1 kHz, is the
// same search and palpation: 22 s of sweeping and 9 s of holding. Told apart per tick, the mouse's
// sweep was nearly all "palpation" (its point stands still between events).
TEST(ForcePhases, AMouseAndADeviceMovingAlikeGiveTheSamePhases) {
    const double windowS = ForcePhaseDef{}.speedWindowS;
    for (const double eventsPerS : {0.0, 60.0, 125.0}) {
        const ForceByPhase r = phasesOf(eventsPerS, windowS);
        ASSERT_TRUE(r.search && r.palpation) << eventsPerS;
        // A few turns of the sweep stand still over the window (about 40 ms each).
        EXPECT_NEAR(double(r.search->samples), 22000.0, 0.05 * 22000.0) << eventsPerS << " events/s";
        EXPECT_NEAR(double(r.palpation->samples), 9000.0, 0.1 * 9000.0) << eventsPerS << " events/s";
        EXPECT_NEAR(r.search->p50N, 0.7, 1e-12);
        EXPECT_NEAR(r.palpation->p50N, 1.0, 1e-12);
        ASSERT_TRUE(r.palpationOverSearch);
        EXPECT_GT(*r.palpationOverSearch, 1.0) << "pressed harder to palpate, whatever moved the tool";
    }
    const ForceByPhase perTick = phasesOf(60.0, 0.001);
    ASSERT_TRUE(perTick.search && perTick.palpation);
    EXPECT_LT(perTick.search->samples, 2000u) << "per tick, a mouse's sweep is mostly standing still";
}

// The window's speed is the travel since its start over the time since; a contact begins afresh.
TEST(ForcePhases, TheSpeedIsTheTravelAlongTheSurfaceOverTheWindow) {
    SurfaceSpeed speed(0.01, 0.001);  // ten ticks
    const glm::dvec3 up(0.0, 0.0, 1.0);
    EXPECT_FALSE(speed.add(0.001, {0.0, 0.0, 0.0}, up)) << "a contact's first tick has no speed";
    for (int i = 1; i <= 30; ++i) {
        // 5 mm/s along x, and pressing in along the normal at 100 mm/s, which is not travel.
        const auto v = speed.add(0.001, {0.005 * i, 0.0, -0.1 * i}, up);
        ASSERT_TRUE(v);
        EXPECT_NEAR(*v, 5.0, 1e-9) << i;
    }
    // Stopped: the speed falls as the window slides past the motion, to zero after one window.
    for (int i = 1; i <= 10; ++i) speed.add(0.001, {0.15, 0.0, -3.0}, up);
    EXPECT_NEAR(*speed.add(0.001, {0.15, 0.0, -3.0}, up), 0.0, 1e-12);
    // A long tick (a missed deadline) counts its length.
    speed.reset();
    speed.add(0.001, {0.0, 0.0, 0.0}, up);
    EXPECT_NEAR(*speed.add(0.004, {0.02, 0.0, 0.0}, up), 5.0, 1e-9);
}

}  // namespace
}  // namespace palpate
