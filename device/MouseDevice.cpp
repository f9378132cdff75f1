#include "device/MouseDevice.h"

#include <cmath>
#include <utility>

namespace palpate {

DeviceSpec mouseDeviceSpec() {
    DeviceSpec spec;
    spec.name = "mouse";
    spec.maxForceN = 3.3;
    spec.actuated = false;
    spec.buttonCount = 3;
    return spec;
}

MouseDevice::MouseDevice(DeviceSpec spec) : mSpec(std::move(spec)) { mSpec.actuated = false; }

bool MouseDevice::open() {
    mState.store(DeviceState::Ready, std::memory_order_release);
    return true;
}

void MouseDevice::close() {
    mLastForceN.store(glm::vec3(0.0f));
    mState.store(DeviceState::Disconnected, std::memory_order_release);
}

bool MouseDevice::setTargetMm(const glm::vec3& positionMm) {
    if (!std::isfinite(positionMm.x) || !std::isfinite(positionMm.y) || !std::isfinite(positionMm.z)) return false;
    mTargetMm.store(positionMm);
    return true;
}

bool MouseDevice::read(DeviceSample& sample) {
    if (mState.load(std::memory_order_acquire) != DeviceState::Ready) return false;
    glm::vec3 positionMm;
    // Each read is a fresh reading of the target (the GUI need not move for the sample to be
    // current); only a read that lost to the writer every time repeats the previous sample.
    if (mTargetMm.tryLoad(positionMm)) {
        ++mSample.sequence;
        mSample.timeS = mTimeS;
        mSample.positionMm = positionMm;
        mSample.buttons = mButtons.load(std::memory_order_acquire);
    }
    sample = mSample;
    return true;
}

void MouseDevice::writeForce(const glm::vec3& forceN) {
    if (mState.load(std::memory_order_acquire) != DeviceState::Ready) return;
    mLastForceN.store(forceN);
}

void MouseDevice::emergencyStop() {
    mState.store(DeviceState::Fault, std::memory_order_release);
    mLastForceN.store(glm::vec3(0.0f));
}

}  // namespace palpate
