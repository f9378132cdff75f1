#include "app/gui/ExerciseController.h"

#include "engine/scoring/GuidanceFade.h"
#include "engine/scoring/Staircase.h"
#include "widgets/PreferencesDialog.h"

#include "base/resources/ShippedResources.h"
#include "engine/exercise/ExerciseBundle.h"
#include "engine/exercise/ExerciseFile.h"
#include "engine/record/RecordingReader.h"
#include "engine/scoring/ReplayScorer.h"
#include "widgets/GuardedLoad.h"
#include "widgets/HistoryPanel.h"
#include "widgets/ScoreCard.h"
#include "report/ExerciseWords.h"
#include "report/MetricText.h"
#include "report/ScoreReportFromRecording.h"
#include "report/ScoreReportPdf.h"
#include "widgets/TraineePanel.h"
#include "widgets/Viewport.h"
#include "engine/exercise/ExerciseKind.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>

#include "results/DataFolder.h"

#include <algorithm>
#include <cmath>

namespace palpate {

namespace {

QString joined(const std::vector<std::string>& lines) {
    QStringList out;
    for (const auto& l : lines) out << QString::fromStdString(l);
    return out.join(QLatin1Char('\n'));
}

/// A file-name-safe form of an exercise's name ("Press three targets" -> "press-three-targets").
QString slug(const std::string& name) {
    QString s = QString::fromStdString(name).toLower();
    s.replace(QRegularExpression(QStringLiteral("[^a-z0-9]+")), QStringLiteral("-"));
    s = s.left(40);
    while (s.startsWith(QLatin1Char('-'))) s.remove(0, 1);
    while (s.endsWith(QLatin1Char('-'))) s.chop(1);
    return s.isEmpty() ? QStringLiteral("exercise") : s;
}

}  // namespace

ExerciseController::ExerciseController(HapticSession& session, Viewport& viewport, TraineePanel& panel,
                                       HistoryPanel& history, std::function<QString()> recordingFolder, QObject* parent)
    : QObject(parent), mSession(session), mViewport(viewport), mPanel(panel), mHistory(history),
      mRecordingFolder(std::move(recordingFolder)) {
    connect(&mPanel, &TraineePanel::startRequested, this, [this] {
        if (const QString error = start(); !error.isEmpty()) mPanel.setMessage(error);
    });
    connect(&mPanel, &TraineePanel::stopRequested, this, [this] { stop(); });
    connect(&mPanel, &TraineePanel::markRequested, this, [this] { mark(); });
    connect(&mPanel, &TraineePanel::finishRequested, this, [this] { finishExamination(); });
    connect(&mPanel, &TraineePanel::exerciseChanged, this, [this](const QString& path) { showExerciseDescription(path); });
    connect(&mPanel, &TraineePanel::exercisePicked, this, [this] { mExercisePicked = true; });
    connect(&mPanel, &TraineePanel::traineeChanged, this, [this](qint64 id) {
        if (id >= 0) mHistory.setTrainee(id);
    });
    connect(mPanel.scoreCard(), &ScoreCard::historyRequested, this, [this] { mHistory.setTrainee(mPanel.traineeId()); });
}

ExerciseController::~ExerciseController() = default;

QString ExerciseController::defaultDatabasePath() { return defaultResultsStore(); }

QString ExerciseController::openDatabase(const QString& path) {
    QDir().mkpath(QFileInfo(path).absolutePath());
    QString error;
    if (!mDatabase.open(path, &error)) {
        mDatabaseError = error;
        mPanel.setMessage(error);
        return error;
    }
    mDatabaseError.clear();
    refreshTrainees(-1);
    mHistory.setDatabase(&mDatabase);
    return {};
}

void ExerciseController::refreshTrainees(qint64 select) {
    QList<QPair<QString, qint64>> list;
    if (mDatabase.isOpen())
        for (const TraineeRecord& t : mDatabase.trainees()) list.append({t.name, t.id});
    mPanel.setTrainees(list, select);
    mHistory.refresh();
    if (mPanel.traineeId() >= 0) mHistory.setTrainee(mPanel.traineeId());
}

QString ExerciseController::databaseProblem() const {
    if (!mDatabaseError.isEmpty()) return mDatabaseError;
    return tr("no results database is open");
}

QString ExerciseController::addTrainee(const QString& name) {
    if (!mDatabase.isOpen()) return tr("%1: trainees cannot be stored.").arg(databaseProblem());
    QString error;
    const qint64 id = mDatabase.addTrainee(name.trimmed(), &error);
    if (id < 0) return error;
    refreshTrainees(id);
    return {};
}

void ExerciseController::listExampleExercises() {
    QList<QPair<QString, QString>> list;
    const std::string anchor = findResource("exercises/press_targets.json");
    if (!anchor.empty()) {
        const QDir dir = QFileInfo(QString::fromStdString(anchor)).absoluteDir();
        for (const QFileInfo& file : dir.entryInfoList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
            const auto loaded = guardedLoad(file.absoluteFilePath().toStdString(),
                                            [&] { return loadExercise(file.absoluteFilePath().toStdString()); });
            if (loaded.exercise) list.append({shownExerciseName(*loaded.exercise), file.absoluteFilePath()});
        }
    }
    mShippedExercises.clear();
    for (const auto& entry : list) mShippedExercises << entry.second;
    // Then the ones opened before, oldest last; one that no longer opens is left out of the list
    // (and kept in the settings: a folder on a network drive may be back tomorrow).
    for (const QString& path : openedExercises()) {
        const auto loaded = guardedLoad(path.toStdString(), [&] { return loadExercise(path.toStdString()); });
        if (loaded.exercise) list.append({shownExerciseName(*loaded.exercise), path});
    }
    mPanel.setExercises(list);
}

QString ExerciseController::importedExercisesFolder() {
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
        .filePath(QStringLiteral("exercises"));
}

QString ExerciseController::addExerciseFile(const QString& path) {
    if (path.endsWith(QLatin1String(".palpex"), Qt::CaseInsensitive)) {
        // A bundle: its files go into the exercises folder (nothing there is overwritten), and the
        // exercise it holds is what is added.
        const QString folder = importedExercisesFolder();
        if (!QDir().mkpath(folder)) return tr("%1: the folder to import the exercise into cannot be made").arg(folder);
        std::string error;
        const auto imported = importExerciseBundle(path.toStdString(), folder.toStdString(), error);
        if (!imported) return QString::fromStdString(error);
        return addExerciseFile(QString::fromStdString(imported->exercisePath));
    }
    const auto loaded = guardedLoad(path.toStdString(), [&] { return loadExercise(path.toStdString()); });
    if (!loaded.exercise) return joined(loaded.errors);
    const QString absolute = QFileInfo(path).absoluteFilePath();
    const bool shipped = std::any_of(mShippedExercises.begin(), mShippedExercises.end(),
                                     [&](const QString& s) { return QFileInfo(s) == QFileInfo(absolute); });
    if (!shipped) {
        // Kept for the next start: the trainee's list holds what was opened, newest first.
        QStringList opened = QSettings().value(QLatin1String(kOpenedExercisesKey)).toStringList();
        opened.removeAll(absolute);
        opened.prepend(absolute);
        while (opened.size() > kMaxOpenedExercises) opened.removeLast();
        QSettings().setValue(QLatin1String(kOpenedExercisesKey), opened);
    }
    mPanel.addExercise(shownExerciseName(*loaded.exercise), absolute);
    mExercisePicked = true;
    return {};
}

QStringList ExerciseController::openedExercises() {
    return QSettings().value(QLatin1String(kOpenedExercisesKey)).toStringList();
}

void ExerciseController::followMesh(const QString& meshPath) {
    if (running() || mExercisePicked || meshPath.isEmpty()) return;
    const QString shown = QFileInfo(meshPath).canonicalFilePath();
    for (const auto& [title, path] : mPanel.exercises()) {
        const auto loaded = guardedLoad(path.toStdString(), [&] { return loadExercise(path.toStdString()); });
        if (!loaded.exercise) continue;
        const std::string mesh = resolveExercisePath(*loaded.exercise, loaded.exercise->meshPath, findResource);
        if (!mesh.empty() && QFileInfo(QString::fromStdString(mesh)).canonicalFilePath() == shown) {
            if (path != mPanel.exercisePath()) mPanel.addExercise(title, path);
            return;
        }
    }
}

void ExerciseController::showExerciseDescription(const QString& path) {
    if (path.isEmpty()) {
        mPanel.setExerciseDescription({});
        return;
    }
    const auto loaded = guardedLoad(path.toStdString(), [&] { return loadExercise(path.toStdString()); });
    mPanel.setExerciseDescription(loaded.exercise ? shownExerciseDescription(*loaded.exercise) : joined(loaded.errors));
    if (!running()) mPanel.setState(TraineePanel::State::Idle);
}

QString ExerciseController::start() {
    if (mPanel.traineeId() < 0) return tr("Choose a trainee, or add one with New…, before starting.");
    const QString path = mPanel.exercisePath();
    if (path.isEmpty()) return tr("Choose an exercise first.");
    const auto loaded = guardedLoad(path.toStdString(), [&] { return loadExercise(path.toStdString()); });
    if (!loaded.exercise) return joined(loaded.errors);
    return begin(*loaded.exercise, false);
}

QString ExerciseController::startPreview(const Exercise& exercise) { return begin(exercise, true); }

std::optional<Staircase> ExerciseController::traineeStaircase(const Exercise& exercise, qint64 traineeId,
                                                              QString& key) const {
    const auto& def = exercise.detectLumps.staircase;
    if (!exerciseKind(exercise.type).adaptive() || !def || !mDatabase.isOpen() || traineeId < 0) return std::nullopt;
    if (!staircaseDefProblem(*def).empty()) return std::nullopt;
    key = exerciseKey(QString::fromStdString(exercise.sourcePath), QString::fromStdString(exercise.name));
    const QString stored = mDatabase.staircase(traineeId, key);
    if (stored.isEmpty()) return Staircase(*def);
    std::string why;
    std::optional<Staircase> s = Staircase::fromJson(stored.toStdString(), why);
    if (!s) return Staircase(*def);  // a state that no longer reads starts afresh
    s->redefine(*def);
    return s;
}

QString ExerciseController::begin(const Exercise& requested, bool preview) {
    if (running()) return tr("An exercise is already running: stop it first.");
    std::vector<std::string> errors = messagesOf(validateExercise(requested));
    if (!errors.empty()) return joined(errors);
    // A staircase runs the trainee's trial at their level (docs/scoring.md, "Staircase").
    mStaircaseKey.clear();
    mStaircaseLevel.reset();
    Exercise exercise = requested;
    if (!preview && !mPanel.expertSession()) {  // an expert's reference runs the exercise as written
        if (const auto staircase = traineeStaircase(requested, mPanel.traineeId(), mStaircaseKey)) {
            mStaircaseLevel = staircase->level();
            exercise = exerciseAtLevel(requested, *mStaircaseLevel);
        }
    }
    std::optional<ExerciseAssets> assets;
    try {
        assets = loadExerciseAssets(exercise, findResource, errors);
    } catch (const std::exception& e) {  // the loaders should not throw; no file may abort the window
        errors.push_back(exercise.sourcePath + ": " + e.what());
    }
    if (!assets) return joined(errors);
    if (const std::string error = mSession.loadExercise(*assets); !error.empty()) return QString::fromStdString(error);
    mAssets = std::move(assets);
    mPreview = preview;
    mTraineeId = preview ? -1 : mPanel.traineeId();
    mExpertSession = !preview && mPanel.expertSession();
    mTraineeName = preview ? tr("Preview") : mPanel.traineeName();
    mLive.reset();
    mRecordingPath.clear();
    mLastReport.reset();
    mLastResultId = -1;
    mLastMarkers = -1;
    mPhase = Phase::Starting;
    mPanel.scoreCard()->clear();
    mPanel.setState(TraineePanel::State::Starting);
    mPanel.setMessage(preview           ? tr("Preview of \"%1\": not stored.").arg(shownExerciseName(exercise))
                      : mStaircaseLevel ? tr("Your level: every lump at %1 %2 (the staircase adapts it to you).")
                                              .arg(QString::fromUtf8(
                                                  staircaseParameterName(exercise.detectLumps.staircase->parameter)))
                                              .arg(*mStaircaseLevel, 0, 'g', 4)
                                        : QString());
    mPanel.setExerciseDescription(shownExerciseDescription(exercise));
    mPanel.setFinishShown(exerciseKind(exercise.type).finishedByTrainee());
    mGaugeLevel = preview ? 1.0 : gaugeLevelFor(exercise);
    mPanel.setGaugeLevel(mGaugeLevel);
    // The combo names what runs (a preview from the welcome page or the editor too).
    mPanel.showRunningExercise(shownExerciseName(exercise),
                               exercise.sourcePath.empty()
                                   ? QString()
                                   : QFileInfo(QString::fromStdString(exercise.sourcePath)).absoluteFilePath());
    updateMarkers();
    emit runningChanged(true);
    poll();  // the first scene of a new loop is the loop's at once
    return {};
}

void ExerciseController::startRecording() {
    const QString folder = mRecordingFolder ? mRecordingFolder() : QString();
    if (folder.isEmpty() || !QDir().mkpath(folder)) {
        fail(tr("The recordings folder %1 cannot be created: the exercise cannot be recorded and scored.").arg(folder));
        return;
    }
    const QString stamp = QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-hhmmss-zzz"));
    const QString stem = QStringLiteral("exercise-%1-%2").arg(slug(mAssets->exercise.name), stamp);
    QString path = QDir(folder).filePath(stem + QStringLiteral(".palprec"));
    // An automatic name never replaces a file: two sessions in one millisecond, or a copied folder.
    for (int n = 2; QFileInfo::exists(path); ++n)
        path = QDir(folder).filePath(QStringLiteral("%1-%2.palprec").arg(stem).arg(n));
    // The note carries the exercise with its paths resolved, so the recording scores on its own.
    Exercise carried = mAssets->exercise;
    carried.meshPath = mAssets->meshPath;
    carried.tissuePresetPath = mAssets->presetPath;
    std::string error;
    const std::string note = exerciseRecordingNote(
        carried, (mPreview ? std::string("preview") : "trainee: " + mTraineeName.toStdString()), error);
    if (note.empty()) {
        fail(QString::fromStdString(error));
        return;
    }
    if (const std::string problem = mSession.startRecording(path.toStdString(), note); !problem.empty()) {
        fail(QString::fromStdString(problem));
        return;
    }
    LiveScorerDef def;
    def.options.findResource = findResource;
    mLive = std::make_unique<LiveScorer>(path.toStdString(), mAssets->exercise, def);
    mRecordingPath = path;
    emit recordingStateChanged(true, path);
    mStartedUtc = QDateTime::currentDateTimeUtc();
    mPhase = Phase::Running;
    mPanel.setState(TraineePanel::State::Running);
    emit message(tr("Exercise \"%1\" started; recording to %2").arg(shownExerciseName(mAssets->exercise), path));
}

void ExerciseController::poll() {
    switch (mPhase) {
        case Phase::Idle:
        case Phase::Finished: return;  // the window clears the markers when another mesh is drawn
        case Phase::Starting:
            if (!mSession.sceneSwitchPending() && mSession.hasLoop()) startRecording();
            return;
        case Phase::Running: break;
    }
    if (!mSession.recording()) {
        // Stopped from the Recorder dock, or a new haptic rate ended it: score what was recorded.
        finish(tr("the recording was stopped"));
        return;
    }
    mLive->poll();
    if (!mLive->error().empty()) {
        fail(QString::fromStdString(mLive->error()));
        return;
    }
    if (mLive->started()) {
        mPanel.showGuidance(mAssets->exercise, mLive->guidance(), mLive->scoreSoFar());
        updateMarkers();
    }
    if (mLive->exerciseOver()) finish({});
}

void ExerciseController::updateMarkers() {
    if (!mAssets || !mAssets->geometry) return;
    const ScoreGuidance* guidance = mLive && mLive->started() ? &mLive->guidance() : nullptr;
    // Rebuilt only when what they show changes (a target done, the mark): not every frame.
    const int key = (guidance ? (guidance->completed ? 1000 : guidance->targetIndex) + (guidance->marked ? 2000 : 0) : -3) +
                    (mPhase == Phase::Finished ? 4000 : 0) + (mShowCoverageHeat ? 8000 : 0);
    if (key == mLastMarkers) return;
    mLastMarkers = key;
    ExerciseMarkers markers = exerciseMarkers(*mAssets->geometry,
                                              mPreview ? MarkerAudience::Instructor : MarkerAudience::Trainee, guidance);
    // After a palpation exercise: what was examined, how firmly, and where the trainee marked.
    if (mPhase == Phase::Finished && mLastReport && mLastReport->palpation) {
        if (mShowCoverageHeat) addCoverageHeat(markers, *mAssets->geometry, *mLastReport->palpation);
        for (const glm::dvec3& f : mLastReport->palpation->findingsMm) {
            ExerciseMarker m;
            m.kind = ExerciseMarker::Kind::Mark;
            m.positionMm = glm::vec3(f);
            markers.markers.push_back(m);
        }
    }
    mViewport.setExerciseMarkers(std::move(markers));
}

bool ExerciseController::mark() {
    if (mPhase != Phase::Running || !mSession.recordingSession()) return false;
    mSession.recordingSession()->mark("mark (trainee)");
    // Show where it was: the touched vertex, as the scorer takes it.
    const VertexId touched = mSession.observed().touched;
    const auto& mesh = mSession.drawnMesh();
    if (mesh && touched != kNoVertex && touched < mesh->restPositionsMm().size()) {
        ExerciseMarkers markers = mViewport.exerciseMarkers();
        ExerciseMarker m;
        m.kind = ExerciseMarker::Kind::Mark;
        m.positionMm = mesh->restPositionsMm()[touched];
        m.normal = mesh->restNormals()[touched];
        markers.markers.push_back(m);
        mViewport.setExerciseMarkers(std::move(markers));
    }
    emit message(tr("Marked"));
    return true;
}

QString ExerciseController::recordStaircaseTrial(const ScoreReport& report) {
    // A stopped session is no trial: its partial finding is not a result.
    if (!mStaircaseLevel || !mAssets || !isScored(outcomeOf(report))) return {};
    const std::optional<bool> passed = staircaseTrialPassed(report);
    if (!passed) return {};
    QString key;
    std::optional<Staircase> staircase = traineeStaircase(mAssets->exercise, mTraineeId, key);
    if (!staircase || std::abs(staircase->level() - *mStaircaseLevel) > 1e-9) return {};
    staircase->record(*passed);
    QString error;
    if (!mDatabase.putStaircase(mTraineeId, mStaircaseKey, QString::fromStdString(staircase->toJson()), &error))
        return QLatin1Char(' ') + tr("The staircase was not moved: %1").arg(error);
    return QLatin1Char(' ') + (*passed ? tr("Trial passed; next level %1.") : tr("Trial failed; next level %1."))
                                  .arg(staircase->level(), 0, 'g', 4);
}

double ExerciseController::gaugeLevelFor(const Exercise& exercise) const {
    const Preferences prefs = Preferences::load();
    GuidanceFadeDef def;
    def.enabled = prefs.fadeGauge;
    def.sessionsToFade = prefs.fadeSessions;
    def.goodScore = prefs.goodScore;
    std::vector<double> scores;
    if (mDatabase.isOpen() && mTraineeId >= 0) {
        const QString path = exercise.sourcePath.empty()
                                 ? QString()
                                 : QFileInfo(QString::fromStdString(exercise.sourcePath)).absoluteFilePath();
        for (const ResultRecord& r : mDatabase.results(mTraineeId)) {
            const bool same = path.isEmpty() || r.exercisePath.isEmpty()
                                  ? r.exerciseName == QString::fromStdString(exercise.name)
                                  : QFileInfo(r.exercisePath).absoluteFilePath() == path;
            if (same && isScored(r.outcome) && !r.expert) scores.push_back(r.score);
        }
    }
    return forceGaugeLevel(scores, def);
}

bool ExerciseController::finishExamination() {
    if (mPhase != Phase::Running || !mSession.recordingSession() || !mAssets ||
        !exerciseKind(mAssets->exercise.type).finishedByTrainee())
        return false;
    mSession.recordingSession()->mark(kExaminationDoneMark);
    emit message(tr("Examination finished"));
    return true;
}

void ExerciseController::stop() {
    if (mPhase == Phase::Starting) {
        mPhase = Phase::Idle;
        mPanel.setState(TraineePanel::State::Idle);
        mPanel.setMessage(tr("Stopped before the session began: nothing recorded."));
        emit runningChanged(false);
        return;
    }
    if (mPhase == Phase::Running) finish(tr("stopped"));
}

void ExerciseController::fail(const QString& why) {
    if (mSession.recording()) {
        mSession.stopRecording();
        emit recordingStateChanged(false, mRecordingPath);
    }
    mLive.reset();
    mPhase = Phase::Idle;
    mPanel.setState(TraineePanel::State::Idle);
    mPanel.setMessage(tr("The exercise could not go on: %1").arg(why));
    emit message(tr("Exercise ended: %1").arg(why));
    emit runningChanged(false);
}

void ExerciseController::finish(const QString& why) {
    const bool wasRecording = mSession.recording();
    const std::string problem = mSession.stopRecording();
    if (wasRecording) emit recordingStateChanged(false, mRecordingPath);
    ScoreReport report = mLive->finish();
    if (!mLive->error().empty()) {
        fail(QString::fromStdString(mLive->error()));
        return;
    }
    if (!problem.empty()) report.warnings.push_back("recording: " + problem);
    // What guidance the trainee had: stored with the result (docs/scoring.md, "Fading guidance").
    report.aids.push_back({"force_gauge", mGaugeLevel});
    mLastReport = report;
    mPhase = Phase::Finished;
    ScoreReport shown = report;  // the card names the exercise in the trainee's language; the store by its name
    shown.exerciseName = shownExerciseName(mAssets->exercise).toStdString();
    mPanel.scoreCard()->setReport(shown, mTraineeName);
    mPanel.setState(TraineePanel::State::Finished);
    QString stored;
    if (!mPreview) {
        QString error;
        mLastResultId = mDatabase.isOpen()
                            ? mDatabase.addResult(mTraineeId, report, QString::fromStdString(mAssets->exercise.name),
                                                  QString::fromStdString(mAssets->exercise.sourcePath), mStartedUtc,
                                                  report.guidance.exerciseTimeS, mRecordingPath, mExpertSession, &error)
                            : -1;
        if (mLastResultId < 0) {
            // Never lost silently: say what keeps the session, from which it can be scored again.
            const QString kept = mRecordingPath.isEmpty()
                                     ? tr("the session was not recorded, so it is lost")
                                     : tr("the session is kept in the recording %1 (palpate-cli score scores it again)")
                                           .arg(QDir::toNativeSeparators(mRecordingPath));
            stored = tr("The result was NOT stored: %1; %2.").arg(error.isEmpty() ? databaseProblem() : error, kept);
        } else {
            stored = mExpertSession ? tr("Expert reference session stored for %1: it sets the pass marks.").arg(mTraineeName)
                                    : tr("Result stored for %1.").arg(mTraineeName);
            if (!mExpertSession) stored += recordStaircaseTrial(report);
            emit resultStored();
        }
        mHistory.refresh();
        mHistory.setTrainee(mTraineeId);
    }
    mPanel.setMessage((why.isEmpty() ? QString() : tr("Ended: %1. ").arg(why)) + stored);
    emit message(tr("Exercise \"%1\": score %2").arg(shownExerciseName(mAssets->exercise), scoreText(report.score)));
    updateMarkers();
    emit runningChanged(false);
    emit finished();
}

void ExerciseController::setShowCoverageHeat(bool on) {
    mShowCoverageHeat = on;
    updateMarkers();
}

QString ExerciseController::exportLastReportPdf(const QString& path) {
    if (!mLastReport) return tr("There is no score to export yet.");
    return exportReportPdf(mRecordingPath, mTraineeName, path);
}

QString ExerciseController::exportResultPdf(const ResultRecord& result, const QString& path) {
    if (result.recordingPath.isEmpty()) return tr("This result has no recording to report from.");
    QString trainee;
    for (const TraineeRecord& t : mDatabase.trainees())
        if (t.id == result.traineeId) trainee = t.name;
    return exportReportPdf(result.recordingPath, trainee, path);
}

QString ExerciseController::exportReportPdf(const QString& recordingPath, const QString& trainee, const QString& path) {
    // An input is never overwritten by an output: the PDF over its own recording would lose the session.
    const QFileInfo out(path), in(recordingPath);
    if (out.exists() && in.exists() && out.canonicalFilePath() == in.canonicalFilePath())
        return tr("%1: is the recording the report is made from; choose another file for the PDF")
            .arg(QDir::toNativeSeparators(path));
    // The same report as `palpate-cli score --pdf`: the recording re-scored (report/).
    ReplayScorerDef options;
    options.findResource = findResource;
    ScoreReportContent content;
    QString error;
    if (!scoreReportFromRecording(recordingPath, nullptr, trainee, options, content, &error) ||
        !writeScoreReportPdf(path, content, &error))
        return error;
    return {};
}

}  // namespace palpate
