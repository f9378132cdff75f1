// Safety filter: every rule on both sides. NaN/Inf zeroed and counted; the clamp keeps the
// direction; hold-off until the command is small, then a ramp that reaches full force at
// rampTimeS and not before; stale samples zero the force on the tick they occur; a late tick
// keeps its fresh force, and only a long run of them fades it out at a bounded rate and back in
// without a step; a reconnect re-arms. And the filter does not allocate.

#include "tests/support/AllocationCounter.h"
#include "device/SafetyFilter.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace palpate {
namespace {

constexpr float kNaNf = std::numeric_limits<float>::quiet_NaN();
constexpr float kInff = std::numeric_limits<float>::infinity();
constexpr double kTickS = 0.001;

DeviceSpec testSpec(double maxForceN = 3.0) {
    DeviceSpec spec;
    spec.name = "test";
    spec.maxForceN = maxForceN;
    spec.actuated = true;
    return spec;
}

/// Drives a filter like a 1 kHz loop with a fresh sample every tick.
struct Loop {
    explicit Loop(SafetyFilterDef def = {}, double maxForceN = 3.0) : filter(testSpec(maxForceN), def) {}

    glm::vec3 tick(const glm::vec3& forceN, bool overran = false, bool ready = true) {
        SafetyInput in;
        in.nowS = nowS;
        in.sampleSequence = ++sequence;
        in.sampleTimeS = nowS;
        in.tickOverran = overran;
        in.deviceReady = ready;
        const glm::vec3 out = filter.filter(forceN, in);
        lastFreshS = nowS;
        nowS += kTickS;
        return out;
    }
    /// Same sample as last tick (the device delivered nothing new).
    glm::vec3 tickStale(const glm::vec3& forceN) {
        SafetyInput in;
        in.nowS = nowS;
        in.sampleSequence = sequence;
        in.sampleTimeS = lastFreshS;
        const glm::vec3 out = filter.filter(forceN, in);
        nowS += kTickS;
        return out;
    }
    /// Hold-off passed and ramp complete.
    void arm() {
        tick(glm::vec3(0.0f));
        for (int i = 0; i < 200 && filter.phase() != SafetyPhase::Armed; ++i) tick(glm::vec3(0.0f));
        ASSERT_EQ(filter.phase(), SafetyPhase::Armed);
    }

    SafetyFilter filter;
    double nowS = 0.0;
    double lastFreshS = 0.0;
    std::uint64_t sequence = 0;
};

bool isZero(const glm::vec3& v) { return v.x == 0.0f && v.y == 0.0f && v.z == 0.0f; }

double lengthD(const glm::vec3& v) {
    const double x = v.x, y = v.y, z = v.z;
    return std::sqrt(x * x + y * y + z * z);
}

TEST(SafetyFilter, ArmedFilterPassesAnInRangeForceUnchanged) {
    Loop loop;
    loop.arm();
    const glm::vec3 f(0.5f, -1.25f, 2.0f);
    const glm::vec3 out = loop.tick(f);
    EXPECT_EQ(out, f);
    EXPECT_EQ(loop.filter.lastFlags(), 0u);
}

TEST(SafetyFilter, NaNInAnyComponentGivesZeroAndIsCounted) {
    Loop loop;
    loop.arm();
    const glm::vec3 cases[] = {{kNaNf, 0, 0}, {0, kNaNf, 0}, {0, 0, kNaNf}, {kNaNf, kNaNf, kNaNf}};
    std::uint64_t expected = 0;
    for (const glm::vec3& f : cases) {
        const glm::vec3 out = loop.tick(f);
        EXPECT_TRUE(isZero(out));
        EXPECT_TRUE(loop.filter.lastFlags() & kSafetyNonFinite);
        EXPECT_EQ(loop.filter.stats().nonFiniteCommands, ++expected);
    }
    // The next finite command goes straight through: NaN does not disarm.
    EXPECT_EQ(loop.tick(glm::vec3(1.0f, 0, 0)), glm::vec3(1.0f, 0, 0));
}

TEST(SafetyFilter, InfinityGivesZeroAndIsCounted) {
    Loop loop;
    loop.arm();
    EXPECT_TRUE(isZero(loop.tick({kInff, 0, 0})));
    EXPECT_TRUE(isZero(loop.tick({0, -kInff, 0})));
    EXPECT_TRUE(isZero(loop.tick({1.0f, 1.0f, kInff})));
    EXPECT_EQ(loop.filter.stats().nonFiniteCommands, 3u);
    EXPECT_EQ(loop.filter.stats().clampedCommands, 0u);  // zeroed, not clamped
}

TEST(SafetyFilter, ClampKeepsTheDirectionAndCapsTheMagnitude) {
    Loop loop({}, 3.0);
    loop.arm();
    const glm::vec3 f(10.0f, -20.0f, 5.0f);
    const glm::vec3 out = loop.tick(f);
    EXPECT_TRUE(loop.filter.lastFlags() & kSafetyClamped);
    EXPECT_LE(lengthD(out), 3.0);
    EXPECT_NEAR(lengthD(out), 3.0, 3.0 * 1e-6);
    // Same direction: every component scaled by one factor.
    const double k = double(out.x) / f.x;
    EXPECT_NEAR(double(out.y) / f.y, k, 1e-6 * k);
    EXPECT_NEAR(double(out.z) / f.z, k, 1e-6 * k);
    EXPECT_GT(k, 0.0);
    EXPECT_EQ(loop.filter.stats().clampedCommands, 1u);
}

TEST(SafetyFilter, ClampNeverExceedsTheLimitAndNeverBendsTheForce) {
    Loop loop({}, 3.3);
    loop.arm();
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> component(-1.0f, 1.0f);
    std::uniform_real_distribution<float> logScale(-3.0f, 30.0f);
    for (int i = 0; i < 2000; ++i) {
        glm::vec3 f(component(rng), component(rng), component(rng));
        f *= std::pow(10.0f, logScale(rng));
        if (!std::isfinite(f.x) || !std::isfinite(f.y) || !std::isfinite(f.z)) continue;
        const glm::vec3 out = loop.tick(f);
        ASSERT_LE(lengthD(out), 3.3) << i;
        if (lengthD(f) > 3.3) {
            const glm::dvec3 a = glm::normalize(glm::dvec3(f)), b = glm::normalize(glm::dvec3(out));
            ASSERT_NEAR(glm::dot(a, b), 1.0, 1e-6) << i;
            ASSERT_NEAR(lengthD(out), 3.3, 3.3 * 1e-6) << i;
        } else {
            ASSERT_EQ(out, f) << i;  // below the limit: untouched, bit for bit
        }
    }
}

TEST(SafetyFilter, HugeFiniteComponentsDoNotOverflowTheClamp) {
    Loop loop({}, 3.0);
    loop.arm();
    const float big = std::numeric_limits<float>::max();
    const glm::vec3 out = loop.tick({big, big, -big});
    EXPECT_NEAR(lengthD(out), 3.0, 1e-5);
    EXPECT_NEAR(out.x, std::sqrt(3.0f), 1e-5f);
    EXPECT_NEAR(out.z, -std::sqrt(3.0f), 1e-5f);
}

TEST(SafetyFilter, ForceExactlyAtTheLimitIsNotClamped) {
    Loop loop({}, 2.0);
    loop.arm();
    EXPECT_EQ(loop.tick({0.0f, 2.0f, 0.0f}), glm::vec3(0.0f, 2.0f, 0.0f));
    EXPECT_EQ(loop.filter.lastFlags() & kSafetyClamped, 0u);
}

TEST(SafetyFilter, DeviceWithoutForceRatingGetsZero) {
    Loop loop({}, 0.0);
    for (int i = 0; i < 300; ++i) EXPECT_TRUE(isZero(loop.tick({0.001f, 0, 0})));
    Loop nanSpec({}, std::numeric_limits<double>::quiet_NaN());
    EXPECT_EQ(nanSpec.filter.maxForceN(), 0.0);
}

TEST(SafetyFilter, HoldsOffWhileTheCommandIsLarge) {
    SafetyFilterDef def;
    def.holdOffThresholdFraction = 0.05;  // 0.15 N of 3 N
    Loop loop(def, 3.0);
    for (int i = 0; i < 500; ++i) {
        ASSERT_TRUE(isZero(loop.tick({0.0f, 0.0f, 1.0f}))) << i;
        ASSERT_EQ(loop.filter.phase(), SafetyPhase::HoldOff);
    }
    // Exactly at the threshold is not "below" it.
    EXPECT_TRUE(isZero(loop.tick({0.0f, 0.0f, 0.15f})));
    EXPECT_EQ(loop.filter.phase(), SafetyPhase::HoldOff);
    EXPECT_GE(loop.filter.stats().heldOffTicks, 501u);
    // Just below: the ramp starts (at zero).
    EXPECT_TRUE(isZero(loop.tick({0.0f, 0.0f, 0.149f})));
    EXPECT_EQ(loop.filter.phase(), SafetyPhase::RampIn);
}

TEST(SafetyFilter, NaNIsNotASmallCommandForTheHoldOff) {
    Loop loop;
    EXPECT_TRUE(isZero(loop.tick({kNaNf, 0, 0})));
    EXPECT_EQ(loop.filter.phase(), SafetyPhase::HoldOff);
}

TEST(SafetyFilter, RampReachesFullForceAfterRampTimeAndNotBefore) {
    // Times and ramp are binary fractions, so "at rampTimeS" is exact, not a rounding question.
    SafetyFilterDef def;
    def.rampTimeS = 0.125;
    SafetyFilter filter(testSpec(3.0), def);
    std::uint64_t seq = 0;
    auto at = [&](double t, const glm::vec3& f) {
        SafetyInput in;
        in.nowS = t;
        in.sampleSequence = ++seq;
        in.sampleTimeS = t;
        return filter.filter(f, in);
    };
    const double stepS = 1.0 / 1024.0;
    const glm::vec3 full(0.0f, 0.0f, 2.0f);
    const double startS = 0.25;
    for (double t = startS - 16 * stepS; t < startS; t += stepS) EXPECT_TRUE(isZero(at(t, full)));  // held off
    EXPECT_TRUE(isZero(at(startS, glm::vec3(0.01f))));  // small: the ramp starts here, at scale 0
    EXPECT_EQ(filter.phase(), SafetyPhase::RampIn);
    float previous = 0.0f;
    for (int i = 1; i < 128; ++i) {  // strictly before startS + rampTimeS
        const double t = startS + stepS * i;
        const glm::vec3 out = at(t, full);
        ASSERT_LT(out.z, full.z) << "full force before rampTimeS at t=" << t;
        ASSERT_GT(out.z, previous) << "ramp not increasing at t=" << t;
        ASSERT_NEAR(out.z, full.z * float(i) / 128.0f, 1e-5f);  // linear
        ASSERT_EQ(out.x, 0.0f);
        previous = out.z;
        ASSERT_EQ(filter.phase(), SafetyPhase::RampIn);
        ASSERT_TRUE(filter.lastFlags() & kSafetyRamping);
    }
    EXPECT_EQ(at(startS + 0.125, full), full);  // at rampTimeS: full force
    EXPECT_EQ(filter.phase(), SafetyPhase::Armed);
    EXPECT_EQ(at(startS + 0.25, full), full);
}

TEST(SafetyFilter, ZeroRampTimeSwitchesOnAtOnce) {
    SafetyFilterDef def;
    def.rampTimeS = 0.0;
    Loop loop(def);
    EXPECT_EQ(loop.tick({0.01f, 0, 0}), glm::vec3(0.01f, 0, 0));
    EXPECT_EQ(loop.filter.phase(), SafetyPhase::Armed);
    EXPECT_EQ(loop.tick({2.0f, 0, 0}), glm::vec3(2.0f, 0, 0));
}

TEST(SafetyFilter, StaleSequenceZeroesForceOnTheFirstTickPastTheLimit) {
    SafetyFilterDef def;
    def.staleSampleMaxTicks = 5;
    def.staleSampleTimeoutS = 1.0;  // only the tick count matters here
    def.maxSampleAgeS = 0.0;
    Loop loop(def);
    loop.arm();
    const glm::vec3 f(1.0f, 0, 0);
    EXPECT_EQ(loop.tick(f), f);
    for (int repeat = 1; repeat <= 5; ++repeat) EXPECT_EQ(loop.tickStale(f), f) << repeat;  // allowed
    EXPECT_TRUE(isZero(loop.tickStale(f)));  // the 6th repeat: zero on that very tick
    EXPECT_TRUE(loop.filter.lastFlags() & kSafetyStaleSample);
    EXPECT_TRUE(isZero(loop.tickStale(f)));
    EXPECT_EQ(loop.filter.stats().staleSampleTicks, 2u);
}

TEST(SafetyFilter, StaleSequenceByTimeZeroesForce) {
    SafetyFilterDef def;
    def.staleSampleMaxTicks = 1000000;
    def.staleSampleTimeoutS = 0.0105;
    def.maxSampleAgeS = 0.0;
    Loop loop(def);
    loop.arm();
    const glm::vec3 f(1.0f, 0, 0);
    EXPECT_EQ(loop.tick(f), f);  // fresh at t0
    for (int i = 1; i <= 10; ++i) EXPECT_EQ(loop.tickStale(f), f) << i;  // t0 + 10 ms
    EXPECT_TRUE(isZero(loop.tickStale(f)));                                // t0 + 11 ms > 10.5 ms
}

TEST(SafetyFilter, OldSampleTimeStampZeroesForce) {
    SafetyFilterDef def;
    def.maxSampleAgeS = 0.005;
    Loop loop(def);
    loop.arm();
    const glm::vec3 f(1.0f, 0, 0);
    SafetyInput in;
    in.nowS = loop.nowS;
    in.sampleSequence = ++loop.sequence;
    in.sampleTimeS = loop.nowS - 0.004;  // young enough
    EXPECT_EQ(loop.filter.filter(f, in), f);
    in.nowS += 0.001;
    in.sampleSequence = ++loop.sequence;
    in.sampleTimeS = in.nowS - 0.006;  // too old, though its sequence is new
    EXPECT_TRUE(isZero(loop.filter.filter(f, in)));
    EXPECT_TRUE(loop.filter.lastFlags() & kSafetyStaleSample);
    in.nowS += 0.001;
    in.sampleSequence = ++loop.sequence;
    in.sampleTimeS = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(isZero(loop.filter.filter(f, in)));
}

TEST(SafetyFilter, AgeCheckCanBeDisabledForDevicesWithTheirOwnClock) {
    SafetyFilterDef def;
    def.maxSampleAgeS = 0.0;
    SafetyFilter filter(testSpec(), def);
    SafetyInput in;
    in.sampleTimeS = -1000.0;  // the device's clock, unrelated to the loop's
    for (int i = 0; i < 300; ++i) {
        in.nowS = 0.001 * i;
        in.sampleSequence = std::uint64_t(i) + 1;
        filter.filter(glm::vec3(0.0f), in);
    }
    EXPECT_EQ(filter.phase(), SafetyPhase::Armed);
    EXPECT_EQ(filter.stats().staleSampleTicks, 0u);
}

TEST(SafetyFilter, FreshSampleAfterAStaleTripRearms) {
    SafetyFilterDef def;
    def.staleSampleMaxTicks = 2;
    Loop loop(def);
    loop.arm();
    const glm::vec3 big(2.0f, 0, 0);
    loop.tick(big);
    for (int i = 0; i < 3; ++i) loop.tickStale(big);
    ASSERT_TRUE(loop.filter.lastFlags() & kSafetyStaleSample);
    // Fresh again, but the tool may be deep: held off until small, then ramped.
    EXPECT_TRUE(isZero(loop.tick(big)));
    EXPECT_EQ(loop.filter.phase(), SafetyPhase::HoldOff);
    EXPECT_TRUE(isZero(loop.tick(glm::vec3(0.01f, 0, 0))));
    EXPECT_EQ(loop.filter.phase(), SafetyPhase::RampIn);
}

TEST(SafetyFilter, StaleTripWithoutRearmResumesAtOnce) {
    SafetyFilterDef def;
    def.staleSampleMaxTicks = 2;
    def.rearmAfterStale = false;
    Loop loop(def);
    loop.arm();
    const glm::vec3 big(2.0f, 0, 0);
    loop.tick(big);
    for (int i = 0; i < 3; ++i) loop.tickStale(big);
    EXPECT_EQ(loop.tick(big), big);
}

TEST(SafetyFilter, LateTicksKeepTheirFreshForce) {
    Loop loop;
    loop.arm();
    const glm::vec3 f(0.0f, 1.5f, 0.0f);
    EXPECT_EQ(loop.tick(f), f);
    // Every other tick late (a loaded desktop), and a run as long as the limit: no dropout.
    for (int i = 0; i < 200; ++i) {
        const glm::vec3 g = f * (1.0f + 0.001f * float(i % 7));
        ASSERT_EQ(loop.tick(g, /*overran=*/i % 2 == 0), g) << "tick " << i;
    }
    for (int i = 0; i < SafetyFilterDef{}.maxConsecutiveOverruns; ++i) ASSERT_EQ(loop.tick(f, true), f) << i;
    EXPECT_TRUE(loop.filter.lastFlags() & kSafetyOverrun);
    EXPECT_FALSE(loop.filter.lastFlags() & kSafetyOverrunFade);
    EXPECT_EQ(loop.filter.stats().overrunTicks, 100u + std::uint64_t(SafetyFilterDef{}.maxConsecutiveOverruns));
    EXPECT_EQ(loop.filter.stats().overrunFadeTicks, 0u);
    EXPECT_EQ(loop.tick(f), f);  // no re-arm for late ticks
    EXPECT_EQ(loop.filter.phase(), SafetyPhase::Armed);
}

TEST(SafetyFilter, ALongRunOfLateTicksFadesOutAtABoundedRateAndRampsBackWithoutAStep) {
    SafetyFilterDef def;
    def.maxConsecutiveOverruns = 5;
    def.overrunFadeTimeS = 0.010;  // 10 ticks
    def.rampTimeS = 0.020;         // 20 ticks
    Loop loop(def);
    loop.arm();
    const glm::vec3 f(0.0f, 0.0f, 2.0f);
    const float full = glm::length(f);
    EXPECT_EQ(loop.tick(f), f);
    for (int i = 0; i < def.maxConsecutiveOverruns; ++i) ASSERT_EQ(loop.tick(f, true), f);
    // Past the limit: down, never by more than full * tick / fadeTime per tick, to zero.
    float last = full;
    int fadeTicks = 0;
    while (last > 0.0f && fadeTicks < 100) {
        const float now = glm::length(loop.tick(f, true));
        ASSERT_LE(now, last) << "fade tick " << fadeTicks;
        ASSERT_LE(last - now, full * float(kTickS / def.overrunFadeTimeS) * 1.001f + 1e-6f) << "fade tick " << fadeTicks;
        EXPECT_TRUE(loop.filter.lastFlags() & kSafetyOverrunFade);
        last = now;
        ++fadeTicks;
    }
    EXPECT_EQ(last, 0.0f);
    EXPECT_GE(fadeTicks, 10);
    // On time again: up, never by more than full * tick / rampTime per tick, to the full force.
    int rampTicks = 0;
    while (last < full && rampTicks < 100) {
        const float now = glm::length(loop.tick(f));
        ASSERT_GE(now, last) << "ramp tick " << rampTicks;
        ASSERT_LE(now - last, full * float(kTickS / def.rampTimeS) * 1.001f + 1e-6f) << "ramp tick " << rampTicks;
        last = now;
        ++rampTicks;
    }
    EXPECT_EQ(loop.tick(f), f);
    EXPECT_EQ(loop.filter.phase(), SafetyPhase::Armed);
    EXPECT_GE(rampTicks, 19);

    // A fade cut short: the ramp starts from the level the fade reached, not from zero or full.
    for (int i = 0; i < def.maxConsecutiveOverruns; ++i) loop.tick(f, true);
    float faded = full;
    for (int i = 0; i < 4; ++i) faded = glm::length(loop.tick(f, true));
    ASSERT_GT(faded, 0.0f);
    ASSERT_LT(faded, full);
    const float back = glm::length(loop.tick(f));
    EXPECT_GE(back, faded);
    EXPECT_LE(back - faded, full * float(kTickS / def.rampTimeS) * 1.001f + 1e-6f);
}

TEST(SafetyFilter, OverrunRulesAreValidated) {
    SafetyFilterDef def;
    def.maxConsecutiveOverruns = -1;
    EXPECT_TRUE(hasProblem(validateSafetyFilterDef(def), "maxConsecutiveOverruns"))
        << joinedMessages(validateSafetyFilterDef(def));
    def = {};
    def.overrunFadeTimeS = 0.0;
    EXPECT_TRUE(hasProblem(validateSafetyFilterDef(def), "overrunFadeTimeS"))
        << joinedMessages(validateSafetyFilterDef(def));
}

TEST(SafetyFilter, ReconnectRearms) {
    Loop loop;
    loop.arm();
    const glm::vec3 big(0.0f, 0.0f, 2.5f);
    EXPECT_EQ(loop.tick(big), big);
    for (int i = 0; i < 50; ++i) EXPECT_TRUE(isZero(loop.tick(big, false, /*ready=*/false)));
    EXPECT_EQ(loop.filter.stats().notReadyTicks, 50u);
    EXPECT_TRUE(loop.filter.lastFlags() & kSafetyNotReady);
    // Back: held off while the command is large, then a full ramp.
    const std::uint64_t rearms = loop.filter.stats().rearms;
    EXPECT_TRUE(isZero(loop.tick(big)));
    EXPECT_EQ(loop.filter.phase(), SafetyPhase::HoldOff);
    EXPECT_EQ(loop.filter.stats().rearms, rearms + 1);
    EXPECT_TRUE(isZero(loop.tick(glm::vec3(0.0f))));
    EXPECT_EQ(loop.filter.phase(), SafetyPhase::RampIn);
    const glm::vec3 mid = loop.tick(big);
    EXPECT_GT(mid.z, 0.0f);
    EXPECT_LT(mid.z, big.z);
}

TEST(SafetyFilter, ExplicitRearmHoldsOffAgain) {
    Loop loop;
    loop.arm();
    loop.filter.rearm();
    EXPECT_EQ(loop.filter.phase(), SafetyPhase::HoldOff);
    EXPECT_TRUE(isZero(loop.tick({1.0f, 0, 0})));
}

TEST(SafetyFilter, NonFiniteClockGivesZero) {
    Loop loop;
    loop.arm();
    SafetyInput in;
    in.nowS = std::numeric_limits<double>::quiet_NaN();
    in.sampleSequence = ++loop.sequence;
    EXPECT_TRUE(isZero(loop.filter.filter({1.0f, 0, 0}, in)));
    EXPECT_TRUE(loop.filter.lastFlags() & kSafetyBadTime);
}

TEST(SafetyFilter, InvalidDefinitionsAreRejectedNamingTheField) {
    auto expectBad = [](SafetyFilterDef def, const char* field) {
        const std::string problem = joinedMessages(validateSafetyFilterDef(def));
        EXPECT_NE(problem.find(field), std::string::npos) << problem;
        EXPECT_THROW(SafetyFilter(testSpec(), def), std::invalid_argument);
    };
    EXPECT_TRUE(validateSafetyFilterDef({}).empty());
    SafetyFilterDef d;
    d.holdOffThresholdFraction = 0.0;
    expectBad(d, "holdOffThresholdFraction");
    d = {};
    d.holdOffThresholdFraction = 1.5;
    expectBad(d, "holdOffThresholdFraction");
    d = {};
    d.rampTimeS = -0.1;
    expectBad(d, "rampTimeS");
    d = {};
    d.rampTimeS = std::numeric_limits<double>::infinity();
    expectBad(d, "rampTimeS");
    d = {};
    d.staleSampleMaxTicks = -1;
    expectBad(d, "staleSampleMaxTicks");
    d = {};
    d.staleSampleTimeoutS = 0.0;
    expectBad(d, "staleSampleTimeoutS");
    d = {};
    d.maxSampleAgeS = std::numeric_limits<double>::quiet_NaN();
    expectBad(d, "maxSampleAgeS");
}

TEST(SafetyFilter, FilterDoesNotAllocate) {
    Loop loop;
    loop.arm();
    const test::AllocationCounter counter;
    for (int i = 0; i < 10000; ++i) {
        const float s = float(i % 7) - 3.0f;
        if (i % 3 == 0) loop.tickStale({s, 1.0f, kNaNf});
        else loop.tick({s * 100.0f, s, 0.1f}, i % 11 == 0, i % 13 != 0);
    }
    EXPECT_EQ(counter.count(), 0u);
}

}  // namespace
}  // namespace palpate
