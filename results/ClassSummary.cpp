#include "results/ClassSummary.h"

#include "base/io/CsvField.h"

#include "results/LearningCurve.h"
#include "engine/exercise/ExerciseFile.h"
#include "engine/scoring/Proficiency.h"

#include <QDir>
#include <QFileInfo>

#include <map>
#include <tuple>

namespace palpate {

std::vector<ClassRow> classSummary(const std::vector<ResultRecord>& results, const ExerciseLookup& lookup) {
    // Expert sessions per exercise (the marks) and trainees' scored sessions per (trainee, exercise).
    std::map<QString, std::vector<const ResultRecord*>> experts;
    // By class, then trainee, then exercise: the view's order.
    std::map<std::tuple<QString, QString, QString>, std::vector<const ResultRecord*>> sessions;
    for (const ResultRecord& r : results) {
        if (!isScored(r.outcome)) continue;
        if (r.expert) experts[r.exerciseName].push_back(&r);
        else sessions[{r.traineeClass, r.traineeName, r.exerciseName}].push_back(&r);
    }
    std::map<QString, std::optional<Exercise>> exercises;
    auto exerciseNamed = [&](const QString& name, const std::vector<const ResultRecord*>& rows) -> const std::optional<Exercise>& {
        auto it = exercises.find(name);
        if (it != exercises.end()) return it->second;
        std::optional<Exercise> found;
        for (const ResultRecord* r : rows)
            if (!found) found = lookup(r->exercisePath, r->exerciseName);
        for (const ResultRecord* r : experts[name])
            if (!found) found = lookup(r->exercisePath, r->exerciseName);
        return exercises[name] = found;
    };
    std::vector<ClassRow> out;
    for (const auto& [key, rows] : sessions) {
        // Oldest first (the results come ordered by start time).
        ClassRow row;
        const auto& [className, trainee, exerciseName] = key;
        row.className = className;
        row.trainee = trainee;
        row.exercise = exerciseName;
        row.sessions = int(rows.size());
        row.latestScore = rows.back()->score;
        row.latestUtc = rows.back()->startedUtc;
        for (const ResultRecord* r : rows) row.bestScore = std::max(row.bestScore, r->score);
        const std::optional<Exercise>& exercise = exerciseNamed(exerciseName, rows);
        if (!exercise) {
            row.verdict = QStringLiteral("no standard");
            row.standardNote = QStringLiteral("the exercise file was not found");
        } else {
            std::vector<MetricValues> expertValues, values;
            for (const ResultRecord* r : experts[exerciseName]) expertValues.push_back(storedMetricValues(*r));
            for (const ResultRecord* r : rows) values.push_back(storedMetricValues(*r));
            const ProficiencyStandard standard = buildProficiencyStandard(*exercise, expertValues);
            if (!standard.valid()) {
                row.verdict = QStringLiteral("no standard");
                row.standardNote = QString::fromStdString(standard.problem);
            } else {
                const ProficiencyProgress progress = judgeSessions(standard, values);
                row.verdict = progress.proficient()              ? QStringLiteral("proficient")
                              : progress.sessions.back().passed ? QStringLiteral("passed")
                                                                : QStringLiteral("not yet");
            }
        }
        out.push_back(std::move(row));
    }
    return out;
}

QString classSummaryCsv(const std::vector<ClassRow>& rows) {
    const auto field = [](const QString& s) { return QString::fromStdString(csvTextField(s.toStdString())); };
    QString out = QStringLiteral("class,trainee,exercise,sessions,latest_score,latest_time,best_score,verdict,note\n");
    for (const ClassRow& r : rows)
        out += QStringList{field(r.className),
                           field(r.trainee),
                           field(r.exercise),
                           QString::number(r.sessions),
                           QString::number(r.latestScore),
                           r.latestUtc.toString(Qt::ISODate),
                           QString::number(r.bestScore),
                           field(r.verdict),
                           field(r.standardNote)}
                   .join(QLatin1Char(',')) +
               QLatin1Char('\n');
    return out;
}

ExerciseLookup defaultExerciseLookup(const QString& examplesFolder) {
    return [examplesFolder](const QString& path, const QString& name) -> std::optional<Exercise> {
        if (!path.isEmpty() && QFileInfo::exists(path))
            if (ExerciseLoadResult r = loadExercise(path.toStdString()); r.exercise) return r.exercise;
        const QDir dir(examplesFolder);
        for (const QString& file : dir.entryList({QStringLiteral("*.json")}, QDir::Files))
            if (ExerciseLoadResult r = loadExercise(dir.filePath(file).toStdString());
                r.exercise && QString::fromStdString(r.exercise->name) == name)
                return r.exercise;
        return std::nullopt;
    };
}

}  // namespace palpate
