#include "engine/scoring/ReplayScorer.h"

#include "engine/exercise/ExerciseKind.h"

#include "engine/core/MeshHash.h"
#include "engine/exercise/RecordedExercise.h"

#include <algorithm>
#include <sstream>

namespace palpate {

namespace {

/// The same task and grading (the files may name the mesh and preset differently; whether the
/// mesh, in its unit, is the recorded one is the mesh hash's to say; translations change no task).
bool sameExercise(Exercise a, Exercise b) {
    a.translations.clear();
    b.translations.clear();
    a.meshPath = b.meshPath = a.tissuePresetPath = b.tissuePresetPath = "";
    a.meshUnit = b.meshUnit = kMillimetres;
    return exerciseToJson(a, -1) == exerciseToJson(b, -1);
}

std::string hex(std::uint64_t v) {
    std::ostringstream s;
    s << std::hex << v;
    return s.str();
}

}  // namespace

std::unique_ptr<ReplayScorer> ReplayScorer::open(const RecordingReader& reader, const Exercise* exercise,
                                                 std::string& error, const ReplayScorerDef& options) {
    if (!reader.fileError().empty()) {
        error = reader.fileError();
        return nullptr;
    }
    if (!reader.headerOk()) {
        error = reader.name() + ": cannot score without the header: " + reader.headerError();
        return nullptr;
    }
    std::unique_ptr<ReplayScorer> s(new ReplayScorer(reader));
    const RecordingHeader& h = reader.header();
    std::vector<std::string> noteErrors;
    const std::optional<Exercise> recorded = recordedExercise(h, noteErrors);
    if (!noteErrors.empty())
        s->mWarnings.push_back("the recording's note carries an exercise that does not read (" + noteErrors.front() + ")");
    if (!exercise && !recorded) {
        error = reader.name() + ": the recording does not say which exercise it was (give the exercise file)";
        return nullptr;
    }
    const Exercise& grade = exercise ? *exercise : *recorded;
    const std::string exerciseName = exercise && !exercise->sourcePath.empty() ? exercise->sourcePath : "exercise '" + grade.name + "'";

    if (exercise) {
        // The recording must be of the exercise's mesh: vertex ids, targets and damage refer to it.
        const std::string meshPath = resolveExercisePath(*exercise, exercise->meshPath, options.findResource);
        if (meshPath.empty()) {
            s->mWarnings.push_back("the exercise's mesh " + exercise->meshPath +
                                   " was not found: the exercise is placed on the recording's mesh " + h.scene.meshPath);
        } else {
            auto loaded = TissueMesh::load(meshPath, exercise->meshUnit);
            if (!loaded.mesh) {
                error = exerciseName + ": " + loaded.error();
                return nullptr;
            }
            const std::uint64_t hash = meshHash(*loaded.mesh);
            if (hash != h.scene.meshHash) {
                error = reader.name() + " was recorded on " + h.scene.meshPath + " (" + std::to_string(h.scene.vertexCount) +
                        " vertices, hash " + hex(h.scene.meshHash) + "), but " + exerciseName + " is on " + meshPath +
                        " (" + std::to_string(loaded.mesh->vertexCount()) + " vertices, hash " + hex(hash) +
                        "): a different mesh";
                return nullptr;
            }
        }
        if (recorded && !sameExercise(*recorded, *exercise))
            s->mWarnings.push_back("the recording was made with another version of exercise '" + recorded->name +
                                   "': graded by " + exerciseName + ", replayed with the recorded one's physics");
    }
    if (!recorded && exerciseKind(grade.type).changesTissue())
        s->mWarnings.push_back("the recording does not carry the exercise: replayed without the inclusion (the damage "
                               "metrics are right only if the session had none)");

    // The player gives the scenes the recorded exercise's physics (RecordedExercise.h).
    ReplayDef replay;
    replay.meshPath = options.meshPath;
    replay.meshUnit = options.meshUnit;
    s->mPlayer = RecordingPlayer::open(reader, error, replay);
    if (!s->mPlayer) return nullptr;
    std::string problem;
    auto geometry = ExerciseGeometry::build(grade, s->mPlayer->mesh(), problem);
    if (!geometry) {
        error = exerciseName + ": " + problem;
        return nullptr;
    }
    s->mProbe = std::make_unique<DamageProbe>(geometry->restMm(), geometry->vertexAreasMm2(), grade.displacementLimitMm);
    s->mScorer = std::make_unique<Scorer>(geometry, reader.periodS());
    return s;
}

void ReplayScorer::feedMarks(std::uint64_t throughTick) {
    const auto& events = mReader.events();
    // Events are ordered by tick; a live reader may insert some, so find the place by tick.
    auto it = !mMarksStarted ? events.begin()
                             : std::upper_bound(events.begin(), events.end(), mMarksThroughTick,
                                                [](std::uint64_t t, const RecordingEvent& e) { return t < e.tick; });
    for (; it != events.end() && it->tick <= throughTick; ++it)
        if (it->kind == EventKind::Mark) {
            mScorer->addMark(it->tick, Scorer::isExaminationDone(it->text));
            ++mMarksFed;
        }
    mMarksStarted = true;
    mMarksThroughTick = std::max(mMarksThroughTick, throughTick);
}

std::uint64_t ReplayScorer::advanceTo(std::uint64_t tick) {
    tick = std::min(tick, mPlayer->lastTick());
    std::uint64_t replayed = 0;
    while (!mStarted || mCurrentTick < tick) {
        if (mStarted && mScorer->over()) {
            // Nothing more to score: the rest is counted, not replayed.
            feedMarks(tick);
            mScorer->skipTicksAfterEnd(tick - mCurrentTick);
            mCurrentTick = tick;
            break;
        }
        if (mPlayer->step(1) == 0) break;  // the replay stopped (gap, damage) or reached the end so far
        mStarted = true;
        mCurrentTick = mPlayer->currentTick();
        feedMarks(mCurrentTick);
        ScoreSample sample;
        sample.tick = *mPlayer->recordedTick();
        if (mPlayer->mesh().vertexCount() == mScorer->geometry().vertexCount())
            sample.damage = mProbe->measure(mPlayer->snapshot(), [this] { return mPlayer->positionsMm(); });
        mScorer->addSample(sample);
        ++replayed;
    }
    return replayed;
}

ScoreReport ReplayScorer::report() const {
    ScoreReport r = mScorer->report();
    for (const std::string& w : mWarnings) r.warnings.push_back(w);
    const ReplayStatus& status = mPlayer->status();
    if (status.mismatch)
        r.warnings.push_back("the replay differs from the recording (first at " + status.firstMismatch +
                             "): the damage metrics follow the replay, the others the recording");
    if (!status.stopReason.empty())
        r.warnings.push_back("scored through tick " + std::to_string(mCurrentTick) + " only: " + status.stopReason);
    if (!mReader.live()) {
        if (!mReader.damage().empty())
            r.warnings.push_back("the recording is damaged (" + std::to_string(mReader.damage().size()) +
                                 " regions): scored what replays");
        else if (!mReader.summary().closedCleanly)
            r.warnings.push_back("the recording did not close cleanly (the session crashed or was killed): scored what is there");
    }
    return r;
}

ScoreReport scoreRecording(const RecordingReader& reader, const Exercise* exercise, std::string& error,
                           const ReplayScorerDef& options) {
    auto scorer = ReplayScorer::open(reader, exercise, error, options);
    if (!scorer) return {};
    scorer->advanceAll();
    return scorer->report();
}

}  // namespace palpate
