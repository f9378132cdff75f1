#pragma once
// What every palpation exercise measures of the examination (docs/scoring.md, "Palpation"): the
// surface covered firmly enough, the force while searching and while palpating, and how deep the
// surface sank over each lump and elsewhere. The find-the-lump and detect-lumps tasks each hold
// one and add what is their own.

#include "engine/exercise/ExerciseGeometry.h"
#include "engine/exercise/ExerciseTask.h"
#include "engine/exercise/ForcePhases.h"
#include "engine/exercise/PalpationCoverage.h"

#include <memory>
#include <optional>
#include <vector>

namespace palpate {

class PalpationExamination {
public:
    /// `periodS`: the loop period; room for the force samples of the whole time limit is kept now
    /// (no allocation per tick).
    PalpationExamination(std::shared_ptr<const ExerciseGeometry> geometry, double periodS);

    /// One tick of exercise time; keeps the covered share in `guidance`.
    void add(const TaskTick& tick, ScoreGuidance& guidance);

    double coveredFraction() const { return mCoverage.coveredFraction(); }
    /// The deepest the surface sank over each lump, mm.
    const std::vector<double>& lumpMaxSinkMm() const { return mLumpMaxSinkMm; }
    /// The tissue's force per mm of sink away from lumps (none before a press deep enough).
    std::optional<double> forcePerMm() const;
    /// Coverage, and with `detail` the heat map and the force by phase (no feedback yet).
    PalpationSummary summary(bool detail) const;
    /// The feedback every palpation exercise gives, after the kind's own; `somethingToFind`: the
    /// tissue hides a lump (healthy tissue has no spot to press in on).
    void addCommonFeedback(PalpationSummary& summary, bool somethingToFind) const;

private:
    std::shared_ptr<const ExerciseGeometry> mGeometry;
    PalpationCoverage mCoverage;
    std::vector<ForceMotionSample> mPhaseSamples;  // reserved for the time limit
    SurfaceSpeed mSurfaceSpeed;
    std::vector<double> mLumpMaxSinkMm;
    double mSoftForceSumN = 0.0, mSoftSinkSumMm = 0.0;  // away from lumps
};

/// A number with one decimal, as feedback prints it.
std::string oneDecimal(double value);

}  // namespace palpate
