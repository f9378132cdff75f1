#pragma once
// The last gate before a force reaches a device (docs/devices.md). Every force command of every device
// goes through one SafetyFilter: whatever the deformation model, the parameters or the timing did,
// the device never gets a NaN, never more than its rated force, no jolt at start or reconnect, and
// no force computed from a position the device no longer has.

#include "base/params/Problem.h"

#include "device/HapticDevice.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <string>

namespace palpate {

/// Tuning of the safety rules; the defaults suit a 1 kHz loop and a desktop device.
struct SafetyFilterDef {
    /// Forces stay off (after start, re-arm or a watchdog trip) until the commanded force is below
    /// this fraction of the device's maxForceN: switching on while the user is deep in the tissue
    /// would kick their hand.
    double holdOffThresholdFraction = 0.05;
    /// Then the output scales linearly from 0 to 1 over this time, so even a small force comes on
    /// smoothly. <= 0 switches on at once.
    double rampTimeS = 0.1;
    /// Stale sample: the sample sequence has not changed for more than this many ticks ...
    int staleSampleMaxTicks = 20;
    /// ... or for longer than this (loop clock), whichever trips first.
    double staleSampleTimeoutS = 0.02;
    /// Also stale when nowS - sampleTimeS exceeds this. Only meaningful when the sample is stamped
    /// on the loop's clock (simulated devices, or backends whose I/O thread stamps samples with
    /// it); <= 0 disables the age check for devices with their own clock.
    double maxSampleAgeS = 0.02;
    /// After a stale-sample trip, go through hold-off and ramp again: the tool may have moved far
    /// while the sample was frozen, so the first fresh force can be large.
    bool rearmAfterStale = true;
    /// A late tick is not a fault: it renders the force it computed (from a fresh sample). Only
    /// after more than this many late ticks in a row (the loop is not keeping up at all) ...
    int maxConsecutiveOverruns = 50;
    /// ... does the force fade out, linearly over this time (never a step); once ticks are on
    /// time again it ramps back in from where the fade left it (docs/devices.md).
    double overrunFadeTimeS = 0.05;
};

/// Returns "" when the definition is usable, else a message naming the field.
Problems validateSafetyFilterDef(const SafetyFilterDef& def);

/// What the haptic loop knows about this tick, besides the force.
struct SafetyInput {
    double nowS = 0.0;                 ///< loop clock (monotonic, seconds)
    std::uint64_t sampleSequence = 0;  ///< sequence of the sample the force was computed from; when
                                       ///< read() gave nothing, pass the last one (it then goes stale)
    double sampleTimeS = 0.0;          ///< that sample's time stamp (see maxSampleAgeS)
    bool tickOverran = false;          ///< the tick missed its deadline: its force is late
    bool deviceReady = true;           ///< device state is Ready; false zeroes force, and the return to
                                       ///< true re-arms (reconnect)
};

/// Where the filter is in its start-up sequence.
enum class SafetyPhase { HoldOff, RampIn, Armed };

const char* safetyPhaseName(SafetyPhase phase);

/// Why the last output differs from the command; bits of SafetyFilter::lastFlags().
enum SafetyFlag : std::uint32_t {
    kSafetyNonFinite = 1u << 0,      ///< NaN/Inf command replaced by zero
    kSafetyClamped = 1u << 1,        ///< magnitude clamped to maxForceN
    kSafetyHeldOff = 1u << 2,        ///< zero: waiting for a small command
    kSafetyRamping = 1u << 3,        ///< scaled down by the ramp
    kSafetyStaleSample = 1u << 4,    ///< zero: sample stale
    kSafetyOverrun = 1u << 5,        ///< the tick was late; its fresh force is kept
    kSafetyOverrunFade = 1u << 8,    ///< scaled down: too many late ticks in a row
    kSafetyNotReady = 1u << 6,       ///< zero: device not Ready
    kSafetyBadTime = 1u << 7,        ///< zero: nowS not finite
};

/// Counters over the filter's life (per tick, each rule that acted counts once).
struct SafetyStats {
    std::uint64_t ticks = 0;
    std::uint64_t nonFiniteCommands = 0;
    std::uint64_t clampedCommands = 0;
    std::uint64_t heldOffTicks = 0;
    std::uint64_t rampTicks = 0;
    std::uint64_t staleSampleTicks = 0;
    std::uint64_t overrunTicks = 0;      ///< late ticks (their force kept)
    std::uint64_t overrunFadeTicks = 0;  ///< ticks scaled down by the overrun fade
    std::uint64_t notReadyTicks = 0;
    std::uint64_t badTimeTicks = 0;
    std::uint64_t rearms = 0;        ///< explicit, reconnect or after a stale trip
};

class SafetyFilter {
public:
    /// Copies what it needs from the spec. A device with maxForceN <= 0 (or not finite) gets zero.
    explicit SafetyFilter(const DeviceSpec& spec, SafetyFilterDef def = {});

    /// The force to write to the device for this tick. Real-time: no allocation, no locks, no I/O,
    /// no exceptions. Call once per tick, from the haptic thread only.
    glm::vec3 filter(const glm::vec3& commandedForceN, const SafetyInput& in);

    /// Back to hold-off: forces stay off until the command is small, then ramp in. Call on start,
    /// reconnect, device switch, or after an emergency stop is cleared.
    void rearm();

    SafetyPhase phase() const { return mPhase; }
    /// SafetyFlag bits of the last filter() call.
    std::uint32_t lastFlags() const { return mLastFlags; }
    /// Not synchronised: read it on the haptic thread (or after it stopped) and publish a copy.
    SafetyStats stats() const { return mStats; }
    double maxForceN() const { return mMaxForceN; }
    const SafetyFilterDef& def() const { return mDef; }

private:
    bool sampleIsStale(const SafetyInput& in);

    SafetyFilterDef mDef;
    double mMaxForceN = 0.0;
    SafetyPhase mPhase = SafetyPhase::HoldOff;
    double mRampStartS = 0.0;
    bool mHaveSequence = false;
    std::uint64_t mLastSequence = 0;
    std::uint64_t mTicksSinceSequenceChange = 0;
    double mSequenceChangeS = 0.0;
    bool mWasReady = true;
    bool mWasStale = false;
    int mConsecutiveOverruns = 0;
    double mFadeStartS = 0.0;     ///< when the overrun fade began
    float mFadeScale = 1.0f;      ///< what the fade left of the force (1: no fade)
    std::uint32_t mLastFlags = 0;
    SafetyStats mStats;
};

}  // namespace palpate
