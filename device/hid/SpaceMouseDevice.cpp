#include "device/hid/SpaceMouseDevice.h"

#include "device/UdevHint.h"

#include <array>
#include <chrono>
#include <utility>

namespace palpate {

bool HidSelector::matches(const HidDeviceInfo& info) const {
    if (any) return true;
    if (info.vendorId != vendorId || info.productId != productId) return false;
    return serial.empty() || info.serial == serial;
}

DeviceSpec spaceMouseDeviceSpec() {
    DeviceSpec spec;
    spec.name = "SpaceMouse";
    spec.maxForceN = 3.3;
    spec.actuated = false;
    spec.buttonCount = 2;
    spec.workspaceRadiusMm = 80.0;
    return spec;
}

SpaceMouseDevice::SpaceMouseDevice(std::shared_ptr<HidBackend> backend, HidSelector selector, SpaceMouseDeviceDef def)
    : mBackend(std::move(backend)),
      mSelector(std::move(selector)),
      mDef(def),
      mSpec(spaceMouseDeviceSpec()),
      mControl(def.control) {
    mSpec.workspaceRadiusMm = def.control.workspaceRadiusMm;
}

SpaceMouseDevice::~SpaceMouseDevice() { close(); }

void SpaceMouseDevice::setError(std::string error) {
    std::lock_guard lock(mInfoMutex);
    mError = std::move(error);
}

std::string SpaceMouseDevice::lastError() const {
    std::lock_guard lock(mInfoMutex);
    return mError;
}

std::string SpaceMouseDevice::devicePath() const {
    std::lock_guard lock(mInfoMutex);
    return mInfo.path;
}

std::string SpaceMouseDevice::connect() {
    std::string error;
    error.clear();
    const std::string what = mSelector.any ? std::string("SpaceMouse")
                                           : "SpaceMouse " + formatVidPid(mSelector.vendorId, mSelector.productId) +
                                                 (mSelector.serial.empty() ? "" : " serial " + mSelector.serial);
    std::vector<HidDeviceInfo> found;
    for (const HidDeviceInfo& info : mBackend->enumerate()) {
        if (!mSelector.matches(info)) continue;
        if (mSelector.any && !isSpaceMouseVidPid(info.vendorId, info.productId)) continue;
        // A unit exposes several interfaces (and hidapi lists every top-level collection); the
        // 6-DoF one is Generic Desktop / Multi-axis Controller. Usage 0 means the backend could not
        // tell (older hidraw kernels): accept it rather than miss the device.
        if (info.usagePage != 0 &&
            !(info.usagePage == kHidUsagePageGenericDesktop && info.usage == kHidUsageMultiAxisController))
            continue;
        found.push_back(info);
    }
    if (found.empty()) {
        error = what + ": not found (is it plugged in? 'palpate-cli devices' lists what is connected)";
        return error;
    }
    std::string openError;
    for (const HidDeviceInfo& info : found) {
        auto transport = mBackend->open(info, openError);
        if (!transport) continue;
        if (mDef.led) {
            const auto led = encodeSpaceMouseLed(true);
            transport->write(led.data(), led.size());  // cosmetic: a unit without the LED report still works
        }
        mTransport = std::move(transport);
        std::lock_guard lock(mInfoMutex);
        mInfo = info;
        return {};
    }
    error = what + ": " + openError;
    return error;
}

bool SpaceMouseDevice::open() {
    close();
    if (!mBackend) {
        setError("SpaceMouse: this build has no HID support (hidapi-hidraw was not found at configure time)");
        return false;
    }
    mState.store(DeviceState::Opening, std::memory_order_release);
    std::string error;
    if (!(error = connect()).empty()) {
        setError(error);
        mState.store(DeviceState::Disconnected, std::memory_order_release);
        return false;
    }
    setError("");
    mStopped.store(false);
    mRaw.store(SpaceMouseRaw{});
    mReportsDecoded.store(0);
    mShortReports.store(0);
    mResetRequested.store(true, std::memory_order_release);
    mState.store(DeviceState::Ready, std::memory_order_release);
    mIo.start([this] { ioLoop(); });
    return true;
}

void SpaceMouseDevice::ioLoop() {
    std::array<std::uint8_t, 64> buffer{};
    SpaceMouseRaw raw{};
    while (!mIo.stopRequested()) {
        if (!mTransport) {
            // Unplugged: look for the unit again, at a gentle pace.
            if (!mIo.sleepFor(std::chrono::milliseconds(mDef.reconnectPeriodMs))) break;
            std::string error;
            if ((error = connect()).empty()) {
                raw = SpaceMouseRaw{};
                mRaw.store(raw);
                mReconnects.fetch_add(1, std::memory_order_relaxed);
                mResetRequested.store(true, std::memory_order_release);
                setError("");
                if (!mStopped.load()) mState.store(DeviceState::Ready, std::memory_order_release);
            }
            continue;
        }
        const int n = mTransport->read(buffer.data(), buffer.size(), mDef.readTimeoutMs);
        if (n == kHidReadTimeout) continue;
        if (n < 0) {
            // hidapi's -1: the unit is gone (or the node broke). Stop at once, then look for it again.
            if (!mStopped.load()) mState.store(DeviceState::Disconnected, std::memory_order_release);
            const std::string why = mTransport->lastError();
            mTransport.reset();
            setError("SpaceMouse at " + devicePath() + ": read failed (" + (why.empty() ? "unplugged?" : why) +
                     "); waiting for it to come back");
            raw = SpaceMouseRaw{};  // a lost unit must not leave the tool drifting at the last rate
            mRaw.store(raw);
            continue;
        }
        const SpaceMouseReport kind = decodeSpaceMouseReport(buffer.data(), std::size_t(n), raw);
        if (kind == SpaceMouseReport::ShortReport || kind == SpaceMouseReport::Empty) {
            mShortReports.fetch_add(1, std::memory_order_relaxed);
            continue;
        }
        if (kind == SpaceMouseReport::Ignored) continue;
        mRaw.store(raw);
        mReportsDecoded.fetch_add(1, std::memory_order_relaxed);
    }
    if (mTransport && mDef.led) {
        const auto led = encodeSpaceMouseLed(false);
        mTransport->write(led.data(), led.size());
    }
    mTransport.reset();
}

void SpaceMouseDevice::close() {
    mIo.stop();
    mTransport.reset();
    mState.store(DeviceState::Disconnected, std::memory_order_release);
}

void SpaceMouseDevice::emergencyStop() {
    // Nothing to switch off (input only); stay out of Ready (until reopened) so that the loop
    // renders nothing.
    mStopped.store(true);
    mState.store(DeviceState::Fault, std::memory_order_release);
}

bool SpaceMouseDevice::read(DeviceSample& sample) {
    if (mState.load(std::memory_order_acquire) != DeviceState::Ready) return false;
    if (mResetRequested.exchange(false, std::memory_order_acq_rel)) {
        mControl.reset();
        mHaveTime = false;
    }
    SpaceMouseRaw raw;
    if (!mRaw.tryLoad(raw)) {  // the I/O thread is mid-write: repeat the last sample (it goes stale)
        sample = mSample;
        return true;
    }
    const double dtS = mHaveTime ? mTimeS - mLastTimeS : 0.0;
    mLastTimeS = mTimeS;
    mHaveTime = true;
    ++mSample.sequence;
    mSample.timeS = mTimeS;
    mSample.positionMm = mControl.update(raw, dtS);
    mSample.buttons = raw.buttons;
    sample = mSample;
    return true;
}

}  // namespace palpate
