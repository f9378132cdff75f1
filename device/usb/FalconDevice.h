#pragma once
// The Novint Falcon over libusb: 3-axis position in, 3-axis force out, about 1 kHz, on the
// device's own I/O thread. open() finds the unit, uploads Novint's firmware if it is not running
// yet (the user names the file), and starts the thread; the device is NeedsCalibration until the
// firmware reports all three encoders homed (the user moves the grip through its range) and
// renders no force before that. Unplugged (hotplug removal or LIBUSB_ERROR_NO_DEVICE), it goes
// Disconnected at once with zero force, and reconnects when the unit returns (firmware and homing
// again, since a replug power-cycles it).

#include "device/HapticDevice.h"
#include "device/IoThread.h"
#include "base/concurrency/SeqLock.h"
#include "device/usb/FalconKinematics.h"
#include "device/usb/FalconProtocol.h"
#include "device/usb/HotplugTracker.h"
#include "device/usb/UsbTransport.h"

#include <glm/vec3.hpp>

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace palpate {

/// About 9 N peak (Novint's figure is 2 lbf); a 4" cube of workspace.
DeviceSpec falconDeviceSpec();

struct FalconDeviceDef {
    int index = 0;             ///< which Falcon, in enumeration order
    std::string firmwarePath;  ///< Novint's firmware; needed when the unit was just powered up
    /// The Falcon-frame point (mm) that is the scene origin. Falcon frame: x right, y up, z out of
    /// the device toward the user; so pushing the grip in presses along -z, into the tissue.
    glm::vec3 centreMm{0.0f, 0.0f, 110.0f};
    FalconForceMapDef forceMap;
    FalconGeometry geometry;
    int ioTimeoutMs = 10;         ///< one bulk transfer's timeout
    int maxConsecutiveTimeouts = 200;  ///< this many silent exchanges in a row = lost (about 2 s)
    int reconnectPeriodMs = 500;  ///< while unplugged, look again this often (hotplug wakes it sooner)
};

/// Threads: read/writeForce/setTimeS from the haptic thread; state/lastError/emergencyStop/counters
/// from any thread; open/close while no loop runs on the device.
class FalconDevice final : public HapticDevice {
public:
    FalconDevice(std::shared_ptr<UsbBackend> backend, FalconDeviceDef def = {});
    ~FalconDevice() override;

    bool open() override;
    void close() override;
    /// Homing is done by the user moving the grip; this only tells whether it is done.
    bool calibrate() override { return state() == DeviceState::Ready; }
    DeviceState state() const override { return mState.load(std::memory_order_acquire); }
    const DeviceSpec& spec() const override { return mSpec; }
    bool read(DeviceSample& sample) override;
    void writeForce(const glm::vec3& forceN) override;
    void emergencyStop() override;
    void setTimeS(double timeS) override { mTimeS = timeS; }
    std::string lastError() const override;

    std::uint64_t reportsReceived() const { return mReports.load(std::memory_order_relaxed); }
    std::uint64_t reconnects() const { return mReconnects.load(std::memory_order_relaxed); }
    /// Times the unit was lost (unplug, NO_DEVICE, silence), and the last reason, naming it.
    std::uint64_t losses() const { return mLosses.load(std::memory_order_relaxed); }
    std::string lastLossReason() const;
    std::uint64_t firmwareUploads() const { return mUploads.load(std::memory_order_relaxed); }
    /// The last motor commands sent (any thread; tests check "no force before homing").
    std::array<std::int16_t, 3> lastMotorCommand() const { return mLastMotor.load(); }
    /// Commands sent with a non-zero motor value while not homed (must stay 0).
    std::uint64_t forcedWhileNotHomed() const { return mForcedWhileNotHomed.load(std::memory_order_relaxed); }

private:
    struct Reading {
        std::uint64_t sequence = 0;
        double steadyS = 0.0;  ///< steady_clock time of the report
        glm::vec3 positionMm{0.0f};
        std::uint32_t buttons = 0;
    };

    std::string connect();                   // find, open, firmware, normal mode
    bool probeFirmware(UsbTransport& usb);   // does the firmware answer?
    void ioLoop();
    void dropTransport(const std::string& why);
    void setError(std::string error);
    void onHotplug(UsbHotplugEvent event, const UsbDeviceInfo& info);

    std::shared_ptr<UsbBackend> mBackend;
    FalconDeviceDef mDef;
    DeviceSpec mSpec;
    std::vector<std::uint8_t> mFirmware;  // read at open(); kept for reconnects

    std::atomic<DeviceState> mState{DeviceState::Disconnected};
    std::atomic<bool> mStopped{false};  // emergency stop latched until reopened
    std::atomic<bool> mLost{false};     // hotplug said our unit left
    SeqLock<Reading> mReading;
    SeqLock<glm::vec3> mForceN;
    SeqLock<std::array<std::int16_t, 3>> mLastMotor;
    std::atomic<std::uint64_t> mReports{0};
    std::atomic<std::uint64_t> mReconnects{0};
    std::atomic<std::uint64_t> mLosses{0};
    std::atomic<std::uint64_t> mUploads{0};
    std::atomic<std::uint64_t> mForcedWhileNotHomed{0};

    mutable std::mutex mInfoMutex;  // mError, mInfo; never taken by the haptic thread
    std::string mError;
    UsbDeviceInfo mInfo;
    HotplugTracker mTracker;
    int mHotplugHandle = -1;

    std::unique_ptr<UsbTransport> mUsb;  // the I/O thread's once it runs
    std::string mLossReason;             // why the unit was last lost (guarded by mInfoMutex)
    IoThread mIo;

    // Haptic thread.
    DeviceSample mSample;
    double mTimeS = 0.0;
};

}  // namespace palpate
