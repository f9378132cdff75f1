#include "device/ScriptedDevice.h"

namespace palpate {

const char* deviceStateName(DeviceState state) {
    switch (state) {
        case DeviceState::Disconnected: return "Disconnected";
        case DeviceState::Opening: return "Opening";
        case DeviceState::NeedsCalibration: return "NeedsCalibration";
        case DeviceState::Ready: return "Ready";
        case DeviceState::Fault: return "Fault";
    }
    return "Unknown";
}

ScriptedDevice::ScriptedDevice(std::vector<glm::vec3> pathMm, double periodS)
    : mPath(std::move(pathMm)), mPeriodS(periodS) {
    mSpec.name = "scripted";
    mSpec.actuated = true;
}

bool ScriptedDevice::open() {
    mState = DeviceState::Ready;
    mNext = 0;
    return true;
}

void ScriptedDevice::close() { mState = DeviceState::Disconnected; }

bool ScriptedDevice::read(DeviceSample& sample) {
    if (mState != DeviceState::Ready || mPath.empty()) return false;
    const std::size_t i = mNext < mPath.size() ? mNext : mPath.size() - 1;
    sample.sequence = mNext + 1;
    sample.timeS = double(mNext) * mPeriodS;
    sample.positionMm = mPath[i];
    sample.buttons = 0;
    if (mNext < mPath.size()) ++mNext;
    return true;
}

void ScriptedDevice::writeForce(const glm::vec3& forceN) {
    mLastForceN = mState == DeviceState::Ready ? forceN : glm::vec3(0.0f);
}

void ScriptedDevice::emergencyStop() {
    mLastForceN = glm::vec3(0.0f);
    mState = DeviceState::Fault;
}

}  // namespace palpate
