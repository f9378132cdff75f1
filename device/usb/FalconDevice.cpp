#include "device/usb/FalconDevice.h"

#include "device/UdevHint.h"
#include "device/usb/FalconFirmware.h"

#include <array>
#include <chrono>
#include <cmath>

namespace palpate {
namespace {

double steadyNowS() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

DeviceSpec falconDeviceSpec() {
    DeviceSpec spec;
    spec.name = "Novint Falcon";
    spec.maxForceN = 8.0;
    spec.maxStiffnessNPerMm = 2.0;
    spec.maxDampingNsPerMm = 0.01;
    spec.workspaceRadiusMm = 50.0;
    spec.actuated = true;
    spec.buttonCount = 4;
    return spec;
}

FalconDevice::FalconDevice(std::shared_ptr<UsbBackend> backend, FalconDeviceDef def)
    : mBackend(std::move(backend)), mDef(std::move(def)), mSpec(falconDeviceSpec()) {}

FalconDevice::~FalconDevice() { close(); }

void FalconDevice::setError(std::string error) {
    std::lock_guard lock(mInfoMutex);
    mError = std::move(error);
}

std::string FalconDevice::lastError() const {
    std::lock_guard lock(mInfoMutex);
    return mError;
}

bool FalconDevice::probeFirmware(UsbTransport& usb) {
    // The firmware answers every command with a report; the boot loader does not. Zero force,
    // homing off: probing must not move anything.
    const auto command = encodeFalconCommand(FalconCommand{});
    FalconReportParser parser;
    std::array<std::uint8_t, 64> in{}, payload{};
    for (int attempt = 0; attempt < 50; ++attempt) {
        int sent = 0, got = 0;
        if (usb.bulkWrite(kFalconEndpointOut, command.data(), int(command.size()), sent, mDef.ioTimeoutMs) == kUsbErrorNoDevice)
            return false;
        const int r = usb.bulkRead(kFalconEndpointIn, in.data(), int(in.size()), got, mDef.ioTimeoutMs);
        if (r == kUsbErrorNoDevice) return false;
        if (r != 0) continue;
        FalconReport report;
        const std::size_t n = stripFtdiStatus(in.data(), std::size_t(got), payload.data());
        if (parser.push(payload.data(), n, report) > 0) return true;
    }
    return false;
}

std::string FalconDevice::connect() {
    std::string error;
    const std::string name = "Falcon " + std::to_string(mDef.index);
    const std::vector<UsbDeviceInfo> found = mBackend->enumerate(kFalconVendorId, kFalconProductId);
    if (mDef.index < 0 || std::size_t(mDef.index) >= found.size()) {
        error = name + ": not found (" + std::to_string(found.size()) + " Falcon" + (found.size() == 1 ? "" : "s") +
                " connected, USB " + formatVidPid(kFalconVendorId, kFalconProductId) + ")";
        return error;
    }
    const UsbDeviceInfo info = found[std::size_t(mDef.index)];
    std::string openError;
    std::unique_ptr<UsbTransport> usb = mBackend->open(info, openError);
    if (!usb) {
        error = name + ": " + openError;
        return error;
    }
    const std::string where = name + " at " + info.node();
    if (const int r = setFalconNormalMode(*usb); r != 0) {
        error = where + ": setting up its FTDI bridge failed (" + usbErrorText(r) + ")";
        return error;
    }
    if (!probeFirmware(*usb)) {
        if (mFirmware.empty()) {
            error = where + ": its firmware is not running and no firmware file was given (falcon:" +
                    std::to_string(mDef.index) +
                    "?firmware=PATH or PALPATE_FALCON_FIRMWARE; docs/devices.md says where to find Novint's file)";
            return error;
        }
        std::string uploadError;
        if (!(uploadError = uploadFalconFirmware(*usb, mFirmware)).empty()) {
            error = where + ": " + uploadError;
            return error;
        }
        mUploads.fetch_add(1, std::memory_order_relaxed);
        if (!probeFirmware(*usb)) {
            error = where + ": the firmware was uploaded but the Falcon does not answer (wrong firmware file?)";
            return error;
        }
    }
    mUsb = std::move(usb);
    std::lock_guard lock(mInfoMutex);
    mInfo = info;
    return {};
}

bool FalconDevice::open() {
    close();
    mStopped.store(false);
    mLost.store(false);
    const std::string name = "Falcon " + std::to_string(mDef.index);
    if (!mBackend) {
        setError(name + ": this build has no USB support (libusb-1.0 was not found at configure time)");
        return false;
    }
    std::string error;
    mFirmware.clear();
    if (!mDef.firmwarePath.empty() && !(error = readFalconFirmwareFile(mDef.firmwarePath, mFirmware)).empty()) {
        setError(name + ": " + error);
        return false;
    }
    mState.store(DeviceState::Opening, std::memory_order_release);
    if (!(error = connect()).empty()) {
        setError(error);
        mState.store(DeviceState::Disconnected, std::memory_order_release);
        return false;
    }
    for (const UsbDeviceInfo& info : mBackend->enumerate(kFalconVendorId, kFalconProductId)) mTracker.arrived(info);
    std::string hotplugError;
    mHotplugHandle = mBackend->addHotplug(
        kFalconVendorId, kFalconProductId, [this](UsbHotplugEvent e, const UsbDeviceInfo& i) { onHotplug(e, i); },
        hotplugError);  // without hotplug, a lost unit is still found by NO_DEVICE and polling
    mForceN.store(glm::vec3(0.0f));
    mState.store(DeviceState::NeedsCalibration, std::memory_order_release);
    setError(name + ": homing - move the grip slowly all the way in, out and around until its LED turns green");
    mIo.start([this] { ioLoop(); });
    return true;
}

void FalconDevice::onHotplug(UsbHotplugEvent event, const UsbDeviceInfo& info) {
    if (event == UsbHotplugEvent::Arrived) {
        if (mTracker.arrived(info)) mIo.wake();  // try to reconnect now rather than at the next poll
        return;
    }
    if (!mTracker.left(info)) return;  // a removal we never saw arrive, or a repeat
    bool ours = false;
    {
        std::lock_guard lock(mInfoMutex);
        ours = mInfo.sameDevice(info);
    }
    if (!ours) return;
    // Zero force at once: the loop sees not-Ready on its next tick, before the I/O thread's next
    // transfer fails.
    if (mState.load() != DeviceState::Fault) mState.store(DeviceState::Disconnected, std::memory_order_release);
    mLost.store(true, std::memory_order_release);
    mIo.wake();
}

void FalconDevice::dropTransport(const std::string& why) {
    mUsb.reset();
    if (mState.load() != DeviceState::Fault) mState.store(DeviceState::Disconnected, std::memory_order_release);
    std::string node;
    {
        std::lock_guard lock(mInfoMutex);
        node = mInfo.node();
    }
    const std::string reason = "Falcon " + std::to_string(mDef.index) + " at " + node + ": " + why + "; force is off";
    {
        std::lock_guard lock(mInfoMutex);
        mLossReason = reason;
    }
    mLosses.fetch_add(1, std::memory_order_relaxed);
    setError(reason + ", waiting for it to come back");
}

std::string FalconDevice::lastLossReason() const {
    std::lock_guard lock(mInfoMutex);
    return mLossReason;
}

void FalconDevice::ioLoop() {
    FalconReportParser parser;
    std::array<std::uint8_t, 64> in{}, payload{};
    glm::dvec3 positionFalconMm(mDef.centreMm);
    bool homed = false;
    int silent = 0;
    std::uint64_t sequence = 0;
    const std::string name = "Falcon " + std::to_string(mDef.index);

    while (!mIo.stopRequested()) {
        if (!mUsb) {
            if (!mIo.sleepFor(std::chrono::milliseconds(mDef.reconnectPeriodMs))) break;
            mLost.store(false);
            std::string error;
            if (!(error = connect()).empty()) {
                // Keep why it was lost in front: the reconnect error alone would hide it.
                setError(lastLossReason() + "; reconnecting: " + error);
                continue;
            }
            mReconnects.fetch_add(1, std::memory_order_relaxed);
            homed = false;  // a replug power-cycles the Falcon: it homes again
            silent = 0;
            parser.reset();
            if (!mStopped.load()) mState.store(DeviceState::NeedsCalibration, std::memory_order_release);
            setError(name + " is back: homing - move the grip through its range until its LED turns green");
            continue;
        }
        if (mLost.exchange(false)) {
            dropTransport("unplugged");
            continue;
        }

        // One exchange: a command out, the report it provokes back.
        FalconCommand command;
        command.homingMode = !homed;
        command.leds = homed ? kFalconLedGreen : kFalconLedRed;
        // No force before homing: until then the encoders' zero is unknown, so any position (and
        // the force computed from it) may be wrong.
        if (homed && !mStopped.load() && mState.load(std::memory_order_acquire) == DeviceState::Ready) {
            glm::vec3 forceN(0.0f);
            if (mForceN.tryLoad(forceN))
                command.motor = falconMotorCommands(positionFalconMm, glm::dvec3(forceN), mDef.forceMap, mDef.geometry);
        }
        const auto packet = encodeFalconCommand(command);
        int sent = 0, got = 0;
        int r = mUsb->bulkWrite(kFalconEndpointOut, packet.data(), int(packet.size()), sent, mDef.ioTimeoutMs);
        if (r == kUsbErrorNoDevice) {
            dropTransport("unplugged (" + usbErrorText(r) + ")");
            continue;
        }
        mLastMotor.store(command.motor);
        r = mUsb->bulkRead(kFalconEndpointIn, in.data(), int(in.size()), got, mDef.ioTimeoutMs);
        if (r == kUsbErrorNoDevice) {
            dropTransport("unplugged (" + usbErrorText(r) + ")");
            continue;
        }
        FalconReport report;
        const std::size_t n = r == 0 ? stripFtdiStatus(in.data(), std::size_t(got), payload.data()) : 0;
        if (n == 0 || parser.push(payload.data(), n, report) == 0) {
            // Timeouts and other transfer errors: tolerate a few, but a unit that stays silent is lost.
            if (++silent > mDef.maxConsecutiveTimeouts) {
                dropTransport("no answer for " + std::to_string(silent) + " exchanges (last: " +
                              (r == 0 ? std::string("no report") : usbErrorText(r)) + ")");
                silent = 0;
            }
            continue;
        }
        silent = 0;
        mReports.fetch_add(1, std::memory_order_relaxed);

        const glm::dvec3 theta(falconEncoderToThetaRad(report.encoder[0], mDef.geometry),
                               falconEncoderToThetaRad(report.encoder[1], mDef.geometry),
                               falconEncoderToThetaRad(report.encoder[2], mDef.geometry));
        glm::dvec3 solved;
        if (falconForwardKinematics(theta, positionFalconMm, solved, mDef.geometry, 1e-6)) positionFalconMm = solved;
        Reading reading;
        reading.sequence = ++sequence;
        reading.steadyS = steadyNowS();
        reading.positionMm = glm::vec3(positionFalconMm - glm::dvec3(mDef.centreMm));
        reading.buttons = report.buttons;
        mReading.store(reading);

        if (!homed && report.allHomed()) {
            homed = true;
            if (!mStopped.load() && !mLost.load() && mState.load() == DeviceState::NeedsCalibration) {
                mState.store(DeviceState::Ready, std::memory_order_release);
                setError("");
            }
        }
    }
    if (mUsb) {  // leave the Falcon quiet: no force, LEDs off
        const auto packet = encodeFalconCommand(FalconCommand{});
        int sent = 0;
        mUsb->bulkWrite(kFalconEndpointOut, packet.data(), int(packet.size()), sent, mDef.ioTimeoutMs);
    }
    mUsb.reset();
}

void FalconDevice::close() {
    if (mHotplugHandle >= 0 && mBackend) mBackend->removeHotplug(mHotplugHandle);
    mHotplugHandle = -1;
    mForceN.store(glm::vec3(0.0f));
    mIo.stop();
    mUsb.reset();
    mState.store(DeviceState::Disconnected, std::memory_order_release);
}

bool FalconDevice::read(DeviceSample& sample) {
    if (mState.load(std::memory_order_acquire) != DeviceState::Ready) return false;
    Reading reading;
    if (mReading.tryLoad(reading) && reading.sequence != 0) {
        mSample.sequence = reading.sequence;
        mSample.positionMm = reading.positionMm;
        mSample.buttons = reading.buttons;
        // Put the reading on the loop's clock, so that the safety filter's age check sees how old
        // it really is.
        mSample.timeS = mTimeS - (steadyNowS() - reading.steadyS);
    }
    if (mSample.sequence == 0) return false;
    sample = mSample;
    return true;
}

void FalconDevice::writeForce(const glm::vec3& forceN) {
    const bool ok = std::isfinite(forceN.x) && std::isfinite(forceN.y) && std::isfinite(forceN.z);
    if (!ok || mState.load(std::memory_order_acquire) != DeviceState::Ready) {
        mForceN.store(glm::vec3(0.0f));
        return;
    }
    mForceN.store(forceN);
}

void FalconDevice::emergencyStop() {
    mStopped.store(true);
    mForceN.store(glm::vec3(0.0f));
    mState.store(DeviceState::Fault, std::memory_order_release);
    setError("Falcon " + std::to_string(mDef.index) + ": emergency stop; reopen the device to continue");
}

}  // namespace palpate
