#pragma once
// Shared pieces of the scoring tests: the shipped example exercises, their scripted tool paths
// (waypoints plus "# mark-at T" lines), and a stepped, recorded session of an exercise driven by
// such a script, with a hook to poll a live scorer between flushes.

#include "device/WaypointFile.h"
#include "engine/loop/HapticLoop.h"
#include "engine/record/RecordingSession.h"
#include "engine/scoring/ExerciseSession.h"

#include <functional>
#include <string>
#include <vector>

namespace palpate::test {

std::string resourcesDir();
/// Finds resources under the source tree's resources/.
ResourceFinder testResourceFinder();
/// resources/exercises/<name>.json, loaded (fails the test on errors).
Exercise loadExampleExercise(const std::string& name);

/// A scripted trainee: where the tool goes, and when the mark button is pressed.
struct TraineeScript {
    std::vector<Waypoint> waypoints;
    std::vector<double> marksS;  ///< loop times
    double doneS = -1.0;         ///< "# done-at T": the examination is finished then (< 0: never)
    double durationS() const { return waypoints.empty() ? 0.0 : waypoints.back().timeS; }
};
/// Reads a waypoint file and its "# mark-at T" lines.
TraineeScript loadTraineeScript(const std::string& path);

struct SessionRunDef {
    double seconds = -1.0;           ///< < 0: the script's duration + 1 s, at most the time limit + 0.5 s
    std::uint64_t flushEveryTicks = 250;
    /// Called after each flush with the loop's tick (a live scorer polls here).
    std::function<void(std::uint64_t tick)> afterFlush;
    /// Press the mark after the next flush and its afterFlush, so that the mark's tick is already
    /// in the file (and scored) when the mark reaches it: a late mark.
    bool marksAfterFlush = false;
    /// The recorder's ring and chunking (a small ring and rare flushes make gaps).
    RecordingWriterDef writer;
    /// Which ticks (1-based) run late, as on a loaded machine; null: every tick on time.
    std::function<bool(std::uint64_t tick)> tickOverran;
};

/// Runs a stepped session of `exercise` driven by `script` and records it to `recordingPath`
/// (header note carrying the exercise). Returns the loop's determinism hash.
std::uint64_t runScriptedSession(const Exercise& exercise, const TraineeScript& script,
                                 const std::string& recordingPath, const SessionRunDef& def = {});

}  // namespace palpate::test
