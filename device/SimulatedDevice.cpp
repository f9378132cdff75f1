#include "device/SimulatedDevice.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace palpate {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

bool positiveFinite(double v) { return std::isfinite(v) && v > 0.0; }

bool finiteVec(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

const char* simTrajectoryName(SimTrajectory trajectory) {
    switch (trajectory) {
        case SimTrajectory::PressHold: return "press";
        case SimTrajectory::Stroke: return "stroke";
        case SimTrajectory::Scan: return "scan";
        case SimTrajectory::Sine: return "sine";
        case SimTrajectory::Waypoints: return "path";
    }
    return "unknown";
}

DeviceSpec simulatedDeviceSpec() {
    DeviceSpec spec;
    spec.name = "simulated";
    spec.maxForceN = 3.3;
    spec.maxStiffnessNPerMm = 1.0;
    spec.maxDampingNsPerMm = 0.005;
    spec.workspaceRadiusMm = 80.0;
    spec.actuated = true;
    spec.buttonCount = 0;
    return spec;
}

Problems validateSimulatedDeviceDef(const SimulatedDeviceDef& def) {
    if (!positiveFinite(def.approachHeightMm))
        return oneProblem("approachHeightMm", "SimulatedDeviceDef.approachHeightMm must be finite and > 0");
    if (!positiveFinite(def.depthMm)) return oneProblem("depthMm", "SimulatedDeviceDef.depthMm must be finite and > 0");
    if (!positiveFinite(def.descendTimeS))
        return oneProblem("descendTimeS", "SimulatedDeviceDef.descendTimeS must be finite and > 0");
    if (!std::isfinite(def.holdTimeS) || def.holdTimeS < 0.0)
        return oneProblem("holdTimeS", "SimulatedDeviceDef.holdTimeS must be finite and >= 0");
    if (!std::isfinite(def.strokeLengthMm) || def.strokeLengthMm < 0.0)
        return oneProblem("strokeLengthMm", "SimulatedDeviceDef.strokeLengthMm must be finite and >= 0");
    if (!positiveFinite(def.strokeTimeS))
        return oneProblem("strokeTimeS", "SimulatedDeviceDef.strokeTimeS must be finite and > 0");
    if (def.scanGridCount < 1 || def.scanGridCount > 64)
        return oneProblem("scanGridCount", "SimulatedDeviceDef.scanGridCount must be in 1..64");
    if (!std::isfinite(def.scanPatchSizeMm) || def.scanPatchSizeMm < 0.0)
        return oneProblem("scanPatchSizeMm", "SimulatedDeviceDef.scanPatchSizeMm must be finite and >= 0");
    if (!positiveFinite(def.scanMoveTimeS))
        return oneProblem("scanMoveTimeS", "SimulatedDeviceDef.scanMoveTimeS must be finite and > 0");
    if (!positiveFinite(def.scanPressTimeS))
        return oneProblem("scanPressTimeS", "SimulatedDeviceDef.scanPressTimeS must be finite and > 0");
    if (!std::isfinite(def.scanHoldTimeS) || def.scanHoldTimeS < 0.0)
        return oneProblem("scanHoldTimeS", "SimulatedDeviceDef.scanHoldTimeS must be finite and >= 0");
    if (!std::isfinite(def.sineAmplitudeMm) || def.sineAmplitudeMm < 0.0)
        return oneProblem("sineAmplitudeMm", "SimulatedDeviceDef.sineAmplitudeMm must be finite and >= 0");
    if (!positiveFinite(def.sineFrequencyHz))
        return oneProblem("sineFrequencyHz", "SimulatedDeviceDef.sineFrequencyHz must be finite and > 0");
    if (!(def.spec.maxForceN >= 0.0) || !std::isfinite(def.spec.maxForceN))
        return oneProblem("spec.maxForceN", "SimulatedDeviceDef.spec.maxForceN must be finite and >= 0");
    return {};
}

SimulatedDevice::SimulatedDevice(SimTrajectory trajectory, SimulatedDeviceDef def)
    : mTrajectory(trajectory), mDef(std::move(def)), mUnplugAtS(kInf), mStallFromS(kInf), mStallUntilS(kInf) {
    if (trajectory == SimTrajectory::Waypoints)
        throw std::invalid_argument("SimulatedDevice: the Waypoints trajectory needs a waypoint list");
    const std::string problem = joinedMessages(validateSimulatedDeviceDef(mDef));
    if (!problem.empty()) throw std::invalid_argument(problem);
    if (mDef.spec.name == simulatedDeviceSpec().name)
        mDef.spec.name = std::string("simulated (") + simTrajectoryName(trajectory) + ")";
    buildKeyframes();
    mSample.positionMm = positionAtMm(0.0);
}

SimulatedDevice::SimulatedDevice(std::vector<Waypoint> waypoints, SimulatedDeviceDef def)
    : mTrajectory(SimTrajectory::Waypoints), mDef(std::move(def)), mUnplugAtS(kInf), mStallFromS(kInf),
      mStallUntilS(kInf) {
    const std::string problem = joinedMessages(validateSimulatedDeviceDef(mDef));
    if (!problem.empty()) throw std::invalid_argument(problem);
    if (waypoints.empty()) throw std::invalid_argument("SimulatedDevice: empty waypoint list");
    mKeyframes.reserve(waypoints.size());
    for (const Waypoint& w : waypoints) {
        if (!std::isfinite(w.timeS) || !finiteVec(w.positionMm))
            throw std::invalid_argument("SimulatedDevice: waypoint with a non-finite time or position");
        if (!mKeyframes.empty() && !(w.timeS > mKeyframes.back().timeS))
            throw std::invalid_argument("SimulatedDevice: waypoint times must strictly increase");
        mKeyframes.push_back(Keyframe{w.timeS, glm::dvec3(w.positionMm)});
    }
    if (mDef.spec.name == simulatedDeviceSpec().name) mDef.spec.name = "simulated (path)";
    mSample.positionMm = positionAtMm(0.0);
}

std::unique_ptr<SimulatedDevice> SimulatedDevice::fromWaypointFile(const std::string& path, std::string& error,
                                                                   SimulatedDeviceDef def) {
    std::vector<Waypoint> waypoints;
    if (!(error = loadWaypointFile(path, waypoints)).empty()) return nullptr;
    const std::string problem = joinedMessages(validateSimulatedDeviceDef(def));
    if (!problem.empty()) {
        error = problem;
        return nullptr;
    }
    return std::make_unique<SimulatedDevice>(std::move(waypoints), std::move(def));
}

void SimulatedDevice::addKeyframe(double timeS, double tangentMm, double bitangentMm, double heightMm) {
    mKeyframes.push_back(Keyframe{timeS, glm::dvec3(tangentMm, bitangentMm, heightMm)});
}

void SimulatedDevice::buildKeyframes() {
    const SimulatedDeviceDef& d = mDef;
    const double up = d.approachHeightMm;
    const double down = -d.depthMm;
    double t = 0.0;
    switch (mTrajectory) {
        case SimTrajectory::PressHold:
            addKeyframe(t, 0, 0, up);
            addKeyframe(t += d.descendTimeS, 0, 0, down);
            addKeyframe(t += d.holdTimeS, 0, 0, down);
            addKeyframe(t += d.descendTimeS, 0, 0, up);
            break;
        case SimTrajectory::Stroke:
            addKeyframe(t, 0, 0, up);
            addKeyframe(t += d.descendTimeS, 0, 0, down);
            addKeyframe(t += d.strokeTimeS, d.strokeLengthMm, 0, down);
            addKeyframe(t += d.strokeTimeS, 0, 0, down);
            addKeyframe(t += d.descendTimeS, 0, 0, up);
            break;
        case SimTrajectory::Scan: {
            const int n = d.scanGridCount;
            const double half = 0.5 * d.scanPatchSizeMm;
            const double step = n > 1 ? d.scanPatchSizeMm / double(n - 1) : 0.0;
            mKeyframes.reserve(std::size_t(n) * std::size_t(n) * 4u);
            // Boustrophedon: row by row along the bitangent, alternating direction along the tangent,
            // so that the hover between presses is always one grid step.
            for (int row = 0; row < n; ++row) {
                const double v = n > 1 ? -half + step * row : 0.0;
                for (int k = 0; k < n; ++k) {
                    const int col = (row % 2 == 0) ? k : n - 1 - k;
                    const double u = n > 1 ? -half + step * col : 0.0;
                    if (!mKeyframes.empty()) t += d.scanMoveTimeS;
                    addKeyframe(t, u, v, up);
                    addKeyframe(t += d.scanPressTimeS, u, v, down);
                    if (d.scanHoldTimeS > 0.0) addKeyframe(t += d.scanHoldTimeS, u, v, down);
                    addKeyframe(t += d.scanPressTimeS, u, v, up);
                }
            }
            break;
        }
        case SimTrajectory::Sine:
            // Descend to the mean depth; the oscillation (analytic, positionAtMm) then peaks at depthMm.
            addKeyframe(t, 0, 0, up);
            addKeyframe(t += d.descendTimeS, 0, 0, -(d.depthMm - d.sineAmplitudeMm));
            break;
        case SimTrajectory::Waypoints: break;
    }
}

glm::dvec3 SimulatedDevice::keyframePointAt(double timeS) const {
    // Binary search rather than a cursor kept between calls: the answer then depends on t alone,
    // never on the order of earlier calls (determinism), and it is O(log n) without allocation.
    const Keyframe& first = mKeyframes.front();
    const Keyframe& last = mKeyframes.back();
    if (!(timeS > first.timeS)) return first.pointMm;  // also catches NaN
    if (timeS >= last.timeS) return last.pointMm;
    const auto next = std::upper_bound(mKeyframes.begin(), mKeyframes.end(), timeS,
                                       [](double t, const Keyframe& k) { return t < k.timeS; });
    const Keyframe& b = *next;
    const Keyframe& a = *(next - 1);
    const double s = (timeS - a.timeS) / (b.timeS - a.timeS);
    return a.pointMm + (b.pointMm - a.pointMm) * s;
}

glm::vec3 SimulatedDevice::positionAtMm(double timeS) const {
    glm::dvec3 p = keyframePointAt(timeS);
    if (mTrajectory == SimTrajectory::Waypoints) return glm::vec3(p);
    if (mTrajectory == SimTrajectory::Sine && timeS > mKeyframes.back().timeS) {
        const double phase = 2.0 * kPi * mDef.sineFrequencyHz * (timeS - mKeyframes.back().timeS);
        p.z = -(mDef.depthMm - mDef.sineAmplitudeMm) - mDef.sineAmplitudeMm * std::sin(phase);
    }
    return glm::vec3(mTargetMm + mTangent * p.x + mBitangent * p.y + mNormal * p.z);
}

double SimulatedDevice::durationS() const {
    if (mTrajectory == SimTrajectory::Sine) return kInf;
    return mKeyframes.back().timeS;
}

double SimulatedDevice::scriptTimeS(double loopTimeS) const {
    const double t = mEpochSet ? loopTimeS - mEpochS : 0.0;
    const double duration = durationS();
    if (mRepeatRestS < 0.0 || !std::isfinite(duration) || t <= duration) return t;
    return std::fmod(t, duration + mRepeatRestS);  // in the rest, positionAtMm holds the end
}

bool SimulatedDevice::open() {
    mEpochSet = false;
    mOpen.store(true, std::memory_order_release);
    mState.store(DeviceState::Ready, std::memory_order_release);
    ++mSample.sequence;
    mSample.timeS = mLastTimeS;
    mSample.positionMm = positionAtMm(0.0);
    return true;
}

void SimulatedDevice::close() {
    mOpen.store(false, std::memory_order_release);
    mLastForceN.store(glm::vec3(0.0f));
    mState.store(DeviceState::Disconnected, std::memory_order_release);
}

bool SimulatedDevice::calibrate() {
    DeviceState expected = DeviceState::NeedsCalibration;
    mState.compare_exchange_strong(expected, DeviceState::Ready);
    return mState.load() == DeviceState::Ready;
}

void SimulatedDevice::setTimeS(double timeS) {
    if (!std::isfinite(timeS)) return;
    if (timeS >= mUnplugAtS.load(std::memory_order_acquire)) {
        mUnplugAtS.store(kInf, std::memory_order_relaxed);
        mLastForceN.store(glm::vec3(0.0f));  // an unplugged device renders nothing
        mState.store(DeviceState::Disconnected, std::memory_order_release);
    }
    mLastTimeS = timeS;
    if (!mEpochSet) {
        mEpochS = timeS;
        mEpochSet = true;
    }
    if (mState.load(std::memory_order_acquire) != DeviceState::Ready) return;
    if (timeS >= mStallFromS.load(std::memory_order_relaxed) && timeS < mStallUntilS.load(std::memory_order_relaxed))
        return;  // stalled: the sample (and its sequence) stays as it was
    ++mSample.sequence;
    mSample.timeS = timeS;  // stamped on the loop's clock, for the safety filter's age check
    mSample.positionMm = positionAtMm(scriptTimeS(timeS));
}

bool SimulatedDevice::read(DeviceSample& sample) {
    if (mState.load(std::memory_order_acquire) != DeviceState::Ready) return false;
    sample = mSample;
    return true;
}

void SimulatedDevice::writeForce(const glm::vec3& forceN) {
    if (mState.load(std::memory_order_acquire) != DeviceState::Ready) {
        mDroppedForceWrites.fetch_add(1, std::memory_order_relaxed);
        return;
    }
    mLastForceN.store(forceN);
}

void SimulatedDevice::emergencyStop() {
    mState.store(DeviceState::Fault, std::memory_order_release);
    mLastForceN.store(glm::vec3(0.0f));
}

void SimulatedDevice::setScene(const glm::vec3& targetMm, const glm::vec3& outwardNormal, const glm::vec3& tangent) {
    if (!finiteVec(targetMm) || !finiteVec(outwardNormal) || !finiteVec(tangent)) return;
    const glm::dvec3 n(outwardNormal);
    const double nLength = glm::length(n);
    if (!(nLength > 1e-12)) return;
    const glm::dvec3 normal = n / nLength;
    glm::dvec3 t = glm::dvec3(tangent) - normal * glm::dot(glm::dvec3(tangent), normal);
    if (!(glm::length(t) > 1e-9)) {
        // Tangent missing or parallel to the normal: take the axis least aligned with the normal.
        const glm::dvec3 a = std::fabs(normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        t = a - normal * glm::dot(a, normal);
    }
    mTargetMm = glm::dvec3(targetMm);
    mNormal = normal;
    mTangent = glm::normalize(t);
    mBitangent = glm::cross(mNormal, mTangent);
}

void SimulatedDevice::simulateUnplug(double atTimeS) {
    mUnplugAtS.store(std::isnan(atTimeS) ? kInf : atTimeS, std::memory_order_release);
}

void SimulatedDevice::replug() {
    mUnplugAtS.store(kInf, std::memory_order_release);
    if (!mOpen.load(std::memory_order_acquire)) return;  // a closed device stays closed until open()
    DeviceState expected = DeviceState::Disconnected;
    mState.compare_exchange_strong(expected, DeviceState::Ready, std::memory_order_acq_rel);
}

void SimulatedDevice::simulateStall(double fromS, double untilS) {
    mStallFromS.store(fromS, std::memory_order_relaxed);
    mStallUntilS.store(untilS, std::memory_order_relaxed);
}

}  // namespace palpate
