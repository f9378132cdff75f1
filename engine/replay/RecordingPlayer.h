#pragma once
// Replays a recording through the engine: a stepped HapticLoop on the recorded scene, fed by a
// ReplayDevice with the recorded device input, clock and overrun flags, with the recorded parameter
// sets, scene and device switches and pauses re-applied at the ticks where the loop applied them.
// The forces, touched vertices and contact it computes must match the recording bit for bit; each
// chunk's stored determinism hash is checked when the replay passes the chunk's last tick.
//
// For the GUI's player: open, then seek/step and read snapshot() (tool, force, displaced
// vertices) or positionsMm() (the whole surface) at the current tick. All calls on one thread.
// Seeking backwards replays from the start (the model's state is only reachable by replaying; at
// about 10 µs a tick, a minute of recording takes about half a second).

#include "engine/loop/HapticLoop.h"
#include "engine/record/RecordingReader.h"
#include "engine/record/ReplayDevice.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace palpate {

struct ReplayDef {
    /// Load the initial mesh from here instead of the header's path (its hash must still match).
    std::string meshPath;
    /// Read that mesh in this unit instead of the recorded one (its hash must still match).
    std::optional<MeshUnit> meshUnit;
    /// Refuse a mesh whose hash differs from the recorded one (ids and forces would not reproduce).
    bool requireMeshHash = true;
    /// Called on every scene the player builds (the header's and each recorded switch), before the
    /// loop uses it: what the recording session did to its scenes beyond the header. Returns ""
    /// or why the scene cannot be used (the player then fails to open, or stops at the switch).
    /// Unset: the physics of the exercise the header's note carries, if any (a find-the-lump
    /// inclusion, engine/exercise/RecordedExercise.h), as the session had it.
    std::function<std::string(HapticScene& scene)> prepareScene;
    /// Off: replay the bare recorded scenes even when the note carries an exercise.
    bool applyRecordedExercise = true;
};

/// How a replay went, so far.
struct ReplayStatus {
    std::uint64_t ticksReplayed = 0;
    std::uint64_t mismatches = 0;         ///< ticks whose force, touched vertex or contact differ
    bool mismatch = false;
    std::uint64_t firstMismatchTick = 0;
    std::string firstMismatch;            ///< what differed at that tick, recorded vs replayed
    std::uint64_t hashChecks = 0;         ///< chunk hashes compared
    std::uint64_t hashMismatches = 0;
    std::uint64_t finalHash = 0;          ///< the replay's determinism hash after its last tick
    /// Divergence events (format 2) met, and ticks in which the replayed guard fired. A tick whose
    /// recorded and replayed divergence differ counts as a mismatch (format 1 files: not compared).
    std::uint64_t divergencesRecorded = 0;
    std::uint64_t divergencesReplayed = 0;
    bool complete = false;                ///< replayed every recovered tick
    std::string stopReason;               ///< why it stopped early (gap, damage, undescribed scene)
    bool ok() const { return complete && !mismatch && hashMismatches == 0; }
};

class RecordingPlayer {
public:
    /// Builds the recorded scene and a stepped loop. Null with `error` when the header is damaged,
    /// the mesh is missing or differs, or the parameters do not validate. `reader` must outlive
    /// the player.
    static std::unique_ptr<RecordingPlayer> open(const RecordingReader& reader, std::string& error,
                                                 const ReplayDef& options = {});
    ~RecordingPlayer();

    /// First recovered tick, and the last one a replay can reach (before a gap or damage).
    std::uint64_t firstTick() const { return mFirstTick; }
    std::uint64_t lastTick() const { return mLastReplayableTick; }
    /// The last tick replayed (firstTick() - 1 before the first step).
    std::uint64_t currentTick() const { return mCurrentTick; }
    bool atEnd() const { return mEnded; }

    /// For a reader that follows a file being written (RecordingReader::openLive): after its
    /// refresh(), takes in the chunks it added, so that step() can go on past the old end. Returns
    /// true when lastTick() moved.
    bool refresh();

    /// Replays up to n ticks; returns how many ran (fewer at the end or when it must stop).
    std::uint64_t step(std::uint64_t n = 1);
    /// Replays until currentTick() == tick (restarting from the first tick to go back). False
    /// when the tick is outside firstTick()..lastTick().
    bool seek(std::uint64_t tick);

    /// The recording's tick at currentTick() (null before the first step).
    const RecordedTick* recordedTick() const { return mHaveCurrent ? &mCurrent : nullptr; }
    /// The replayed loop's snapshot at currentTick(): tool, force, contact, displaced vertices.
    const HapticSnapshot& snapshot() { return mLoop->newestSnapshot(); }
    /// The whole surface at currentTick(), in the mesh's vertex order.
    std::span<const glm::vec3> positionsMm() { return mLoop->scene().model().positionsMm(); }
    const TissueMesh& mesh() { return mLoop->scene().mesh(); }
    const ReplayStatus& status() const { return mStatus; }

private:
    RecordingPlayer(const RecordingReader& reader, const ReplayDef& options);
    std::string restart();
    std::string findReplayableRange();
    std::unique_ptr<HapticScene> buildScene(const RecordedScene& scene, const std::string& pathOverride,
                                            const std::optional<MeshUnit>& unitOverride, std::string& error);
    bool nextRecord(RecordedTick& out);
    bool stepOne();
    bool applyEvents(std::uint64_t tick);
    void stop(const std::string& reason);

    const RecordingReader& mReader;
    ReplayDef mOptions;
    ReplayFeed mFeed;
    std::unique_ptr<HapticLoop> mLoop;
    std::map<std::pair<std::string, double>, TissueMesh> mMeshes;  // loaded meshes by path and mm per unit, reused on restart
    // The model of the scene last built for the loop: a ParamsApplied event replaces its
    // slope-ring parameters and sends it (HapticLoop::setModelParams).
    ModelDef mModel;

    std::uint64_t mFirstTick = 0, mLastReplayableTick = 0;
    std::uint64_t mCurrentTick = 0;
    bool mEnded = false;
    bool mPaused = false;
    std::size_t mChunk = 0;                // next chunk to decode
    std::vector<RecordedTick> mChunkTicks; // ticks of the chunk being replayed
    std::size_t mChunkPos = 0;
    std::size_t mChunkOfTicks = 0;         // index of that chunk in reader.chunks()
    std::size_t mNextEvent = 0;
    std::size_t mEventsSeen = 0;            // reader.events().size() when mNextEvent was set
    bool mEventsApplied = false;            // events up to mEventsThroughTick were applied
    std::uint64_t mEventsThroughTick = 0;
    std::size_t mRangeChunks = 0, mRangeDamage = 0;  // reader sizes findReplayableRange saw
    bool mStopped = false;                  // stop() ended the replay (not the end of the ticks)
    RecordedTick mCurrent;
    bool mHaveCurrent = false;
    DivergenceKind mExpectedDivergence = DivergenceKind::None;  // the recorded event for mExpectedDivergenceTick
    std::uint64_t mExpectedDivergenceTick = 0;
    ReplayStatus mStatus;
};

/// Replays a whole recording and checks it (what `palpate-cli record replay` does). When the
/// player cannot be built, `error` says why and the status is not ok.
ReplayStatus replayRecording(const RecordingReader& reader, std::string& error, const ReplayDef& options = {});

}  // namespace palpate
