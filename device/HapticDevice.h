#pragma once
// The device interface (docs/devices.md, after CHAI3D's cGenericHapticDevice). Qt-free.
// Backends implement it; the haptic loop reads samples without blocking and writes forces.

#include <glm/vec3.hpp>

#include <cstdint>
#include <string>

namespace palpate {

enum class DeviceState { Disconnected, Opening, NeedsCalibration, Ready, Fault };

const char* deviceStateName(DeviceState state);

/// What a device can do; forces and stiffness sent to it must stay inside these.
struct DeviceSpec {
    std::string name;
    double maxForceN = 3.0;
    double maxStiffnessNPerMm = 1.0;
    double maxDampingNsPerMm = 0.005;
    double workspaceRadiusMm = 80.0;
    bool actuated = false;  ///< false for input-only devices (mouse, SpaceMouse)
    int buttonCount = 0;
};

/// The latest reading of the device.
struct DeviceSample {
    std::uint64_t sequence = 0;    ///< increases with each new reading; a stale sample repeats it
    double timeS = 0.0;            ///< device clock
    glm::vec3 positionMm{0.0f};    ///< tool tip, in the scene's frame
    std::uint32_t buttons = 0;
};

class HapticDevice {
public:
    virtual ~HapticDevice() = default;
    virtual bool open() = 0;
    virtual void close() = 0;
    virtual bool calibrate() = 0;
    virtual DeviceState state() const = 0;
    virtual const DeviceSpec& spec() const = 0;
    /// Latest sample; never blocks. Returns false when no sample is available.
    virtual bool read(DeviceSample& sample) = 0;
    /// Commands a force; never blocks. Input-only devices ignore it.
    virtual void writeForce(const glm::vec3& forceN) = 0;
    /// Zero force at once and stay safe until reopened.
    virtual void emergencyStop() = 0;

    /// Why the device is not Ready (open failed, unplugged, faulted), naming the device and the
    /// problem; "" when there is nothing to tell. Not for the haptic thread (it copies a string).
    virtual std::string lastError() const { return {}; }

    /// The haptic loop's clock, in seconds since the loop started, given once per tick before
    /// read(). Simulated devices are driven by it (so a stepped loop is deterministic) and stamp
    /// their samples with it; hardware backends keep their own clock and ignore it. Haptic thread
    /// only; must not block or allocate.
    virtual void setTimeS(double /*loopTimeS*/) {}

    /// Devices that play a script (simulated trajectories, waypoint paths, a recorded tool) start
    /// it again from its beginning at the next setTimeS. The loop calls it when a recording
    /// attaches, so that a recording starts where the script starts and a scripted run's score
    /// does not depend on how long the GUI took to start recording (docs/haptic-loop.md). Hardware
    /// ignores it. Haptic thread only; must not block or allocate.
    virtual void restartScript() {}

    /// Where the scene wants to be touched: a target point, its outward normal and a tangent (all
    /// in the scene's frame). Devices that script their motion relative to the target (simulated)
    /// use it; others ignore it. Call before the loop starts or from the haptic thread at a tick
    /// boundary; must not allocate.
    virtual void setScene(const glm::vec3& /*targetMm*/, const glm::vec3& /*outwardNormal*/,
                          const glm::vec3& /*tangent*/) {}
};

}  // namespace palpate
