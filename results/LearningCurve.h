#pragma once
// A trainee's learning curve of one exercise from the results database (docs/scoring.md,
// "Proficiency"): their scored sessions (not experts', not stopped) oldest first, the experts'
// standard, the verdict on each session, and the chart's data. `palpate-cli trainee curve` and the
// History dock both draw it from here.

#include "results/LearningCurveData.h"
#include "results/ResultsDatabase.h"
#include "engine/exercise/Exercise.h"
#include "engine/scoring/Proficiency.h"
#include "engine/scoring/Staircase.h"

#include <string>
#include <vector>

namespace palpate {

/// The metrics a stored result carries (its metricsJson), by name.
MetricValues storedMetricValues(const ResultRecord& result);
/// The trainee's scored sessions of the exercise that are not experts', oldest first.
std::vector<ResultRecord> traineeSessionsOf(const ResultsDatabase& db, qint64 traineeId, const QString& exercisePath,
                                            const QString& exerciseName);
/// The standard from the exercise's scored expert sessions.
ProficiencyStandard expertStandardFor(const ResultsDatabase& db, const Exercise& exercise, const QString& exercisePath);

struct LearningCurve {
    std::vector<ResultRecord> sessions;
    std::vector<MetricValues> values;    ///< per session
    ProficiencyStandard standard;
    ProficiencyProgress progress;
    std::vector<std::string> metrics;    ///< the ones drawn
    LearningCurveData chart;
};

/// The curve; `metrics` empty: the standard's deciding metrics, else every metric the first
/// session has. No sessions gives an empty `sessions` (the caller says so).
LearningCurve learningCurve(const ResultsDatabase& db, qint64 traineeId, const Exercise& exercise,
                            const QString& exercisePath, const QString& title, std::vector<std::string> metrics = {});

}  // namespace palpate
