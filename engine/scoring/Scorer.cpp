#include "engine/scoring/Scorer.h"

#include "engine/exercise/Rubric.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace palpate {

namespace {

/// A tick is at most this long for the sums: a stalled or stopped loop does not make time.
constexpr double kMaxTickS = 0.1;
/// Slack on the hold time: the clock's sum of 1 ms steps is not exact.
constexpr double kHoldSlackS = 1e-9;

double distance(const glm::vec3& a, const glm::vec3& b) { return glm::length(glm::dvec3(a) - glm::dvec3(b)); }

}  // namespace

Scorer::Scorer(std::shared_ptr<const ExerciseGeometry> geometry, double periodS)
    : mGeometry(std::move(geometry)), mExercise(mGeometry->exercise()), mPeriodS(periodS) {
    const std::size_t targets = mGeometry->targets().size();
    mTargets.assign(targets, TargetResult{});
    mTargetErrorSumMmS.assign(targets, 0.0);
    mTargetErrorS.assign(targets, 0.0);
    mCovered.assign(mGeometry->coverageSamplesMm().size(), 0);
    mPendingMarks.reserve(16);
    mGuidance.timeLeftS = mExercise.timeLimitS;
    if (mExercise.type == ExerciseType::PressTargets && targets > 0) {
        mGuidance.targetIndex = 0;
        mGuidance.targetCount = int(targets);
        mGuidance.forceMinN = mGeometry->targets()[0].def.forceMinN;
        mGuidance.forceMaxN = mGeometry->targets()[0].def.forceMaxN;
    } else if (mExercise.type == ExerciseType::Trace) {
        mGuidance.forceMinN = mExercise.trace.forceMinN;
        mGuidance.forceMaxN = mExercise.trace.forceMaxN;
    }
}

void Scorer::addMark(std::uint64_t tick) {
    ++mMarks;
    mPendingMarks.push_back(tick);
}

void Scorer::addWarning(const std::string& warning) {
    if (std::find(mWarnings.begin(), mWarnings.end(), warning) == mWarnings.end()) mWarnings.push_back(warning);
}

void Scorer::complete() {
    mGuidance.completed = true;
    mCompletionTimeS = mElapsedS;
}

void Scorer::addSample(const ScoreSample& s) {
    const RecordedTick& t = s.tick;
    double dt = mPeriodS;
    if (mStarted) {
        dt = std::clamp(t.nowS - mPreviousNowS, 0.0, kMaxTickS);
        if (!std::isfinite(dt)) dt = 0.0;
    } else {
        mStarted = true;
        mFirstTick = t.tick;
    }
    mPreviousNowS = t.nowS;
    mLastTick = t.tick;

    // The device: position and buttons (a rising button bit is a mark).
    bool markNow = false;
    if (t.readOk) {
        if (mHaveButtons && (t.sample.buttons & ~mButtons) != 0) {
            markNow = true;
            ++mMarks;
        }
        mButtons = t.sample.buttons;
        mHaveButtons = true;
        mToolMm = t.sample.positionMm;
        mHaveTool = std::isfinite(mToolMm.x) && std::isfinite(mToolMm.y) && std::isfinite(mToolMm.z);
    }
    for (std::size_t i = 0; i < mPendingMarks.size();) {
        if (mPendingMarks[i] <= t.tick) {
            markNow = true;
            mPendingMarks[i] = mPendingMarks.back();
            mPendingMarks.pop_back();
        } else {
            ++i;
        }
    }

    if (over()) {
        ++mTicksAfterEnd;
        return;
    }
    if (t.paused) {
        // No exercise time passes; motion while paused is not counted.
        if (mHaveTool) mPreviousToolMm = mToolMm;
        return;
    }
    ++mTicksScored;
    mElapsedS += dt;

    // The contact point: the tip projected along the touched vertex's rest normal onto its
    // tangent plane (on the surface under the tool, without the mesh's vertex spacing).
    const bool haveContactPoint = mHaveTool;
    if (mHaveTool) {
        if (t.touched < mGeometry->vertexCount()) {
            const glm::vec3 n = mGeometry->normals()[t.touched];
            mContactPointMm = mToolMm + glm::dot(mGeometry->restMm()[t.touched] - mToolMm, n) * n;
        } else {
            mContactPointMm = mToolMm;
        }
        if (mHavePreviousTool) mPathLengthMm += distance(mToolMm, mPreviousToolMm);
        else mStartToolMm = mToolMm;
        mPreviousToolMm = mToolMm;
        mHavePreviousTool = true;
    }

    const double forceN = glm::length(glm::dvec3(t.forceN));
    mPeakForceN = std::max(mPeakForceN, forceN);
    mImpulseNs += forceN * dt;
    if (t.contact) {
        mContactS += dt;
        mContactForceNs += forceN * dt;
    }
    const bool above = forceN > mExercise.excessiveForceN;
    if (above && !mAboveExcessive) ++mExcessiveEvents;
    if (above) mExcessiveS += dt;
    mAboveExcessive = above;
    mMaxDisplacementMm = std::max(mMaxDisplacementMm, double(s.damage.maxDisplacementMm));
    if (double(s.damage.maxDisplacementMm) > mExercise.displacementLimitMm) mDamageS += dt;
    mDamageAreaMm2 = std::max(mDamageAreaMm2, double(s.damage.areaAboveLimitMm2));

    switch (mExercise.type) {
        case ExerciseType::PressTargets: scorePressTargets(s, dt, forceN, haveContactPoint); break;
        case ExerciseType::FindLump: scoreFindLump(markNow, haveContactPoint); break;
        case ExerciseType::Trace: scoreTrace(s, dt, forceN, haveContactPoint); break;
    }

    if (!mGuidance.completed && mElapsedS >= mExercise.timeLimitS) mGuidance.timeUp = true;
    mGuidance.exerciseTimeS = mElapsedS;
    mGuidance.timeLeftS = std::max(0.0, mExercise.timeLimitS - mElapsedS);
    mGuidance.forceN = forceN;
    mGuidance.contact = t.contact;
}

void Scorer::scorePressTargets(const ScoreSample& s, double dt, double forceN, bool haveContactPoint) {
    const auto& targets = mGeometry->targets();
    if (mTarget >= targets.size()) return;
    const ResolvedTarget& target = targets[mTarget];
    const bool contact = s.tick.contact;
    const double dist = haveContactPoint ? distance(mContactPointMm, target.pointMm) : std::numeric_limits<double>::infinity();
    const bool inWindow = contact && forceN >= target.def.forceMinN && forceN <= target.def.forceMaxN;
    const bool onTarget = contact && haveContactPoint && dist <= target.def.toleranceMm;
    TargetResult& result = mTargets[mTarget];
    // The press that achieved the previous target is not one for this target: it counts from
    // the first tick the force leaves the window.
    if (!inWindow) mCarriedPress = false;
    if (inWindow && haveContactPoint && !mCarriedPress) {
        mTargetErrorSumMmS[mTarget] += dist * dt;
        mTargetErrorS[mTarget] += dt;
    }
    // The hold time on a target runs from the first time the force is inside its window there
    // (pressing in to the window is not holding).
    if (onTarget && inWindow) mHoldStarted = true;
    if (onTarget && mHoldStarted) result.onTargetS += dt;
    if (onTarget && inWindow) {
        result.inWindowS += dt;
        mHoldS += dt;
    } else {
        mHoldS = 0.0;
    }
    mGuidance.onTarget = onTarget;
    mGuidance.distanceToTargetMm = haveContactPoint ? dist : 0.0;
    mGuidance.holdProgress = target.def.holdS > 0.0 ? std::min(1.0, mHoldS / target.def.holdS) : 0.0;
    if (onTarget && inWindow && mHoldS >= target.def.holdS - kHoldSlackS) {
        result.achieved = true;
        result.achievedAtS = mElapsedS;
        ++mTarget;
        mHoldS = 0.0;
        mHoldStarted = false;
        mCarriedPress = true;
        mGuidance.holdProgress = 0.0;
        mGuidance.onTarget = false;
        if (mTarget == targets.size()) {
            mGuidance.targetIndex = -1;
            complete();
        } else {
            mGuidance.targetIndex = int(mTarget);
            mGuidance.forceMinN = targets[mTarget].def.forceMinN;
            mGuidance.forceMaxN = targets[mTarget].def.forceMaxN;
        }
    }
}

void Scorer::scoreFindLump(bool markNow, bool haveContactPoint) {
    if (!markNow || mMarked) return;
    mMarked = true;
    mGuidance.marked = true;
    if (haveContactPoint) {
        mLumpErrorMm = distance(mContactPointMm, mGeometry->lumpCentreMm());
        mMarkMeasured = true;
    }
    complete();
}

void Scorer::scoreTrace(const ScoreSample& s, double dt, double forceN, bool haveContactPoint) {
    const TraceDef& def = mExercise.trace;
    const bool contact = s.tick.contact;
    const double dist = haveContactPoint ? mGeometry->distanceToPathMm(mContactPointMm) : std::numeric_limits<double>::infinity();
    mGuidance.distanceToPathMm = haveContactPoint ? dist : 0.0;
    if (contact) mTracing = true;  // tracing time starts at the first contact
    if (!mTracing) return;
    mTracingS += dt;
    if (contact) {
        mTraceContactS += dt;
        if (haveContactPoint) mPathDistanceSumMmS += dist * dt;
        if (forceN >= def.forceMinN && forceN <= def.forceMaxN) mBandS += dt;
        if (haveContactPoint && dist <= def.toleranceMm) {
            const auto& samples = mGeometry->coverageSamplesMm();
            const double tol2 = def.toleranceMm * def.toleranceMm;
            for (std::size_t i = 0; i < samples.size(); ++i) {
                if (mCovered[i]) continue;
                const glm::dvec3 d = glm::dvec3(samples[i]) - glm::dvec3(mContactPointMm);
                if (glm::dot(d, d) <= tol2) {
                    mCovered[i] = 1;
                    ++mCoveredCount;
                }
            }
        }
    }
    mGuidance.pathCovered = mCovered.empty() ? 0.0 : double(mCoveredCount) / double(mCovered.size());
    if (!mCovered.empty() && mCoveredCount == mCovered.size()) complete();
}

ScoreReport Scorer::report() const {
    ScoreReport r;
    r.exerciseName = mExercise.name;
    r.type = mExercise.type;
    r.targets = mTargets;
    for (std::size_t i = 0; i < r.targets.size(); ++i) {
        r.targets[i].errorMeasured = mTargetErrorS[i] > 0.0;
        r.targets[i].errorMm = r.targets[i].errorMeasured ? mTargetErrorSumMmS[i] / mTargetErrorS[i] : 0.0;
    }
    r.guidance = mGuidance;
    r.ticksScored = mTicksScored;
    r.ticksAfterEnd = mTicksAfterEnd;
    r.firstTick = mFirstTick;
    r.lastTick = mLastTick;
    r.marks = mMarks;
    r.warnings = mWarnings;
    if (mTicksScored == 0) r.warnings.push_back("no tick was scored: the session has no exercise time");

    double completion = 0.0;
    double idealMm = 0.0;
    bool idealKnown = false;
    switch (mExercise.type) {
        case ExerciseType::PressTargets: {
            const auto& targets = mGeometry->targets();
            completion = targets.empty() ? 0.0 : double(mTarget) / double(targets.size());
            if (mTarget > 0 && mHavePreviousTool) {
                idealMm = distance(mStartToolMm, targets[0].pointMm);
                for (std::size_t i = 1; i < mTarget; ++i) idealMm += distance(targets[i].pointMm, targets[i - 1].pointMm);
                idealKnown = true;
            }
            break;
        }
        case ExerciseType::FindLump:
            completion = mMarked ? 1.0 : 0.0;
            if (mMarked && mHavePreviousTool) {
                idealMm = distance(mStartToolMm, mGeometry->lumpCentreMm());
                idealKnown = true;
            }
            break;
        case ExerciseType::Trace:
            completion = mCovered.empty() ? 0.0 : double(mCoveredCount) / double(mCovered.size());
            if (mCoveredCount > 0 && mHavePreviousTool) {
                idealMm = distance(mStartToolMm, mGeometry->pathMm().front()) + completion * mGeometry->pathLengthMm();
                idealKnown = true;
            }
            break;
    }

    auto put = [&](Metric m, double value, bool measured = true) {
        if (!metricApplies(m, mExercise.type)) return;
        MetricResult line;
        line.metric = m;
        line.measured = measured;
        line.value = measured ? value : 0.0;
        r.metrics.push_back(line);
    };
    put(Metric::Completion, completion);
    put(Metric::TimeS, mGuidance.completed ? mCompletionTimeS : std::min(mElapsedS, mExercise.timeLimitS));
    {
        double sum = 0.0;
        int n = 0;
        for (const TargetResult& t : r.targets)
            if (t.errorMeasured) {
                sum += t.errorMm;
                ++n;
            }
        put(Metric::TargetErrorMm, n > 0 ? sum / n : 0.0, n > 0);
        double on = 0.0, in = 0.0;
        for (const TargetResult& t : r.targets) {
            on += t.onTargetS;
            in += t.inWindowS;
        }
        put(Metric::HoldInWindowFraction, on > 0.0 ? in / on : 0.0, on > 0.0);
    }
    put(Metric::PeakForceN, mPeakForceN);
    put(Metric::MeanForceN, mContactS > 0.0 ? mContactForceNs / mContactS : 0.0, mContactS > 0.0);
    put(Metric::ImpulseNs, mImpulseNs);
    put(Metric::ExcessiveForceEvents, double(mExcessiveEvents));
    put(Metric::ExcessiveForceFraction, mContactS > 0.0 ? std::min(1.0, mExcessiveS / mContactS) : (mExcessiveS > 0.0 ? 1.0 : 0.0));
    put(Metric::DamageTimeS, mDamageS);
    put(Metric::DamageAreaMm2, mDamageAreaMm2);
    put(Metric::MaxDisplacementMm, mMaxDisplacementMm);
    put(Metric::PathLengthMm, mPathLengthMm);
    put(Metric::Economy, idealKnown && mPathLengthMm > 0.0 ? std::min(1.0, idealMm / mPathLengthMm) : 0.0,
        idealKnown && mPathLengthMm > 0.0);
    put(Metric::LumpErrorMm, mLumpErrorMm, mMarkMeasured);
    put(Metric::ContactFraction, mTracingS > 0.0 ? mTraceContactS / mTracingS : 0.0, mTracingS > 0.0);
    put(Metric::BandFraction, mTracingS > 0.0 ? mBandS / mTracingS : 0.0, mTracingS > 0.0);
    put(Metric::PathDistanceMm, mTraceContactS > 0.0 ? mPathDistanceSumMmS / mTraceContactS : 0.0, mTraceContactS > 0.0);
    applyRubric(mGeometry->rubric(), r);
    return r;
}

}  // namespace palpate
