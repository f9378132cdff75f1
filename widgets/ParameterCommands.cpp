#include "widgets/ParameterCommands.h"

#include <utility>

namespace palpate {

namespace {

bool sameTissue(const std::optional<TissueProperties>& a, const std::optional<TissueProperties>& b) {
    if (a.has_value() != b.has_value()) return false;
    if (!a) return true;
    return a->youngsModulusKPa == b->youngsModulusKPa && a->poissonRatio == b->poissonRatio &&
           a->toolRadiusMm == b->toolRadiusMm && a->source == b->source;
}

bool sameParams(const SlopeRingParams& a, const SlopeRingParams& b) {
    return a.ringCount == b.ringCount && a.slopeMagnitudeMmPerN == b.slopeMagnitudeMmPerN &&
           a.slopeLimitMmPerN == b.slopeLimitMmPerN && a.contactStiffnessNPerMm == b.contactStiffnessNPerMm &&
           a.forceRelaxation == b.forceRelaxation && a.springStiffnessNPerMm == b.springStiffnessNPerMm &&
           a.dampingRatio == b.dampingRatio && a.vertexMassKg == b.vertexMassKg;
}

bool sameModelParams(const TissuePreset& a, const TissuePreset& b) {
    const MassSpringParams &m = a.massSpring, &n = b.massSpring;
    const bool massSpring = m.vertexMassKg == n.vertexMassKg && m.anchorStiffnessNPerMm == n.anchorStiffnessNPerMm &&
                            m.edgeStiffnessNPerMm == n.edgeStiffnessNPerMm &&
                            m.contactStiffnessNPerMm == n.contactStiffnessNPerMm && m.dampingRatio == n.dampingRatio &&
                            m.substeps == n.substeps && m.maxSubsteps == n.maxSubsteps &&
                            m.cgMaxIterations == n.cgMaxIterations && m.cgTolerance == n.cgTolerance &&
                            m.localRingCount == n.localRingCount && m.localIntegrator == n.localIntegrator &&
                            m.restEpsilonMm == n.restEpsilonMm;
    const RadiusOfInfluenceParams &r = a.radiusOfInfluence, &s = b.radiusOfInfluence;
    const bool radius = r.radiusMm == s.radiusMm && r.degree == s.degree && r.coefficients == s.coefficients &&
                        r.stiffnessNPerMm == s.stiffnessNPerMm;
    const FfdParams &f = a.ffd, &g = b.ffd;
    const bool ffd = f.controlPointsPerAxis == g.controlPointsPerAxis && f.movedPerAxis == g.movedPerAxis &&
                     f.marginFraction == g.marginFraction && f.stiffnessNPerMm == g.stiffnessNPerMm;
    return a.modelKind == b.modelKind && massSpring && radius && ffd;
}

}  // namespace

bool samePreset(const TissuePreset& a, const TissuePreset& b) {
    return a.name == b.name && a.description == b.description && a.method == b.method && sameParams(a.params, b.params) &&
           a.octree.maxDepth == b.octree.maxDepth && a.octree.leafCapacity == b.octree.leafCapacity &&
           a.hapticRateHz == b.hapticRateHz && sameTissue(a.tissue, b.tissue) && sameModelParams(a, b);
}

ParameterEditCommand::ParameterEditCommand(const TissuePreset& before, const TissuePreset& after, const QString& text,
                                           int mergeKey, bool alreadyShown, PresetSink sink, QUndoCommand* parent)
    : QUndoCommand(text, parent),
      mBefore(before),
      mAfter(after),
      mMergeKey(mergeKey),
      mSkipNextRedo(alreadyShown),
      mSink(std::move(sink)) {}

void ParameterEditCommand::undo() {
    mSealed = true;
    mSink(mBefore);
}

void ParameterEditCommand::redo() {
    if (mSkipNextRedo) {
        mSkipNextRedo = false;
        return;
    }
    mSink(mAfter);
}

int ParameterEditCommand::id() const { return mMergeKey < 0 ? -1 : kIdBase + mMergeKey; }

bool ParameterEditCommand::mergeWith(const QUndoCommand* other) {
    if (mSealed || other->id() != id()) return false;
    const auto* edit = static_cast<const ParameterEditCommand*>(other);
    mAfter = edit->mAfter;
    setObsolete(samePreset(mBefore, mAfter));
    return true;
}

}  // namespace palpate
