#pragma once
// Storing a scored recording as a trainee's session, as `trainee add-session` and
// `score --trainee` do (docs/scoring.md, "Proficiency" and "Staircase"): the trainee is added when
// new, the result committed, and the trainee's staircase moved when the session is its trial.

#include "results/ResultsDatabase.h"
#include "engine/exercise/Exercise.h"
#include "engine/exercise/ScoreReport.h"
#include "engine/record/RecordingReader.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace palpate::cli {

struct StoredSession {
    bool stored = false;             ///< the result is committed (even when `error` says more)
    qint64 resultId = -1;
    std::string exerciseName;
    nlohmann::json staircase;        ///< null, or {passed, level} when the session moved it
    std::string notice;              ///< stored, but something to tell (not a staircase trial, ...)
    std::string error;               ///< what failed ("" when all went)
};

/// `exercise`: the exercise the session was scored against (nullopt: the report's name only);
/// `exercisePath`: its exerciseKey ("" for the recording's own).
StoredSession storeScoredSession(ResultsDatabase& db, const std::string& traineeName, const ScoreReport& report,
                                 const std::optional<Exercise>& exercise, const QString& exercisePath,
                                 const RecordingReader& reader, const std::string& recordingPath, bool expert);

}  // namespace palpate::cli
