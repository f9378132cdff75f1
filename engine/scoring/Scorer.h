#pragma once
// Scores an exercise session tick by tick: feed it every tick's ScoreSample in order (and marks),
// ask for report() or guidance() at any time. The one scoring path: live sessions (LiveScorer)
// and recordings (ReplayScorer) both come here with the same samples, so they give the same
// score bit for bit. docs/scoring.md defines every metric in terms of what is done here.
//
// Not thread-safe; no allocation per sample (the GUI's 60 Hz polling may call report(), which
// allocates its result).

#include "engine/exercise/ExerciseGeometry.h"
#include "engine/exercise/ExerciseTask.h"
#include "engine/exercise/ScoreReport.h"
#include "engine/scoring/ScoreSample.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

class Scorer {
public:
    /// `periodS`: the loop period (the first tick's length; later ticks use the clock).
    Scorer(std::shared_ptr<const ExerciseGeometry> geometry, double periodS);

    /// A user's mark (a Mark event) at `tick`. Give a tick's marks before its sample; a mark for a
    /// tick already scored is taken at the next sample (LiveScorer prevents that case).
    /// `examinationDone`: the mark ends a detect-lumps examination (kExaminationDoneMark) instead
    /// of being a finding.
    void addMark(std::uint64_t tick, bool examinationDone = false);
    /// Whether a Mark event's text is the one that ends an examination.
    static bool isExaminationDone(const std::string& markText);
    /// The next tick. Ticks must come in order.
    void addSample(const ScoreSample& sample);
    /// Ticks after the end of the exercise (completion or time limit) that were not looked at.
    void skipTicksAfterEnd(std::uint64_t count) { mTicksAfterEnd += count; }
    /// A warning for the report (gaps, replay differences), kept once.
    void addWarning(const std::string& warning);

    /// Completed or out of time: later samples are counted, not scored.
    bool over() const { return mGuidance.over(); }
    bool started() const { return mStarted; }
    std::uint64_t lastTick() const { return mLastTick; }
    const ScoreGuidance& guidance() const { return mGuidance; }
    const ExerciseGeometry& geometry() const { return *mGeometry; }
    /// The score so far (the final one once over() or the session ended).
    ScoreReport report() const { return report(true); }
    /// The same score without what only the end needs: the palpation summary's heat map and force
    /// by phase (sorting every contact tick's force), which no metric reads. For a display's
    /// every frame.
    double scoreSoFar() const { return report(false).score; }

private:
    ScoreReport report(bool detail) const;
    void complete();

    std::shared_ptr<const ExerciseGeometry> mGeometry;
    const Exercise& mExercise;
    double mPeriodS;
    /// What the exercise's kind asks the trainee to do (ExerciseKind::makeTask).
    std::unique_ptr<ExerciseTask> mTask;

    // Stream state.
    bool mStarted = false;
    std::uint64_t mFirstTick = 0, mLastTick = 0;
    double mPreviousNowS = 0.0;
    bool mHaveTool = false, mHavePreviousTool = false;
    glm::vec3 mToolMm{0.0f}, mPreviousToolMm{0.0f}, mStartToolMm{0.0f};
    glm::vec3 mContactPointMm{0.0f};
    bool mHaveButtons = false;
    std::uint32_t mButtons = 0;
    struct PendingMark {
        std::uint64_t tick;
        bool done;
    };
    std::vector<PendingMark> mPendingMarks;  // not yet reached
    std::uint64_t mMarks = 0;
    bool mAboveExcessive = false;
    std::uint64_t mTicksScored = 0, mTicksAfterEnd = 0;
    std::vector<std::string> mWarnings;

    // Sums every kind measures.
    double mElapsedS = 0.0;
    double mCompletionTimeS = 0.0;
    double mPeakForceN = 0.0, mImpulseNs = 0.0;
    double mContactS = 0.0, mContactForceNs = 0.0;
    std::uint64_t mExcessiveEvents = 0;
    double mExcessiveS = 0.0;
    double mDamageS = 0.0, mDamageAreaMm2 = 0.0, mMaxDisplacementMm = 0.0;
    double mPathLengthMm = 0.0;

    ScoreGuidance mGuidance;
};

}  // namespace palpate
