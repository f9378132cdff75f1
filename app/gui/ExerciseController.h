#pragma once
// Trainee mode's engine room: runs a graded exercise in the window's haptic session and keeps the
// results. Start loads the exercise's mesh, tissue and physics into the session, waits for the
// loop to run that scene, records the session (the recording's note carries the exercise) and
// follows the file with a LiveScorer, so the score shown live is the score a replay gives. Each
// frame it updates the guidance (Exercise dock, the viewport's target markers); when the exercise
// is over, or on Stop, it closes the recording, shows the score card and stores the result
// (trainee, exercise, time, metrics, score, recording path) in the results database.
//
// The same path serves the instructor's preview ("Try it" in the exercise editor): no trainee,
// nothing stored.

#include "app/gui/HapticSession.h"
#include "engine/scoring/ExerciseSession.h"
#include "engine/scoring/Staircase.h"
#include "engine/scoring/LiveScorer.h"
#include "results/ResultsDatabase.h"

#include <QDateTime>
#include <QObject>
#include <QString>
#include <QStringList>

#include <functional>
#include <memory>
#include <optional>

namespace palpate {

class HistoryPanel;
class TraineePanel;
class Viewport;

class ExerciseController final : public QObject {
    Q_OBJECT
public:
    enum class Phase { Idle, Starting, Running, Finished };

    /// `recordingFolder` gives the folder new recordings go to (the Recorder dock's).
    ExerciseController(HapticSession& session, Viewport& viewport, TraineePanel& panel, HistoryPanel& history,
                       std::function<QString()> recordingFolder, QObject* parent = nullptr);
    ~ExerciseController() override;

    /// Opens (creating, migrating) the results database. "" or the error (naming the file).
    QString openDatabase(const QString& path);
    ResultsDatabase& database() { return mDatabase; }
    /// The default: results.sqlite in the data folder (results/DataFolder.h), as the CLI's.
    static QString defaultDatabasePath();

    /// Adds a trainee (or finds one of that name) and selects it. "" or the error.
    QString addTrainee(const QString& name);
    /// Lists the shipped examples (resources/exercises), then the exercises opened before (the
    /// settings' "exercises/opened"), and selects the first.
    void listExampleExercises();
    /// Adds an exercise file to the dock's list and selects it; one not shipped stays in the list
    /// at the next start. A bundle (.palpex) is imported into importedExercisesFolder() first.
    /// "" or the errors naming the keys.
    QString addExerciseFile(const QString& path);
    /// Where bundles are imported: "exercises" in the application's data folder.
    static QString importedExercisesFolder();
    /// The exercise files opened before, newest first (whether or not they still open).
    static QStringList openedExercises();
    /// The window shows `meshPath` now: while nothing runs and the trainee has not picked an
    /// exercise themselves, the dock selects the first listed exercise on that mesh (its text then
    /// speaks of what is on screen).
    void followMesh(const QString& meshPath);

    /// Starts the exercise selected in the dock for the selected trainee. "" or why not.
    QString start();
    /// Starts `exercise` as the instructor's preview (unsaved; nothing stored). "" or why not.
    QString startPreview(const Exercise& exercise);
    /// Ends the exercise now and scores it (also what happens when it is over by itself).
    void stop();
    /// The trainee's mark (find the lump: "the lump is where I press now"). False when not running.
    bool mark();
    /// The trainee ends a detect-lumps examination (the Mark event kExaminationDoneMark; the
    /// scorer then completes it). False when not running or not a detect-lumps exercise.
    bool finishExamination();
    /// After a palpation exercise the viewport shows the coverage heat map (View > Coverage Heat
    /// Map); off hides it.
    void setShowCoverageHeat(bool on);
    /// The force gauge's level for the running session (fading guidance; 1 in a preview).
    double gaugeLevel() const { return mGaugeLevel; }
    /// The staircase level the running or last session ran at (detect lumps with a staircase).
    std::optional<double> staircaseLevel() const { return mStaircaseLevel; }
    bool showsCoverageHeat() const { return mShowCoverageHeat; }
    /// Follows the session: call every frame (and after stepped ticks). Starts the recording once
    /// the loop runs the exercise's scene, updates guidance and markers, finishes when over.
    void poll();

    Phase phase() const { return mPhase; }
    bool running() const { return mPhase == Phase::Starting || mPhase == Phase::Running; }
    bool preview() const { return mPreview; }
    /// The exercise being run (or last run).
    const std::optional<ExerciseAssets>& assets() const { return mAssets; }
    /// The last finished session's score, recording and database row (-1: not stored).
    const std::optional<ScoreReport>& lastReport() const { return mLastReport; }
    const QString& lastRecordingPath() const { return mRecordingPath; }
    qint64 lastResultId() const { return mLastResultId; }

    /// The PDF of the last report (score, breakdown, force-time plot). "" or the error.
    QString exportLastReportPdf(const QString& path);
    /// Re-scores a stored result's recording and writes its PDF. "" or the error.
    QString exportResultPdf(const ResultRecord& result, const QString& path);

signals:
    /// The window disables what must not change during a run (parameters, mesh) and back.
    void runningChanged(bool running);
    /// Something for the status bar.
    void message(const QString& text);
    /// A finished session's score card is showing (the window raises the dock).
    void finished();
    /// The exercise's recording started or ended (the Recorder dock shows it like its own).
    void recordingStateChanged(bool recording, const QString& path);
    /// A result was committed to the workstation's database (the class's server may take it now).
    void resultStored();

private:
    static constexpr const char* kOpenedExercisesKey = "exercises/opened";
    static constexpr int kMaxOpenedExercises = 30;
    QStringList mShippedExercises;  ///< the shipped examples' files, as listed

    /// Why no database is open: openDatabase's error, naming the file and the reason.
    QString databaseProblem() const;
    QString begin(const Exercise& exercise, bool preview);
    void startRecording();
    void finish(const QString& why);
    /// Fading guidance: the gauge's level from the trainee's scored sessions of this exercise.
    double gaugeLevelFor(const Exercise& exercise) const;
    /// The trainee's staircase of a detect-lumps exercise with one (stored, else fresh), and its
    /// key; nullopt without one.
    std::optional<Staircase> traineeStaircase(const Exercise& exercise, qint64 traineeId, QString& key) const;
    /// After a stored session run at the staircase's level: the trial moves it; the sentence says so.
    QString recordStaircaseTrial(const ScoreReport& report);
    void fail(const QString& why);
    QString exportReportPdf(const QString& recordingPath, const QString& trainee, const QString& path);
    void refreshTrainees(qint64 select);
    void showExerciseDescription(const QString& path);
    void updateMarkers();

    HapticSession& mSession;
    Viewport& mViewport;
    TraineePanel& mPanel;
    HistoryPanel& mHistory;
    std::function<QString()> mRecordingFolder;
    ResultsDatabase mDatabase;
    QString mDatabaseError;  ///< why openDatabase failed (naming the file), for every later message

    Phase mPhase = Phase::Idle;
    bool mPreview = false;
    std::optional<ExerciseAssets> mAssets;
    std::unique_ptr<LiveScorer> mLive;
    QString mRecordingPath;
    QDateTime mStartedUtc;
    qint64 mTraineeId = -1;
    QString mTraineeName;
    std::optional<ScoreReport> mLastReport;
    qint64 mLastResultId = -1;
    bool mExercisePicked = false;  // the trainee chose an exercise (the dock no longer follows the mesh)
    int mLastMarkers = -1;  // guidance state the markers were built for (target index; -2: finished)
    bool mShowCoverageHeat = true;
    double mGaugeLevel = 1.0;  // the force gauge's level this session (fading guidance)
    std::optional<double> mStaircaseLevel;  // the staircase level this session runs at
    QString mStaircaseKey;
    bool mExpertSession = false;  // stored as an instructor's reference (docs/scoring.md, "Proficiency")
};

}  // namespace palpate
