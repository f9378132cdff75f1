// MouseDevice: the GUI thread steers, the haptic thread reads, through a seqlock. Two threads for
// ~200 ms: every position written is (k, k, k), so a torn read would show unequal components; the
// reader must also never see k go backwards. Run under TSan too (build dir tsan-dev).

#include "tests/support/AllocationCounter.h"
#include "device/MouseDevice.h"
#include "base/concurrency/SeqLock.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

namespace palpate {
namespace {

using Clock = std::chrono::steady_clock;

TEST(MouseDevice, IsAnInputOnlyDeviceThatFollowsTheTarget) {
    MouseDevice m;
    DeviceSample s;
    EXPECT_FALSE(m.read(s));  // not open
    ASSERT_TRUE(m.open());
    EXPECT_EQ(m.state(), DeviceState::Ready);
    EXPECT_FALSE(m.spec().actuated);
    EXPECT_TRUE(m.calibrate());
    EXPECT_TRUE(m.setTargetMm({1.0f, 2.0f, 3.0f}));
    m.setButtons(0b101u);
    m.setTimeS(0.25);
    ASSERT_TRUE(m.read(s));
    EXPECT_EQ(s.positionMm, glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(s.buttons, 0b101u);
    EXPECT_EQ(s.timeS, 0.25);
    const std::uint64_t first = s.sequence;
    ASSERT_TRUE(m.read(s));
    EXPECT_GT(s.sequence, first);  // each read is a fresh reading, so the watchdog stays quiet
    EXPECT_EQ(m.targetMm(), glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(m.targetVersion(), 1u);
}

TEST(MouseDevice, RejectsNonFiniteTargets) {
    MouseDevice m;
    ASSERT_TRUE(m.open());
    ASSERT_TRUE(m.setTargetMm({1.0f, 1.0f, 1.0f}));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(m.setTargetMm({nan, 0.0f, 0.0f}));
    EXPECT_FALSE(m.setTargetMm({0.0f, std::numeric_limits<float>::infinity(), 0.0f}));
    DeviceSample s;
    ASSERT_TRUE(m.read(s));
    EXPECT_EQ(s.positionMm, glm::vec3(1.0f, 1.0f, 1.0f));
}

TEST(MouseDevice, ForcesAreKeptForDisplayOnlyWhileReady) {
    MouseDevice m;
    m.writeForce({1.0f, 0.0f, 0.0f});  // not open: dropped
    EXPECT_EQ(m.lastForceN(), glm::vec3(0.0f));
    ASSERT_TRUE(m.open());
    m.writeForce({0.0f, 0.5f, 0.0f});
    EXPECT_EQ(m.lastForceN(), glm::vec3(0.0f, 0.5f, 0.0f));
    m.emergencyStop();
    EXPECT_EQ(m.state(), DeviceState::Fault);
    EXPECT_EQ(m.lastForceN(), glm::vec3(0.0f));
    DeviceSample s;
    EXPECT_FALSE(m.read(s));
    m.close();
    EXPECT_EQ(m.state(), DeviceState::Disconnected);
}

TEST(MouseDevice, ReadAndWriteForceDoNotAllocate) {
    MouseDevice m;
    ASSERT_TRUE(m.open());
    m.setTargetMm({1.0f, 2.0f, 3.0f});
    const test::AllocationCounter counter;
    DeviceSample s;
    for (int i = 0; i < 10000; ++i) {
        m.setTimeS(i * 0.001);
        m.read(s);
        m.writeForce({float(i), 0.0f, 0.0f});
    }
    EXPECT_EQ(counter.count(), 0u);
}

TEST(MouseDevice, ReaderNeverSeesATornPositionWhileTheGuiWrites) {
    MouseDevice m;
    ASSERT_TRUE(m.open());
    ASSERT_TRUE(m.setTargetMm({0.0f, 0.0f, 0.0f}));
    std::atomic<bool> stop{false};
    std::atomic<std::uint64_t> written{0};

    // GUI thread: positions (k, k, k); k stays exact in float up to 2^24.
    std::thread gui([&] {
        std::uint64_t k = 0;
        while (!stop.load(std::memory_order_relaxed)) {
            k = (k + 1) % (1u << 24);
            const float v = float(k);
            m.setTargetMm({v, v, v});
            m.setButtons(std::uint32_t(k));
            written.store(k, std::memory_order_relaxed);
        }
    });

    // Haptic thread: reads as fast as it can and also writes forces (k, k, k) for the GUI to show.
    std::uint64_t reads = 0, torn = 0, backwards = 0, lastSequence = 0;
    float lastK = 0.0f;
    std::atomic<std::uint64_t> tornForces{0};
    std::thread haptic([&] {
        DeviceSample s;
        while (!stop.load(std::memory_order_relaxed)) {
            if (!m.read(s)) continue;
            ++reads;
            if (!(s.positionMm.x == s.positionMm.y && s.positionMm.y == s.positionMm.z)) ++torn;
            // k wraps at 2^24 only after ~16M writes; treat a big drop as the wrap.
            if (s.positionMm.x < lastK && lastK - s.positionMm.x < 1e6f) ++backwards;
            if (s.sequence < lastSequence) ++backwards;
            lastK = s.positionMm.x;
            lastSequence = s.sequence;
            m.writeForce(s.positionMm);
        }
    });

    // A third thread, like the GUI's display timer, reads the force back.
    std::uint64_t forceReads = 0;
    std::thread display([&] {
        while (!stop.load(std::memory_order_relaxed)) {
            const glm::vec3 f = m.lastForceN();
            if (!(f.x == f.y && f.y == f.z)) tornForces.fetch_add(1, std::memory_order_relaxed);
            ++forceReads;
        }
    });

    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    stop.store(true);
    gui.join();
    haptic.join();
    display.join();

    EXPECT_GT(written.load(), 100u);
    EXPECT_GT(reads, 100u);
    EXPECT_GT(forceReads, 100u);
    EXPECT_EQ(torn, 0u);
    EXPECT_EQ(backwards, 0u);
    EXPECT_EQ(tornForces.load(), 0u);
}

TEST(SeqLock, WideValuesAreNeverTornAcrossThreads) {
    // A value spanning several words, where tearing is likelier than for a vec3.
    struct Wide {
        std::uint64_t a, b, c, d, e;
    };
    SeqLock<Wide> lock(Wide{0, 0, 0, 0, 0});
    std::atomic<bool> stop{false};
    std::thread writer([&] {
        for (std::uint64_t k = 1; !stop.load(std::memory_order_relaxed); ++k) lock.store(Wide{k, k, k, k, k});
    });
    std::uint64_t torn = 0, reads = 0, failedTries = 0;
    // At least 100 ms and 1000 reads (a loaded machine may starve the reader), at most 2 s.
    const auto start = Clock::now();
    while ((Clock::now() < start + std::chrono::milliseconds(100) || reads < 1000) &&
           Clock::now() < start + std::chrono::seconds(2)) {
        Wide w{};
        if (!lock.tryLoad(w, 4)) {
            ++failedTries;  // a bounded reader may give up, but never returns a torn value
            continue;
        }
        ++reads;
        if (!(w.a == w.b && w.b == w.c && w.c == w.d && w.d == w.e)) ++torn;
    }
    stop.store(true);
    writer.join();
    EXPECT_GT(reads, 100u);
    EXPECT_EQ(torn, 0u);
    EXPECT_GE(lock.version(), 1u);
}

}  // namespace
}  // namespace palpate
