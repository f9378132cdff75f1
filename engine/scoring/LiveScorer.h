#pragma once
// The running score of a session being recorded: follows the recording file as the writer appends
// to it (RecordingReader::openLive), replays the new ticks with the exercise's physics and scores
// them with the same ReplayScorer that scores a finished recording, so the final live score
// equals the replayed one bit for bit. The GUI polls it at display rate for the score so far and
// the guidance (current target, hold progress, force window, path covered, time left).
//
//   LiveScorer live(session->path(), exercise);   // after RecordingSession::start
//   every frame:  live.poll();  show(live.guidance(), live.report().score);
//   at the end:   session->stop();  ScoreReport final = live.finish();
//
// Ticks within holdBackS of the newest written tick wait one more poll: a mark can reach the file
// one chunk after its tick, and it must be scored at its tick. A mark later than that makes the
// scorer start again from the beginning (exact, and rare). One thread.

#include "engine/record/RecordingReader.h"
#include "engine/scoring/ReplayScorer.h"

#include <memory>
#include <optional>
#include <string>

namespace palpate {

struct LiveScorerDef {
    double holdBackS = 0.1;
    ReplayScorerDef options;
};

class LiveScorer {
public:
    /// `exercise`: what to grade by; nullopt takes the one in the recording's note.
    LiveScorer(std::string recordingPath, std::optional<Exercise> exercise, LiveScorerDef def = {});
    LiveScorer(const LiveScorer&) = delete;
    LiveScorer& operator=(const LiveScorer&) = delete;

    /// Reads what was appended, replays and scores it (up to the hold-back). Returns the ticks
    /// replayed by this call. Cheap when nothing is new.
    std::uint64_t poll();
    /// The session has ended (RecordingSession::stop returned) or its writer is gone: reads the
    /// rest, scores every tick and returns the final report.
    ScoreReport finish();

    /// Why it cannot score (no exercise in the file, another mesh, ...); "" while all is well.
    const std::string& error() const { return mError; }
    /// Scoring has begun (the file has a header and ticks).
    bool started() const { return mScorer != nullptr; }
    /// The writer closed the file (its end chunk was read).
    bool recordingEnded() const { return mReader.summary().closedCleanly; }
    /// The exercise is over (completed or out of time): the session may stop.
    bool exerciseOver() const { return mScorer && mScorer->scorer().over(); }
    const ScoreGuidance& guidance() const;
    /// The score so far (an empty report before started()).
    ScoreReport report() const;
    /// Its score alone, cheaply enough for every frame (Scorer::scoreSoFar); 0 before started().
    double scoreSoFar() const;
    std::uint64_t scoredThroughTick() const { return mScorer ? mScorer->currentTick() : 0; }
    /// Times a late mark made it score again from the start.
    int restarts() const { return mRestarts; }
    const RecordingReader& reader() const { return mReader; }

private:
    bool ensureScorer();
    bool lateMark() const;

    std::string mPath;
    std::optional<Exercise> mExercise;
    LiveScorerDef mDef;
    RecordingReader mReader;
    bool mOpened = false;
    std::unique_ptr<ReplayScorer> mScorer;
    std::string mError;
    int mRestarts = 0;
    ScoreGuidance mNoGuidance;
};

}  // namespace palpate
