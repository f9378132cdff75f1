// Simulated device: every scripted trajectory starts above the surface, reaches the configured
// depth and is deterministic (equal times give bit-identical positions, whatever the call order);
// the scene frame moves it; waypoints interpolate; an unplug mid-run fails reads, drops forces
// and reads Disconnected until a replug brings it back Ready; a stall trips the watchdog.

#include "tests/support/AllocationCounter.h"
#include "device/SafetyFilter.h"
#include "device/SimulatedDevice.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace palpate {

/// Readable parameter values in test output and ctest names.
void PrintTo(SimTrajectory trajectory, std::ostream* out) { *out << simTrajectoryName(trajectory); }

namespace {

constexpr double kTickS = 0.001;
const SimTrajectory kScripted[] = {SimTrajectory::PressHold, SimTrajectory::Stroke, SimTrajectory::Scan,
                                   SimTrajectory::Sine};

/// Height above the target along its normal.
double heightMm(const glm::vec3& p, const glm::vec3& targetMm, const glm::vec3& normal) {
    return glm::dot(glm::dvec3(p) - glm::dvec3(targetMm), glm::normalize(glm::dvec3(normal)));
}

/// Samples the trajectory every millisecond over [0, endS].
std::vector<glm::vec3> sampled(const SimulatedDevice& d, double endS) {
    std::vector<glm::vec3> out;
    for (int i = 0; i * kTickS <= endS; ++i) out.push_back(d.positionAtMm(i * kTickS));
    return out;
}

double horizonS(const SimulatedDevice& d) { return std::isfinite(d.durationS()) ? d.durationS() + 0.5 : 5.0; }

class EachTrajectory : public ::testing::TestWithParam<SimTrajectory> {};

TEST_P(EachTrajectory, StartsAboveTheSurfaceAndReachesTheDepth) {
    SimulatedDeviceDef def;
    def.approachHeightMm = 2.0;
    def.depthMm = 3.5;
    SimulatedDevice d(GetParam(), def);
    const glm::vec3 target(0.0f), normal(0, 0, 1);
    EXPECT_NEAR(heightMm(d.positionAtMm(0.0), target, normal), 2.0, 1e-6);
    EXPECT_NEAR(heightMm(d.positionAtMm(-1.0), target, normal), 2.0, 1e-6);  // before the start
    double deepest = 1e9;
    for (const glm::vec3& p : sampled(d, horizonS(d))) deepest = std::min(deepest, heightMm(p, target, normal));
    EXPECT_NEAR(deepest, -3.5, 1e-4) << simTrajectoryName(GetParam());
    if (std::isfinite(d.durationS())) {  // comes back up at the end
        EXPECT_NEAR(heightMm(d.positionAtMm(d.durationS() + 1.0), target, normal), 2.0, 1e-6);
    }
}

TEST_P(EachTrajectory, SameTimesGiveBitIdenticalPositions) {
    SimulatedDevice a(GetParam()), b(GetParam());
    const glm::vec3 target(1.5f, -2.0f, 7.25f), normal(0.3f, 0.4f, 0.866f), tangent(1, 0, 0);
    a.setScene(target, normal, tangent);
    b.setScene(target, normal, tangent);
    const std::vector<glm::vec3> forward = sampled(a, horizonS(a));
    // b is queried backwards and twice: no hidden cursor may change the answer.
    std::vector<glm::vec3> backward(forward.size());
    for (std::size_t i = forward.size(); i-- > 0;) backward[i] = b.positionAtMm(double(i) * kTickS);
    for (std::size_t i = forward.size(); i-- > 0;) backward[i] = b.positionAtMm(double(i) * kTickS);
    ASSERT_EQ(forward.size(), backward.size());
    EXPECT_EQ(std::memcmp(forward.data(), backward.data(), forward.size() * sizeof(glm::vec3)), 0);
    // And through the device interface, as the loop sees it.
    ASSERT_TRUE(a.open());
    for (std::size_t i = 0; i < forward.size(); i += 37) {
        a.setTimeS(double(i) * kTickS);
        DeviceSample s;
        ASSERT_TRUE(a.read(s));
        ASSERT_EQ(std::memcmp(&s.positionMm, &forward[i], sizeof(glm::vec3)), 0) << i;
        ASSERT_EQ(s.timeS, double(i) * kTickS);
    }
}

TEST_P(EachTrajectory, FollowsTheSceneFrame) {
    SimulatedDevice d(GetParam());
    const glm::vec3 target(10.0f, 20.0f, 30.0f);
    const glm::vec3 normal = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));
    d.setScene(target, normal * 5.0f, glm::vec3(0, 0, 1));  // normal need not be unit
    const glm::vec3 start = d.positionAtMm(0.0);
    const glm::vec3 expected = target + 2.0f * normal;
    if (GetParam() != SimTrajectory::Scan) {  // the scan starts at a corner of its patch
        EXPECT_NEAR(start.x, expected.x, 1e-4f);
        EXPECT_NEAR(start.y, expected.y, 1e-4f);
        EXPECT_NEAR(start.z, expected.z, 1e-4f);
    }
    EXPECT_NEAR(heightMm(start, target, normal), 2.0, 1e-4);
    double deepest = 1e9;
    for (const glm::vec3& p : sampled(d, horizonS(d))) deepest = std::min(deepest, heightMm(p, target, normal));
    EXPECT_NEAR(deepest, -3.0, 1e-4);
}

INSTANTIATE_TEST_SUITE_P(SimulatedDevice, EachTrajectory, ::testing::ValuesIn(kScripted),
                         [](const auto& info) { return std::string(simTrajectoryName(info.param)); });

TEST(SimulatedDevice, PressHoldsAtDepthForTheHoldTime) {
    SimulatedDeviceDef def;
    def.descendTimeS = 0.5;
    def.holdTimeS = 1.0;
    SimulatedDevice d(SimTrajectory::PressHold, def);
    EXPECT_FLOAT_EQ(d.positionAtMm(0.25).z, 2.0f - 0.5f * 5.0f);  // half way down, linear
    for (double t = 0.5; t <= 1.5; t += 0.01) EXPECT_FLOAT_EQ(d.positionAtMm(t).z, -3.0f);
    EXPECT_DOUBLE_EQ(d.durationS(), 2.0);
}

TEST(SimulatedDevice, StrokeSlidesAlongTheTangentAtDepthAndBack) {
    SimulatedDeviceDef def;
    def.strokeLengthMm = 12.0;
    SimulatedDevice d(SimTrajectory::Stroke, def);
    d.setScene(glm::vec3(0.0f), glm::vec3(0, 0, 1), glm::vec3(0, 1, 0));
    float furthest = 0.0f;
    for (const glm::vec3& p : sampled(d, horizonS(d))) {
        furthest = std::max(furthest, p.y);
        if (p.y > 0.01f) {
            EXPECT_FLOAT_EQ(p.z, -3.0f);  // sliding only while pressed in
        }
        EXPECT_FLOAT_EQ(p.x, 0.0f);
    }
    EXPECT_NEAR(furthest, 12.0f, 1e-4f);
    EXPECT_NEAR(d.positionAtMm(d.durationS()).y, 0.0f, 1e-6f);
}

TEST(SimulatedDevice, ScanPressesOnceAtEveryGridPointOfThePatch) {
    SimulatedDeviceDef def;
    def.scanGridCount = 3;
    def.scanPatchSizeMm = 8.0;
    SimulatedDevice d(SimTrajectory::Scan, def);
    std::vector<glm::vec2> pressedAt;
    bool in = false;
    for (const glm::vec3& p : sampled(d, horizonS(d))) {
        if (!in && p.z <= -3.0f + 1e-4f) {
            in = true;
            pressedAt.emplace_back(p.x, p.y);
        } else if (in && p.z > 0.0f) {
            in = false;
        }
        EXPECT_LE(std::fabs(p.x), 4.0f + 1e-4f);
        EXPECT_LE(std::fabs(p.y), 4.0f + 1e-4f);
    }
    ASSERT_EQ(pressedAt.size(), 9u);
    for (int gx = -1; gx <= 1; ++gx)
        for (int gy = -1; gy <= 1; ++gy) {
            int hits = 0;
            for (const glm::vec2& q : pressedAt)
                if (std::fabs(q.x - 4.0f * gx) < 1e-3f && std::fabs(q.y - 4.0f * gy) < 1e-3f) ++hits;
            EXPECT_EQ(hits, 1) << gx << "," << gy;
        }
}

TEST(SimulatedDevice, SineOscillatesBetweenItsBoundsAtItsFrequency) {
    SimulatedDeviceDef def;
    def.depthMm = 4.0;
    def.sineAmplitudeMm = 1.0;
    def.sineFrequencyHz = 2.0;
    def.descendTimeS = 1.0;
    SimulatedDevice d(SimTrajectory::Sine, def);
    EXPECT_TRUE(std::isinf(d.durationS()));
    double lo = 1e9, hi = -1e9;
    for (double t = 1.0; t < 3.0; t += 0.0005) {
        const double z = d.positionAtMm(t).z;
        lo = std::min(lo, z);
        hi = std::max(hi, z);
    }
    EXPECT_NEAR(lo, -4.0, 1e-4);  // deepest = depthMm
    EXPECT_NEAR(hi, -2.0, 1e-4);  // shallowest = depthMm - 2 * amplitude
    // Period 0.5 s: the same depth half a second later.
    EXPECT_NEAR(d.positionAtMm(1.3).z, d.positionAtMm(1.8).z, 1e-5);
    EXPECT_NEAR(d.positionAtMm(1.125).z, -4.0f, 1e-5f);  // quarter period after the descent: deepest
}

TEST(SimulatedDevice, WaypointsInterpolateLinearlyAndHoldTheEnds) {
    std::vector<Waypoint> w = {{0.0, {0, 0, 2}}, {1.0, {0, 0, -2}}, {3.0, {4, 0, -2}}};
    SimulatedDevice d(w);
    EXPECT_EQ(d.trajectory(), SimTrajectory::Waypoints);
    EXPECT_EQ(d.positionAtMm(-5.0), glm::vec3(0, 0, 2));
    EXPECT_EQ(d.positionAtMm(0.5), glm::vec3(0, 0, 0));
    EXPECT_EQ(d.positionAtMm(2.0), glm::vec3(2, 0, -2));
    EXPECT_EQ(d.positionAtMm(99.0), glm::vec3(4, 0, -2));
    EXPECT_DOUBLE_EQ(d.durationS(), 3.0);
    d.setScene(glm::vec3(100.0f), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0));  // waypoints are in scene frame
    EXPECT_EQ(d.positionAtMm(0.5), glm::vec3(0, 0, 0));
}

TEST(SimulatedDevice, RejectsBadWaypointListsAndDefinitions) {
    EXPECT_THROW(SimulatedDevice(std::vector<Waypoint>{}), std::invalid_argument);
    EXPECT_THROW(SimulatedDevice(std::vector<Waypoint>{{1.0, {}}, {1.0, {}}}), std::invalid_argument);
    EXPECT_THROW({ SimulatedDevice device(SimTrajectory::Waypoints); }, std::invalid_argument);
    SimulatedDeviceDef def;
    def.depthMm = -1.0;
    EXPECT_TRUE(hasProblem(validateSimulatedDeviceDef(def), "depthMm"))
        << joinedMessages(validateSimulatedDeviceDef(def));
    EXPECT_THROW(SimulatedDevice(SimTrajectory::PressHold, def), std::invalid_argument);
    def = {};
    def.scanGridCount = 0;
    EXPECT_TRUE(hasProblem(validateSimulatedDeviceDef(def), "scanGridCount"))
        << joinedMessages(validateSimulatedDeviceDef(def));
    def = {};
    def.sineFrequencyHz = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(hasProblem(validateSimulatedDeviceDef(def), "sineFrequencyHz"))
        << joinedMessages(validateSimulatedDeviceDef(def));
}

TEST(SimulatedDevice, BadSceneInputIsIgnored) {
    SimulatedDevice d(SimTrajectory::PressHold);
    const glm::vec3 before = d.positionAtMm(0.0);
    d.setScene(glm::vec3(std::numeric_limits<float>::quiet_NaN()), glm::vec3(0, 0, 1), glm::vec3(1, 0, 0));
    d.setScene(glm::vec3(1.0f), glm::vec3(0.0f), glm::vec3(1, 0, 0));  // no normal
    EXPECT_EQ(d.positionAtMm(0.0), before);
    d.setScene(glm::vec3(0.0f), glm::vec3(0, 0, 1), glm::vec3(0, 0, 1));  // tangent parallel to normal
    const glm::vec3 p = d.positionAtMm(0.0);
    EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
}

TEST(SimulatedDevice, ReadsFollowTheLoopClockWithANewSequencePerTick) {
    SimulatedDevice d(SimTrajectory::PressHold);
    DeviceSample s;
    EXPECT_FALSE(d.read(s));  // not open
    EXPECT_EQ(d.state(), DeviceState::Disconnected);
    ASSERT_TRUE(d.open());
    EXPECT_EQ(d.state(), DeviceState::Ready);
    EXPECT_TRUE(d.spec().actuated);
    std::uint64_t last = 0;
    for (int i = 0; i < 100; ++i) {
        d.setTimeS(i * kTickS);
        ASSERT_TRUE(d.read(s));
        EXPECT_GT(s.sequence, last);
        last = s.sequence;
        EXPECT_EQ(s.timeS, i * kTickS);
        EXPECT_EQ(s.positionMm, d.positionAtMm(i * kTickS));
    }
    d.writeForce(glm::vec3(0.5f, 0, 1));
    EXPECT_EQ(d.lastForceN(), glm::vec3(0.5f, 0, 1));
    d.close();
    EXPECT_FALSE(d.read(s));
    EXPECT_EQ(d.lastForceN(), glm::vec3(0.0f));
}

/// The loop's view of one tick: time, read, filter, write. Returns the force written.
struct MiniLoop {
    explicit MiniLoop(SimulatedDevice& d, SafetyFilterDef def = {}) : device(d), filter(d.spec(), def) {}
    glm::vec3 tick(const glm::vec3& commandN) {
        device.setTimeS(nowS);
        DeviceSample s;
        const bool fresh = device.read(s);
        if (fresh) last = s;
        SafetyInput in;
        in.nowS = nowS;
        in.sampleSequence = last.sequence;
        in.sampleTimeS = last.timeS;
        in.deviceReady = device.state() == DeviceState::Ready;
        const glm::vec3 f = filter.filter(commandN, in);
        device.writeForce(f);
        nowS += kTickS;
        readOk = fresh;
        return f;
    }
    SimulatedDevice& device;
    SafetyFilter filter;
    DeviceSample last;
    double nowS = 0.0;
    bool readOk = false;
};

TEST(SimulatedDevice, UnplugMidRunFailsReadsDropsForcesAndReplugRestoresReady) {
    SimulatedDevice d(SimTrajectory::PressHold);
    ASSERT_TRUE(d.open());
    MiniLoop loop(d);
    const glm::vec3 small(0.0f, 0.0f, 0.05f), pressing(0.0f, 0.0f, 1.5f);
    for (int i = 0; i < 300; ++i) loop.tick(i < 10 ? small : pressing);  // armed after hold-off + ramp
    ASSERT_EQ(loop.filter.phase(), SafetyPhase::Armed);
    EXPECT_EQ(d.lastForceN(), pressing);

    d.simulateUnplug(loop.nowS + 0.0005);  // between this tick and the next
    loop.tick(pressing);                   // still plugged
    EXPECT_EQ(d.lastForceN(), pressing);
    const glm::vec3 f = loop.tick(pressing);  // unplugged during this tick's setTimeS
    EXPECT_FALSE(loop.readOk);
    EXPECT_EQ(d.state(), DeviceState::Disconnected);
    EXPECT_EQ(f, glm::vec3(0.0f));  // zero force within one tick
    EXPECT_EQ(d.lastForceN(), glm::vec3(0.0f));
    const std::uint64_t dropped = d.droppedForceWrites();
    EXPECT_GE(dropped, 1u);
    d.writeForce(glm::vec3(1.0f, 0, 0));  // even an unfiltered write is dropped
    EXPECT_EQ(d.droppedForceWrites(), dropped + 1);
    EXPECT_EQ(d.lastForceN(), glm::vec3(0.0f));
    DeviceSample s;
    for (int i = 0; i < 100; ++i) {
        EXPECT_EQ(loop.tick(pressing), glm::vec3(0.0f));
        EXPECT_FALSE(d.read(s));
    }

    d.replug();
    EXPECT_EQ(d.state(), DeviceState::Ready);
    const std::uint64_t before = loop.last.sequence;
    EXPECT_EQ(loop.tick(pressing), glm::vec3(0.0f));  // re-armed: held off while pressing hard
    EXPECT_TRUE(loop.readOk);
    EXPECT_GT(loop.last.sequence, before);
    EXPECT_EQ(loop.filter.phase(), SafetyPhase::HoldOff);
    for (int i = 0; i < 200; ++i) loop.tick(i < 5 ? small : pressing);
    EXPECT_EQ(loop.filter.phase(), SafetyPhase::Armed);
    EXPECT_EQ(d.lastForceN(), pressing);
}

TEST(SimulatedDevice, StalledSamplesTripTheWatchdog) {
    SimulatedDevice d(SimTrajectory::PressHold);
    ASSERT_TRUE(d.open());
    SafetyFilterDef def;
    def.staleSampleMaxTicks = 20;
    def.staleSampleTimeoutS = 1.0;  // the tick count decides here
    def.maxSampleAgeS = 0.0;
    MiniLoop loop(d, def);
    for (int i = 0; i < 300; ++i) loop.tick(glm::vec3(0.0f, 0.0f, 0.1f));
    ASSERT_EQ(loop.filter.phase(), SafetyPhase::Armed);
    d.simulateStall(loop.nowS, loop.nowS + 1.0);
    const int maxTicks = loop.filter.def().staleSampleMaxTicks;
    int zeroAt = -1;
    for (int i = 0; i < 100 && zeroAt < 0; ++i)
        if (loop.tick(glm::vec3(0.0f, 0.0f, 0.1f)) == glm::vec3(0.0f)) zeroAt = i;
    // The first stalled tick repeats the last sample once; the limit allows maxTicks repeats.
    EXPECT_EQ(zeroAt, maxTicks);
    EXPECT_EQ(d.state(), DeviceState::Ready);  // a stall is not an unplug
}

TEST(SimulatedDevice, EmergencyStopZeroesAndDropsUntilReopened) {
    SimulatedDevice d(SimTrajectory::PressHold);
    ASSERT_TRUE(d.open());
    d.writeForce(glm::vec3(1.0f));
    d.emergencyStop();
    EXPECT_EQ(d.state(), DeviceState::Fault);
    EXPECT_EQ(d.lastForceN(), glm::vec3(0.0f));
    d.writeForce(glm::vec3(1.0f));
    EXPECT_EQ(d.lastForceN(), glm::vec3(0.0f));
    DeviceSample s;
    EXPECT_FALSE(d.read(s));
    d.replug();  // a replug does not clear a fault
    EXPECT_EQ(d.state(), DeviceState::Fault);
    ASSERT_TRUE(d.open());
    EXPECT_EQ(d.state(), DeviceState::Ready);
}

TEST(SimulatedDevice, TickPathDoesNotAllocate) {
    SimulatedDevice d(SimTrajectory::Scan);
    ASSERT_TRUE(d.open());
    MiniLoop loop(d);
    d.simulateUnplug(2.0);
    const test::AllocationCounter counter;
    for (int i = 0; i < 3000; ++i) {
        loop.tick(glm::vec3(0.0f, 0.0f, 0.1f));
        if (i == 2500) d.replug();
        if (i % 500 == 0) d.setScene(glm::vec3(float(i)), glm::vec3(0, 1, 0), glm::vec3(1, 0, 0));
    }
    EXPECT_EQ(counter.count(), 0u);
}

}  // namespace
}  // namespace palpate

namespace palpate {
namespace {

TEST(SimulatedDeviceClock, ScriptStartsAtTheFirstTickAfterOpen) {
    // A device swapped into a loop that has run for 10 s starts its script from the beginning.
    SimulatedDevice fresh(SimTrajectory::Stroke);
    ASSERT_TRUE(fresh.open());
    SimulatedDevice reference(SimTrajectory::Stroke);
    fresh.setTimeS(10.0);
    DeviceSample sample;
    ASSERT_TRUE(fresh.read(sample));
    EXPECT_EQ(sample.positionMm, reference.positionAtMm(0.0));
    EXPECT_EQ(sample.timeS, 10.0);  // stamped on the loop's clock
    fresh.setTimeS(11.5);
    ASSERT_TRUE(fresh.read(sample));
    EXPECT_EQ(sample.positionMm, reference.positionAtMm(1.5));
    // Reopening restarts the script.
    fresh.close();
    ASSERT_TRUE(fresh.open());
    fresh.setTimeS(20.0);
    ASSERT_TRUE(fresh.read(sample));
    EXPECT_EQ(sample.positionMm, reference.positionAtMm(0.0));
}

TEST(SimulatedDeviceClock, RepeatPlaysTheScriptAgainAfterTheRest) {
    SimulatedDevice device(SimTrajectory::PressHold);
    const double duration = device.durationS();
    ASSERT_TRUE(std::isfinite(duration));
    device.setRepeat(1.0);
    ASSERT_TRUE(device.open());
    device.setTimeS(0.0);
    EXPECT_EQ(device.scriptTimeS(duration * 0.5), duration * 0.5);
    EXPECT_EQ(device.positionAtMm(device.scriptTimeS(duration + 0.5)), device.positionAtMm(duration));  // resting
    EXPECT_NEAR(device.scriptTimeS(duration + 1.0 + 0.25), 0.25, 1e-9);                                // again
    SimulatedDevice once(SimTrajectory::PressHold);
    ASSERT_TRUE(once.open());
    once.setTimeS(0.0);
    EXPECT_EQ(once.positionAtMm(once.scriptTimeS(duration + 1.25)), once.positionAtMm(duration));  // stays at the end
}

}  // namespace
}  // namespace palpate
