#include "engine/scoring/LiveScorer.h"

#include <cmath>

namespace palpate {

LiveScorer::LiveScorer(std::string recordingPath, std::optional<Exercise> exercise, LiveScorerDef def)
    : mPath(std::move(recordingPath)), mExercise(std::move(exercise)), mDef(std::move(def)) {
    if (mExercise) mNoGuidance.timeLeftS = mExercise->timeLimitS;
}

const ScoreGuidance& LiveScorer::guidance() const { return mScorer ? mScorer->scorer().guidance() : mNoGuidance; }

ScoreReport LiveScorer::report() const { return mScorer ? mScorer->report() : ScoreReport{}; }

double LiveScorer::scoreSoFar() const { return mScorer ? mScorer->scorer().scoreSoFar() : 0.0; }

bool LiveScorer::ensureScorer() {
    if (mScorer) return true;
    if (!mReader.headerOk() || mReader.summary().ticks == 0) return false;  // nothing to replay yet
    mScorer = ReplayScorer::open(mReader, mExercise ? &*mExercise : nullptr, mError, mDef.options);
    return mScorer != nullptr;
}

bool LiveScorer::lateMark() const {
    // Marks at or before the ticks already scored that the scorer has not had.
    std::uint64_t marks = 0;
    for (const RecordingEvent& e : mReader.events()) {
        if (e.tick > mScorer->marksThroughTick()) break;
        if (e.kind == EventKind::Mark) ++marks;
    }
    return marks != mScorer->marksFed();
}

std::uint64_t LiveScorer::poll() {
    if (!mError.empty()) return 0;
    if (!mOpened) {
        mReader = RecordingReader::openLive(mPath);
        mOpened = true;
    } else if (mReader.live()) {
        if (!mReader.refresh() && !mScorer) return 0;
    }
    if (!mScorer) {
        if (!ensureScorer()) return 0;
    } else {
        mScorer->refresh();
    }
    if (lateMark()) {
        // A mark reached the file after its tick was scored: score again from the start.
        mScorer.reset();
        ++mRestarts;
        if (!ensureScorer()) return 0;
    }
    const bool ended = mReader.summary().closedCleanly;
    const std::uint64_t holdBack =
        ended ? 0 : std::uint64_t(std::ceil(mDef.holdBackS * mReader.header().rateHz));
    const std::uint64_t newest = mScorer->lastReplayableTick();
    if (newest < holdBack) return 0;
    return mScorer->advanceTo(newest - holdBack);
}

ScoreReport LiveScorer::finish() {
    if (!mOpened) {
        mReader = RecordingReader::openLive(mPath);
        mOpened = true;
    }
    if (mReader.live()) {
        mReader.refresh();
        mReader.finishLive();
    }
    if (!mError.empty()) return {};
    if (!mScorer) {
        if (!ensureScorer()) {
            if (mError.empty()) mError = mPath + ": no ticks to score";
            return {};
        }
    } else {
        mScorer->refresh();
        if (lateMark()) {
            mScorer.reset();
            ++mRestarts;
            if (!ensureScorer()) return {};
        }
    }
    mScorer->advanceAll();
    return mScorer->report();
}

}  // namespace palpate
