#include "app/gui/RecordingController.h"

#include "app/gui/ExerciseController.h"
#include "widgets/RecorderPanel.h"
#include "widgets/RecordingTimeline.h"
#include "widgets/Viewport.h"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QKeySequence>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QStatusBar>
#include <QThread>

namespace palpate {

RecordingController::RecordingController(QMainWindow& window, HapticSession& session, Viewport& viewport,
                                         std::function<void()> presentFrame, QObject* parent)
    : QObject(parent), mWindow(window), mSession(session), mViewport(viewport), mPresentFrame(std::move(presentFrame)) {
    mPanel = new RecorderPanel(&window);
    mDock = new QDockWidget(tr("Recorder"), &window);
    mDock->setObjectName(QStringLiteral("recorderDock"));
    mDock->setWidget(mPanel);
    // Under the viewport, room for the timeline; the right column keeps its whole height.
    window.setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    window.addDockWidget(Qt::BottomDockWidgetArea, mDock);
    connect(mPanel, &RecorderPanel::recordRequested, this, [this] { startRecording(); });
    connect(mPanel, &RecorderPanel::stopRequested, this, [this] { stopRecording(); });
    connect(mPanel, &RecorderPanel::markRequested, this, [this](const QString& text) { addMark(text); });
    connect(mPanel, &RecorderPanel::playbackStarted, this, &RecordingController::enterPlayback);
    connect(mPanel, &RecorderPanel::playbackMeshChanged, this, [this](const TissueMesh& mesh) {
        if (!mPlayback) return;
        mViewport.setMesh(mesh);
        emit statusChanged();  // the recording's mesh in the status bar
    });
    connect(mPanel, &RecorderPanel::playbackFrame, this, [this](const SceneSnapshot& frame) {
        if (mPlayback) mViewport.setSnapshot(frame);
    });
    connect(mPanel, &RecorderPanel::backToLiveRequested, this, &RecordingController::backToLive);
    connect(mPanel, &RecorderPanel::openFailed, this, [this](const QString& error) {
        mDock->show();
        mDock->raise();
        showMessage(error, 15000);
    });
}

void RecordingController::addMenuActions(QMenu* simulation) {
    mRecordAction = simulation->addAction(tr("Re&cord"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R), this,
                                          [this](bool on) {
                                              if (on) startRecording();
                                              else stopRecording();
                                          });
    mRecordAction->setCheckable(true);
    mRecordAction->setStatusTip(
        tr("Record the live session to a new file (again: stop). Starting resets the tissue "
           "to rest and the force ramps in again"));
    mMarkAction = simulation->addAction(tr("Add &Mark"), QKeySequence(Qt::Key_M), this, [this] { addMark(); });
    mMarkAction->setStatusTip(tr("Mark the current moment of the recording (the Recorder dock's text, if any)"));
    mMarkAction->setEnabled(false);
}

void RecordingController::showMessage(const QString& text, int timeoutMs) {
    mWindow.statusBar()->showMessage(text, timeoutMs);
}

QString RecordingController::startRecording() {
    QString error;
    if (mSession.recording()) return {};
    if (mPlayback) {
        error = tr("Go back to the live session before recording");
    } else if (!mSession.hasLoop()) {
        error = tr("Load a mesh before recording: there is no session to record");
    } else {
        const QString path = mPanel->newRecordingPath(&error);
        if (!path.isEmpty()) {
            // A scene just handed to the running loop shows up within a tick or two: wait for it
            // (bounded), so that the header describes the scene the recorder starts on.
            QElapsedTimer waited;
            waited.start();
            while (mSession.threadRunning() && mSession.sceneSwitchPending() && waited.elapsed() < 250) {
                mPresentFrame();
                QThread::msleep(2);
            }
            error = QString::fromStdString(mSession.startRecording(path.toStdString()));
            if (error.isEmpty()) {
                mPanel->setRecordingStarted(path);
                showMessage(tr("Recording to %1").arg(QDir::toNativeSeparators(path)), 5000);
            }
        }
    }
    if (!error.isEmpty()) showError(tr("Cannot record: %1").arg(error));
    update();
    return error;
}

QString RecordingController::stopRecording() {
    if (!mSession.recording()) {
        if (mRecordAction) mRecordAction->setChecked(false);
        return {};
    }
    const QString path = QString::fromStdString(mSession.recordingSession()->path());
    const QString error = QString::fromStdString(mSession.stopRecording());
    mPanel->setRecordingStopped(error.isEmpty() ? QString() : tr("The recording failed: %1").arg(error));
    mPanel->showRecordingStats(mSession.lastRecordingStats());
    if (error.isEmpty()) showMessage(tr("Recording saved: %1").arg(QDir::toNativeSeparators(path)), 8000);
    else showMessage(tr("The recording failed: %1").arg(error), 15000);
    update();
    return error;
}

bool RecordingController::addMark(const QString& text) {
    RecordingSession* recording = mSession.recordingSession();
    if (!recording) return false;
    // During an exercise, M is the trainee's mark (find the lump): the scorer reads it from the file.
    if (mExercises && mExercises->phase() == ExerciseController::Phase::Running && text.isEmpty()) {
        mExercises->mark();
        mPanel->noteMarkAdded(tr("mark (trainee)"));
        return true;
    }
    const QString mark = text.isEmpty() ? mPanel->nextMarkText() : text;
    recording->mark(mark.toStdString());
    mPanel->noteMarkAdded(mark);
    showMessage(tr("Mark added: %1").arg(mark), 3000);
    return true;
}

void RecordingController::showExerciseRecording(bool recording, const QString& path) {
    if (recording) {
        mPanel->setRecordingStarted(path);
    } else {
        mPanel->setRecordingStopped(QString());
        mPanel->showRecordingStats(mSession.lastRecordingStats());
    }
    update();
}

void RecordingController::showError(const QString& message) {
    mPanel->showRecordingError(message);
    mDock->show();
    mDock->raise();
    showMessage(message, 15000);
}

void RecordingController::update() {
    if (mPanel->isRecording() && !mSession.recording()) {
        // It ended without Stop: a new haptic rate made a new loop.
        const QString why = QString::fromStdString(mSession.takeRecordingEndedReason());
        mPanel->setRecordingStopped(QString());
        if (!why.isEmpty()) showError(why);
        mPanel->showRecordingStats(mSession.lastRecordingStats());
    }
    if (RecordingSession* recording = mSession.recordingSession()) {
        const RecordingStats stats = recording->stats();
        mPanel->showRecordingStats(stats);
        if (!stats.error.empty()) {
            // A write error (disk full, removed drive): stop safely, keep what was written.
            const QString path = QString::fromStdString(recording->path());
            const QString error = QString::fromStdString(stats.error);
            mSession.stopRecording();
            mPanel->setRecordingStopped(QString());
            showError(tr("Recording stopped: %1 (%2 keeps what was written before)").arg(error, path));
            mPanel->showRecordingStats(mSession.lastRecordingStats());
        }
    }
    const bool recording = mSession.recording();
    if (mRecordAction) {
        mRecordAction->setChecked(recording);
        mRecordAction->setEnabled(!mPlayback);
    }
    if (mMarkAction) mMarkAction->setEnabled(recording);
    mPanel->setRecordingAllowed(!mPlayback);
    if (!mStatusField) return;
    if (recording) {
        mStatusField->setText(
            tr("● REC %1").arg(RecordingTimeline::formatTime(mSession.recordingSession()->stats().elapsedS)));
        mStatusField->setStyleSheet(QStringLiteral("color: #c62828; font-weight: bold;"));
        mStatusField->show();
    } else if (mPlayback) {
        mStatusField->setText(tr("▶ playback"));
        mStatusField->setStyleSheet(QString());
        mStatusField->show();
    } else {
        mStatusField->hide();
    }
}

void RecordingController::openRecordingDialog() {
    mDock->show();
    mDock->raise();
    mPanel->chooseRecording();
}

void RecordingController::openRecording(const QString& path) {
    mDock->show();
    mDock->raise();
    if (!mPanel->openRecording(path))
        showMessage(tr("A recording is still being opened; try again when it is done"), 5000);
}

void RecordingController::enterPlayback(const QString& path) {
    const bool fromLive = !mPlayback;
    if (fromLive) {
        if (mSession.recording()) {
            stopRecording();
            showMessage(tr("Recording stopped to play %1 back").arg(QFileInfo(path).fileName()), 8000);
        }
        mPlayback = true;
    }
    emit playbackStarted(path, fromLive);
    update();
}

void RecordingController::backToLive() {
    if (!mPlayback) return;
    mPanel->closePlayback();
    mPlayback = false;
    emit liveResumed();
    update();
}

}  // namespace palpate
