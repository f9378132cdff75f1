#pragma once
// A virtual tool the GUI steers (the viewport's mouse drag) while the haptic thread reads it.
// The two threads share only a seqlock and atomics: the GUI never takes a lock the haptic thread
// takes (docs/architecture.md), and the haptic thread never waits for the GUI. Not actuated: forces written
// to it are kept only so the GUI can show what would have been rendered.

#include "device/HapticDevice.h"
#include "base/concurrency/SeqLock.h"

#include <glm/vec3.hpp>

#include <atomic>
#include <cstdint>

namespace palpate {

/// Input only (actuated = false); maxForceN is nominal (a Phantom Omni's), so the safety filter
/// shapes the displayed force as it would a real device's.
DeviceSpec mouseDeviceSpec();

/// Threads: setTargetMm and setButtons from one GUI thread; read, writeForce and setTimeS from
/// the haptic thread; state, targetMm, lastForceN and emergencyStop from any thread; open, close,
/// calibrate while no loop runs on the device.
class MouseDevice final : public HapticDevice {
public:
    explicit MouseDevice(DeviceSpec spec = mouseDeviceSpec());

    bool open() override;
    void close() override;
    bool calibrate() override { return state() == DeviceState::Ready; }
    DeviceState state() const override { return mState.load(std::memory_order_acquire); }
    const DeviceSpec& spec() const override { return mSpec; }
    /// Never blocks: if the GUI is mid-write for a whole bounded retry, the previous sample is
    /// returned again (same sequence). A new target read gets a new sequence.
    bool read(DeviceSample& sample) override;
    /// Stored for display only (nothing is rendered); dropped unless Ready.
    void writeForce(const glm::vec3& forceN) override;
    void emergencyStop() override;
    /// Stamps samples with the loop's clock.
    void setTimeS(double timeS) override { mTimeS = timeS; }

    /// GUI thread: moves the virtual tool tip (scene frame). Non-finite positions are rejected
    /// (returns false) so that a bad unprojection never reaches the haptic thread.
    bool setTargetMm(const glm::vec3& positionMm);
    void setButtons(std::uint32_t buttons) { mButtons.store(buttons, std::memory_order_release); }
    /// The last target set (any thread).
    glm::vec3 targetMm() const { return mTargetMm.load(); }
    /// How many targets have been set.
    std::uint64_t targetVersion() const { return mTargetMm.version(); }
    /// The force last written while Ready, for display (any thread).
    glm::vec3 lastForceN() const { return mLastForceN.load(); }

private:
    DeviceSpec mSpec;
    std::atomic<DeviceState> mState{DeviceState::Disconnected};
    SeqLock<glm::vec3> mTargetMm;
    std::atomic<std::uint32_t> mButtons{0};
    SeqLock<glm::vec3> mLastForceN;

    // Haptic thread.
    double mTimeS = 0.0;
    DeviceSample mSample;
};

}  // namespace palpate
