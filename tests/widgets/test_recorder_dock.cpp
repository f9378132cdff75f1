// The Recorder dock under QT_QPA_PLATFORM=offscreen: a session recorded from the main window (stepped
// loop, scripted device) verifies and carries its mark and its scene, device and parameter changes;
// the recording plays back in the dock (markers, seeks that show the recorded tick, 4x faster than
// 1x, a matching verdict at the end); garbage and damaged files are reported by name; Back to live
// resumes the loop; a recording stops cleanly on a write problem and on window close.
#include "base/resources/ShippedResources.h"
#include "app/gui/MainWindow.h"
#include "engine/replay/RecordingPlayer.h"
#include "engine/record/RecordingReader.h"
#include "widgets/ParameterPanel.h"
#include "widgets/RecorderPanel.h"
#include "widgets/RecordingTimeline.h"

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <algorithm>
#include <cstring>

using namespace palpate;

// QStrings in gtest's messages as text.
void PrintTo(const QString& text, std::ostream* out) { *out << '"' << text.toStdString() << '"'; }

namespace {

constexpr int kWaitMs = 20000;
constexpr double kFrameS = 1.0 / 60.0;

QString meshPath() { return QString::fromStdString(findResource(kDefaultMesh)); }

/// A stepped window with the scripted stroke on the default mesh, recording into `folder`.
std::unique_ptr<MainWindow> liveWindow(const QString& folder) {
    auto window = std::make_unique<MainWindow>(RendererChoice::Software, LoopMode::Stepped);
    EXPECT_EQ(window->setDeviceUri(QStringLiteral("sim:stroke")), QString());
    EXPECT_EQ(window->loadMesh(meshPath()), QString());
    window->recorderPanel()->setRecordingFolder(folder);
    window->advanceTicks(300);
    return window;
}

bool waitIdle(RecorderPanel* panel) {
    return QTest::qWaitFor([panel] { return !panel->isBusy(); }, kWaitMs);
}

bool sameBits(const glm::vec3& a, const glm::vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// One recording shared by the playback tests: 9000 ticks of sim:stroke with a mark at 3 s. More
/// than the recorder's ring holds (8192): stepping must hand the ticks to the writer as it goes.
class RecorderDock : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        sDir = new QTemporaryDir;
        auto window = liveWindow(sDir->path());
        ASSERT_EQ(window->startRecording(), QString());
        sPath = window->recorderPanel()->recordingPath();
        window->advanceTicks(3000);
        ASSERT_TRUE(window->addRecordingMark(QStringLiteral("nodule")));
        window->advanceTicks(3000);
        window->advanceTicks(3000);
        ASSERT_EQ(window->stopRecording(), QString());
    }
    static void TearDownTestSuite() {
        delete sDir;
        sDir = nullptr;
    }

    /// A live window with the shared recording open in the dock.
    std::unique_ptr<MainWindow> playbackWindow() {
        auto window = liveWindow(sDir->path());
        window->openRecording(sPath);
        EXPECT_TRUE(waitIdle(window->recorderPanel()));
        EXPECT_TRUE(window->inPlayback()) << window->recorderPanel()->playbackErrorText().toStdString();
        return window;
    }

    static QTemporaryDir* sDir;
    static QString sPath;
};

QTemporaryDir* RecorderDock::sDir = nullptr;
QString RecorderDock::sPath;

}  // namespace

TEST_F(RecorderDock, RecordingFromTheWindowVerifiesAndHoldsTheMark) {
    ASSERT_TRUE(sPath.startsWith(sDir->path()));
    EXPECT_TRUE(QFileInfo(sPath).fileName().startsWith(QStringLiteral("palpate-")));
    EXPECT_TRUE(sPath.endsWith(QStringLiteral(".palprec")));
    const RecordingReader reader = RecordingReader::open(sPath.toStdString());
    ASSERT_TRUE(reader.fileError().empty()) << reader.fileError();
    EXPECT_TRUE(reader.summary().intact);
    EXPECT_TRUE(reader.summary().closedCleanly);
    EXPECT_GE(reader.summary().ticks, 9000u);
    EXPECT_EQ(reader.summary().droppedTicks, 0u);
    const auto& events = reader.events();
    const auto mark = std::find_if(events.begin(), events.end(), [](const RecordingEvent& e) { return e.kind == EventKind::Mark; });
    ASSERT_NE(mark, events.end());
    EXPECT_EQ(mark->text, "nodule");
    // Attached after 300 live ticks: the file starts there, and the mark lies half-way in.
    EXPECT_GT(mark->tick, reader.summary().firstTick + 2900);
    EXPECT_LT(mark->tick, reader.summary().firstTick + 3100);
    std::string error;
    EXPECT_TRUE(replayRecording(reader, error).ok()) << error;
}

TEST_F(RecorderDock, StatusLineActionsAndStatusBarFollowTheRecording) {
    auto window = liveWindow(sDir->path());
    RecorderPanel* panel = window->recorderPanel();
    ASSERT_EQ(window->startRecording(), QString());
    EXPECT_TRUE(panel->isRecording());
    window->advanceTicks(1000);
    const QString status = panel->recordingStatusText();
    EXPECT_TRUE(status.contains(QStringLiteral("REC"))) << status.toStdString();
    EXPECT_TRUE(status.contains(QStringLiteral("ticks"))) << status.toStdString();
    EXPECT_TRUE(status.contains(QStringLiteral("B/tick"))) << status.toStdString();
    EXPECT_TRUE(status.contains(QStringLiteral("drops 0"))) << status.toStdString();
    auto* field = window->findChild<QLabel*>(QStringLiteral("recordingStatusField"));
    ASSERT_NE(field, nullptr);
    EXPECT_TRUE(field->text().contains(QStringLiteral("REC")));
    // The dock's Mark button with its text.
    window->findChild<QLineEdit*>(QStringLiteral("markEdit"))->setText(QStringLiteral("from the button"));
    QTest::mouseClick(window->findChild<QPushButton*>(QStringLiteral("markButton")), Qt::LeftButton);
    window->advanceTicks(100);
    const QString path = panel->recordingPath();
    // The window's close path stops the recording: the file closes cleanly.
    window->close();
    EXPECT_FALSE(window->isRecording());
    const RecordingReader reader = RecordingReader::open(path.toStdString());
    EXPECT_TRUE(reader.summary().closedCleanly);
    EXPECT_TRUE(reader.summary().intact);
    const auto& events = reader.events();
    EXPECT_TRUE(std::any_of(events.begin(), events.end(), [](const RecordingEvent& e) {
        return e.kind == EventKind::Mark && e.text == "from the button";
    }));
}

TEST_F(RecorderDock, RecordingSurvivesDeviceParameterAndSceneChanges) {
    auto window = liveWindow(sDir->path());
    ASSERT_EQ(window->startRecording(), QString());
    window->advanceTicks(500);
    ASSERT_EQ(window->setDeviceUri(QStringLiteral("sim:press")), QString());
    window->advanceTicks(1500);
    TissuePreset preset = window->session().preset();
    preset.model.slopeRing.springStiffnessNPerMm *= 1.5;  // the running scene takes it at a tick boundary
    ASSERT_EQ(window->applyPreset(preset), QString());
    window->advanceTicks(500);
    preset.model.slopeRingMethod = SlopeRingMethod::Proposed;  // a new scene of the same mesh
    ASSERT_EQ(window->applyPreset(preset), QString());
    window->advanceTicks(1000);
    EXPECT_TRUE(window->isRecording());
    ASSERT_EQ(window->stopRecording(), QString());

    const RecordingReader reader = RecordingReader::open(window->recorderPanel()->recordingPath().toStdString());
    EXPECT_TRUE(reader.summary().intact);
    bool device = false, params = false, scene = false;
    for (const RecordingEvent& e : reader.events()) {
        device |= e.kind == EventKind::DeviceChanged && e.device && e.device->uri == "sim:press";
        params |= e.kind == EventKind::ParamsApplied;
        scene |= e.kind == EventKind::SceneChanged && e.scene.has_value();
    }
    EXPECT_TRUE(device);
    EXPECT_TRUE(params);
    EXPECT_TRUE(scene);  // described: a replay rebuilds it
    std::string error;
    const ReplayStatus status = replayRecording(reader, error);
    EXPECT_TRUE(status.ok()) << error << status.stopReason << status.firstMismatch;
}

TEST_F(RecorderDock, ThreadedSessionRecordsAndReplaysBitForBit) {
    // The interactive window: the haptic thread runs; scene and device swaps land while it ticks.
    MainWindow window(RendererChoice::Software, LoopMode::Threaded);
    ASSERT_EQ(window.setDeviceUri(QStringLiteral("sim:stroke")), QString());
    ASSERT_EQ(window.loadMesh(meshPath()), QString());
    window.recorderPanel()->setRecordingFolder(sDir->path());
    QTest::qWait(100);
    ASSERT_EQ(window.startRecording(), QString());
    QTest::qWait(250);
    EXPECT_TRUE(window.addRecordingMark(QStringLiteral("threaded")));
    ASSERT_EQ(window.setDeviceUri(QStringLiteral("sim:sine")), QString());
    QTest::qWait(150);
    TissuePreset preset = window.session().preset();
    preset.model.slopeRingMethod = SlopeRingMethod::Proposed;
    ASSERT_EQ(window.applyPreset(preset), QString());
    QTest::qWait(150);
    const QString path = window.recorderPanel()->recordingPath();
    window.close();  // stops the recording, then the thread
    const RecordingReader reader = RecordingReader::open(path.toStdString());
    EXPECT_TRUE(reader.summary().intact);
    EXPECT_GT(reader.summary().ticks, 200u);
    std::string error;
    const ReplayStatus status = replayRecording(reader, error);
    EXPECT_TRUE(status.ok()) << error << status.stopReason << status.firstMismatch;
}

TEST_F(RecorderDock, ANewHapticRateEndsTheRecordingAndSaysWhy) {
    auto window = liveWindow(sDir->path());
    ASSERT_EQ(window->startRecording(), QString());
    window->advanceTicks(200);
    TissuePreset preset = window->session().preset();
    preset.hapticRateHz = 500.0;  // a new loop: the recording cannot follow
    ASSERT_EQ(window->applyPreset(preset), QString());
    window->advanceTicks(10);
    EXPECT_FALSE(window->isRecording());
    EXPECT_FALSE(window->recorderPanel()->isRecording());
    EXPECT_TRUE(window->recorderPanel()->recordingErrorText().contains(QStringLiteral("haptic rate")))
        << window->recorderPanel()->recordingErrorText().toStdString();
    const RecordingReader reader = RecordingReader::open(window->recorderPanel()->recordingPath().toStdString());
    EXPECT_TRUE(reader.summary().intact);  // closed cleanly all the same
}

TEST_F(RecorderDock, AFolderThatCannotBeCreatedIsReportedAndTheSessionRunsOn) {
    QTemporaryDir dir;
    QFile blocker(dir.filePath(QStringLiteral("file")));
    ASSERT_TRUE(blocker.open(QIODevice::WriteOnly));
    blocker.close();
    auto window = liveWindow(dir.filePath(QStringLiteral("file/recordings")));  // under a file: no folder
    const QString error = window->startRecording();
    EXPECT_FALSE(error.isEmpty());
    EXPECT_FALSE(window->isRecording());
    EXPECT_TRUE(window->recorderPanel()->recordingErrorText().contains(QStringLiteral("file/recordings")))
        << window->recorderPanel()->recordingErrorText().toStdString();
    EXPECT_TRUE(window->statusBar()->currentMessage().contains(QStringLiteral("file/recordings")));
    const auto tick = window->session().observed().tick;
    window->advanceTicks(10);
    EXPECT_EQ(window->session().observed().tick, tick + 10);
}

TEST_F(RecorderDock, OpenedRecordingShowsItsMarkerAndPausesTheLiveSession) {
    auto window = playbackWindow();
    RecorderPanel* panel = window->recorderPanel();
    EXPECT_TRUE(window->session().pauseRequested());
    EXPECT_TRUE(panel->playbackWarningText().isEmpty()) << panel->playbackWarningText().toStdString();
    const auto& markers = panel->timeline()->markers();
    const auto mark = std::find_if(markers.begin(), markers.end(), [](const RecordingTimeline::Marker& m) {
        return m.kind == RecordingTimeline::MarkerKind::Mark;
    });
    ASSERT_NE(mark, markers.end());
    EXPECT_TRUE(mark->text.contains(QStringLiteral("nodule")));
    // Its tooltip names it and its time.
    window->show();
    const QString tip = panel->timeline()->toolTipAt(QPoint(panel->timeline()->xOfTick(mark->tick), 5));
    EXPECT_TRUE(tip.contains(QStringLiteral("nodule"))) << tip.toStdString();
    EXPECT_TRUE(tip.contains(QStringLiteral("0:02.9")) || tip.contains(QStringLiteral("0:03.0"))) << tip.toStdString();
    // The keys move the handle; Ctrl+Right goes to the next event.
    RecordingTimeline* timeline = panel->timeline();
    QSignalSpy scrubbed(timeline, &RecordingTimeline::scrubbed);
    QTest::keyClick(timeline, Qt::Key_End);
    EXPECT_EQ(timeline->value(), timeline->lastTick());
    QTest::keyClick(timeline, Qt::Key_Home);
    EXPECT_EQ(timeline->value(), timeline->firstTick());
    QTest::keyClick(timeline, Qt::Key_PageUp);
    EXPECT_EQ(timeline->value(), timeline->firstTick() + timeline->pageStep());
    QTest::keyClick(timeline, Qt::Key_Right);
    EXPECT_EQ(timeline->value(), timeline->firstTick() + timeline->pageStep() + timeline->singleStep());
    EXPECT_EQ(scrubbed.count(), 4);
    EXPECT_TRUE(waitIdle(panel));
    // Space on the timeline plays and pauses the recording; the live session stays paused.
    QTest::keyClick(timeline, Qt::Key_Space);
    EXPECT_TRUE(panel->isPlaying());
    QTest::keyClick(timeline, Qt::Key_Space);
    EXPECT_FALSE(panel->isPlaying());
    EXPECT_TRUE(window->session().pauseRequested());
}

TEST_F(RecorderDock, SeekingShowsTheRecordedToolAndForce) {
    auto window = playbackWindow();
    RecorderPanel* panel = window->recorderPanel();
    const RecordingReader& reader = *panel->reader();
    const std::uint64_t first = reader.summary().firstTick;
    for (const std::uint64_t offset : {4000ull, 1500ull, 1501ull, 5200ull, 20ull}) {  // forwards and back
        const std::uint64_t tick = first + offset;
        ASSERT_TRUE(panel->seekTo(tick));
        ASSERT_TRUE(waitIdle(panel));
        ASSERT_EQ(panel->currentTick(), tick);
        const auto recorded = reader.tickAt(tick);
        ASSERT_TRUE(recorded.has_value());
        RecordingPlayer* player = panel->player();
        ASSERT_NE(player, nullptr);
        EXPECT_TRUE(sameBits(player->snapshot().forceN, recorded->forceN)) << "tick " << tick;
        EXPECT_EQ(player->snapshot().touched, recorded->touched);
        EXPECT_TRUE(sameBits(player->snapshot().toolTipMm, recorded->sample.positionMm)) << "tick " << tick;
        // What the viewport was given.
        EXPECT_TRUE(sameBits(panel->frame().forceN, recorded->forceN));
        EXPECT_EQ(window->viewport()->scene().touched(), recorded->contact ? recorded->touched : kNoVertex);
        const auto drawn = window->viewport()->scene().positionsMm();
        const auto replayed = player->positionsMm();
        ASSERT_EQ(drawn.size(), replayed.size());
        EXPECT_TRUE(std::equal(drawn.begin(), drawn.end(), replayed.begin()));
        EXPECT_EQ(panel->timeline()->value(), tick);
    }
    // Through the worker thread (as a long seek goes): retargeted while it runs, as scrubbing does.
    panel->setSyncSeekBudgetUs(0.0);
    ASSERT_TRUE(panel->seekTo(first + 5000));
    EXPECT_TRUE(panel->isBusy());
    EXPECT_EQ(panel->player(), nullptr);  // the worker's until it is done
    panel->seekTo(first + 3000);
    panel->seekTo(first + 3500);
    ASSERT_TRUE(waitIdle(panel));
    ASSERT_EQ(panel->currentTick(), first + 3500);
    const auto recorded = reader.tickAt(first + 3500);
    ASSERT_TRUE(recorded.has_value());
    EXPECT_TRUE(sameBits(panel->player()->snapshot().forceN, recorded->forceN));
    EXPECT_TRUE(sameBits(panel->frame().toolTipMm, recorded->sample.positionMm));
    ASSERT_TRUE(panel->seekTo(first + 100));  // backwards: replays from the start on the worker
    EXPECT_TRUE(panel->isBusy());
    ASSERT_TRUE(waitIdle(panel));
    EXPECT_EQ(panel->currentTick(), first + 100);
    EXPECT_TRUE(sameBits(panel->frame().forceN, reader.tickAt(first + 100)->forceN));
    panel->setSyncSeekBudgetUs(RecorderPanel::kSyncSeekBudgetUs);

    // Somewhere in the stroke the tool presses the tissue: the frame shows a contact.
    bool contact = false;
    for (std::uint64_t t = first + 200; t < first + 6000 && !contact; t += 200) {
        panel->seekTo(t);
        ASSERT_TRUE(waitIdle(panel));
        contact = panel->frame().contact;
    }
    EXPECT_TRUE(contact);
}

TEST_F(RecorderDock, FourTimesSpeedStepsFourTimesTheTicksPerFrame) {
    auto window = playbackWindow();
    RecorderPanel* panel = window->recorderPanel();
    const std::uint64_t first = panel->reader()->summary().firstTick;
    auto ticksOver30Frames = [&](double speed) {
        panel->seekTo(first);
        EXPECT_TRUE(waitIdle(panel));
        panel->setSpeed(speed);
        panel->setPlaying(true);
        const std::uint64_t before = panel->currentTick();
        for (int i = 0; i < 30; ++i) panel->advanceFrame(kFrameS);
        panel->setPlaying(false);
        return panel->currentTick() - before;
    };
    const std::uint64_t slow = ticksOver30Frames(1.0), fast = ticksOver30Frames(4.0);
    EXPECT_NEAR(double(slow), 500.0, 2.0);  // 30 frames of 1/60 s at 1 kHz
    EXPECT_NEAR(double(fast), 2000.0, 2.0);
    EXPECT_NEAR(double(panel->reader()->header().rateHz), 1000.0, 1e-9);
    panel->setSpeed(0.25);
    EXPECT_EQ(panel->speed(), 0.25);

    // The frame timer drives it too (wall time: only "it moves, and stops when paused").
    panel->setSpeed(1.0);
    const std::uint64_t frames = panel->framesPlayed(), tick = panel->currentTick();
    panel->setPlaying(true);
    QTest::qWait(300);
    panel->setPlaying(false);
    EXPECT_GT(panel->framesPlayed(), frames);
    EXPECT_GT(panel->currentTick(), tick);
    const std::uint64_t stopped = panel->currentTick();
    QTest::qWait(100);
    EXPECT_EQ(panel->currentTick(), stopped);
}

TEST_F(RecorderDock, PlaybackToTheEndReportsAMatchingReplay) {
    auto window = playbackWindow();
    RecorderPanel* panel = window->recorderPanel();
    EXPECT_TRUE(panel->verdictText().isEmpty());
    panel->setSpeed(4.0);
    panel->setPlaying(true);
    for (int frame = 0; frame < 2000 && panel->isPlaying(); ++frame) panel->advanceFrame(kFrameS);
    EXPECT_FALSE(panel->isPlaying());  // stopped at the end
    ASSERT_NE(panel->player(), nullptr);
    EXPECT_TRUE(panel->player()->atEnd());
    EXPECT_TRUE(panel->player()->status().ok());
    EXPECT_TRUE(panel->verdictText().contains(QStringLiteral("bit for bit"))) << panel->verdictText().toStdString();
    // Going back clears the verdict; End reaches it again (on the worker thread here).
    panel->setSyncSeekBudgetUs(0.0);
    panel->seekTo(panel->reader()->summary().firstTick + 10);
    ASSERT_TRUE(waitIdle(panel));
    EXPECT_TRUE(panel->verdictText().isEmpty());
    panel->timeline()->setFocus();
    QTest::keyClick(panel->timeline(), Qt::Key_End);
    ASSERT_TRUE(waitIdle(panel));
    EXPECT_TRUE(panel->verdictText().contains(QStringLiteral("bit for bit"))) << panel->verdictText().toStdString();
}

TEST_F(RecorderDock, GarbageIsAnErrorNamingTheFileAndTheLiveSessionRunsOn) {
    auto window = liveWindow(sDir->path());
    QTemporaryDir dir;
    const QString garbage = dir.filePath(QStringLiteral("garbage.palprec"));
    QFile file(garbage);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(QByteArray(5000, 'x'));
    file.close();
    QSignalSpy failed(window->recorderPanel(), &RecorderPanel::openFailed);
    window->openRecording(garbage);
    ASSERT_TRUE(waitIdle(window->recorderPanel()));
    ASSERT_EQ(failed.count(), 1);
    EXPECT_TRUE(failed.front().front().toString().contains(garbage));
    EXPECT_TRUE(window->recorderPanel()->playbackErrorText().contains(garbage))
        << window->recorderPanel()->playbackErrorText().toStdString();
    EXPECT_FALSE(window->inPlayback());
    EXPECT_FALSE(window->session().pauseRequested());
    const auto tick = window->session().observed().tick;
    window->advanceTicks(10);
    EXPECT_EQ(window->session().observed().tick, tick + 10);
    EXPECT_FALSE(window->session().observed().paused);

    // A file that is not there is named too.
    window->openRecording(dir.filePath(QStringLiteral("missing.palprec")));
    ASSERT_TRUE(waitIdle(window->recorderPanel()));
    EXPECT_TRUE(window->recorderPanel()->playbackErrorText().contains(QStringLiteral("missing.palprec")));
}

TEST_F(RecorderDock, DamagedFileOpensWithAWarningAndItsLostStretch) {
    QFile in(sPath);
    ASSERT_TRUE(in.open(QIODevice::ReadOnly));
    QByteArray bytes = in.readAll();
    in.close();
    // Flip bytes in the middle of the file: one chunk's CRC fails, the rest is recovered.
    for (int i = 0; i < 8; ++i) bytes[bytes.size() / 2 + i] = char(bytes[bytes.size() / 2 + i] ^ 0x5a);
    QTemporaryDir dir;
    const QString damaged = dir.filePath(QStringLiteral("damaged.palprec"));
    QFile out(damaged);
    ASSERT_TRUE(out.open(QIODevice::WriteOnly));
    out.write(bytes);
    out.close();

    auto window = liveWindow(sDir->path());
    window->openRecording(damaged);
    RecorderPanel* panel = window->recorderPanel();
    ASSERT_TRUE(waitIdle(panel));
    ASSERT_TRUE(window->inPlayback()) << panel->playbackErrorText().toStdString();
    EXPECT_TRUE(panel->playbackWarningText().contains(QStringLiteral("damaged"))) << panel->playbackWarningText().toStdString();
    EXPECT_TRUE(panel->playbackWarningText().contains(QStringLiteral("Recovered")));
    EXPECT_FALSE(panel->timeline()->regions().empty());
    // Played to where it can go: the verdict says it stopped early.
    panel->seekTo(panel->timeline()->lastTick());
    ASSERT_TRUE(waitIdle(panel));
    EXPECT_TRUE(panel->verdictText().contains(QStringLiteral("stopped early"))) << panel->verdictText().toStdString();
}

TEST_F(RecorderDock, BackToLiveResumesTheLiveLoop) {
    auto window = playbackWindow();
    EXPECT_TRUE(window->session().pauseRequested());
    window->advanceTicks(50);
    EXPECT_TRUE(window->session().observed().paused);
    // Recording is refused during playback.
    EXPECT_FALSE(window->startRecording().isEmpty());
    QTest::mouseClick(window->findChild<QPushButton*>(QStringLiteral("backToLiveButton")), Qt::LeftButton);
    EXPECT_FALSE(window->inPlayback());
    EXPECT_FALSE(window->recorderPanel()->inPlayback());
    EXPECT_FALSE(window->session().pauseRequested());
    const auto tick = window->session().observed().tick;
    window->advanceTicks(20);
    EXPECT_EQ(window->session().observed().tick, tick + 20);
    EXPECT_FALSE(window->session().observed().paused);
    EXPECT_EQ(window->viewport()->scene().vertexCount(), window->session().drawnMesh()->vertexCount());
    EXPECT_EQ(window->startRecording(), QString());  // and recording works again
    EXPECT_EQ(window->stopRecording(), QString());
}

TEST_F(RecorderDock, StatusBarShowsTheRecordingsMeshInPlaybackAndTheLiveOneAfter) {
    auto window = liveWindow(sDir->path());
    // The live session on another mesh than the recording's (stomach_3970).
    const QString sphere = QString::fromStdString(findResource("meshes/sphere_1442.off"));
    ASSERT_EQ(window->loadMesh(sphere), QString());
    window->advanceTicks(10);
    auto* meshStatus = window->findChild<QLabel*>(QStringLiteral("meshStatus"));
    ASSERT_NE(meshStatus, nullptr);
    EXPECT_TRUE(meshStatus->text().startsWith(QStringLiteral("sphere_1442.off · ")) &&
                meshStatus->text().contains(QStringLiteral(" · 1442 vertices"))) << meshStatus->text().toStdString();

    window->openRecording(sPath);
    ASSERT_TRUE(waitIdle(window->recorderPanel()));
    ASSERT_TRUE(window->inPlayback());
    EXPECT_TRUE(meshStatus->text().startsWith(QStringLiteral("stomach_3970.off · ")) &&
                meshStatus->text().contains(QStringLiteral(" · 3970 vertices"))) << meshStatus->text().toStdString();
    EXPECT_TRUE(meshStatus->toolTip().contains(QStringLiteral("stomach_3970.off"))) << meshStatus->toolTip().toStdString();
    window->advanceTicks(1);  // the status bar's own refresh keeps it
    EXPECT_TRUE(meshStatus->text().startsWith(QStringLiteral("stomach_3970.off · ")) &&
                meshStatus->text().contains(QStringLiteral(" · 3970 vertices"))) << meshStatus->text().toStdString();

    window->backToLive();
    EXPECT_TRUE(meshStatus->text().startsWith(QStringLiteral("sphere_1442.off · ")) &&
                meshStatus->text().contains(QStringLiteral(" · 1442 vertices"))) << meshStatus->text().toStdString();
    EXPECT_TRUE(meshStatus->toolTip().contains(QStringLiteral("sphere_1442.off"))) << meshStatus->toolTip().toStdString();
}

TEST_F(RecorderDock, StatusBarFollowsAMeshSwitchInTheRecording) {
    QTemporaryDir dir;
    auto window = liveWindow(dir.path());
    ASSERT_EQ(window->startRecording(), QString());
    window->advanceTicks(500);
    ASSERT_EQ(window->loadMesh(QString::fromStdString(findResource("meshes/sphere_1442.off"))), QString());
    window->advanceTicks(500);
    ASSERT_EQ(window->stopRecording(), QString());
    const QString path = window->recorderPanel()->recordingPath();

    window->openRecording(path);
    RecorderPanel* panel = window->recorderPanel();
    ASSERT_TRUE(waitIdle(panel));
    ASSERT_TRUE(window->inPlayback()) << panel->playbackErrorText().toStdString();
    auto* meshStatus = window->findChild<QLabel*>(QStringLiteral("meshStatus"));
    ASSERT_NE(meshStatus, nullptr);
    EXPECT_TRUE(meshStatus->text().startsWith(QStringLiteral("stomach_3970.off · ")) &&
                meshStatus->text().contains(QStringLiteral(" · 3970 vertices"))) << meshStatus->text().toStdString();
    ASSERT_TRUE(panel->seekTo(panel->timeline()->lastTick()));
    ASSERT_TRUE(waitIdle(panel));
    window->advanceTicks(1);
    EXPECT_TRUE(meshStatus->text().startsWith(QStringLiteral("sphere_1442.off · ")) &&
                meshStatus->text().contains(QStringLiteral(" · 1442 vertices"))) << meshStatus->text().toStdString();
    ASSERT_TRUE(panel->seekTo(panel->timeline()->firstTick()));  // back: the first scene again
    ASSERT_TRUE(waitIdle(panel));
    window->advanceTicks(1);
    EXPECT_TRUE(meshStatus->text().startsWith(QStringLiteral("stomach_3970.off · ")) &&
                meshStatus->text().contains(QStringLiteral(" · 3970 vertices"))) << meshStatus->text().toStdString();
}

namespace {

/// Triggers `action`, which opens a modal file dialog; answers it with `choose` (rejects it when
/// empty) and returns the folder the dialog started in ("" when no dialog came).
QString answerFileDialog(QAction* action, const QString& choose) {
    QString startedIn;
    QTimer poll;
    poll.setInterval(10);
    QObject::connect(&poll, &QTimer::timeout, [&] {
        auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
        if (!dialog) return;
        poll.stop();
        startedIn = dialog->directory().absolutePath();
        auto* name = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
        if (choose.isEmpty() || !name) {
            dialog->reject();
        } else {
            // Typed, as a user would: selectFile() leaves a focused name field alone.
            name->setText(choose);
            static_cast<QDialog*>(dialog)->accept();  // QFileDialog::accept, as its Open button
        }
    });
    poll.start();
    QTimer giveUp;  // no dialog, or one that is not a QFileDialog: do not hang
    giveUp.setSingleShot(true);
    giveUp.start(kWaitMs);
    QObject::connect(&giveUp, &QTimer::timeout, [] {
        if (QWidget* modal = QApplication::activeModalWidget()) {
            ADD_FAILURE() << "left open: " << modal->metaObject()->className() << " " << modal->windowTitle().toStdString();
            modal->close();
        }
    });
    action->trigger();
    return startedIn;
}

}  // namespace

TEST_F(RecorderDock, OpenMeshAndOpenRecordingDialogsStartInTheirOwnFolders) {
    QSettings().remove(QStringLiteral("meshes/lastFolder"));
    QSettings().remove(QStringLiteral("recorder/openFolder"));
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString meshes = dir.filePath(QStringLiteral("my-meshes"));
    const QString elsewhere = dir.filePath(QStringLiteral("old-recordings"));
    ASSERT_TRUE(QDir().mkpath(meshes) && QDir().mkpath(elsewhere));
    const QString sphere = QDir(meshes).filePath(QStringLiteral("sphere.off"));
    ASSERT_TRUE(QFile::copy(QString::fromStdString(findResource("meshes/sphere_1442.off")), sphere));
    const QString recording = QDir(elsewhere).filePath(QStringLiteral("old.palprec"));
    ASSERT_TRUE(QFile::copy(sPath, recording));

    auto window = liveWindow(dir.filePath(QStringLiteral("recordings")));
    window->show();
    auto* openMesh = window->findChild<QAction*>(QStringLiteral("openMeshAction"));
    auto* openRecording = window->findChild<QAction*>(QStringLiteral("openRecordingAction"));
    ASSERT_NE(openMesh, nullptr);
    ASSERT_NE(openRecording, nullptr);
    const QString bundled = QFileInfo(meshPath()).absolutePath();
    const QString recordings = QFileInfo(window->recorderPanel()->recordingFolder()).absoluteFilePath();
    QDir().mkpath(recordings);  // a dialog starts only in a folder that exists

    // First time: the bundled meshes, and the recordings folder.
    EXPECT_EQ(answerFileDialog(openRecording, {}), recordings);
    EXPECT_EQ(answerFileDialog(openMesh, sphere), bundled);
    window->advanceTicks(1);  // the loop takes the new scene
    EXPECT_EQ(QString::fromStdString(window->session().drawnPath()), sphere);
    // Each dialog starts where it was last used, whatever the other did in between.
    EXPECT_EQ(answerFileDialog(openRecording, recording), recordings);
    ASSERT_TRUE(waitIdle(window->recorderPanel()));
    EXPECT_TRUE(window->inPlayback()) << window->recorderPanel()->playbackErrorText().toStdString();
    window->backToLive();
    EXPECT_EQ(answerFileDialog(openMesh, {}), meshes);
    EXPECT_EQ(answerFileDialog(openRecording, {}), elsewhere);
    EXPECT_EQ(answerFileDialog(openMesh, {}), meshes);
    // Kept for the next start.
    auto next = liveWindow(dir.filePath(QStringLiteral("recordings")));
    EXPECT_EQ(next->meshDialogFolder(), meshes);
    EXPECT_EQ(next->recorderPanel()->openDialogFolder(), elsewhere);
    QSettings().remove(QStringLiteral("meshes/lastFolder"));
    QSettings().remove(QStringLiteral("recorder/openFolder"));
}

TEST_F(RecorderDock, BackToLiveWhileAFileOpensDropsIt) {
    auto window = playbackWindow();
    window->openRecording(sPath);  // a second open, replacing the first
    window->backToLive();
    EXPECT_FALSE(window->inPlayback());
    ASSERT_TRUE(waitIdle(window->recorderPanel()));
    QTest::qWait(20);
    EXPECT_FALSE(window->inPlayback());
    EXPECT_FALSE(window->recorderPanel()->inPlayback());
    EXPECT_FALSE(window->session().pauseRequested());
}

// Not a check: writes a demo recording (marks, a device switch, a parameter set, a model change) to
// $PALPATE_DEMO_RECORDING for screenshots of the dock (palpate --open-recording FILE --grab-after-ms).
TEST_F(RecorderDock, DISABLED_WriteDemoRecording) {
    const QString target = qEnvironmentVariable("PALPATE_DEMO_RECORDING");
    ASSERT_FALSE(target.isEmpty()) << "set PALPATE_DEMO_RECORDING";
    auto window = liveWindow(sDir->path());
    ASSERT_EQ(window->startRecording(), QString());
    window->advanceTicks(2200);
    window->addRecordingMark(QStringLiteral("first press"));
    window->advanceTicks(1800);
    TissuePreset preset = window->session().preset();
    preset.model.slopeRing.springStiffnessNPerMm *= 1.5;
    ASSERT_EQ(window->applyPreset(preset), QString());
    window->advanceTicks(2000);
    ASSERT_EQ(window->setDeviceUri(QStringLiteral("sim:press")), QString());
    window->advanceTicks(2500);
    window->addRecordingMark(QStringLiteral("deep hold"));
    window->advanceTicks(1500);
    window->resize(1280, 876);
    window->show();
    window->recorderPanel()->showRecordingStats(window->session().recordingSession()->stats());
    QTest::qWait(100);
    window->grab().save(target + QStringLiteral(".recording.png"));
    ASSERT_EQ(window->stopRecording(), QString());
    QFile::remove(target);
    ASSERT_TRUE(QFile::copy(window->recorderPanel()->recordingPath(), target));
    // Played back to the end: the verdict.
    window->openRecording(target);
    ASSERT_TRUE(waitIdle(window->recorderPanel()));
    window->recorderPanel()->seekTo(window->recorderPanel()->timeline()->lastTick());
    ASSERT_TRUE(waitIdle(window->recorderPanel()));
    QTest::qWait(100);
    window->grab().save(target + QStringLiteral(".verdict.png"));
}

int main(int argc, char** argv) {
    // Before QApplication: the platform is chosen in its constructor. No GPU, no display needed.
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QStandardPaths::setTestModeEnabled(true);  // QSettings of these tests never touch the user's
    QApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
