// Trainee mode under QT_QPA_PLATFORM=offscreen, end to end in a stepped main window: a trainee runs
// the shipped exercises with the scripted good and bad paths as the device; the guidance follows
// the task (target markers, force window on the gauge, hold progress); the score shown at the end
// equals the score of replaying the recording the session left; the result (trainee, exercise,
// score, metrics, recording) is in the database, which survives reopening; the History view plots
// it; the score report PDF holds the score; errors are reported, not crashed on.
#include "base/resources/ShippedResources.h"
#include "app/gui/ExerciseController.h"
#include "engine/exercise/ExerciseBundle.h"
#include "report/ScoreReportFromRecording.h"
#include "app/gui/MainWindow.h"
#include "results/ResultUploader.h"
#include "widgets/ClassDialog.h"
#include "engine/record/RecordingReader.h"
#include "engine/scoring/ReplayScorer.h"
#include "widgets/ExerciseEditorPanel.h"
#include "widgets/ForceGauge.h"
#include "widgets/HistoryPanel.h"
#include "widgets/LodPanel.h"
#include "widgets/ParameterPanel.h"
#include "widgets/RecorderPanel.h"
#include "widgets/ScoreCard.h"
#include "widgets/TraineePanel.h"
#include "engine/exercise/ExerciseFile.h"
#include "widgets/DevicePanel.h"
#include "widgets/Viewport.h"

#include <gtest/gtest.h>

#include "results/LearningCurve.h"
#include "engine/exercise/RecordedExercise.h"
#include "engine/scoring/Staircase.h"

#include <QApplication>
#include <QLabel>
#include <QSignalSpy>
#include <QCheckBox>
#include <QDialog>
#include <QComboBox>
#include <QDockWidget>
#include <QFileInfo>
#include <QFile>
#include <QImage>
#include <QChart>
#include <QLineSeries>
#include <QLocale>
#include <QProcess>
#include <QPushButton>
#include <QStandardPaths>
#include <QStyle>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoGroup>
#include <QUndoStack>
#include <QScrollArea>
#include <QChartView>
#include <QValueAxis>

#include <algorithm>

using namespace palpate;

namespace {

QString resource(const char* relative) { return QString::fromStdString(findResource(relative)); }

/// A stepped window whose device plays `script` (resources/exercises/...path), with the results
/// database and the recordings in `dir`.
std::unique_ptr<MainWindow> traineeWindow(const QTemporaryDir& dir, const char* script) {
    auto window = std::make_unique<MainWindow>(RendererChoice::Software, LoopMode::Stepped);
    window->recorderPanel()->setRecordingFolder(dir.filePath(QStringLiteral("recordings")));
    EXPECT_EQ(window->exercises().openDatabase(dir.filePath(QStringLiteral("results.sqlite"))), QString());
    EXPECT_EQ(window->setDeviceUri(QStringLiteral("sim:path:") + resource(script)), QString());
    window->resize(1200, 800);
    window->show();  // laid out: the viewport has its real size
    return window;
}

/// Trainee mode, the trainee Ada selected and "press the targets" chosen.
void readyAdaForPressTargets(MainWindow& window) {
    window.setMode(MainWindow::Mode::Trainee);
    ASSERT_EQ(window.exercises().addTrainee(QStringLiteral("Ada")), QString());
    ASSERT_EQ(window.exercises().addExerciseFile(resource("exercises/press_targets.json")), QString());
}

/// Steps until the exercise is over (or `maxTicks`), 100 ticks a frame as the window would poll.
void runToEnd(MainWindow& window, int maxTicks) {
    for (int done = 0; done < maxTicks && window.exercises().running(); done += 100) window.advanceTicks(100);
}

int countMarkers(const ExerciseMarkers& markers, ExerciseMarker::Kind kind) {
    return int(std::count_if(markers.markers.begin(), markers.markers.end(),
                             [kind](const ExerciseMarker& m) { return m.kind == kind; }));
}

ScoreReport replayScore(const QString& recordingPath) {
    const RecordingReader reader = RecordingReader::open(recordingPath.toStdString());
    std::string error;
    ReplayScorerDef options;
    options.findResource = findResource;
    ScoreReport report = scoreRecording(reader, nullptr, error, options);
    EXPECT_EQ(error, "");
    return report;
}

}  // namespace

TEST(TraineeMode, PressTargetsRunsGuidesScoresAndStores) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    auto window = traineeWindow(dir, "exercises/press_targets.good.path");
    ASSERT_NO_FATAL_FAILURE(readyAdaForPressTargets(*window));
    TraineePanel* panel = window->traineePanel();
    EXPECT_EQ(panel->traineeName(), QStringLiteral("Ada"));
    ASSERT_EQ(window->exercises().start(), QString());
    EXPECT_TRUE(window->exercises().running());
    // The tissue belongs to the exercise while it runs.
    EXPECT_FALSE(window->parameterPanel()->isEnabled());

    // Early on: the first target is the current one, the gauge shows its window, nothing is done.
    window->advanceTicks(1500);
    EXPECT_EQ(window->exercises().phase(), ExerciseController::Phase::Running);
    EXPECT_TRUE(panel->instructionText().contains(QStringLiteral("Target 1 of 3"))) << panel->instructionText().toStdString();
    EXPECT_DOUBLE_EQ(panel->forceGauge()->windowMinN(), 1.0);
    EXPECT_DOUBLE_EQ(panel->forceGauge()->windowMaxN(), 2.0);
    const ExerciseMarkers& early = window->viewport()->exerciseMarkers();
    EXPECT_EQ(countMarkers(early, ExerciseMarker::Kind::CurrentTarget), 1);
    EXPECT_EQ(countMarkers(early, ExerciseMarker::Kind::Target), 2);
    EXPECT_EQ(countMarkers(early, ExerciseMarker::Kind::DoneTarget), 0);
    // The markers are drawn: the current target's colour is in the viewport's picture.
    const QImage image = window->viewport()->grabImage();
    const QColor current = exerciseMarkerColour(ExerciseMarker::Kind::CurrentTarget);
    bool seen = false;
    for (int y = 0; y < image.height() && !seen; ++y)
        for (int x = 0; x < image.width() && !seen; ++x) seen = image.pixelColor(x, y) == current;
    EXPECT_TRUE(seen) << "no pixel of the current target's colour";

    runToEnd(*window, 45000);
    ASSERT_EQ(window->exercises().phase(), ExerciseController::Phase::Finished);
    EXPECT_TRUE(window->parameterPanel()->isEnabled());
    ASSERT_TRUE(window->exercises().lastReport().has_value());
    const ScoreReport& live = *window->exercises().lastReport();
    EXPECT_TRUE(live.guidance.completed);
    EXPECT_EQ(countMarkers(window->viewport()->exerciseMarkers(), ExerciseMarker::Kind::DoneTarget), 3);
    // The good path does the task: a high score; and the same score when the recording is replayed.
    EXPECT_GT(live.score, 80.0);
    const ScoreReport replayed = replayScore(window->exercises().lastRecordingPath());
    EXPECT_EQ(replayed.score, live.score);
    ASSERT_EQ(replayed.metrics.size(), live.metrics.size());
    for (std::size_t i = 0; i < live.metrics.size(); ++i) EXPECT_EQ(replayed.metrics[i].value, live.metrics[i].value);

    // The score card shows it.
    EXPECT_TRUE(panel->scoreCard()->hasReport());
    EXPECT_TRUE(panel->scoreCard()->scoreText().contains(QString::number(live.score, 'f', 0)));
    EXPECT_EQ(panel->scoreCard()->breakdownTable()->rowCount(), int(live.metrics.size()));

    // Stored, with the recording; the History view plots it.
    const qint64 trainee = panel->traineeId();
    const auto results = window->exercises().database().results(trainee);
    ASSERT_EQ(results.size(), 1u);
    EXPECT_EQ(results[0].score, live.score);
    EXPECT_EQ(results[0].exerciseName, QStringLiteral("Press three targets"));
    EXPECT_EQ(results[0].recordingPath, window->exercises().lastRecordingPath());
    EXPECT_TRUE(QFile::exists(results[0].recordingPath));
    EXPECT_TRUE(results[0].metricsJson.contains(QStringLiteral("target_error_mm")));
    EXPECT_EQ(window->historyPanel()->results().size(), 1u);
    EXPECT_EQ(window->historyPanel()->plottedPointCount(), 1);
}

// With a class's server set, a stored result is copied after the session; while the server does
// not answer the status bar says the result waits (docs/results-store.md).
TEST(TraineeMode, AStoredResultWaitsForTheClassServerInTheStatusBar) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    auto window = traineeWindow(dir, "exercises/press_targets.good.path");
    ASSERT_NO_FATAL_FAILURE(readyAdaForPressTargets(*window));
    ResultUploader* uploader = window->resultUploader();
    ASSERT_NE(uploader, nullptr);
    uploader->setLocations(window->exercises().database().path(), QStringLiteral("postgresql://localhost:1/class"));
    ASSERT_TRUE(QTest::qWaitFor([&] { return uploader->hasReport() && !uploader->busy(); }, 30000));
    auto* label = window->findChild<QLabel*>(QStringLiteral("resultsServerStatus"));
    ASSERT_NE(label, nullptr);
    EXPECT_TRUE(label->text().contains(QStringLiteral("does not answer"))) << label->text().toStdString();  // none yet

    ASSERT_EQ(window->exercises().start(), QString());
    runToEnd(*window, 45000);
    ASSERT_EQ(window->exercises().phase(), ExerciseController::Phase::Finished);
    // The copy runs off the GUI thread after the result was stored.
    ASSERT_TRUE(QTest::qWaitFor([&] { return uploader->lastReport().waiting == 1 && !uploader->busy(); }, 30000));
    EXPECT_TRUE(label->isVisible());
    EXPECT_TRUE(label->text().contains(QStringLiteral("1 waiting"))) << label->text().toStdString();
    EXPECT_TRUE(label->toolTip().contains(QStringLiteral("stopped"))) << label->toolTip().toStdString();
    EXPECT_EQ(window->exercises().database().unsyncedResults().size(), 1u);

    // The instructor's Class view reads it (off the GUI thread) and exports it.
    ClassDialog view(window->exercises().database().path(), QString(),
                     QFileInfo(resource("exercises/press_targets.json")).absolutePath());
    QSignalSpy loaded(&view, &ClassDialog::loaded);
    ASSERT_TRUE(loaded.wait(30000) || loaded.count() == 1);
    EXPECT_TRUE(loaded.at(0).at(0).toBool()) << view.statusText().toStdString();
    ASSERT_EQ(view.rows().size(), 1u);
    EXPECT_EQ(view.rows()[0].trainee, QStringLiteral("Ada"));
    EXPECT_EQ(view.rows()[0].exercise, QStringLiteral("Press three targets"));
    EXPECT_EQ(view.rows()[0].sessions, 1);
    EXPECT_EQ(view.rows()[0].verdict, QStringLiteral("no standard"));  // no expert has set the marks
    EXPECT_EQ(view.findChild<QTableWidget*>(QStringLiteral("classTable"))->rowCount(), 1);
    const QString csv = dir.filePath(QStringLiteral("class.csv"));
    EXPECT_EQ(view.exportCsv(csv), QString());
    QFile file(csv);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_EQ(file.readAll().count('\n'), 2);
    EXPECT_FALSE(view.exportCsv(window->exercises().database().path()).isEmpty());  // never over the database
}

// The Class view by class: the rows of two classes (as an instructor reads them from the server;
// here a file whose trainees have classes), one class chosen, and Export CSV… writes what is shown.
TEST(ClassViewTest, ShowsOneClassAndExportsWhatItShows) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("class.sqlite"));
    {
        ResultsDatabase db;
        QString error;
        ASSERT_TRUE(db.open(path, &error)) << error.toStdString();
        ScoreReport done;
        done.score = 80.0;
        done.guidance.completed = true;
        for (const char* name : {"Ann", "Ben", "Cleo"}) {
            const qint64 id = db.addTrainee(QString::fromLatin1(name));
            ASSERT_GE(db.addResult(id, done, QStringLiteral("Press three targets"), QString(), QDateTime::currentDateTimeUtc(),
                                   20.0, QString(), &error),
                      0)
                << error.toStdString();
        }
        // The server's word for a trainee's class (docs/results-store.md, "Roles"), written here by hand.
        ASSERT_TRUE(db.runStatements({QStringLiteral("UPDATE trainees SET class_name = '3A' WHERE name IN ('Ann', 'Ben')"),
                                      QStringLiteral("UPDATE trainees SET class_name = '3B' WHERE name = 'Cleo'")},
                                     &error))
            << error.toStdString();
    }
    ClassDialog view(path, QString(), QFileInfo(resource("exercises/press_targets.json")).absolutePath());
    QSignalSpy loaded(&view, &ClassDialog::loaded);
    ASSERT_TRUE(loaded.wait(30000) || loaded.count() == 1);
    ASSERT_EQ(view.rows().size(), 3u);
    auto* table = view.findChild<QTableWidget*>(QStringLiteral("classTable"));
    auto* filter = view.findChild<QComboBox*>(QStringLiteral("classFilterCombo"));
    ASSERT_NE(filter, nullptr);
    EXPECT_TRUE(filter->isEnabled());
    EXPECT_EQ(filter->count(), 3);  // All, 3A, 3B
    EXPECT_EQ(table->item(0, 0)->text(), QStringLiteral("3A"));
    EXPECT_EQ(table->item(2, 0)->text(), QStringLiteral("3B"));
    view.setClassFilter(QStringLiteral("3B"));
    ASSERT_EQ(table->rowCount(), 1);
    EXPECT_EQ(table->item(0, 1)->text(), QStringLiteral("Cleo"));
    EXPECT_TRUE(view.statusText().contains(QStringLiteral("1 trainee"))) << view.statusText().toStdString();
    const QString csv = dir.filePath(QStringLiteral("3b.csv"));
    ASSERT_EQ(view.exportCsv(csv), QString());
    QFile file(csv);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = file.readAll().trimmed().split('\n');
    ASSERT_EQ(lines.size(), 2);
    EXPECT_TRUE(lines[0].startsWith("class,trainee,"));
    EXPECT_TRUE(lines[1].startsWith("3B,Cleo,"));
    // A refresh keeps the chosen class.
    ASSERT_TRUE(view.refresh());
    ASSERT_TRUE(loaded.wait(30000));
    EXPECT_EQ(filter->currentText(), QStringLiteral("3B"));
    EXPECT_EQ(table->rowCount(), 1);
}

// The score depends only on what the trainee did: a scripted trainee's path starts with the
// exercise's recording, so a window that is slow to start recording (a busy machine: here 5 s of
// ticks pass before the window looks) scores as a prompt one does, and so does a second run.
TEST(TraineeMode, AScriptedPathStartsWithTheExerciseHoweverLateTheWindowLooks) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    auto window = traineeWindow(dir, "exercises/press_targets.good.path");
    ASSERT_NO_FATAL_FAILURE(readyAdaForPressTargets(*window));
    window->advanceTicks(3000);  // the device was connected a while before Start
    auto scoreWithDelay = [&](int delayTicks) {
        EXPECT_EQ(window->exercises().start(), QString());
        EXPECT_FALSE(window->devicePanel()->isEnabled());  // no device switch within a run
        window->session().step(delayTicks);  // the loop runs on; the window has not looked yet
        runToEnd(*window, 45000);
        EXPECT_EQ(window->exercises().phase(), ExerciseController::Phase::Finished);
        return window->exercises().lastReport() ? window->exercises().lastReport()->score : -1.0;
    };
    const double first = scoreWithDelay(0);
    const double late = scoreWithDelay(5000);
    // Between runs the device can be switched (the Device dock is the trainee's again) ...
    EXPECT_TRUE(window->devicePanel()->isEnabled());
    ASSERT_EQ(window->setDeviceUri(QStringLiteral("sim:stroke")), QString());
    ASSERT_EQ(window->setDeviceUri(QStringLiteral("sim:path:") + resource("exercises/press_targets.good.path")), QString());
    // ... and the path, connected again, still starts with the next run.
    window->advanceTicks(4000);
    const double prompt = scoreWithDelay(0);
    EXPECT_GE(first, 90.0);
    EXPECT_GE(late, 90.0);
    EXPECT_GE(prompt, 90.0);
    EXPECT_NEAR(late, prompt, 0.5);
}

TEST(TraineeMode, ResultsSurviveReopeningAndTheHistoryChartsEachSession) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    double firstScore = 0.0, secondScore = 0.0;
    {
        auto window = traineeWindow(dir, "exercises/press_targets.good.path");
        ASSERT_EQ(window->exercises().addTrainee(QStringLiteral("Ben")), QString());
        ASSERT_EQ(window->exercises().addExerciseFile(resource("exercises/press_targets.json")), QString());
        ASSERT_EQ(window->exercises().start(), QString());
        runToEnd(*window, 45000);
        ASSERT_TRUE(window->exercises().lastReport());
        firstScore = window->exercises().lastReport()->score;
        // A second session of the bad path, stopped early: stored as stopped, not as a score.
        ASSERT_EQ(window->setDeviceUri(QStringLiteral("sim:path:") + resource("exercises/press_targets.bad.path")), QString());
        ASSERT_EQ(window->exercises().start(), QString());
        window->advanceTicks(5000);
        window->exercises().stop();
        ASSERT_EQ(window->exercises().phase(), ExerciseController::Phase::Finished);
        secondScore = window->exercises().lastReport()->score;
        EXPECT_FALSE(window->exercises().lastReport()->guidance.completed);
        EXPECT_LT(secondScore, firstScore);
    }
    // A new window on the same database: both results, oldest first, charted.
    auto window = traineeWindow(dir, "exercises/press_targets.good.path");
    HistoryPanel* history = window->historyPanel();
    ASSERT_EQ(history->traineeBox()->count(), 1);
    EXPECT_EQ(history->traineeBox()->currentText(), QStringLiteral("Ben"));
    ASSERT_EQ(history->results().size(), 2u);
    EXPECT_EQ(history->results()[0].score, firstScore);
    EXPECT_EQ(history->results()[1].score, secondScore);
    EXPECT_EQ(history->results()[0].outcome, ResultOutcome::Completed);
    EXPECT_EQ(history->results()[1].outcome, ResultOutcome::Stopped);
    EXPECT_EQ(history->plottedPointCount(), 1);  // the stopped session is marked, not plotted as a score
    EXPECT_EQ(history->stoppedMarkCount(), 1);
    EXPECT_EQ(history->table()->rowCount(), 2);
    EXPECT_EQ(history->table()->item(0, 2)->text(), QStringLiteral("stopped"));
    EXPECT_TRUE(history->summaryText().contains(QStringLiteral("mean %1").arg(QLocale().toString(firstScore, 'f', 1))))
        << history->summaryText().toStdString();

    // The stored result's report: its recording is re-scored (the same score) into a PDF.
    history->selectRow(0);  // newest first in the table: the stopped session
    const auto selected = history->selectedResult();
    ASSERT_TRUE(selected);
    EXPECT_EQ(selected->score, secondScore);
    const QString pdf = dir.filePath(QStringLiteral("history.pdf"));
    ASSERT_EQ(window->exercises().exportResultPdf(*selected, pdf), QString());
    EXPECT_GT(QFileInfo(pdf).size(), 1000);
}

TEST(TraineeMode, FindTheLumpHidesTheInclusionFromTheTraineeAndScoresTheMark) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    auto window = traineeWindow(dir, "exercises/find_lump.good.path");
    ASSERT_EQ(window->exercises().addTrainee(QStringLiteral("Cy")), QString());
    ASSERT_EQ(window->exercises().addExerciseFile(resource("exercises/find_lump.json")), QString());
    ASSERT_EQ(window->exercises().start(), QString());
    window->advanceTicks(100);
    EXPECT_EQ(countMarkers(window->viewport()->exerciseMarkers(), ExerciseMarker::Kind::Inclusion), 0);
    // The good path presses the lump at 18.6 s of its script (the script starts with the exercise).
    window->advanceTicks(18600 - 100 - 1);
    ASSERT_TRUE(window->exercises().mark());
    EXPECT_EQ(countMarkers(window->viewport()->exerciseMarkers(), ExerciseMarker::Kind::Mark), 1);
    window->advanceTicks(500);
    window->exercises().stop();
    ASSERT_TRUE(window->exercises().lastReport());
    const ScoreReport& live = *window->exercises().lastReport();
    const MetricResult* lump = live.find(Metric::LumpErrorMm);
    ASSERT_NE(lump, nullptr);
    ASSERT_TRUE(lump->measured);
    EXPECT_LT(lump->value, 10.0);  // within the inclusion's radius
    EXPECT_EQ(replayScore(window->exercises().lastRecordingPath()).score, live.score);

    // The instructor's preview of the same exercise shows the inclusion, and stores nothing.
    const std::size_t stored = window->exercises().database().results(window->traineePanel()->traineeId()).size();
    const auto loaded = loadExercise(resource("exercises/find_lump.json").toStdString());
    ASSERT_TRUE(loaded.exercise);
    ASSERT_EQ(window->exercises().startPreview(*loaded.exercise), QString());
    window->advanceTicks(100);
    EXPECT_EQ(countMarkers(window->viewport()->exerciseMarkers(), ExerciseMarker::Kind::Inclusion), 1);
    window->exercises().stop();
    EXPECT_TRUE(window->exercises().preview());
    EXPECT_EQ(window->exercises().database().results(window->traineePanel()->traineeId()).size(), stored);
}

TEST(TraineeMode, DetectLumpsHidesTheLumpsUntilTheEndThenShowsThemTheFindingsAndTheHeatMap) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    // The light presser: marks the two shallow lumps at 73.831 and 78.331 s of its script,
    // finishes at 83.831 s, never presses deep enough for the 8 mm one.
    auto window = traineeWindow(dir, "exercises/detect_lumps.light.path");
    ASSERT_EQ(window->exercises().addTrainee(QStringLiteral("Di")), QString());
    ASSERT_EQ(window->exercises().addExerciseFile(resource("exercises/detect_lumps.json")), QString());
    EXPECT_FALSE(window->exercises().finishExamination()) << "not before the session runs";
    ASSERT_EQ(window->exercises().start(), QString());
    EXPECT_FALSE(window->traineePanel()->finishButton()->isHidden());
    window->advanceTicks(100);
    EXPECT_EQ(countMarkers(window->viewport()->exerciseMarkers(), ExerciseMarker::Kind::Inclusion), 0);
    EXPECT_TRUE(window->viewport()->exerciseMarkers().heat.empty());
    window->advanceTicks(73831 - 100 - 1);
    ASSERT_TRUE(window->exercises().mark());
    window->advanceTicks(78331 - 73831);
    ASSERT_TRUE(window->exercises().mark());
    window->advanceTicks(83831 - 78331);
    EXPECT_EQ(countMarkers(window->viewport()->exerciseMarkers(), ExerciseMarker::Kind::Inclusion), 0);
    ASSERT_TRUE(window->exercises().finishExamination());
    runToEnd(*window, 5000);
    ASSERT_FALSE(window->exercises().running());
    ASSERT_TRUE(window->exercises().lastReport());
    const ScoreReport& live = *window->exercises().lastReport();
    EXPECT_TRUE(live.guidance.completed) << "Finish completes the examination";
    ASSERT_TRUE(live.palpation && live.palpation->detection);
    EXPECT_EQ(live.palpation->detection->hits, 2u);
    EXPECT_EQ(live.palpation->detection->misses, 1u);
    EXPECT_EQ(live.palpation->detection->falseAlarms, 0u);
    EXPECT_EQ(replayScore(window->exercises().lastRecordingPath()).score, live.score);

    // Now the lumps, the two findings and the surface examined (only covered vertices).
    const ExerciseMarkers& markers = window->viewport()->exerciseMarkers();
    EXPECT_EQ(countMarkers(markers, ExerciseMarker::Kind::Inclusion), 3);
    EXPECT_EQ(countMarkers(markers, ExerciseMarker::Kind::Mark), 2);
    std::size_t covered = 0;
    for (float f : live.palpation->peakForceN) covered += f > 0.0f ? 1 : 0;
    EXPECT_GT(covered, 0u);
    EXPECT_EQ(markers.heat.size(), covered);
    EXPECT_DOUBLE_EQ(markers.heatMinN, 0.4);  // the exercise's coverage force (amber)
    EXPECT_DOUBLE_EQ(markers.heatMaxN, 4.0);  // to its excessive force (red), not the session's largest
    const QString card = window->traineePanel()->scoreCard()->palpationText();
    EXPECT_TRUE(card.contains(QStringLiteral("2 of 3"))) << card.toStdString();
    EXPECT_TRUE(card.contains(QStringLiteral("Pressed too lightly"))) << card.toStdString();
    // View > Coverage Heat Map off hides it, on shows it again.
    window->exercises().setShowCoverageHeat(false);
    EXPECT_TRUE(window->viewport()->exerciseMarkers().heat.empty());
    window->exercises().setShowCoverageHeat(true);
    EXPECT_EQ(window->viewport()->exerciseMarkers().heat.size(), covered);

    // Fading guidance: the first session had the full gauge, and says so; it scored 87.7 (good at
    // 80 by default), so the next one starts with the gauge at 1 - 1/5.
    ASSERT_EQ(live.aids.size(), 1u);
    EXPECT_EQ(live.aids[0].name, "force_gauge");
    EXPECT_DOUBLE_EQ(live.aids[0].level, 1.0);
    ASSERT_GT(live.score, 80.0);
    ASSERT_EQ(window->exercises().start(), QString());
    EXPECT_DOUBLE_EQ(window->exercises().gaugeLevel(), 0.8);
    EXPECT_DOUBLE_EQ(window->traineePanel()->gauge()->level(), 0.8);
    window->exercises().stop();
}

TEST(TraineeMode, AStaircaseRunsEachTrialAtTheTraineesLevelAndMovesWithTheResult) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    // Detect the lumps with a contrast staircase: 2-down-1-up from 5 in steps of 1.
    auto loaded = loadExercise(resource("exercises/detect_lumps.json").toStdString());
    ASSERT_TRUE(loaded.exercise);
    Exercise e = *loaded.exercise;
    e.meshPath = resource("meshes/sphere_8664.off").toStdString();
    e.tissuePresetPath = resource("presets/tissues/muscle.json").toStdString();
    e.detectLumps.staircase = StaircaseDef{StaircaseDef::Parameter::Contrast, 5.0, 1.0, 6.0, 2.0, 2, 1};
    const QString file = dir.filePath(QStringLiteral("stair.json"));
    ASSERT_EQ(saveExercise(e, file.toStdString()), "");
    auto window = traineeWindow(dir, "exercises/detect_lumps.good.path");
    ASSERT_EQ(window->exercises().addTrainee(QStringLiteral("Eve")), QString());
    ASSERT_EQ(window->exercises().addExerciseFile(file), QString());
    // The thorough examiner: marks at 73.831, 78.331 and 82.831 s, finishes at 88.331 s.
    auto session = [&] {
        EXPECT_EQ(window->exercises().start(), QString());
        const double level = window->exercises().staircaseLevel().value_or(-1.0);
        window->advanceTicks(73831 - 1);
        EXPECT_TRUE(window->exercises().mark());
        window->advanceTicks(4500);
        EXPECT_TRUE(window->exercises().mark());
        window->advanceTicks(4500);
        EXPECT_TRUE(window->exercises().mark());
        window->advanceTicks(88331 - 82831);
        EXPECT_TRUE(window->exercises().finishExamination());
        runToEnd(*window, 5000);
        EXPECT_EQ(window->exercises().lastReport()->palpation->detection->hits, 3u);
        return level;
    };
    EXPECT_EQ(session(), 5.0);
    EXPECT_EQ(session(), 5.0);  // one pass: the 2-down rule waits for a second
    EXPECT_EQ(session(), 4.0);  // two in a row: one step harder (lower contrast)
    // The session ran at it: the recording carries the exercise with every lump at contrast 4.
    std::vector<std::string> errors;
    const auto ran = recordedExercise(
        RecordingReader::open(window->exercises().lastRecordingPath().toStdString()).header(), errors);
    ASSERT_TRUE(ran);
    for (const LumpDef& l : ran->detectLumps.lumps) EXPECT_EQ(l.contrast, 4.0);
    // Stopped at once: stored as stopped, no trial, the level stays.
    ASSERT_EQ(window->exercises().start(), QString());
    window->advanceTicks(500);
    window->exercises().stop();
    ASSERT_EQ(window->exercises().start(), QString());
    EXPECT_EQ(window->exercises().staircaseLevel().value_or(-1.0), 4.0);
    window->exercises().stop();
}

TEST(TraineeMode, AnExpertReferenceSessionIsStoredAsAnExperts) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    auto window = traineeWindow(dir, "exercises/press_targets.good.path");
    readyAdaForPressTargets(*window);
    window->traineePanel()->expertBox()->setChecked(true);
    ASSERT_EQ(window->exercises().start(), QString());
    EXPECT_FALSE(window->traineePanel()->expertBox()->isEnabled()) << "fixed while the session runs";
    runToEnd(*window, 30000);
    ASSERT_EQ(window->exercises().start(), QString());
    runToEnd(*window, 30000);
    window->traineePanel()->expertBox()->setChecked(false);
    ASSERT_EQ(window->exercises().start(), QString());
    runToEnd(*window, 30000);
    const auto results = window->exercises().database().results(window->traineePanel()->traineeId());
    ASSERT_EQ(results.size(), 3u);
    EXPECT_TRUE(results[0].expert);
    EXPECT_TRUE(results[1].expert);
    EXPECT_FALSE(results[2].expert);
    // The experts' sessions are no trainee scores: they did not fade the trainee's gauge.
    EXPECT_DOUBLE_EQ(window->exercises().gaugeLevel(), 1.0);

    // History > Learning Curve…: the trainee's one session against the two experts' marks. The
    // same scripted path scores the same, so it sits at the experts' mean (SD 0): a pass.
    const LearningCurve curve = learningCurve(window->exercises().database(), results[2].traineeId,
                                              *loadExercise(resource("exercises/press_targets.json").toStdString()).exercise,
                                              results[2].exercisePath, QStringLiteral("Ada"));
    ASSERT_EQ(curve.sessions.size(), 1u);
    ASSERT_TRUE(curve.standard.valid()) << curve.standard.problem;
    ASSERT_EQ(curve.chart.passed.size(), 1u);
    EXPECT_TRUE(curve.chart.passed[0]);
    window->historyPanel()->refresh();
    window->historyPanel()->selectRow(2);
    EXPECT_TRUE(window->historyPanel()->learningCurveButton()->isEnabled());
    EXPECT_EQ(window->historyPanel()->showLearningCurve(), QString());
    QDialog* dialog = window->historyPanel()->learningCurveDialog();
    ASSERT_NE(dialog, nullptr);
    EXPECT_TRUE(dialog->isVisible());
    // One metric at a time, the score first, each large enough to read; the choice switches it.
    auto* metric = dialog->findChild<QComboBox*>(QStringLiteral("curveMetricCombo"));
    ASSERT_NE(metric, nullptr);
    ASSERT_EQ(metric->count(), int(curve.chart.metrics.size()) + 1);
    EXPECT_EQ(metric->itemText(0), QStringLiteral("Score (of 100)"));
    QApplication::processEvents();
    auto* chart = dialog->findChild<QChartView*>(QStringLiteral("curveChart"));
    ASSERT_NE(chart, nullptr);
    EXPECT_GE(chart->height(), 300);
    EXPECT_EQ(chart->chart()->title(), QStringLiteral("Score (of 100)"));
    metric->setCurrentIndex(1);
    QApplication::processEvents();
    chart = dialog->findChild<QChartView*>(QStringLiteral("curveChart"));
    ASSERT_NE(chart, nullptr);
    EXPECT_EQ(chart->chart()->title(), metric->itemText(1));
    EXPECT_EQ(dialog->findChildren<QChartView*>().size(), 1) << "one chart at a time";
    if (const QByteArray shots = qgetenv("PALPATE_SHOT_DIR"); !shots.isEmpty())
        dialog->grab().save(QString::fromLocal8Bit(shots) + QStringLiteral("/learning-curve.png"));
}

TEST(ForceGauge, AFadedGaugeDrawsFainterAndAHiddenOneSaysSo) {
    ForceGauge gauge;
    gauge.resize(260, 44);
    gauge.setWindow(1.0, 2.0);
    gauge.setForceN(1.5);
    auto barPixel = [&](double level) {
        gauge.setLevel(level);
        const QImage image = gauge.grab().toImage();
        return image.pixelColor(int(4 + (gauge.width() - 8) * 0.3), 10);  // on the bar, inside the window
    };
    const QColor full = barPixel(1.0), faded = barPixel(0.3);
    const QColor background = gauge.palette().color(QPalette::Window);
    auto distance = [](const QColor& a, const QColor& b) {
        return std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) + std::abs(a.blue() - b.blue());
    };
    EXPECT_GT(distance(full, background), distance(faded, background) + 30);
    gauge.setLevel(-1.0);
    EXPECT_EQ(gauge.level(), 0.0);
}

TEST(CoverageHeat, ColoursRunFromAmberToRedAndLeaveTheTissueAlone) {
    EXPECT_EQ(heatColour(0.5, 0.5, 2.5), QColor(255, 214, 70));
    EXPECT_EQ(heatColour(2.5, 0.5, 2.5), QColor(190, 20, 40));
    EXPECT_EQ(heatColour(9.0, 0.5, 2.5), heatColour(2.5, 0.5, 2.5)) << "clamped";
    const QColor mid = heatColour(1.5, 0.5, 2.5);
    EXPECT_GT(mid.red(), 190);
    EXPECT_LT(mid.green(), 214);
    EXPECT_GT(mid.green(), 20);
}

TEST(TraineeMode, ScoreReportPdfHoldsTheScore) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    auto window = traineeWindow(dir, "exercises/trace.good.path");
    ASSERT_EQ(window->runExercise(resource("exercises/trace.json"), QStringLiteral("Dee")), QString());
    EXPECT_EQ(window->traineePanel()->traineeName(), QStringLiteral("Dee"));
    runToEnd(*window, 45000);
    ASSERT_TRUE(window->exercises().lastReport());
    const double score = window->exercises().lastReport()->score;
    // The force-time series comes from the recording: one point per tick up to the thinning.
    const RecordingReader reader = RecordingReader::open(window->exercises().lastRecordingPath().toStdString());
    const auto series = recordedForceSeries(reader, 100000);
    EXPECT_GT(series.size(), 1000u);
    EXPECT_GT(std::max_element(series.begin(), series.end(), [](auto a, auto b) { return a.forceN < b.forceN; })->forceN, 0.5);
    const auto thin = recordedForceSeries(reader, 500);
    EXPECT_LE(thin.size(), 500u);

    const QString pdf = dir.filePath(QStringLiteral("score.pdf"));
    ASSERT_EQ(window->exercises().exportLastReportPdf(pdf), QString());
    ASSERT_TRUE(QFile::exists(pdf));
    const QString pdftotext = QStandardPaths::findExecutable(QStringLiteral("pdftotext"));
    if (pdftotext.isEmpty()) GTEST_SKIP() << "pdftotext not installed (poppler-utils): the PDF's text is not checked";
    QProcess proc;
    proc.start(pdftotext, {pdf, QStringLiteral("-")});
    ASSERT_TRUE(proc.waitForFinished(30000));
    const QString text = QString::fromUtf8(proc.readAllStandardOutput()).simplified();
    EXPECT_TRUE(text.contains(QStringLiteral("Dee"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("Score: %1 / 100").arg(QLocale().toString(score, 'f', 1)))) << text.toStdString();
}

TEST(TraineeMode, ErrorsAreReportedNotCrashedOn) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    auto window = traineeWindow(dir, "exercises/press_targets.good.path");
    // No trainee yet.
    window->traineePanel()->setTrainees({});
    EXPECT_TRUE(window->exercises().start().contains(QStringLiteral("trainee")));
    EXPECT_FALSE(window->exercises().running());
    // A malformed exercise: the error names the file and the key; the list is unchanged.
    const QString bad = dir.filePath(QStringLiteral("bad.json"));
    QFile file(bad);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "palpate-exercise", "version": 1, "name": "x", "type": "press_targets",
                  "mesh": "meshes/sphere_1442.off", "tissue_preset": "presets/tissues/liver.json",
                  "time_limit_s": -3, "press_targets": {"targets": [{"vertex": 1}]}})");
    file.close();
    const QString error = window->exercises().addExerciseFile(bad);
    EXPECT_TRUE(error.contains(QStringLiteral("time_limit_s"))) << error.toStdString();
    EXPECT_TRUE(error.contains(bad)) << error.toStdString();
    // An exercise whose target is not on its mesh: refused at start, the session untouched.
    ASSERT_EQ(window->exercises().addTrainee(QStringLiteral("Eve")), QString());
    const QString offMesh = dir.filePath(QStringLiteral("offmesh.json"));
    QFile f2(offMesh);
    ASSERT_TRUE(f2.open(QIODevice::WriteOnly));
    f2.write(R"({"format": "palpate-exercise", "version": 1, "name": "off", "type": "press_targets",
                 "mesh": "meshes/sphere_1442.off", "tissue_preset": "presets/tissues/liver.json",
                 "time_limit_s": 30, "press_targets": {"targets": [{"vertex": 999999}]}})");
    f2.close();
    ASSERT_EQ(window->exercises().addExerciseFile(offMesh), QString());
    const QString startError = window->exercises().start();
    EXPECT_TRUE(startError.contains(QStringLiteral("press_targets.targets[0]"))) << startError.toStdString();
    EXPECT_FALSE(window->exercises().running());
    // Stop and mark with nothing running do nothing.
    window->exercises().stop();
    EXPECT_FALSE(window->exercises().mark());
}

namespace {

/// The mesh an exercise file names, as a canonical path.
QString exerciseMesh(const QString& exercisePath) {
    const auto loaded = loadExercise(exercisePath.toStdString());
    if (!loaded.exercise) return {};
    return QFileInfo(QString::fromStdString(
                         resolveExercisePath(*loaded.exercise, loaded.exercise->meshPath, findResource)))
        .canonicalFilePath();
}

}  // namespace

// The Exercise dock offers an exercise on the mesh on screen (its text speaks of what is shown)
// until the trainee picks one; then it keeps theirs.
TEST(ExerciseDock, SelectsAnExerciseOnTheShownMeshUntilTheTraineePicks) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    auto window = traineeWindow(dir, "exercises/press_targets.good.path");
    TraineePanel* panel = window->traineePanel();
    const QString stomach = QFileInfo(resource("meshes/stomach_3970.off")).canonicalFilePath();
    const QString sphere = QFileInfo(resource("meshes/sphere_1442.off")).canonicalFilePath();
    ASSERT_EQ(window->loadMesh(stomach), QString());
    window->advanceTicks(2);
    EXPECT_EQ(exerciseMesh(panel->exercisePath()), stomach) << panel->exercisePath().toStdString();
    ASSERT_EQ(window->loadMesh(sphere), QString());
    window->advanceTicks(2);
    EXPECT_EQ(exerciseMesh(panel->exercisePath()), sphere) << panel->exercisePath().toStdString();
    // The trainee picks one on the stomach; loading the sphere again keeps it.
    auto* combo = panel->findChild<QComboBox*>(QStringLiteral("exerciseCombo"));
    ASSERT_NE(combo, nullptr);
    int stomachIndex = -1;
    for (int i = 0; i < combo->count(); ++i)
        if (exerciseMesh(combo->itemData(i).toString()) == stomach) stomachIndex = i;
    ASSERT_GE(stomachIndex, 0);
    combo->setCurrentIndex(stomachIndex);
    emit combo->activated(stomachIndex);
    ASSERT_EQ(window->loadMesh(stomach), QString());
    window->advanceTicks(2);
    ASSERT_EQ(window->loadMesh(sphere), QString());
    window->advanceTicks(2);
    EXPECT_EQ(exerciseMesh(panel->exercisePath()), stomach);
}

// A preview (the welcome page's example, the editor's Try it) shows its own exercise in the combo
// above the score card, not whichever was selected before.
// An exercise opened from a file stays in the trainee's list at the next start (newest first,
// after the shipped ones); a shipped one is not listed twice; one that no longer opens is left out.
TEST(ExerciseDock, AnOpenedExerciseStaysInTheListAtTheNextStart) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString mine = dir.filePath(QStringLiteral("my_targets.json"));
    ASSERT_TRUE(QFile::copy(resource("exercises/press_targets.json"), mine));
    {
        // The shipped files' relative paths resolve through the resources, wherever the copy is.
        QFile file(mine);
        ASSERT_TRUE(file.open(QIODevice::ReadOnly));
        QByteArray text = file.readAll();
        file.close();
        text.replace("\"name\": \"Press three targets\"", "\"name\": \"My targets\"");
        ASSERT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(text);
    }
    const QString gone = dir.filePath(QStringLiteral("gone.json"));
    ASSERT_TRUE(QFile::copy(mine, gone));
    const auto listed = [](MainWindow& window) {
        auto* combo = window.traineePanel()->findChild<QComboBox*>(QStringLiteral("exerciseCombo"));
        QStringList paths;
        for (int i = 0; combo && i < combo->count(); ++i) paths << combo->itemData(i).toString();
        return paths;
    };
    int shippedCount = 0;
    {
        auto window = traineeWindow(dir, "exercises/press_targets.good.path");
        shippedCount = int(listed(*window).size());
        ASSERT_GT(shippedCount, 0);
        ASSERT_EQ(window->exercises().addExerciseFile(gone), QString());
        ASSERT_EQ(window->exercises().addExerciseFile(mine), QString());
        ASSERT_EQ(window->exercises().addExerciseFile(resource("exercises/press_targets.json")), QString());
        EXPECT_EQ(listed(*window).size(), shippedCount + 2);
    }
    ASSERT_TRUE(QFile::remove(gone));
    auto again = traineeWindow(dir, "exercises/press_targets.good.path");
    const QStringList paths = listed(*again);
    ASSERT_EQ(paths.size(), shippedCount + 1) << paths.join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(QFileInfo(paths.back()), QFileInfo(mine));
    EXPECT_EQ(ExerciseController::openedExercises().size(), 2);  // the gone one is kept in the settings
    EXPECT_EQ(QFileInfo(ExerciseController::openedExercises().front()), QFileInfo(mine));
}

// A bundle opens like an exercise file: its files go into the application's exercises folder
// and the exercise is listed and selected; a broken bundle is refused naming the key.
TEST(ExerciseDock, ABundleOpensAsAnExercise) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString bundle = dir.filePath(QStringLiteral("trace.palpex"));
    ASSERT_EQ(writeExerciseBundle(findResource("exercises/trace.json"), bundle.toStdString(), findResource), "");
    auto window = traineeWindow(dir, "exercises/trace.good.path");
    ASSERT_EQ(window->exercises().addExerciseFile(bundle), QString());
    const QString imported = window->traineePanel()->exercisePath();
    EXPECT_EQ(QFileInfo(imported).absolutePath(),
              QFileInfo(ExerciseController::importedExercisesFolder()).absoluteFilePath());
    EXPECT_TRUE(QFile::exists(QFileInfo(imported).absoluteDir().filePath(QStringLiteral("stomach_3970.off"))));
    // The shipped trace of the same name is listed too: the copy is told apart by its folder.
    auto* combo = window->traineePanel()->findChild<QComboBox*>(QStringLiteral("exerciseCombo"));
    ASSERT_NE(combo, nullptr);
    const QString name = QString::fromStdString(loadExercise(findResource("exercises/trace.json")).exercise->name);
    EXPECT_NE(combo->findText(name), -1);
    EXPECT_EQ(combo->currentText(), QStringLiteral("%1 (in exercises)").arg(name));
    const auto loaded = loadExercise(imported.toStdString());
    ASSERT_TRUE(loaded.exercise) << loaded.error();
    EXPECT_EQ(loaded.exercise->name, loadExercise(findResource("exercises/trace.json")).exercise->name);
    // It runs: the scripted trainee traces it.
    window->setMode(MainWindow::Mode::Trainee);
    ASSERT_EQ(window->exercises().addTrainee(QStringLiteral("Bo")), QString());
    ASSERT_EQ(window->exercises().start(), QString());
    runToEnd(*window, 60000);
    ASSERT_TRUE(window->exercises().lastReport());
    EXPECT_GT(window->exercises().lastReport()->score, 80.0);

    QFile broken(dir.filePath(QStringLiteral("broken.palpex")));
    ASSERT_TRUE(broken.open(QIODevice::WriteOnly));
    broken.write(R"({"format": "palpate-exercise-bundle", "version": 7})");
    broken.close();
    const QString error = window->exercises().addExerciseFile(broken.fileName());
    EXPECT_TRUE(error.contains(QStringLiteral("version"))) << error.toStdString();
    EXPECT_EQ(window->traineePanel()->exercisePath(), imported);
}

TEST(ExerciseDock, APreviewShowsTheExerciseThatRuns) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    auto window = traineeWindow(dir, "exercises/press_targets.good.path");
    TraineePanel* panel = window->traineePanel();
    ASSERT_EQ(window->loadMesh(resource("meshes/sphere_1442.off")), QString());
    window->advanceTicks(2);
    ASSERT_TRUE(panel->exercisePath().endsWith(QStringLiteral("find_lump.json"))) << panel->exercisePath().toStdString();
    const QString pressTargets = QFileInfo(resource("exercises/press_targets.json")).absoluteFilePath();
    ASSERT_EQ(window->runExercise(pressTargets, QString()), QString());
    EXPECT_EQ(panel->exercisePath(), pressTargets);
    window->exercises().stop();
    // An exercise with no file (the editor's, unsaved) is shown as such.
    auto loaded = loadExercise(pressTargets.toStdString());
    ASSERT_TRUE(loaded.exercise);
    Exercise unsaved = *loaded.exercise;
    unsaved.name = "My new exercise";
    unsaved.meshPath = resolveExercisePath(unsaved, unsaved.meshPath, findResource);
    unsaved.tissuePresetPath = resolveExercisePath(unsaved, unsaved.tissuePresetPath, findResource);
    unsaved.sourcePath.clear();
    ASSERT_EQ(window->exercises().startPreview(unsaved), QString());
    EXPECT_TRUE(panel->exerciseTitle().contains(QStringLiteral("My new exercise"))) << panel->exerciseTitle().toStdString();
    EXPECT_TRUE(panel->exercisePath().isEmpty());
}

// Instructor mode is the instructor's tools: the trainee's Exercise and History docks are not shown
// (the Exercise dock comes while an exercise is tried); trainee mode shows them.
TEST(InstructorMode, HidesTheTraineesDocks) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    auto window = traineeWindow(dir, "exercises/press_targets.good.path");
    auto* exerciseDock = window->findChild<QDockWidget*>(QStringLiteral("exerciseDock"));
    auto* historyDock = window->findChild<QDockWidget*>(QStringLiteral("historyDock"));
    ASSERT_TRUE(exerciseDock && historyDock);
    window->setMode(MainWindow::Mode::Instructor);
    EXPECT_TRUE(exerciseDock->isHidden());
    EXPECT_TRUE(historyDock->isHidden());
    window->setMode(MainWindow::Mode::Trainee);
    EXPECT_FALSE(exerciseDock->isHidden());
    EXPECT_FALSE(historyDock->isHidden());
}

// The instructor's draft of a detection exercise (its lumps) is drawn for the instructor and gone
// the moment the window is a trainee's; back in instructor mode it is there again.
TEST(InstructorMode, TheDraftsLumpsAreNeverShownInTraineeMode) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    auto window = traineeWindow(dir, "exercises/press_targets.good.path");
    ASSERT_EQ(window->loadMesh(resource("meshes/sphere_1442.off")), QString());
    window->advanceTicks(10);
    window->setMode(MainWindow::Mode::Instructor);
    auto* editorDock = window->findChild<QDockWidget*>(QStringLiteral("exerciseEditorDock"));
    ASSERT_NE(editorDock, nullptr);
    editorDock->raise();  // the editor's tab in front: its draft is drawn
    QApplication::processEvents();
    ExerciseEditorPanel* editor = window->exerciseEditor();
    editor->newExercise(ExerciseType::DetectLumps);
    editor->setPlacing(ExerciseEditorPanel::Placing::AddItem);
    editor->vertexPicked(10);
    editor->vertexPicked(200);
    editor->setPlacing(ExerciseEditorPanel::Placing::None);
    QApplication::processEvents();
    ASSERT_EQ(editor->exercise().detectLumps.lumps.size(), 2u);
    EXPECT_EQ(countMarkers(window->viewport()->exerciseMarkers(), ExerciseMarker::Kind::Inclusion), 2);
    window->setMode(MainWindow::Mode::Trainee);
    EXPECT_TRUE(window->viewport()->exerciseMarkers().markers.empty());
    window->setMode(MainWindow::Mode::Instructor);
    editorDock->raise();
    QApplication::processEvents();
    EXPECT_EQ(countMarkers(window->viewport()->exerciseMarkers(), ExerciseMarker::Kind::Inclusion), 2);
}

namespace {

/// The visible widgets of the Exercise dock that reach past the dock's visible width.
QStringList clippedInExerciseDock(MainWindow& window) {
    QStringList clipped;
    TraineePanel* panel = window.traineePanel();
    auto* scroll = qobject_cast<QScrollArea*>(panel->parentWidget()->parentWidget());
    if (!scroll) return {QStringLiteral("(no scroll area)")};
    const int visiblePx = scroll->viewport()->width();
    for (QWidget* w : panel->findChildren<QWidget*>()) {
        if (!w->isVisibleTo(panel) || w->width() <= 0) continue;
        const int rightPx = w->mapTo(scroll->viewport(), QPoint(w->width(), 0)).x();
        if (rightPx > visiblePx + 1)
            clipped << QStringLiteral("%1 %2 ends at %3 of %4")
                           .arg(QString::fromLatin1(w->metaObject()->className()), w->objectName())
                           .arg(rightPx)
                           .arg(visiblePx);
    }
    return clipped;
}

}  // namespace

// At 1280x800 the Exercise dock wraps its text and shows its buttons, gauge and score card whole:
// nothing reaches past its edge, while an examination runs and when its card is shown.
TEST(ExerciseDock, WrapsAndNeverClipsAt1280x800) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    auto window = traineeWindow(dir, "exercises/detect_lumps.light.path");
    window->resize(1280, 800);
    window->setMode(MainWindow::Mode::Trainee);
    // The window itself fits the screen: its docks scroll rather than push it taller, in either mode.
    EXPECT_LE(window->height(), 800) << "trainee: the docks need " << window->minimumSizeHint().height() << " px";
    window->setMode(MainWindow::Mode::Instructor);
    window->resize(1280, 800);
    EXPECT_LE(window->height(), 800) << "instructor: the docks need " << window->minimumSizeHint().height() << " px";
    window->setMode(MainWindow::Mode::Trainee);
    ASSERT_EQ(window->exercises().addTrainee(QStringLiteral("Eli")), QString());
    ASSERT_EQ(window->exercises().addExerciseFile(resource("exercises/detect_lumps.json")), QString());
    ASSERT_EQ(window->exercises().start(), QString());
    window->advanceTicks(2000);
    QApplication::processEvents();
    QStringList clipped = clippedInExerciseDock(*window);
    EXPECT_TRUE(clipped.isEmpty()) << "running: " << clipped.join(QStringLiteral("; ")).toStdString();
    window->advanceTicks(83831 - 2000);
    window->exercises().finishExamination();
    runToEnd(*window, 5000);
    ASSERT_FALSE(window->exercises().running());
    QApplication::processEvents();
    QApplication::processEvents();
    clipped = clippedInExerciseDock(*window);
    EXPECT_TRUE(clipped.isEmpty()) << "score card: " << clipped.join(QStringLiteral("; ")).toStdString();
    if (const QByteArray shots = qgetenv("PALPATE_SHOT_DIR"); !shots.isEmpty())
        window->grab().save(QString::fromLocal8Bit(shots) + QStringLiteral("/trainee-1280x800.png"));
}

// An instructor's Try it of a detection exercise ends with its lumps revealed beside the score;
// the next person, in trainee mode, does not find them drawn.
TEST(InstructorMode, ATriedExercisesRevealedLumpsAreGoneInTraineeMode) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    auto window = traineeWindow(dir, "exercises/detect_lumps.light.path");
    window->setMode(MainWindow::Mode::Instructor);
    const auto loaded = loadExercise(findResource("exercises/detect_lumps.json"));
    ASSERT_TRUE(loaded.exercise) << loaded.error();
    ASSERT_EQ(window->exercises().startPreview(*loaded.exercise), QString());
    window->advanceTicks(83831);
    window->exercises().finishExamination();
    runToEnd(*window, 5000);
    ASSERT_FALSE(window->exercises().running());
    EXPECT_EQ(countMarkers(window->viewport()->exerciseMarkers(), ExerciseMarker::Kind::Inclusion), 3)
        << "revealed to the instructor who tried it";
    window->setMode(MainWindow::Mode::Trainee);
    EXPECT_EQ(countMarkers(window->viewport()->exerciseMarkers(), ExerciseMarker::Kind::Inclusion), 0);
    EXPECT_TRUE(window->viewport()->exerciseMarkers().heat.empty());
}

TEST(InstructorMode, ClickingTheMeshPlacesTargetsTheViewportShowsAndUndoRemoves) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    auto window = traineeWindow(dir, "exercises/press_targets.good.path");
    ASSERT_EQ(window->loadMesh(resource("meshes/sphere_1442.off")), QString());
    window->advanceTicks(10);
    window->setMode(MainWindow::Mode::Instructor);
    ExerciseEditorPanel* editor = window->exerciseEditor();
    ASSERT_NE(editor, nullptr);
    editor->newExercise(ExerciseType::PressTargets);
    // The window's Undo acts on the editor once it is worked in.
    window->undoGroup()->setActiveStack(editor->undoStack());
    editor->setPlacing(ExerciseEditorPanel::Placing::AddItem);
    ASSERT_TRUE(window->viewport()->pickHandlerSet());

    // A click (no drag) at the viewport's centre places a target on the vertex under it.
    QWidget* view = window->viewport()->widget();
    const QPoint centre(view->width() / 2, view->height() / 2);
    const auto expected = window->viewport()->pickVertexAt(QPointF(centre), view->size());
    ASSERT_TRUE(expected);
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, centre);
    ASSERT_EQ(editor->exercise().pressTargets.targets.size(), 1u);
    const auto& mesh = *window->session().drawnMesh();
    EXPECT_EQ(editor->exercise().pressTargets.targets[0].at.vertex, mesh.originalIndex()[*expected]);
    const ExerciseMarkers& shown = window->viewport()->exerciseMarkers();
    ASSERT_EQ(countMarkers(shown, ExerciseMarker::Kind::Target), 1);
    EXPECT_EQ(shown.markers[0].positionMm, mesh.restPositionsMm()[*expected]);
    // A drag orbits and places nothing.
    QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, centre);
    QMouseEvent move(QEvent::MouseMove, QPointF(centre + QPoint(40, 10)), view->mapToGlobal(QPointF(centre + QPoint(40, 10))),
                     Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(view, &move);
    QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, centre + QPoint(40, 10));
    EXPECT_EQ(editor->exercise().pressTargets.targets.size(), 1u);
    if (const QByteArray shots = qgetenv("PALPATE_SHOT_DIR"); !shots.isEmpty()) {
        if (auto* dock = qobject_cast<QDockWidget*>(editor->parentWidget())) dock->raise();
        QApplication::processEvents();
        window->grab().save(QString::fromLocal8Bit(shots) + QStringLiteral("/instructor.png"));
    }

    // Edit > Undo (the window's group) takes the target back, and the viewport follows.
    window->undoGroup()->undo();
    EXPECT_EQ(editor->exercise().pressTargets.targets.size(), 0u);
    EXPECT_EQ(countMarkers(window->viewport()->exerciseMarkers(), ExerciseMarker::Kind::Target), 0);
    // Leaving placing mode gives the left button back to the camera.
    editor->setPlacing(ExerciseEditorPanel::Placing::None);
    EXPECT_FALSE(window->viewport()->pickHandlerSet());
}

TEST(InstructorMode, LevelOfDetailUseLoadsTheChosenLevelAndRingCount) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    // A copy: the level cache is written beside the mesh, never into resources/.
    const QString mesh = dir.filePath(QStringLiteral("sphere.off"));
    ASSERT_TRUE(QFile::copy(resource("meshes/sphere_1442.off"), mesh));
    auto window = traineeWindow(dir, "exercises/press_targets.good.path");
    ASSERT_EQ(window->loadMesh(mesh), QString());
    window->advanceTicks(10);
    LodPanel* lod = window->lodPanel();
    ASSERT_NE(lod, nullptr);
    EXPECT_EQ(lod->meshPath(), mesh);
    ASSERT_TRUE(lod->plan());
    ASSERT_TRUE(QTest::qWaitFor([lod] { return !lod->busy(); }, 120000));
    ASSERT_FALSE(lod->candidates().empty());
    const auto chosen = lod->currentPlan().chosen;
    ASSERT_TRUE(chosen) << lod->currentPlan().reason;
    const LodCandidate c = lod->candidates()[*chosen];
    const std::size_t measured = lod->candidates().size();
    const int ringsBefore = window->session().preset().model.slopeRing.ringCount;
    auto* undoUse = lod->findChild<QPushButton*>(QStringLiteral("lodUndoUseButton"));
    ASSERT_NE(undoUse, nullptr);
    EXPECT_FALSE(undoUse->isEnabled());
    lod->useChosen();
    window->advanceTicks(10);
    // The loop now runs the chosen level with the chosen rings; the panel keeps the source.
    const QString expectedMesh = c.level == 0 ? mesh : lod->levelMeshPath(*chosen);
    EXPECT_EQ(QString::fromStdString(window->session().drawnPath()), expectedMesh);
    EXPECT_EQ(window->session().drawnMesh()->vertexCount(), c.vertices);
    EXPECT_EQ(window->session().preset().model.slopeRing.ringCount, c.rings);
    EXPECT_EQ(lod->meshPath(), mesh);
    EXPECT_EQ(lod->candidates().size(), measured);  // the level is a choice within the scene: the table stays
    EXPECT_TRUE(lod->currentPlan().chosen);
    // It says what it changed, and Undo use goes back to the mesh and rings from before.
    auto* used = lod->findChild<QLabel*>(QStringLiteral("lodUsedLabel"));
    ASSERT_NE(used, nullptr);
    std::printf("[ figures  ] used: %s\n", used->text().toStdString().c_str());
    EXPECT_TRUE(used->isVisibleTo(lod));
    if (c.rings != ringsBefore)
        EXPECT_TRUE(used->text().contains(QStringLiteral("%1 rings instead of %2").arg(c.rings).arg(ringsBefore)))
            << used->text().toStdString();
    if (expectedMesh != mesh)
        EXPECT_TRUE(used->text().contains(QStringLiteral("sphere.off"))) << used->text().toStdString();
    ASSERT_TRUE(undoUse->isEnabled());
    undoUse->click();
    window->advanceTicks(10);
    EXPECT_EQ(QString::fromStdString(window->session().drawnPath()), mesh);
    EXPECT_EQ(window->session().preset().model.slopeRing.ringCount, ringsBefore);
    EXPECT_FALSE(undoUse->isEnabled());
    // Used again, then another mesh opened: the level's rings stay with the level's scene.
    lod->useSelected();  // nothing selected: nothing happens
    lod->useChosen();
    window->advanceTicks(10);
    EXPECT_EQ(window->session().preset().model.slopeRing.ringCount, c.rings);
    ASSERT_EQ(window->loadMesh(resource("meshes/stomach_3970.off")), QString());
    window->advanceTicks(10);
    EXPECT_EQ(window->session().preset().model.slopeRing.ringCount, ringsBefore);
    EXPECT_FALSE(undoUse->isEnabled());
}

TEST(ForceGauge, ZonesFollowTheWindowAndTheExcessiveForce) {
    ForceGauge gauge;
    gauge.resize(300, 44);
    gauge.setWindow(1.0, 2.0);
    gauge.setExcessiveN(3.0);
    gauge.setForceN(0.5);
    EXPECT_EQ(gauge.zone(), -1);
    gauge.setForceN(1.5);
    EXPECT_EQ(gauge.zone(), 0);
    gauge.setForceN(2.5);
    EXPECT_EQ(gauge.zone(), 1);
    gauge.setForceN(3.0);
    EXPECT_EQ(gauge.zone(), 2);
    gauge.setForceN(std::numeric_limits<double>::quiet_NaN());
    EXPECT_EQ(gauge.forceN(), 0.0);
    // Inside the window the bar is drawn in the inside colour, and that colour is in the picture.
    gauge.setForceN(1.5);
    const QImage image = gauge.grab().toImage();
    const QColor inside = gauge.barColour();
    int hits = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) hits += image.pixelColor(x, y) == inside;
    EXPECT_GT(hits, 50);
}

// A small window (what a soft tissue reaches with the mouse) fills a good part of the gauge, not a
// sliver beside a far-away excessive level; a window near the excessive level shares its scale.
TEST(ForceGauge, TheScaleFitsTheWindow) {
    ForceGauge gauge;
    gauge.resize(300, 44);
    gauge.setExcessiveN(3.0);
    gauge.setWindow(0.082, 0.16);
    EXPECT_GE((gauge.windowMaxN() - gauge.windowMinN()) / gauge.shownScaleN(), 0.2);
    gauge.setForceN(0.12);
    EXPECT_EQ(gauge.zone(), 0);
    gauge.setWindow(1.0, 2.0);
    EXPECT_GT(gauge.shownScaleN(), 3.0);  // the 3 N excessive zone is on the scale
    EXPECT_GE((gauge.windowMaxN() - gauge.windowMinN()) / gauge.shownScaleN(), 0.2);
    if (const QString dir = qEnvironmentVariable("PALPATE_SHOT_DIR"); !dir.isEmpty()) {
        gauge.setWindow(0.082, 0.16);
        gauge.grab().save(dir + QStringLiteral("/gauge-small.png"));
        gauge.setWindow(1.0, 2.0);
        gauge.setForceN(1.5);
        gauge.grab().save(dir + QStringLiteral("/gauge-1-2.png"));
    }
}

namespace {

ScoreReport reportOf(double score, bool completed) {
    ScoreReport r;
    r.exerciseName = "Press three targets";
    r.score = score;
    r.guidance.completed = completed;
    return r;
}

}  // namespace

// Sessions a minute apart are each their own place on the chart; a stopped one is marked, listed
// as stopped and left out of the best and the mean.
TEST(HistoryPanelChart, SessionsAMinuteApartAreSpacedAndAStoppedOneIsNotAScore) {
    QTemporaryDir dir;
    ResultsDatabase db;
    ASSERT_TRUE(db.open(dir.filePath(QStringLiteral("h.sqlite"))));
    const qint64 ada = db.addTrainee(QStringLiteral("Ada"));
    const QDateTime t = QDateTime(QDate(2026, 12, 2), QTime(9, 36, 41), Qt::UTC);
    ASSERT_GE(db.addResult(ada, reportOf(100.0, true), QStringLiteral("Press"), QString(), t, 14.4, QString()), 0);
    ASSERT_GE(db.addResult(ada, reportOf(0.0, false), QStringLiteral("Press"), QString(), t.addSecs(60), 6.2, QString()), 0);
    ASSERT_GE(db.addResult(ada, reportOf(80.0, true), QStringLiteral("Press"), QString(), t.addSecs(124), 15.0, QString()), 0);
    ASSERT_GE(db.addResult(ada, reportOf(60.0, true), QStringLiteral("Press"), QString(), t.addSecs(169), 30.0, QString()), 0);
    // Another exercise's session: its score is not mixed into the other's best and mean.
    ASSERT_GE(db.addResult(ada, reportOf(20.0, true), QStringLiteral("Detect"), QString(), t.addSecs(30), 90.0,
                           QString()),
              0);

    HistoryPanel history;
    history.resize(340, 640);
    history.setDatabase(&db);
    history.show();
    QApplication::processEvents();
    ASSERT_EQ(history.results().size(), 5u);
    EXPECT_EQ(history.plottedPointCount(), 4);
    EXPECT_EQ(history.stoppedMarkCount(), 1);
    EXPECT_TRUE(history.summaryText().contains(QStringLiteral("Press: best 100.0, mean 80.0")))
        << history.summaryText().toStdString();
    EXPECT_TRUE(history.summaryText().contains(QStringLiteral("Detect: best 20.0, mean 20.0")))
        << history.summaryText().toStdString();
    EXPECT_TRUE(history.summaryText().contains(QStringLiteral("1 stopped"))) << history.summaryText().toStdString();
    // Newest first: the stopped session is the third row, shown as stopped, not as 0.
    EXPECT_EQ(history.table()->item(2, 2)->text(), QStringLiteral("stopped"));
    EXPECT_EQ(history.table()->item(0, 2)->text(), QStringLiteral("60.0"));

    // The scored points, on screen, are well apart (not a vertical line) and in session order.
    QLineSeries* line = nullptr;
    for (QAbstractSeries* s : history.chart()->series())
        if (s->name() == QStringLiteral("Press")) line = qobject_cast<QLineSeries*>(s);
    ASSERT_NE(line, nullptr);
    ASSERT_EQ(line->count(), 3);
    const QRectF plot = history.chart()->plotArea();
    double previousX = -1e9;
    for (const QPointF& p : line->points()) {
        const double x = history.chart()->mapToPosition(p, line).x();
        EXPECT_GT(x - previousX, plot.width() / 8.0) << "points closer than an eighth of the plot";
        EXPECT_GE(x, plot.left());
        EXPECT_LE(x, plot.right());
        previousX = x;
    }
    // The axis counts sessions; the summary gives their dates on a 24-hour clock.
    auto* axis = qobject_cast<QValueAxis*>(history.chart()->axes(Qt::Horizontal).value(0));
    ASSERT_NE(axis, nullptr);
    EXPECT_LT(axis->min(), 1.0);
    EXPECT_GT(axis->max(), 4.0);
    const QDateTime local = t.toLocalTime();
    EXPECT_TRUE(history.summaryText().contains(local.toString(QStringLiteral("yyyy-MM-dd, HH:mm"))))
        << history.summaryText().toStdString();
    EXPECT_TRUE(history.summaryText().contains(local.addSecs(169).toString(QStringLiteral("HH:mm"))))
        << history.summaryText().toStdString();
}

// Every metric name is readable in a narrow card: wrapped onto the rows' height, never cut off.
TEST(ScoreCardLayout, MetricNamesWrapInsteadOfBeingCutOff) {
    ScoreReport report = reportOf(72.0, true);
    for (Metric m : {Metric::Completion, Metric::TimeS, Metric::TargetErrorMm, Metric::HoldInWindowFraction,
                     Metric::ExcessiveForceEvents, Metric::ExcessiveForceFraction, Metric::MaxDisplacementMm,
                     Metric::PathLengthMm, Metric::Economy}) {
        MetricResult line;
        line.metric = m;
        line.value = 0.5;
        line.weight = 1.0;
        report.metrics.push_back(line);
    }
    ScoreCard card;
    card.resize(300, 600);
    card.setReport(report, QStringLiteral("Ada"));
    card.show();
    QApplication::processEvents();
    QTableWidget* table = card.breakdownTable();
    const QFontMetrics metrics = table->fontMetrics();
    // The cell's text margins, as the style lays the text out.
    const int marginPx = table->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, table) + 1;
    const int nameWidthPx = table->columnWidth(0) - 2 * marginPx;
    for (int row = 0; row < table->rowCount(); ++row) {
        const QString name = table->item(row, 0)->text();
        for (const QString& word : name.split(QLatin1Char(' ')))
            EXPECT_LE(metrics.horizontalAdvance(word), nameWidthPx) << name.toStdString();
        const QRect needed = metrics.boundingRect(QRect(0, 0, nameWidthPx, 10000), Qt::TextWordWrap, name);
        EXPECT_LE(needed.height(), table->rowHeight(row)) << name.toStdString();
        EXPECT_TRUE(table->item(row, 0)->toolTip().startsWith(name)) << name.toStdString();
    }
    // The name column gets the width it needs: the table is not wider than the card allows.
    EXPECT_LE(table->width(), std::max(card.width(), table->minimumWidth()));
}

// The card names each metric from its row, translated, and shows its value in the user's locale.
TEST(ScoreCardLayout, ValuesReadFromTheMetricRowsInTheLocale) {
    ScoreReport report = reportOf(72.0, true);
    auto line = [](Metric m, double value) {
        MetricResult r;
        r.metric = m;
        r.measured = true;
        r.value = value;
        r.weight = 1.0;
        return r;
    };
    report.metrics = {line(Metric::Completion, 0.85), line(Metric::PeakForceN, 3.2), line(Metric::FalseAlarms, 2.0)};
    report.metrics.push_back(line(Metric::LumpErrorMm, 0.0));
    report.metrics.back().measured = false;
    const QLocale before;
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    ScoreCard card;
    card.setReport(report, QStringLiteral("Ada"));
    QLocale::setDefault(before);
    QTableWidget* table = card.breakdownTable();
    ASSERT_EQ(table->rowCount(), 4);
    EXPECT_EQ(table->item(0, 0)->text(), QStringLiteral("Completion"));
    EXPECT_EQ(table->item(0, 1)->text(), QStringLiteral("85 %"));
    EXPECT_EQ(table->item(1, 0)->text(), QStringLiteral("Peak force"));
    EXPECT_EQ(table->item(1, 1)->text(), QStringLiteral("3,20 N"));
    EXPECT_EQ(table->item(2, 1)->text(), QStringLiteral("2 findings"));
    EXPECT_EQ(table->item(3, 1)->text(), QStringLiteral("-"));
    EXPECT_TRUE(table->item(1, 0)->toolTip().contains(QStringLiteral("largest force rendered")));
    EXPECT_FALSE(card.palpationText().contains(QStringLiteral("Work done"))) << "all the work was done";
}

// A session that did part of its work says why its error lines earn less than their sub-scores.
TEST(ScoreCardLayout, SaysHowMuchOfTheWorkWasDone) {
    ScoreReport report = reportOf(20.0, false);
    report.workDone = 0.34;
    ScoreCard card;
    card.setReport(report, QStringLiteral("Ada"));
    EXPECT_TRUE(card.palpationText().contains(QStringLiteral("Work done 34 %"))) << card.palpationText().toStdString();
}

// The score so far would tell a trainee which marks hit: a detection exercise keeps it for
// Finish unless its file says "show_live_score": true; the other kinds show it.
TEST(TraineePanelScore, DetectionKeepsTheScoreForFinishUnlessTheExerciseShowsIt) {
    TraineePanel panel;
    ScoreGuidance guidance;
    guidance.timeLeftS = 42.0;
    const auto loadedDetect = loadExercise(resource("exercises/detect_lumps.json").toStdString());
    ASSERT_TRUE(loadedDetect.exercise) << loadedDetect.error();
    Exercise detect = *loadedDetect.exercise;
    panel.showGuidance(detect, guidance, 63.0);
    EXPECT_TRUE(panel.timeText().contains(QStringLiteral("score at Finish"))) << panel.timeText().toStdString();
    EXPECT_FALSE(panel.timeText().contains(QStringLiteral("63")));
    detect.showLiveScore = true;
    panel.showGuidance(detect, guidance, 63.0);
    EXPECT_TRUE(panel.timeText().contains(QStringLiteral("score so far 63"))) << panel.timeText().toStdString();
    const auto press = loadExercise(resource("exercises/press_targets.json").toStdString());
    ASSERT_TRUE(press.exercise) << press.error();
    panel.showGuidance(*press.exercise, guidance, 63.0);
    EXPECT_TRUE(panel.timeText().contains(QStringLiteral("score so far 63"))) << panel.timeText().toStdString();
}

// A detection exercise marks on the gauge the force that counts as examined and, while a stroke
// is lighter, says to press deeper; a press at that force or more says nothing of it.
TEST(TraineePanelScore, TheGaugeMarksTheForceThatExaminesAndALightStrokeIsToldToPressDeeper) {
    TraineePanel panel;
    const auto loaded = loadExercise(resource("exercises/detect_lumps.json").toStdString());
    ASSERT_TRUE(loaded.exercise) << loaded.error();
    const Exercise& detect = *loaded.exercise;
    ScoreGuidance guidance;
    guidance.contact = true;
    guidance.forceN = 0.5 * detect.coverage.minForceN;
    panel.showGuidance(detect, guidance, 0.0);
    auto* gauge = panel.findChild<ForceGauge*>();
    ASSERT_NE(gauge, nullptr);
    EXPECT_DOUBLE_EQ(gauge->examineAtN(), detect.coverage.minForceN);
    EXPECT_EQ(gauge->zone(), -1) << "below the force that examines: amber";
    const QString light = panel.detailText();
    EXPECT_TRUE(light.contains(QStringLiteral("press deeper"))) << light.toStdString();
    guidance.forceN = 1.5 * detect.coverage.minForceN;
    panel.showGuidance(detect, guidance, 0.0);
    EXPECT_FALSE(panel.detailText().contains(QStringLiteral("press deeper"))) << panel.detailText().toStdString();
    EXPECT_EQ(gauge->zone(), 0);
    // Press targets have their window instead.
    const auto press = loadExercise(resource("exercises/press_targets.json").toStdString());
    ASSERT_TRUE(press.exercise);
    panel.showGuidance(*press.exercise, guidance, 0.0);
    EXPECT_EQ(gauge->examineAtN(), 0.0);
}

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QStandardPaths::setTestModeEnabled(true);  // QSettings and data folders of these tests are not the user's
    QApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
