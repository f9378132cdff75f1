#include "engine/scoring/Scorer.h"

#include "engine/exercise/Rubric.h"
#include "engine/exercise/ExerciseKind.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace palpate {

namespace {

/// A tick is at most this long for the sums: a stalled or stopped loop does not make time.
constexpr double kMaxTickS = 0.1;

double distance(const glm::vec3& a, const glm::vec3& b) { return glm::length(glm::dvec3(a) - glm::dvec3(b)); }

}  // namespace

Scorer::Scorer(std::shared_ptr<const ExerciseGeometry> geometry, double periodS)
    : mGeometry(std::move(geometry)), mExercise(mGeometry->exercise()), mPeriodS(periodS),
      mTask(exerciseKind(mExercise.type).makeTask(mGeometry, periodS)) {
    mPendingMarks.reserve(16);
    mGuidance.timeLeftS = mExercise.timeLimitS;
    mTask->start(mGuidance);
}

void Scorer::addMark(std::uint64_t tick, bool examinationDone) {
    if (!examinationDone) ++mMarks;
    mPendingMarks.push_back({tick, examinationDone});
}

bool Scorer::isExaminationDone(const std::string& markText) { return markText == kExaminationDoneMark; }

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
    bool markNow = false, doneNow = false;
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
        if (mPendingMarks[i].tick <= t.tick) {
            (mPendingMarks[i].done ? doneNow : markNow) = true;
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

    TaskTick task;
    task.dtS = dt;
    task.elapsedS = mElapsedS;
    task.forceN = forceN;
    task.contact = t.contact;
    task.haveContactPoint = haveContactPoint;
    task.contactPointMm = mContactPointMm;
    task.touched = t.touched;
    task.maxDisplacementMm = s.damage.maxDisplacementMm;
    task.mark = markNow;
    task.done = doneNow;
    if (mTask->step(task, mGuidance)) complete();

    if (!mGuidance.completed && mElapsedS >= mExercise.timeLimitS) mGuidance.timeUp = true;
    mGuidance.exerciseTimeS = mElapsedS;
    mGuidance.timeLeftS = std::max(0.0, mExercise.timeLimitS - mElapsedS);
    mGuidance.forceN = forceN;
    mGuidance.contact = t.contact;
}

ScoreReport Scorer::report(bool detail) const {
    ScoreReport r;
    r.exerciseName = mExercise.name;
    r.type = mExercise.type;
    r.guidance = mGuidance;
    r.ticksScored = mTicksScored;
    r.ticksAfterEnd = mTicksAfterEnd;
    r.firstTick = mFirstTick;
    r.lastTick = mLastTick;
    r.marks = mMarks;
    r.warnings = mWarnings;
    if (mTicksScored == 0) r.warnings.push_back("no tick was scored: the session has no exercise time");

    MeasuredMetrics metrics;
    metrics.put(Metric::Completion, mTask->completion(mGuidance));
    r.workDone = std::clamp(mTask->workDone(mGuidance), 0.0, 1.0);
    metrics.put(Metric::TimeS, mGuidance.completed ? mCompletionTimeS : std::min(mElapsedS, mExercise.timeLimitS));
    metrics.put(Metric::PeakForceN, mPeakForceN);
    metrics.put(Metric::MeanForceN, mContactS > 0.0 ? mContactForceNs / mContactS : 0.0, mContactS > 0.0);
    metrics.put(Metric::ImpulseNs, mImpulseNs);
    metrics.put(Metric::ExcessiveForceEvents, double(mExcessiveEvents));
    metrics.put(Metric::ExcessiveForceFraction,
                mContactS > 0.0 ? std::min(1.0, mExcessiveS / mContactS) : (mExcessiveS > 0.0 ? 1.0 : 0.0));
    metrics.put(Metric::DamageTimeS, mDamageS);
    metrics.put(Metric::DamageAreaMm2, mDamageAreaMm2);
    metrics.put(Metric::MaxDisplacementMm, mMaxDisplacementMm);
    metrics.put(Metric::PathLengthMm, mPathLengthMm);
    const std::optional<double> idealMm = mHavePreviousTool ? mTask->idealPathMm(mStartToolMm) : std::nullopt;
    const bool economyKnown = idealMm && mPathLengthMm > 0.0;
    metrics.put(Metric::Economy, economyKnown ? std::min(1.0, *idealMm / mPathLengthMm) : 0.0, economyKnown);
    mTask->report(r, metrics, detail);

    // In Metric order; only what the exercise's kind measures.
    const ExerciseKind& kind = exerciseKind(mExercise.type);
    for (const auto& line : metrics.lines)
        if (line && kind.measures(line->metric)) r.metrics.push_back(*line);
    applyRubric(mGeometry->rubric(), r);
    return r;
}

}  // namespace palpate
