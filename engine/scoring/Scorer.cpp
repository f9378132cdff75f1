#include "engine/scoring/Scorer.h"

#include "engine/exercise/Rubric.h"
#include "engine/scoring/LumpDetection.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace palpate {

namespace {

/// A tick is at most this long for the sums: a stalled or stopped loop does not make time.
constexpr double kMaxTickS = 0.1;
/// Slack on the hold time: the clock's sum of 1 ms steps is not exact.
constexpr double kHoldSlackS = 1e-9;

double distance(const glm::vec3& a, const glm::vec3& b) { return glm::length(glm::dvec3(a) - glm::dvec3(b)); }

/// Sinks shallower than this say too little about the tissue's force per mm (the estimate of the
/// force that reaches a lump).
constexpr double kMinSinkForStiffnessMm = 0.5;
/// At most this many force samples are kept for the phases (an hour at 1 kHz).
constexpr double kMaxPhaseSamples = 3.6e6;
/// Below this covered share the examination was not systematic enough (feedback).
constexpr double kLowCoverageFraction = 0.6;

std::string oneDecimal(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", v);
    return text;
}

}  // namespace

Scorer::Scorer(std::shared_ptr<const ExerciseGeometry> geometry, double periodS)
    : mGeometry(std::move(geometry)), mExercise(mGeometry->exercise()), mPeriodS(periodS) {
    const std::size_t targets = mGeometry->targets().size();
    mTargets.assign(targets, TargetResult{});
    mTargetErrorSumMmS.assign(targets, 0.0);
    mTargetErrorS.assign(targets, 0.0);
    mCovered.assign(mGeometry->coverageSamplesMm().size(), 0);
    mPendingMarks.reserve(16);
    mPalpation = mExercise.type == ExerciseType::FindLump || mExercise.type == ExerciseType::DetectLumps;
    if (mPalpation) {
        mCoverage.emplace(*mGeometry, mExercise.coverage);
        const double ticks = periodS > 0.0 ? std::ceil(mExercise.timeLimitS / periodS) + 16.0 : 0.0;
        mPhaseSamples.reserve(std::size_t(std::min(ticks, kMaxPhaseSamples)));
        mFindingsMm.reserve(64);
        mLumpMaxSinkMm.assign(mGeometry->lumps().size(), 0.0);
    }
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

    if (mPalpation) examinePalpation(s, dt, forceN, haveContactPoint);
    switch (mExercise.type) {
        case ExerciseType::PressTargets: scorePressTargets(s, dt, forceN, haveContactPoint); break;
        case ExerciseType::FindLump: scoreFindLump(markNow, haveContactPoint); break;
        case ExerciseType::Trace: scoreTrace(s, dt, forceN, haveContactPoint); break;
        case ExerciseType::DetectLumps: scoreDetectLumps(markNow, doneNow, haveContactPoint); break;
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

void Scorer::examinePalpation(const ScoreSample& s, double dt, double forceN, bool haveContactPoint) {
    const VertexId touched = s.tick.touched;
    if (!s.tick.contact || !haveContactPoint || touched >= mGeometry->vertexCount()) {
        mHavePreviousContact = false;
        return;
    }
    mCoverage->add(touched, mContactPointMm, forceN);
    mGuidance.coverageFraction = mCoverage->coveredFraction();
    // The speed along the surface tells search from palpation; a contact's first tick has none.
    if (mHavePreviousContact && dt > 0.0 && mPhaseSamples.size() < mPhaseSamples.capacity()) {
        const glm::dvec3 n(mGeometry->normals()[touched]);
        glm::dvec3 moved = glm::dvec3(mContactPointMm) - glm::dvec3(mPreviousContactMm);
        moved -= glm::dot(moved, n) * n;
        mPhaseSamples.push_back({forceN, glm::length(moved) / dt});
    }
    mPreviousContactMm = mContactPointMm;
    mHavePreviousContact = true;
    // How deep the surface went over each lump, and the tissue's force per mm of sink elsewhere.
    const double sinkMm = s.damage.maxDisplacementMm;
    const int lump = mGeometry->lumpOfVertex().empty() ? -1 : mGeometry->lumpOfVertex()[touched];
    if (lump >= 0 && std::size_t(lump) < mLumpMaxSinkMm.size()) {
        mLumpMaxSinkMm[std::size_t(lump)] = std::max(mLumpMaxSinkMm[std::size_t(lump)], sinkMm);
    } else if (sinkMm >= kMinSinkForStiffnessMm) {
        mSoftForceSumN += forceN;
        mSoftSinkSumMm += sinkMm;
    }
}

void Scorer::scoreDetectLumps(bool markNow, bool doneNow, bool haveContactPoint) {
    if (markNow && haveContactPoint) mFindingsMm.push_back(glm::dvec3(mContactPointMm));
    mGuidance.findings = int(mFindingsMm.size());
    if (doneNow) complete();
}

PalpationSummary Scorer::palpationSummary(bool detail) const {
    PalpationSummary p;
    p.coverage = mExercise.coverage;
    p.coverageFraction = mCoverage->coveredFraction();
    if (detail) {
        p.peakForceN = mCoverage->peakForceN();
        p.forceByPhase = forceByPhase(mPhaseSamples);
    }
    const std::string minForce = oneDecimal(mExercise.coverage.minForceN);
    if (mExercise.type == ExerciseType::DetectLumps) {
        p.findingsMm = mFindingsMm;
        const auto& lumps = mGeometry->lumps();
        std::vector<HiddenLump> hidden;
        for (const ResolvedLump& l : lumps) hidden.push_back({glm::dvec3(l.surfaceMm), l.def.radiusMm});
        p.detection = scoreDetection(hidden, mFindingsMm, {mExercise.detectLumps.toleranceMm});
        // The deepest lump, and whether the surface over it ever sank as deep as its top.
        std::size_t deepest = lumps.size();
        for (std::size_t k = 0; k < lumps.size(); ++k)
            if (deepest == lumps.size() || lumps[k].def.depthMm > lumps[deepest].def.depthMm) deepest = k;
        const double forcePerMm = mSoftSinkSumMm > 0.0 ? mSoftForceSumN / mSoftSinkSumMm : 0.0;
        if (deepest < lumps.size()) {
            const double depthMm = lumps[deepest].def.depthMm;
            if (forcePerMm > 0.0) p.deepestLumpReachForceN = depthMm * forcePerMm;
            const bool missed = p.detection->findingOfLump[deepest] < 0;
            if (missed && mLumpMaxSinkMm[deepest] < depthMm) {
                std::string text = "Pressed too lightly to reach the deepest lump: it lies " + oneDecimal(depthMm) +
                                   " mm under the surface, and over it the surface sank " +
                                   oneDecimal(mLumpMaxSinkMm[deepest]) + " mm at most.";
                if (p.deepestLumpReachForceN)
                    text += " Press to about " + oneDecimal(*p.deepestLumpReachForceN) + " N or more to feel it.";
                p.feedback.push_back({"pressed_too_lightly", text});
            }
        }
        if (p.detection->falseAlarms > 0)
            p.feedback.push_back({"false_alarms", std::to_string(p.detection->falseAlarms) +
                                                      (p.detection->falseAlarms == 1 ? " finding was" : " findings were") +
                                                      " on no lump: mark only where the tissue resists more than around it."});
    }
    // Only an examination of the whole surface is judged on how much of it was covered (find the
    // lump may go straight to it).
    if (mExercise.type == ExerciseType::DetectLumps && p.coverageFraction < kLowCoverageFraction)
        p.feedback.push_back({"low_coverage", "Examined " + oneDecimal(100.0 * p.coverageFraction) +
                                                  " % of the surface at " + minForce +
                                                  " N or more: cover all of it, in overlapping rows."});
    const ForceByPhase& phases = p.forceByPhase;
    if (phases.palpationOverSearch && *phases.palpationOverSearch < 1.0)
        p.feedback.push_back({"light_palpation", "Pressed no harder to palpate than to search (median " +
                                                     oneDecimal(phases.palpation->p50N) + " N against " +
                                                     oneDecimal(phases.search->p50N) +
                                                     " N): press in on a spot that feels different."});
    return p;
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

ScoreReport Scorer::report(bool palpationDetail) const {
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
        case ExerciseType::DetectLumps:
            // Finished by the trainee: done; cut off by the time limit: as far as the surface was
            // examined (only an examination that touched nothing is nothing done).
            completion = mGuidance.completed ? 1.0 : mCoverage->coveredFraction();
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
    if (mPalpation) {
        // In Metric order, as every line before.
        r.palpation = palpationSummary(palpationDetail);
        if (const auto& d = r.palpation->detection) {
            put(Metric::Sensitivity, d->sensitivity.value_or(0.0), d->sensitivity.has_value());
            put(Metric::PositivePredictiveValue, d->positivePredictive.value_or(0.0), d->positivePredictive.has_value());
            put(Metric::FalseAlarms, double(d->falseAlarms));
            const auto localisation = d->meanLocalisationMm();
            put(Metric::LocalisationMm, localisation.value_or(0.0), localisation.has_value());
        }
        put(Metric::CoverageFraction, r.palpation->coverageFraction);
    }
    applyRubric(mGeometry->rubric(), r);
    return r;
}

}  // namespace palpate
