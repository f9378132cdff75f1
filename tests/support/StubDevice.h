#pragma once
// A device that does nothing on its own: Ready, no samples, forces dropped. A test's fake device
// derives from it and overrides only what its scenario needs (a slow open, a stalled read, a
// destructor that reports).

#include "device/HapticDevice.h"

namespace palpate::test {

class StubDevice : public HapticDevice {
public:
    bool open() override {
        mState = DeviceState::Ready;
        return true;
    }
    void close() override { mState = DeviceState::Disconnected; }
    bool calibrate() override { return true; }
    DeviceState state() const override { return mState; }
    const DeviceSpec& spec() const override { return mSpec; }
    bool read(DeviceSample&) override { return false; }
    void writeForce(const glm::vec3&) override {}
    void emergencyStop() override { mState = DeviceState::Fault; }

protected:
    DeviceState mState = DeviceState::Ready;
    DeviceSpec mSpec;
};

}  // namespace palpate::test
