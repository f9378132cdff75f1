#pragma once
// A scripted (simulated) device on its own clock. The haptic loop hands every device the loop's
// clock, and a simulated device plays its script as a function of that clock: a fresh device
// swapped in after ten seconds would start at the end of its script and sit still. Wrapped in
// this, the script starts when the device starts ticking (Restart, the Device menu), and the
// finite scripts (press, stroke, scan) repeat after a short rest so that the window keeps showing
// palpation. Samples are stamped back on the loop's clock, so the safety filter's age check sees
// the real age. Qt-free; real-time safe like the device it wraps.

#include "device/HapticDevice.h"

#include <memory>

namespace palpate {

class ScriptClockDevice final : public HapticDevice {
public:
    /// `repeatPeriodS` <= 0 or infinite: play once (then rest where the script ends).
    ScriptClockDevice(std::unique_ptr<HapticDevice> inner, double repeatPeriodS);

    bool open() override { return mInner->open(); }
    void close() override { mInner->close(); }
    bool calibrate() override { return mInner->calibrate(); }
    DeviceState state() const override { return mInner->state(); }
    const DeviceSpec& spec() const override { return mInner->spec(); }
    bool read(DeviceSample& sample) override;
    void writeForce(const glm::vec3& forceN) override { mInner->writeForce(forceN); }
    void emergencyStop() override { mInner->emergencyStop(); }
    /// The first time given becomes the script's zero.
    void setTimeS(double loopTimeS) override;
    void setScene(const glm::vec3& targetMm, const glm::vec3& outwardNormal, const glm::vec3& tangent) override {
        mInner->setScene(targetMm, outwardNormal, tangent);
    }

    HapticDevice& inner() { return *mInner; }
    double repeatPeriodS() const { return mRepeatPeriodS; }

private:
    std::unique_ptr<HapticDevice> mInner;
    double mRepeatPeriodS;
    bool mStarted = false;
    double mEpochS = 0.0;       // loop time of the first tick
    double mLoopToScriptS = 0.0;  // loop time minus script time, at the last setTimeS
};

/// Opens the device a URI names (openDeviceUri); simulated scripts come wrapped in a
/// ScriptClockDevice (finite ones repeating `restBetweenRepeatsS` after they end). Null with `error`
/// naming the URI on failure.
std::unique_ptr<HapticDevice> openScriptedDeviceUri(const std::string& uri, std::string& error,
                                                    double restBetweenRepeatsS = 1.0);

}  // namespace palpate
