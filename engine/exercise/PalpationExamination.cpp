#include "engine/exercise/PalpationExamination.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace palpate {

namespace {

/// Sinks shallower than this say too little about the tissue's force per mm (the estimate of the
/// force that reaches a lump).
constexpr double kMinSinkForStiffnessMm = 0.5;
/// At most this many force samples are kept for the phases (an hour at 1 kHz).
constexpr double kMaxPhaseSamples = 3.6e6;

}  // namespace

std::string oneDecimal(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", v);
    return text;
}

PalpationExamination::PalpationExamination(std::shared_ptr<const ExerciseGeometry> geometry, double periodS)
    : mGeometry(std::move(geometry)),
      mCoverage(*mGeometry, mGeometry->exercise().coverage),
      mSurfaceSpeed(ForcePhaseDef{}.speedWindowS, periodS) {
    const double ticks = periodS > 0.0 ? std::ceil(mGeometry->exercise().timeLimitS / periodS) + 16.0 : 0.0;
    mPhaseSamples.reserve(std::size_t(std::min(ticks, kMaxPhaseSamples)));
    mLumpMaxSinkMm.assign(mGeometry->lumps().size(), 0.0);
}

void PalpationExamination::add(const TaskTick& t, ScoreGuidance& guidance) {
    const VertexId touched = t.touched;
    if (!t.contact || !t.haveContactPoint || touched >= mGeometry->vertexCount()) {
        mSurfaceSpeed.reset();
        return;
    }
    mCoverage.add(touched, t.contactPointMm, t.forceN);
    guidance.coverageFraction = mCoverage.coveredFraction();
    // The speed along the surface over a window tells search from palpation; a contact's first
    // tick has none.
    const std::optional<double> speed = mSurfaceSpeed.add(t.dtS, glm::dvec3(t.contactPointMm),
                                                          glm::dvec3(mGeometry->normals()[touched]));
    if (speed && mPhaseSamples.size() < mPhaseSamples.capacity()) mPhaseSamples.push_back({t.forceN, *speed});
    // How deep the surface went over each lump, and the tissue's force per mm of sink elsewhere.
    const double sinkMm = t.maxDisplacementMm;
    const int lump = mGeometry->lumpOfVertex().empty() ? -1 : mGeometry->lumpOfVertex()[touched];
    if (lump >= 0 && std::size_t(lump) < mLumpMaxSinkMm.size()) {
        mLumpMaxSinkMm[std::size_t(lump)] = std::max(mLumpMaxSinkMm[std::size_t(lump)], sinkMm);
    } else if (sinkMm >= kMinSinkForStiffnessMm) {
        mSoftForceSumN += t.forceN;
        mSoftSinkSumMm += sinkMm;
    }
}

std::optional<double> PalpationExamination::forcePerMm() const {
    if (mSoftSinkSumMm <= 0.0) return std::nullopt;
    return mSoftForceSumN / mSoftSinkSumMm;
}

PalpationSummary PalpationExamination::summary(bool detail) const {
    PalpationSummary p;
    p.coverage = mGeometry->exercise().coverage;
    p.coverageFraction = mCoverage.coveredFraction();
    if (detail) {
        p.peakForceN = mCoverage.peakForceN();
        p.forceByPhase = forceByPhase(mPhaseSamples);
    }
    return p;
}

void PalpationExamination::addCommonFeedback(PalpationSummary& p, bool somethingToFind) const {
    const ForceByPhase& phases = p.forceByPhase;
    if (somethingToFind && phases.palpationOverSearch && *phases.palpationOverSearch < 1.0)
        p.feedback.push_back({"light_palpation",
                              "Pressed no harder to palpate than to search (median " +
                                  oneDecimal(phases.palpation->p50N) + " N against " + oneDecimal(phases.search->p50N) +
                                  " N): press in on a spot that feels different.",
                              {phases.palpation->p50N, phases.search->p50N}});
}

}  // namespace palpate
