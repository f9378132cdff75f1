#include "device/hid/HidPidDevice.h"

#include "device/UdevHint.h"

#include <array>
#include <chrono>
#include <cmath>

namespace palpate {
namespace {

constexpr std::uint8_t kBlockIndex = 1;  // one effect; devices without Block Load answer use 1
constexpr double kPi = 3.14159265358979323846;

}  // namespace

DeviceSpec hidPidDeviceSpec() {
    DeviceSpec spec;
    spec.name = "HID PID joystick (experimental)";
    spec.maxForceN = 2.0;  // nominal: PID magnitudes are fractions of whatever the motor gives
    spec.actuated = true;
    spec.buttonCount = 8;
    spec.workspaceRadiusMm = 40.0;
    return spec;
}

HidPidDevice::HidPidDevice(std::shared_ptr<HidBackend> backend, HidSelector selector, HidPidDeviceDef def)
    : mBackend(std::move(backend)), mSelector(std::move(selector)), mDef(def), mSpec(hidPidDeviceSpec()) {
    mSpec.workspaceRadiusMm = def.workspaceRadiusMm;
}

HidPidDevice::~HidPidDevice() { close(); }

void HidPidDevice::setError(std::string error) {
    std::lock_guard lock(mInfoMutex);
    mError = std::move(error);
}

std::string HidPidDevice::lastError() const {
    std::lock_guard lock(mInfoMutex);
    return mError;
}

bool HidPidDevice::send(const std::vector<std::uint8_t>& report, bool feature) {
    if (report.empty() || !mTransport) return false;
    const int n = feature ? mTransport->sendFeatureReport(report.data(), report.size())
                          : mTransport->write(report.data(), report.size());
    return n >= 0;
}

std::string HidPidDevice::connect() {
    std::string error;
    const std::string what = mSelector.any ? std::string("HID PID joystick")
                                           : "HID PID device " + formatVidPid(mSelector.vendorId, mSelector.productId);
    std::string lastProblem;
    for (const HidDeviceInfo& info : mBackend->enumerate()) {
        if (!mSelector.matches(info)) continue;
        std::vector<std::uint8_t> descriptor;
        std::string descriptorError;
        if (!(descriptorError = mBackend->reportDescriptor(info, descriptor)).empty()) {
            lastProblem = descriptorError;
            continue;
        }
        auto layout = std::make_unique<HidPidLayout>();
        std::string layoutError;
        if (!(layoutError = resolveHidPidLayout(descriptor.data(), descriptor.size(), *layout)).empty()) {
            lastProblem = "HID device " + formatVidPid(info.vendorId, info.productId) + " at " + info.path + ": " + layoutError;
            continue;
        }
        std::string openError;
        auto transport = mBackend->open(info, openError);
        if (!transport) {
            lastProblem = openError;
            continue;
        }
        mTransport = std::move(transport);
        mLayout = std::move(layout);
        // Input axes: Generic Desktop X, Y, Z.
        for (int a = 0; a < 3; ++a) {
            mAxis[a] = nullptr;
            for (const HidField& f : mLayout->descriptor.fields)
                if (f.type == HidReportType::Input && f.isVariable() && f.hasUsage(hidUsage(0x01, std::uint16_t(0x30 + a)))) {
                    mAxis[a] = &f;
                    break;
                }
        }
        {
            std::lock_guard lock(mInfoMutex);
            mInfo = info;
        }
        // Start-up as hid-pidff does it: reset, actuators on, one constant force of zero, started.
        send(buildPidDeviceControl(*mLayout, HidPidControl::DeviceReset));
        send(buildPidDeviceControl(*mLayout, HidPidControl::EnableActuators));  // optional in the spec
        send(buildPidCreateNewEffect(*mLayout), true);
        if (!send(buildPidSetEffect(*mLayout, kBlockIndex, mDef.effectDurationMs, 0.0)) ||
            !send(buildPidSetConstantForce(*mLayout, kBlockIndex, 0.0)) ||
            !send(buildPidEffectOperation(*mLayout, kBlockIndex, true))) {
            error = what + " at " + info.path + ": uploading the effect failed (" + mTransport->lastError() + ")";
            mTransport.reset();
            mLayout.reset();
            return error;
        }
        return {};
    }
    error = what + ": " + (lastProblem.empty() ? "not found ('palpate-cli devices' lists what is connected)" : lastProblem);
    return error;
}

bool HidPidDevice::open() {
    close();
    mStopped.store(false);
    if (!mBackend) {
        setError("HID PID: this build has no HID support (hidapi-hidraw was not found at configure time)");
        return false;
    }
    mState.store(DeviceState::Opening);
    std::string error;
    if (!(error = connect()).empty()) {
        setError(error);
        mState.store(DeviceState::Disconnected);
        return false;
    }
    setError("");
    mForceN.store(glm::vec3(0.0f));
    mState.store(DeviceState::Ready);
    mIo.start([this] { ioLoop(); });
    return true;
}

void HidPidDevice::decodeInput(const std::uint8_t* data, int length, Reading& reading) {
    const bool numbered = mLayout->descriptor.numberedReports;
    const std::uint8_t id = numbered && length > 0 ? data[0] : 0;
    const std::size_t offset = numbered ? 1 : 0;
    for (int a = 0; a < 3; ++a) {
        const HidField* f = mAxis[a];
        if (!f || f->reportId != id) continue;
        std::int64_t v = 0;
        if (!hidGetField(data, std::size_t(length), offset, *f, 0, v)) continue;
        const double span = double(f->logicalMax) - double(f->logicalMin);
        if (span <= 0) continue;
        const double unit = 2.0 * (double(v) - f->logicalMin) / span - 1.0;  // -1..1
        // Stick forward (HID -y) moves the tool up the screen (+y); Z: as the stick's z.
        if (a == 0) reading.positionMm.x = float(unit * mDef.workspaceRadiusMm);
        if (a == 1) reading.positionMm.y = float(-unit * mDef.workspaceRadiusMm);
        if (a == 2) reading.positionMm.z = float(unit * mDef.workspaceRadiusMm);
    }
}

void HidPidDevice::ioLoop() {
    std::array<std::uint8_t, 64> buffer{};
    Reading reading;
    reading.positionMm.z = float(mDef.homeHeightMm);
    std::uint64_t sequence = 0;
    auto lastStart = std::chrono::steady_clock::now();
    bool stopSent = false;
    double lastDirectionDeg = 0.0, lastMagnitude = 0.0;  // as uploaded by connect()
    while (!mIo.stopRequested()) {
        if (!mTransport) {
            if (!mIo.sleepFor(std::chrono::milliseconds(mDef.reconnectPeriodMs))) break;
            std::string error;
            if ((error = connect()).empty()) {
                lastDirectionDeg = 0.0;
                lastMagnitude = 0.0;
                if (!mStopped.load()) mState.store(DeviceState::Ready);
                setError("");
            }
            continue;
        }
        const int n = mTransport->read(buffer.data(), buffer.size(), mDef.refreshPeriodMs);
        if (n < 0) {
            mState.store(mStopped.load() ? DeviceState::Fault : DeviceState::Disconnected);
            setError("HID PID device at " + mInfo.path + ": read failed (" + mTransport->lastError() +
                     "); force is off, waiting for it to come back");
            mTransport.reset();
            continue;
        }
        if (n > 0) decodeInput(buffer.data(), n, reading);
        reading.sequence = ++sequence;  // a heartbeat: the stick reports only on change
        mReading.store(reading);

        if (mStopped.load()) {  // emergency stop: everything off once, then only listen
            if (!stopSent) stopEffects();
            stopSent = true;
            continue;
        }
        glm::vec3 forceN(0.0f);
        if (mStopped.load() || mState.load() != DeviceState::Ready || !mForceN.tryLoad(forceN)) forceN = glm::vec3(0.0f);
        // A joystick pushes in its plane: the force's x/y part, as direction and magnitude. Sent
        // only when they change (USB traffic), and the effect restarted before its finite
        // duration runs out.
        const double fx = forceN.x, fy = forceN.y;
        const double magnitude = std::sqrt(fx * fx + fy * fy) / mSpec.maxForceN;
        const double directionDeg = magnitude > 0.0 ? std::atan2(fx, fy) * 180.0 / kPi : lastDirectionDeg;
        bool ok = true;
        if (std::fabs(directionDeg - lastDirectionDeg) > 0.5) {
            ok = send(buildPidSetEffect(*mLayout, kBlockIndex, mDef.effectDurationMs, directionDeg));
            lastDirectionDeg = directionDeg;
        }
        if (ok && std::fabs(magnitude - lastMagnitude) > 1e-4) {
            ok = send(buildPidSetConstantForce(*mLayout, kBlockIndex, magnitude));
            lastMagnitude = magnitude;
        }
        const auto now = std::chrono::steady_clock::now();
        if (ok && now - lastStart > std::chrono::milliseconds(mDef.effectDurationMs / 2)) {
            ok = send(buildPidEffectOperation(*mLayout, kBlockIndex, true));
            lastStart = now;
        }
        if (!ok) {
            mState.store(mStopped.load() ? DeviceState::Fault : DeviceState::Disconnected);
            setError("HID PID device at " + mInfo.path + ": write failed (" + mTransport->lastError() +
                     "); force is off, waiting for it to come back");
            mTransport.reset();
        }
    }
    stopEffects();
    mTransport.reset();
}

void HidPidDevice::stopEffects() {
    if (!mTransport || !mLayout) return;
    send(buildPidDeviceControl(*mLayout, HidPidControl::StopAllEffects));
    send(buildPidDeviceControl(*mLayout, HidPidControl::DisableActuators));
}

void HidPidDevice::close() {
    mForceN.store(glm::vec3(0.0f));
    mIo.stop();
    stopEffects();  // also when the thread never ran or already lost the device (no-op then)
    mTransport.reset();
    mLayout.reset();
    mState.store(DeviceState::Disconnected);
}

bool HidPidDevice::read(DeviceSample& sample) {
    if (mState.load(std::memory_order_acquire) != DeviceState::Ready) return false;
    Reading reading;
    if (mReading.tryLoad(reading) && reading.sequence != 0) {
        mSample.sequence = reading.sequence;
        mSample.positionMm = reading.positionMm;
        mSample.buttons = reading.buttons;
        mSample.timeS = mTimeS;
    }
    if (mSample.sequence == 0) return false;
    sample = mSample;
    return true;
}

void HidPidDevice::writeForce(const glm::vec3& forceN) {
    const bool ok = std::isfinite(forceN.x) && std::isfinite(forceN.y) && std::isfinite(forceN.z);
    mForceN.store(ok && mState.load(std::memory_order_acquire) == DeviceState::Ready ? forceN : glm::vec3(0.0f));
}

void HidPidDevice::emergencyStop() {
    mStopped.store(true);
    mForceN.store(glm::vec3(0.0f));
    mState.store(DeviceState::Fault);
    setError("HID PID joystick: emergency stop; reopen the device to continue");
}

}  // namespace palpate
