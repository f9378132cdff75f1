#pragma once
// The `replay:FILE` device: a recorded session's tool motion, played as a live device. Where
// RecordingPlayer re-runs a recording tick for tick (stepped, to check it), this device only
// replays what the hand did (positions and buttons on the recording's own clock) into whatever
// scene and parameters run now: an instructor's demonstration, re-felt on another tissue. The
// recording is read whole at open(); the tick reads it without allocating.

#include "device/open/DeviceUri.h"
#include "device/HapticDevice.h"

#include <cstdint>
#include <string>
#include <vector>

namespace palpate {

class RecordedToolDevice final : public HapticDevice {
public:
    explicit RecordedToolDevice(std::string recordingPath) : mPath(std::move(recordingPath)) {}

    /// Reads the recording; false (state Fault, lastError() naming the file and the problem) when
    /// it does not open or holds no sample.
    bool open() override;
    void close() override { mState = DeviceState::Disconnected; }
    bool calibrate() override { return mState == DeviceState::Ready; }
    DeviceState state() const override { return mState; }
    const DeviceSpec& spec() const override { return mSpec; }
    /// The recorded sample at the loop's time since this device's first tick (the last one held
    /// after the end); none before open().
    bool read(DeviceSample& sample) override;
    void writeForce(const glm::vec3& forceN) override { mLastForceN = forceN; }
    void emergencyStop() override { mLastForceN = glm::vec3(0.0f); }
    void setTimeS(double loopTimeS) override { mNowS = loopTimeS; }
    /// The recorded motion plays again from its first sample at the next read.
    void restartScript() override {
        mStartS = -1.0;
        mCursor = 0;
    }
    std::string lastError() const override { return mError; }

    std::size_t sampleCount() const { return mSamples.size(); }
    double durationS() const { return mSamples.empty() ? 0.0 : mSamples.back().timeS; }
    glm::vec3 lastForceN() const { return mLastForceN; }

private:
    struct Sample {
        double timeS;  ///< since the recording's first sample
        glm::vec3 positionMm;
        std::uint32_t buttons;
    };
    std::string mPath;
    std::string mError;
    DeviceState mState = DeviceState::Disconnected;
    DeviceSpec mSpec;
    std::vector<Sample> mSamples;
    std::size_t mCursor = 0;       ///< the sample last returned (time only moves forward)
    double mNowS = 0.0;
    double mStartS = -1.0;         ///< loop time of the first read
    std::uint64_t mSequence = 0;
    glm::vec3 mLastForceN{0.0f};
};

/// Makes `replay:FILE` URIs open a RecordedToolDevice (device/ cannot: it does not know
/// recordings). Idempotent; the CLI and the GUI call it at start.
void registerReplayDeviceScheme();

}  // namespace palpate
