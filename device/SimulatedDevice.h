#pragma once
// A haptic device without hardware: the tool tip follows a scripted trajectory as a pure function
// of the loop's clock, so a stepped loop is bit-for-bit reproducible and CI needs no device. It
// records the force written to it (tests, CLI) and can fake an unplug or a stalled sample stream,
// the two faults the safety filter and the loop must survive.

#include "base/params/Problem.h"

#include "device/HapticDevice.h"
#include "base/concurrency/SeqLock.h"
#include "device/WaypointFile.h"

#include <glm/vec3.hpp>

#include <atomic>
#include <memory>
#include <string>
#include <vector>

namespace palpate {

enum class SimTrajectory {
    PressHold,  ///< descend from above the target to depthMm, hold, rise again
    Stroke,     ///< press, slide along the tangent and back, rise
    Scan,       ///< a raster of short presses over a square patch around the target
    Sine,       ///< press, then depth oscillates sinusoidally (forever)
    Waypoints,  ///< a user-supplied list of (time, position), linearly interpolated
};

const char* simTrajectoryName(SimTrajectory trajectory);

/// A desktop device like the Phantom Omni (3.3 N peak, ~80 mm reach), actuated, no buttons.
DeviceSpec simulatedDeviceSpec();

/// Shape and timing of the scripted trajectories. Heights are along the outward normal from the
/// target point; depths are below it (positive = into the tissue).
struct SimulatedDeviceDef {
    double approachHeightMm = 2.0;  ///< every trajectory starts (and ends) this far above the target
    double depthMm = 3.0;           ///< deepest point below the target
    double descendTimeS = 1.0;      ///< from the approach height to the depth (and as long back up)
    double holdTimeS = 3.0;         ///< press: time held at depth
    double strokeLengthMm = 10.0;   ///< stroke: distance along the tangent
    double strokeTimeS = 2.0;       ///< stroke: time out (and as long back)
    int scanGridCount = 4;          ///< scan: presses per side of the patch (1..64)
    double scanPatchSizeMm = 10.0;  ///< scan: side of the square patch, centred on the target
    double scanMoveTimeS = 0.25;    ///< scan: hovering from one press to the next
    double scanPressTimeS = 0.3;    ///< scan: going down (and as long up) for each press
    double scanHoldTimeS = 0.2;     ///< scan: time at depth for each press
    double sineAmplitudeMm = 1.0;   ///< sine: depth swings +- this about (depthMm - amplitude)
    double sineFrequencyHz = 2.0;   ///< sine: oscillation frequency
    DeviceSpec spec = simulatedDeviceSpec();
};

/// Returns "" when the definition is usable, else a message naming the field.
Problems validateSimulatedDeviceDef(const SimulatedDeviceDef& def);

/// Threads: setTimeS, read, writeForce and setScene belong to the haptic thread; state, lastForceN,
/// droppedForceWrites, simulateUnplug, replug, simulateStall and emergencyStop may be called from
/// any thread; open, close, calibrate while no loop runs on the device.
class SimulatedDevice final : public HapticDevice {
public:
    /// A scripted trajectory (not Waypoints) around the default scene: target at the origin,
    /// normal +z, tangent +x. Throws std::invalid_argument on an invalid definition.
    explicit SimulatedDevice(SimTrajectory trajectory, SimulatedDeviceDef def = {});
    /// Plays back waypoints given in the scene's frame (setScene does not move them). Throws
    /// std::invalid_argument when the list is empty or not strictly increasing in time.
    explicit SimulatedDevice(std::vector<Waypoint> waypoints, SimulatedDeviceDef def = {});
    /// Loads a waypoint file; null with `error` naming the file and line on failure.
    static std::unique_ptr<SimulatedDevice> fromWaypointFile(const std::string& path, std::string& error,
                                                             SimulatedDeviceDef def = {});

    bool open() override;
    void close() override;
    bool calibrate() override;
    DeviceState state() const override { return mState.load(std::memory_order_acquire); }
    const DeviceSpec& spec() const override { return mDef.spec; }
    bool read(DeviceSample& sample) override;
    void writeForce(const glm::vec3& forceN) override;
    void emergencyStop() override;
    /// Advances the device to the loop's time: the next read() returns the position at timeS with
    /// a new sequence number (unless unplugged or stalled). Non-finite times are ignored.
    void setTimeS(double timeS) override;
    /// The script starts again at the next setTimeS (as after open()).
    void restartScript() override { mEpochSet = false; }
    /// Moves the scripted trajectory to a new target frame. The normal is normalised; the tangent
    /// is made perpendicular to it (any perpendicular if it is parallel). Non-finite input is
    /// ignored. No allocation.
    void setScene(const glm::vec3& targetMm, const glm::vec3& outwardNormal, const glm::vec3& tangent) override;

    /// Where the tool tip is at time t (seconds); a pure function of t and the scene, so equal
    /// times give bit-identical positions. Before the start it is at the start, after the end at
    /// the end. Reads the scene frame: not concurrently with setScene.
    glm::vec3 positionAtMm(double timeS) const;
    /// When the trajectory comes to rest (infinity for Sine), in script time.
    double durationS() const;
    /// Plays finite scripts again `restS` after they end (< 0: once, the default). Call before the
    /// loop uses the device.
    void setRepeat(double restS) { mRepeatRestS = restS; }
    /// Script time for a loop time: the script starts at the first setTimeS after open(), so a
    /// device swapped into a running loop starts from its beginning.
    double scriptTimeS(double loopTimeS) const;
    SimTrajectory trajectory() const { return mTrajectory; }
    const SimulatedDeviceDef& def() const { return mDef; }

    /// The force last written while Ready (zero after an unplug, close or emergency stop).
    glm::vec3 lastForceN() const { return mLastForceN.load(); }
    /// Forces written while not Ready, and so never rendered.
    std::uint64_t droppedForceWrites() const { return mDroppedForceWrites.load(std::memory_order_relaxed); }

    /// Fault injection: the device disconnects at the first setTimeS(t) with t >= atTimeS: state
    /// Disconnected, read() fails, force zeroed, writes dropped.
    void simulateUnplug(double atTimeS);
    /// Fault injection undone: cancels a pending unplug and, if unplugged while open, comes back
    /// Ready (the next setTimeS gives a fresh sample; the loop's safety filter re-arms).
    void replug();
    /// Fault injection: samples stop updating (sequence frozen) for loop times in [fromS, untilS).
    void simulateStall(double fromS, double untilS);

private:
    struct Keyframe {
        double timeS;
        glm::dvec3 pointMm;  ///< (tangent, bitangent, normal) offsets, or scene coordinates for Waypoints
    };

    void buildKeyframes();
    void addKeyframe(double timeS, double tangentMm, double bitangentMm, double heightMm);
    glm::dvec3 keyframePointAt(double timeS) const;

    SimTrajectory mTrajectory;
    SimulatedDeviceDef mDef;
    std::vector<Keyframe> mKeyframes;  ///< built at construction; never resized afterwards

    // Scene frame (haptic thread).
    glm::dvec3 mTargetMm{0.0};
    glm::dvec3 mNormal{0.0, 0.0, 1.0};
    glm::dvec3 mTangent{1.0, 0.0, 0.0};
    glm::dvec3 mBitangent{0.0, 1.0, 0.0};

    // Sample (haptic thread).
    DeviceSample mSample;
    double mLastTimeS = 0.0;
    double mEpochS = 0.0;        // loop time of the first setTimeS since open()
    bool mEpochSet = false;
    double mRepeatRestS = -1.0;

    std::atomic<DeviceState> mState{DeviceState::Disconnected};
    std::atomic<bool> mOpen{false};
    std::atomic<double> mUnplugAtS;
    std::atomic<double> mStallFromS;
    std::atomic<double> mStallUntilS;
    std::atomic<std::uint64_t> mDroppedForceWrites{0};
    SeqLock<glm::vec3> mLastForceN;
};

}  // namespace palpate
