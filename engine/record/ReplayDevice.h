#pragma once
// A device that plays back a recording: each tick it returns exactly what the recorded device
// returned (sample or none, and state), so that a stepped HapticLoop computes the recorded forces
// again. The player points the shared feed at the tick about to run; several ReplayDevices of one
// replay (a recorded device switch swaps in a fresh one) read the same feed. Lives in engine/
// because it depends on the recording; device/ must not depend on engine/.

#include "device/HapticDevice.h"
#include "engine/loop/RecorderSink.h"

namespace palpate {

/// The recorded tick the loop is about to run (set by the player before each step).
struct ReplayFeed {
    const RecordedTick* tick = nullptr;
};

class ReplayDevice final : public HapticDevice {
public:
    /// `feed` must outlive the device. The spec should be the recorded device's.
    ReplayDevice(const ReplayFeed& feed, DeviceSpec spec) : mFeed(feed), mSpec(std::move(spec)) {}

    bool open() override { return true; }
    void close() override {}
    bool calibrate() override { return true; }
    DeviceState state() const override { return mFeed.tick ? mFeed.tick->deviceState : DeviceState::Disconnected; }
    const DeviceSpec& spec() const override { return mSpec; }
    /// The recorded sample, or false where the recorded read() gave none.
    bool read(DeviceSample& sample) override;
    /// Kept for inspection; nothing is rendered.
    void writeForce(const glm::vec3& forceN) override { mLastForceN = forceN; }
    void emergencyStop() override { mLastForceN = glm::vec3(0.0f); }

    glm::vec3 lastForceN() const { return mLastForceN; }

private:
    const ReplayFeed& mFeed;
    DeviceSpec mSpec;
    glm::vec3 mLastForceN{0.0f};
};

}  // namespace palpate
