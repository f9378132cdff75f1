#pragma once
// The instructor's view of a class (docs/results-store.md, "Class view"): for every trainee and
// exercise, how many sessions, the latest and the best score, and whether they pass against the
// experts' marks (docs/scoring.md, "Proficiency"). Exercises are told apart by name here: the same
// exercise file has a different path on each workstation.

#include "results/ResultsDatabase.h"
#include "engine/exercise/Exercise.h"

#include <QString>

#include <functional>
#include <optional>
#include <vector>

namespace palpate {

struct ClassRow {
    QString className;         ///< the trainee's class on the server ("" when none)
    QString trainee;
    QString exercise;
    int sessions = 0;          ///< scored sessions (not stopped, not an expert's)
    double latestScore = 0.0;
    QDateTime latestUtc;
    double bestScore = 0.0;
    /// "proficient", "passed" (the latest passed, not yet twice in a row), "not yet", or
    /// "no standard" (no expert marks, or the exercise file was not found; `standardNote` says).
    QString verdict;
    QString standardNote;
};

/// Finds an exercise's definition (its rubric sets the marks) from a stored path and name; nullopt
/// when it cannot be read.
using ExerciseLookup = std::function<std::optional<Exercise>(const QString& path, const QString& name)>;

/// The rows, by class, trainee, then exercise. Trainees with no scored session of an exercise have no row
/// for it.
std::vector<ClassRow> classSummary(const std::vector<ResultRecord>& results, const ExerciseLookup& lookup);

/// The rows as CSV (header first).
QString classSummaryCsv(const std::vector<ClassRow>& rows);

/// Reads the exercise from the stored path if that file is there, else the exercise of that name
/// in `examplesFolder` (the shipped resources/exercises: a class usually trains on them).
ExerciseLookup defaultExerciseLookup(const QString& examplesFolder);

}  // namespace palpate
