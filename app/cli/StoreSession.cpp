// Built with the GUI only: the results database is Qt SQL's.
#ifdef PALPATE_HAVE_CHARTS
#include "app/cli/StoreSession.h"

#include "engine/exercise/RecordedExercise.h"
#include "engine/scoring/Staircase.h"

#include <QDateTime>
#include <QFileInfo>

#include <cmath>

namespace palpate::cli {

StoredSession storeScoredSession(ResultsDatabase& db, const std::string& traineeName, const ScoreReport& report,
                                 const std::optional<Exercise>& exercise, const QString& exercisePath,
                                 const RecordingReader& reader, const std::string& recordingPath, bool expert) {
    StoredSession out;
    QString qerror;
    const qint64 trainee = db.addTrainee(QString::fromStdString(traineeName), &qerror);
    if (trainee < 0) {
        out.error = qerror.toStdString();
        return out;
    }
    const QString name = QString::fromStdString(exercise ? exercise->name : report.exerciseName);
    out.exerciseName = name.toStdString();
    const QDateTime started = reader.header().startUnixUs > 0
                                  ? QDateTime::fromMSecsSinceEpoch(reader.header().startUnixUs / 1000, Qt::UTC)
                                  : QDateTime::currentDateTimeUtc();
    out.resultId = db.addResult(trainee, report, name, exercisePath, started, report.guidance.exerciseTimeS,
                                QFileInfo(QString::fromStdString(recordingPath)).absoluteFilePath(), expert, &qerror);
    if (out.resultId < 0) {
        out.error = qerror.toStdString();
        return out;
    }
    out.stored = true;
    // A trial moves the trainee's staircase; an expert's reference session does not.
    const std::optional<bool> trial = staircaseTrialPassed(report);
    // A stopped session is no trial (its partial findings are not a result), nor an expert's.
    if (expert || !trial || !isScored(outcomeOf(report)) || !exercise || !exercise->detectLumps.staircase) return out;
    const QString key = exerciseKey(exercisePath, name);
    const QString stored = db.staircase(trainee, key);
    std::optional<Staircase> staircase;
    if (!stored.isEmpty()) {
        std::string why;
        staircase = Staircase::fromJson(stored.toStdString(), why);
        if (!staircase) {
            out.error = "the stored staircase of " + key.toStdString() + ": " + why +
                        "; the session is stored, the staircase not moved";
            return out;
        }
        staircase->redefine(*exercise->detectLumps.staircase);
    } else {
        if (const std::string problem = staircaseDefProblem(*exercise->detectLumps.staircase); !problem.empty()) {
            out.error = problem;
            return out;
        }
        staircase.emplace(*exercise->detectLumps.staircase);
    }
    // A trial counts at the level it ran at: the lumps of the exercise the recording carries
    // (run --level writes them there). A session at another level is stored, but is not this
    // staircase's trial.
    std::vector<std::string> noteErrors;
    const std::optional<Exercise> ran = recordedExercise(reader.header(), noteErrors);
    const std::optional<double> ranLevel = ran ? staircaseLevelOf(*ran, staircase->def()) : std::nullopt;
    if (!ranLevel || std::fabs(*ranLevel - staircase->level()) > 1e-9) {
        out.notice = "the session ran " +
                     (ranLevel ? "at " + std::string(staircaseParameterName(staircase->def().parameter)) + " " +
                                     std::to_string(*ranLevel)
                               : std::string("without a level the recording says")) +
                     ", the staircase is at " + std::to_string(staircase->level()) +
                     " (palpate-cli run --exercise FILE --level " + std::to_string(staircase->level()) +
                     "): stored, but not a trial of the staircase";
        return out;
    }
    staircase->record(*trial);
    if (!db.putStaircase(trainee, key, QString::fromStdString(staircase->toJson()), &qerror)) {
        out.error = qerror.toStdString();
        return out;
    }
    out.staircase = {{"passed", *trial}, {"level", staircase->level()}};
    return out;
}

}  // namespace palpate::cli

#endif  // PALPATE_HAVE_CHARTS
