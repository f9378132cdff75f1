#include "app/gui/ScriptClockDevice.h"

#include "device/DeviceUri.h"
#include "device/SimulatedDevice.h"

#include <cmath>

namespace palpate {

ScriptClockDevice::ScriptClockDevice(std::unique_ptr<HapticDevice> inner, double repeatPeriodS)
    : mInner(std::move(inner)),
      mRepeatPeriodS(std::isfinite(repeatPeriodS) && repeatPeriodS > 0.0 ? repeatPeriodS : 0.0) {}

void ScriptClockDevice::setTimeS(double loopTimeS) {
    if (!std::isfinite(loopTimeS)) return;
    if (!mStarted) {
        mStarted = true;
        mEpochS = loopTimeS;
    }
    double scriptS = loopTimeS - mEpochS;
    if (mRepeatPeriodS > 0.0) scriptS = std::fmod(scriptS, mRepeatPeriodS);
    mLoopToScriptS = loopTimeS - scriptS;
    mInner->setTimeS(scriptS);
}

bool ScriptClockDevice::read(DeviceSample& sample) {
    if (!mInner->read(sample)) return false;
    sample.timeS += mLoopToScriptS;  // back on the loop's clock
    return true;
}

std::unique_ptr<HapticDevice> openScriptedDeviceUri(const std::string& uri, std::string& error,
                                                    double restBetweenRepeatsS) {
    auto device = openDeviceUri(uri, error);
    if (!device) return nullptr;
    const auto* simulated = dynamic_cast<const SimulatedDevice*>(device.get());
    if (!simulated) return device;
    // Waypoint files play once: a jump from their end back to their start could land inside the tissue.
    const bool repeat = simulated->trajectory() != SimTrajectory::Waypoints && std::isfinite(simulated->durationS());
    const double period = repeat ? simulated->durationS() + restBetweenRepeatsS : 0.0;
    return std::make_unique<ScriptClockDevice>(std::move(device), period);
}

}  // namespace palpate
