#include "app/cli/ExerciseRun.h"

#include "base/resources/ShippedResources.h"
#include "engine/scoring/Staircase.h"
#include "engine/exercise/ExerciseKind.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace palpate::cli {

std::unique_ptr<ExerciseRun> ExerciseRun::load(const std::string& exercisePath, const std::string& markAt,
                                               const std::string& doneAt, const std::string& level,
                                               std::string& error) {
    auto loaded = loadExercise(exercisePath);
    if (!loaded.exercise) {
        for (const auto& e : loaded.errors) error += (error.empty() ? "" : "\n") + e;
        return nullptr;
    }
    if (!level.empty()) {
        const auto& staircase = loaded.exercise->detectLumps.staircase;
        if (!exerciseKind(loaded.exercise->type).adaptive() || !staircase) {
            error = "--level: " + exercisePath + " has no staircase (detect_lumps.staircase)";
            return nullptr;
        }
        std::size_t used = 0;
        double value = std::nan("");
        try {
            value = std::stod(level, &used);
        } catch (...) {
        }
        const double lo = std::min(staircase->easiest, staircase->hardest), hi = std::max(staircase->easiest, staircase->hardest);
        if (used != level.size() || !(value >= lo && value <= hi)) {
            error = "--level: '" + level + "' is not a " + staircaseParameterName(staircase->parameter) + " between " +
                    std::to_string(lo) + " and " + std::to_string(hi) + " (the staircase's range)";
            return nullptr;
        }
        loaded.exercise = exerciseAtLevel(*loaded.exercise, value);
    }
    std::unique_ptr<ExerciseRun> run(new ExerciseRun());
    std::vector<std::string> errors;
    auto assets = loadExerciseAssets(*loaded.exercise, findResource, errors);
    if (!assets) {
        for (const auto& e : errors) error += (error.empty() ? "" : "\n") + e;
        return nullptr;
    }
    run->mAssets = std::move(*assets);
    std::stringstream list(markAt);
    std::string item;
    while (std::getline(list, item, ',')) {
        if (item.empty()) continue;
        try {
            std::size_t used = 0;
            const double s = std::stod(item, &used);
            if (used != item.size() || !std::isfinite(s) || s < 0.0) throw std::invalid_argument(item);
            run->mMarksS.push_back(s);
        } catch (...) {
            error = "--mark-at: '" + item + "' is not a time in seconds";
            return nullptr;
        }
    }
    std::sort(run->mMarksS.begin(), run->mMarksS.end());
    if (!doneAt.empty()) {
        try {
            std::size_t used = 0;
            run->mDoneS = std::stod(doneAt, &used);
            if (used != doneAt.size() || !std::isfinite(run->mDoneS) || run->mDoneS < 0.0) throw std::invalid_argument(doneAt);
        } catch (...) {
            error = "--done-at: '" + doneAt + "' is not a time in seconds";
            return nullptr;
        }
        if (!exerciseKind(run->mAssets.exercise.type).finishedByTrainee()) {
            error = "--done-at: the exercise '" + run->mAssets.exercise.name + "' is " +
                    std::string(exerciseTypeName(run->mAssets.exercise.type)) +
                    ", which ends by itself (only detect_lumps examinations are finished by the trainee)";
            return nullptr;
        }
    }
    return run;
}

std::string ExerciseRun::applyTo(HapticScene& scene) const { return applyExercisePhysics(*mAssets.geometry, scene); }

std::string ExerciseRun::note(const std::string& text, std::string& error) const {
    Exercise carried = mAssets.exercise;
    carried.meshPath = mAssets.meshPath;
    carried.tissuePresetPath = mAssets.presetPath;
    return exerciseRecordingNote(carried, text, error);
}

void ExerciseRun::follow(const std::string& recordingPath) {
    LiveScorerDef def;
    def.options.findResource = findResource;
    mLive = std::make_unique<LiveScorer>(recordingPath, mAssets.exercise, def);
}

void ExerciseRun::poll(HapticLoop& loop, RecordingSession* session) {
    if (session && mNextMark < mMarksS.size()) {
        const double nowS = loop.newestSnapshot().timeS;
        for (; mNextMark < mMarksS.size() && nowS >= mMarksS[mNextMark]; ++mNextMark) session->mark("mark (--mark-at)");
    }
    if (session && mDoneS >= 0.0 && !mDoneMarked && loop.newestSnapshot().timeS >= mDoneS) {
        session->mark(kExaminationDoneMark);
        mDoneMarked = true;
    }
    if (mLive) mLive->poll();
}

std::optional<ScoreReport> ExerciseRun::finish(std::string& error) {
    if (!mLive) {
        error = "the session was not recorded (--record FILE): nothing to score";
        return std::nullopt;
    }
    ScoreReport report = mLive->finish();
    if (!mLive->error().empty()) {
        error = mLive->error();
        return std::nullopt;
    }
    return report;
}

}  // namespace palpate::cli
