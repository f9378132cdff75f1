#pragma once
// Scoring a recording = replaying it: a RecordingPlayer re-runs the engine tick by tick (with the
// exercise's physics, read from the recording's note), a DamageProbe reads the tissue after each
// tick, and a Scorer takes the recorded tick, the damage and the marks. LiveScorer drives the same
// class over a file still being written, which is why live and replayed scores are equal.
//
//   std::string error;
//   RecordingReader reader = RecordingReader::open("session.palprec");
//   ScoreReport report = scoreRecording(reader, &exercise, error);  // or nullptr: the recorded one

#include "engine/replay/RecordingPlayer.h"
#include "engine/record/RecordingReader.h"
#include "engine/scoring/DamageProbe.h"
#include "engine/exercise/ExerciseFile.h"
#include "engine/scoring/Scorer.h"

#include <memory>
#include <optional>
#include <string>

namespace palpate {

struct ReplayScorerDef {
    /// Load the recorded mesh from here instead of the header's path (ReplayDef::meshPath).
    std::string meshPath;
    /// Read it in this unit instead of the recorded one (ReplayDef::meshUnit).
    std::optional<MeshUnit> meshUnit;
    /// Resolves the exercise's mesh path under resources/ (for the check that the recording was
    /// made on the exercise's mesh).
    ResourceFinder findResource;
};

class ReplayScorer {
public:
    /// `exercise`: the exercise to grade by; null takes the one the recording's note carries.
    /// Null with `error` when there is none, the recording was made on another mesh (the message
    /// names both), or it cannot be replayed. `reader` must outlive the scorer.
    static std::unique_ptr<ReplayScorer> open(const RecordingReader& reader, const Exercise* exercise,
                                              std::string& error, const ReplayScorerDef& options = {});

    /// Replays and scores the ticks up to `tick` (at most to the last replayable one), giving the
    /// scorer each tick's marks before its sample. Once the exercise is over, later ticks are
    /// counted without being replayed. Returns the ticks replayed.
    std::uint64_t advanceTo(std::uint64_t tick);
    std::uint64_t advanceAll() { return advanceTo(~std::uint64_t(0)); }
    /// After the reader's refresh() (live): takes in the new chunks.
    bool refresh() { return mPlayer->refresh(); }

    /// The last tick scored or counted (0 before the first).
    std::uint64_t currentTick() const { return mCurrentTick; }
    std::uint64_t lastReplayableTick() const { return mPlayer->lastTick(); }
    /// Mark events given to the scorer, and the tick up to which they were looked for.
    std::uint64_t marksFed() const { return mMarksFed; }
    std::uint64_t marksThroughTick() const { return mMarksThroughTick; }

    const Scorer& scorer() const { return *mScorer; }
    const Exercise& exercise() const { return mScorer->geometry().exercise(); }
    /// The scorer's report with the replay's own warnings (differences, gaps, damage).
    ScoreReport report() const;

private:
    explicit ReplayScorer(const RecordingReader& reader) : mReader(reader) {}
    void feedMarks(std::uint64_t throughTick);

    const RecordingReader& mReader;
    std::unique_ptr<RecordingPlayer> mPlayer;
    std::unique_ptr<Scorer> mScorer;
    std::unique_ptr<DamageProbe> mProbe;
    std::vector<std::string> mWarnings;
    bool mStarted = false;
    std::uint64_t mCurrentTick = 0;
    std::uint64_t mMarksFed = 0;
    bool mMarksStarted = false;
    std::uint64_t mMarksThroughTick = 0;
};

/// Replays and scores a whole recording. On failure `error` says why and the report is empty.
ScoreReport scoreRecording(const RecordingReader& reader, const Exercise* exercise, std::string& error,
                           const ReplayScorerDef& options = {});

}  // namespace palpate
