#pragma once
// A simulated device that replays a list of tool-tip positions, one per read, then holds the last.
// Deterministic; used by the headless demo and tests. (Scripted trajectories by URI come with the
// haptic-loop work.)

#include "device/HapticDevice.h"

#include <vector>

namespace palpate {

class ScriptedDevice final : public HapticDevice {
public:
    explicit ScriptedDevice(std::vector<glm::vec3> pathMm, double periodS = 0.001);

    bool open() override;
    void close() override;
    bool calibrate() override { return true; }
    DeviceState state() const override { return mState; }
    const DeviceSpec& spec() const override { return mSpec; }
    bool read(DeviceSample& sample) override;
    void writeForce(const glm::vec3& forceN) override;
    void emergencyStop() override;

    bool finished() const { return mNext >= mPath.size(); }
    const glm::vec3& lastForceN() const { return mLastForceN; }

private:
    std::vector<glm::vec3> mPath;
    double mPeriodS;
    std::size_t mNext = 0;
    DeviceState mState = DeviceState::Disconnected;
    DeviceSpec mSpec;
    glm::vec3 mLastForceN{0.0f};
};

}  // namespace palpate
