#pragma once
// `palpate-cli run --exercise FILE [--mark-at S,..] [--done-at S]`: a headless session of a graded exercise. The
// session runs on the exercise's mesh and tissue preset with its physics (find the lump's
// inclusion), its recording's note carries the exercise, marks are pressed at the given loop
// times (a scripted trainee's button), and a LiveScorer follows the recording for the score.

#include "engine/loop/HapticLoop.h"
#include "engine/record/RecordingSession.h"
#include "engine/scoring/ExerciseSession.h"
#include "engine/scoring/LiveScorer.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace palpate::cli {

class ExerciseRun {
public:
    /// Loads the exercise, its mesh and preset; null with `error` (every problem, one a line).
    /// `markAt`: loop times in seconds, comma-separated ("" for none); `doneAt`: the loop time at
    /// which a detect-lumps examination is finished ("" for never); `level`: a staircase's level
    /// for every lump ("" for the file's lumps; docs/scoring.md, "Staircase").
    static std::unique_ptr<ExerciseRun> load(const std::string& exercisePath, const std::string& markAt,
                                             const std::string& doneAt, const std::string& level, std::string& error);

    const Exercise& exercise() const { return mAssets.exercise; }
    const TissuePreset& preset() const { return mAssets.preset; }
    const std::string& meshPath() const { return mAssets.meshPath; }
    const std::string& presetPath() const { return mAssets.presetPath; }
    /// The exercise's physics on the loop's scene (before the loop starts). "" or the problem.
    std::string applyTo(HapticScene& scene) const;
    /// The recording note: `text`, then the exercise. "" with `error` if it does not fit.
    std::string note(const std::string& text, std::string& error) const;
    /// After the session started: follow its file.
    void follow(const std::string& recordingPath);
    /// Every few ms while the loop runs: presses marks that are due and polls the live score.
    void poll(HapticLoop& loop, RecordingSession* session);
    /// The exercise is over (completed or out of time).
    bool over() const { return mLive && mLive->exerciseOver(); }
    /// After the session stopped: the final score (live), or nullopt with `error`.
    std::optional<ScoreReport> finish(std::string& error);

private:
    ExerciseAssets mAssets;
    std::vector<double> mMarksS;
    std::size_t mNextMark = 0;
    double mDoneS = -1.0;
    bool mDoneMarked = false;
    std::unique_ptr<LiveScorer> mLive;
};

}  // namespace palpate::cli
