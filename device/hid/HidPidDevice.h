#pragma once
// EXPERIMENTAL: a HID PID force-feedback joystick as a 2-D haptic device. The stick's X/Y (and Z,
// if it has one) steer the tool; the force's x/y part becomes one constant-force effect (direction
// and magnitude), uploaded with a finite duration and refreshed by the device's I/O thread, so
// that a stalled host lets the effect run out instead of pushing forever. On close (and emergency
// stop): Stop All Effects, Disable Actuators. Reports are built from the device's own descriptor
// (read from sysfs). Not tested on hardware; docs/devices.md says what is known.

#include "device/HapticDevice.h"
#include "device/IoThread.h"
#include "base/concurrency/SeqLock.h"
#include "device/hid/HidPidCodec.h"
#include "device/hid/HidTransport.h"
#include "device/hid/SpaceMouseDevice.h"

#include <atomic>
#include <memory>
#include <mutex>
#include <string>

namespace palpate {

DeviceSpec hidPidDeviceSpec();

struct HidPidDeviceDef {
    std::uint32_t effectDurationMs = 100;  ///< each upload lasts this long unless refreshed
    int refreshPeriodMs = 5;               ///< I/O period: magnitude update and input poll
    double workspaceRadiusMm = 40.0;       ///< full stick deflection moves the tool this far
    double homeHeightMm = 5.0;             ///< z when the stick has no Z axis
    int reconnectPeriodMs = 500;
};

class HidPidDevice final : public HapticDevice {
public:
    HidPidDevice(std::shared_ptr<HidBackend> backend, HidSelector selector, HidPidDeviceDef def = {});
    ~HidPidDevice() override;

    bool open() override;
    void close() override;
    bool calibrate() override { return state() == DeviceState::Ready; }
    DeviceState state() const override { return mState.load(std::memory_order_acquire); }
    const DeviceSpec& spec() const override { return mSpec; }
    bool read(DeviceSample& sample) override;
    void writeForce(const glm::vec3& forceN) override;
    void emergencyStop() override;
    void setTimeS(double timeS) override { mTimeS = timeS; }
    std::string lastError() const override;

private:
    struct Reading {
        std::uint64_t sequence = 0;
        glm::vec3 positionMm{0.0f};
        std::uint32_t buttons = 0;
    };
    std::string connect();
    void ioLoop();
    bool send(const std::vector<std::uint8_t>& report, bool feature = false);
    void stopEffects();
    void decodeInput(const std::uint8_t* data, int length, Reading& reading);
    void setError(std::string error);

    std::shared_ptr<HidBackend> mBackend;
    HidSelector mSelector;
    HidPidDeviceDef mDef;
    DeviceSpec mSpec;

    std::unique_ptr<HidPidLayout> mLayout;  // I/O thread (and open/close)
    std::unique_ptr<HidTransport> mTransport;
    const HidField* mAxis[3] = {nullptr, nullptr, nullptr};
    IoThread mIo;

    std::atomic<DeviceState> mState{DeviceState::Disconnected};
    std::atomic<bool> mStopped{false};
    SeqLock<Reading> mReading;
    SeqLock<glm::vec3> mForceN;
    mutable std::mutex mInfoMutex;
    std::string mError;
    HidDeviceInfo mInfo;

    DeviceSample mSample;  // haptic thread
    double mTimeS = 0.0;
};

}  // namespace palpate
