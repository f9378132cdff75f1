#pragma once
// A 3Dconnexion SpaceMouse as a (non-actuated) haptic device: its own I/O thread reads hidraw
// reports through a HidTransport and publishes the raw axes through a seqlock; the haptic tick
// turns them into a tool position (rate or position control) without waiting. Unplugged, it goes
// Disconnected and its thread looks for the unit again until it returns or close() is called.

#include "device/HapticDevice.h"
#include "device/IoThread.h"
#include "base/concurrency/SeqLock.h"
#include "device/hid/HidTransport.h"
#include "device/hid/SpaceMouseControl.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

namespace palpate {

/// Which HID device a URI means: any 3Dconnexion unit (spacemouse:) or one by VID:PID[:SERIAL].
struct HidSelector {
    bool any = true;
    std::uint16_t vendorId = 0;
    std::uint16_t productId = 0;
    std::string serial;  ///< empty: any serial
    bool matches(const HidDeviceInfo& info) const;
};

/// Input only; maxForceN is nominal (as for the mouse) so the safety filter shapes the force that
/// the GUI shows.
DeviceSpec spaceMouseDeviceSpec();

struct SpaceMouseDeviceDef {
    SpaceMouseControlDef control;
    int readTimeoutMs = 20;      ///< I/O thread: how long one read may wait (bounds close() latency)
    int reconnectPeriodMs = 500; ///< while unplugged: how often to look for the unit again
    bool led = true;             ///< switch the LED on while open
};

/// Threads: read/writeForce/setTimeS from the haptic thread; state/lastError/raw/emergencyStop from
/// any thread; open/close while no loop runs on the device.
class SpaceMouseDevice final : public HapticDevice {
public:
    SpaceMouseDevice(std::shared_ptr<HidBackend> backend, HidSelector selector, SpaceMouseDeviceDef def = {});
    ~SpaceMouseDevice() override;

    /// Finds the unit, opens it and starts the I/O thread. False (state Disconnected, lastError
    /// naming the problem) when no unit is found, it cannot be opened (permission: names the udev
    /// rule) or the build has no hidapi.
    bool open() override;
    void close() override;
    bool calibrate() override { return state() == DeviceState::Ready; }
    DeviceState state() const override { return mState.load(std::memory_order_acquire); }
    const DeviceSpec& spec() const override { return mSpec; }
    /// A fresh position every call (rate control integrates over the loop's clock).
    bool read(DeviceSample& sample) override;
    void writeForce(const glm::vec3&) override {}
    void emergencyStop() override;
    void setTimeS(double timeS) override { mTimeS = timeS; }
    std::string lastError() const override;

    /// The latest raw readings (any thread).
    SpaceMouseRaw raw() const { return mRaw.load(); }
    /// Reports decoded / rejected as short since open (any thread).
    std::uint64_t reportsDecoded() const { return mReportsDecoded.load(std::memory_order_relaxed); }
    std::uint64_t shortReports() const { return mShortReports.load(std::memory_order_relaxed); }
    std::uint64_t reconnects() const { return mReconnects.load(std::memory_order_relaxed); }
    /// The device opened (path), for messages and `devices`.
    std::string devicePath() const;

private:
    std::string connect();  // find + open + LED; I/O thread or open()
    void ioLoop();
    void setError(std::string error);

    std::shared_ptr<HidBackend> mBackend;
    HidSelector mSelector;
    SpaceMouseDeviceDef mDef;
    DeviceSpec mSpec;

    std::atomic<DeviceState> mState{DeviceState::Disconnected};
    SeqLock<SpaceMouseRaw> mRaw;
    std::atomic<std::uint64_t> mReportsDecoded{0};
    std::atomic<std::uint64_t> mShortReports{0};
    std::atomic<std::uint64_t> mReconnects{0};
    std::atomic<bool> mResetRequested{false};
    std::atomic<bool> mStopped{false};         ///< emergency stop latched until reopened  ///< the haptic thread should restart from home (reconnect)

    mutable std::mutex mInfoMutex;  // guards mError, mInfo (never taken by the haptic thread)
    std::string mError;
    HidDeviceInfo mInfo;

    std::unique_ptr<HidTransport> mTransport;  // owned by the I/O thread once it runs
    IoThread mIo;

    // Haptic thread.
    SpaceMouseControl mControl;
    DeviceSample mSample;
    double mTimeS = 0.0;
    double mLastTimeS = 0.0;
    bool mHaveTime = false;
};

}  // namespace palpate
