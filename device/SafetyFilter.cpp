#include "device/SafetyFilter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace palpate {

Problems validateSafetyFilterDef(const SafetyFilterDef& def) {
    if (!(def.holdOffThresholdFraction > 0.0 && def.holdOffThresholdFraction <= 1.0))
        return oneProblem("holdOffThresholdFraction", "SafetyFilterDef.holdOffThresholdFraction must be in (0, 1]");
    if (!std::isfinite(def.rampTimeS) || def.rampTimeS < 0.0)
        return oneProblem("rampTimeS", "SafetyFilterDef.rampTimeS must be finite and >= 0");
    if (def.staleSampleMaxTicks < 0)
        return oneProblem("staleSampleMaxTicks", "SafetyFilterDef.staleSampleMaxTicks must be >= 0");
    if (!(def.staleSampleTimeoutS > 0.0) || !std::isfinite(def.staleSampleTimeoutS))
        return oneProblem("staleSampleTimeoutS", "SafetyFilterDef.staleSampleTimeoutS must be finite and > 0");
    if (!std::isfinite(def.maxSampleAgeS))
        return oneProblem("maxSampleAgeS",
                          "SafetyFilterDef.maxSampleAgeS must be finite (<= 0 disables the age check)");
    if (def.maxConsecutiveOverruns < 0)
        return oneProblem("maxConsecutiveOverruns", "SafetyFilterDef.maxConsecutiveOverruns must be >= 0");
    if (!(def.overrunFadeTimeS > 0.0) || !std::isfinite(def.overrunFadeTimeS))
        return oneProblem("overrunFadeTimeS", "SafetyFilterDef.overrunFadeTimeS must be finite and > 0");
    return {};
}

const char* safetyPhaseName(SafetyPhase phase) {
    switch (phase) {
        case SafetyPhase::HoldOff: return "HoldOff";
        case SafetyPhase::RampIn: return "RampIn";
        case SafetyPhase::Armed: return "Armed";
    }
    return "Unknown";
}

SafetyFilter::SafetyFilter(const DeviceSpec& spec, SafetyFilterDef def) : mDef(def) {
    const std::string problem = joinedMessages(validateSafetyFilterDef(def));
    if (!problem.empty()) throw std::invalid_argument(problem);
    // A spec we cannot trust renders nothing rather than something unbounded.
    mMaxForceN = std::isfinite(spec.maxForceN) && spec.maxForceN > 0.0 ? spec.maxForceN : 0.0;
}

void SafetyFilter::rearm() {
    mPhase = SafetyPhase::HoldOff;
    // Forget the sample history too: after a reconnect the device may restart its sequence.
    mHaveSequence = false;
    mTicksSinceSequenceChange = 0;
    mWasStale = false;
    mConsecutiveOverruns = 0;
    mFadeScale = 1.0f;
    ++mStats.rearms;
}

bool SafetyFilter::sampleIsStale(const SafetyInput& in) {
    if (!mHaveSequence || in.sampleSequence != mLastSequence) {
        mHaveSequence = true;
        mLastSequence = in.sampleSequence;
        mTicksSinceSequenceChange = 0;
        mSequenceChangeS = in.nowS;
    } else {
        ++mTicksSinceSequenceChange;
    }
    if (mTicksSinceSequenceChange > std::uint64_t(mDef.staleSampleMaxTicks)) return true;
    if (in.nowS - mSequenceChangeS > mDef.staleSampleTimeoutS) return true;
    // Written so that a NaN sample time counts as stale.
    if (mDef.maxSampleAgeS > 0.0 && !(in.nowS - in.sampleTimeS <= mDef.maxSampleAgeS)) return true;
    return false;
}

glm::vec3 SafetyFilter::filter(const glm::vec3& commandedForceN, const SafetyInput& in) {
    const glm::vec3 zero(0.0f);
    ++mStats.ticks;
    std::uint32_t flags = 0;

    // 1. NaN/Inf: nothing sensible can be rendered from it; zero, and count so that it shows.
    glm::vec3 forceN = commandedForceN;
    if (!std::isfinite(forceN.x) || !std::isfinite(forceN.y) || !std::isfinite(forceN.z)) {
        forceN = zero;
        flags |= kSafetyNonFinite;
        ++mStats.nonFiniteCommands;
    }

    // 2. Clamp the magnitude, keeping the direction: scaling every component by one factor keeps
    //    the force pointing out of the tissue (clamping per axis would bend it). Computed in double
    //    so that huge finite components do not overflow the squared length.
    const double fx = forceN.x, fy = forceN.y, fz = forceN.z;
    double magnitudeN = std::sqrt(fx * fx + fy * fy + fz * fz);
    if (magnitudeN > mMaxForceN) {
        flags |= kSafetyClamped;
        ++mStats.clampedCommands;
        if (mMaxForceN <= 0.0) {
            forceN = zero;
        } else {
            double scale = mMaxForceN / magnitudeN;
            // Rounding to float may land a hair above the limit; shrink by ulps until it does not.
            for (int i = 0; i < 4; ++i) {
                forceN = glm::vec3(float(fx * scale), float(fy * scale), float(fz * scale));
                const double x = forceN.x, y = forceN.y, z = forceN.z;
                if (std::sqrt(x * x + y * y + z * z) <= mMaxForceN) break;
                scale *= 1.0 - 1e-7;
            }
        }
        const double x = forceN.x, y = forceN.y, z = forceN.z;
        magnitudeN = std::sqrt(x * x + y * y + z * z);
    }

    // 3. Device not Ready (unplugged, faulted, closed): zero, and re-arm when it comes back, since
    //    the user's hand may be anywhere by then.
    if (!in.deviceReady) {
        mWasReady = false;
        mLastFlags = flags | kSafetyNotReady;
        ++mStats.notReadyTicks;
        return zero;
    }
    if (!mWasReady) {
        mWasReady = true;
        rearm();
    }

    // 4. Without a valid clock neither the watchdog nor the ramp can be trusted.
    if (!std::isfinite(in.nowS)) {
        mLastFlags = flags | kSafetyBadTime;
        ++mStats.badTimeTicks;
        return zero;
    }

    // 5. Watchdog, stale sample: the force was computed from where the tool was, not where it is.
    //    Tracked every tick (also during hold-off) so that a trip is seen within one tick.
    if (sampleIsStale(in)) {
        mWasStale = true;
        mLastFlags = flags | kSafetyStaleSample;
        ++mStats.staleSampleTicks;
        return zero;
    }
    if (mWasStale) {
        mWasStale = false;
        if (mDef.rearmAfterStale) {
            mPhase = SafetyPhase::HoldOff;  // keep the fresh sample history; only restart the ramp
            ++mStats.rearms;
        }
    }

    // 6. Watchdog, overrun. A late tick still computed its force from a fresh sample (rule 5):
    //    rendering it is right, and zeroing it would be a 1.7 N -> 0 -> 1.7 N jerk within 2 ms
    //    that a loaded desktop turns into a buzz. Only a loop that misses more than
    //    maxConsecutiveOverruns deadlines in a row fades the force out, at a bounded rate; when it
    //    keeps time again the ramp brings the force back from where the fade left it.
    if (in.tickOverran) {
        flags |= kSafetyOverrun;
        ++mStats.overrunTicks;
        if (++mConsecutiveOverruns == mDef.maxConsecutiveOverruns + 1) mFadeStartS = in.nowS;
        if (mConsecutiveOverruns > mDef.maxConsecutiveOverruns) {
            const double faded = 1.0 - (in.nowS - mFadeStartS) / mDef.overrunFadeTimeS;
            mFadeScale = float(std::clamp(faded, 0.0, double(mFadeScale)));
        }
    } else {
        mConsecutiveOverruns = 0;
        if (mFadeScale < 1.0f && mPhase != SafetyPhase::HoldOff) {
            // On time again: continue as a ramp from the faded level, so the force never steps up.
            const double rampScale = mPhase == SafetyPhase::Armed || mDef.rampTimeS <= 0.0
                                         ? 1.0
                                         : std::clamp((in.nowS - mRampStartS) / mDef.rampTimeS, 0.0, 1.0);
            if (mDef.rampTimeS > 0.0) {
                mPhase = SafetyPhase::RampIn;
                mRampStartS = in.nowS - rampScale * double(mFadeScale) * mDef.rampTimeS;
            }
        }
        mFadeScale = 1.0f;
    }

    // 7. Hold-off, then ramp. A non-finite command is not "small": it must not start the ramp.
    if (mPhase == SafetyPhase::HoldOff) {
        const bool small = (flags & kSafetyNonFinite) == 0u &&
                           magnitudeN < mDef.holdOffThresholdFraction * mMaxForceN;
        if (!small) {
            mLastFlags = flags | kSafetyHeldOff;
            ++mStats.heldOffTicks;
            return zero;
        }
        mPhase = SafetyPhase::RampIn;
        mRampStartS = in.nowS;
    }
    if (mPhase == SafetyPhase::RampIn) {
        if (in.nowS < mRampStartS) mRampStartS = in.nowS;  // clock restarted: restart the ramp
        const double elapsedS = in.nowS - mRampStartS;
        if (mDef.rampTimeS <= 0.0 || elapsedS >= mDef.rampTimeS) {
            mPhase = SafetyPhase::Armed;
        } else {
            float scale = float(elapsedS / mDef.rampTimeS);
            if (scale >= 1.0f) scale = 0.99999994f;  // full force only once rampTimeS has passed
            forceN *= scale;
            flags |= kSafetyRamping;
            ++mStats.rampTicks;
        }
    }

    if (mConsecutiveOverruns > mDef.maxConsecutiveOverruns) {
        forceN *= mFadeScale;
        flags |= kSafetyOverrunFade;
        ++mStats.overrunFadeTicks;
    }
    mLastFlags = flags;
    return forceN;
}

}  // namespace palpate
