#pragma once
// The window's recorder: records the live session (the Recorder dock's Record, Simulation > Record,
// Add Mark) and plays recordings back in the viewport (File > Open Recording…, the History dock's
// replay). It owns the Recorder dock, its two menu actions and the status bar's REC field. While a
// recording plays, the live session waits: the window pauses it on playbackStarted and resumes it
// on liveResumed (docs/recording.md).

#include "app/gui/HapticSession.h"

#include <QObject>
#include <QString>

#include <functional>

class QAction;
class QDockWidget;
class QLabel;
class QMainWindow;
class QMenu;

namespace palpate {

class ExerciseController;
class RecorderPanel;
class Viewport;

class RecordingController final : public QObject {
    Q_OBJECT
public:
    /// Adds the Recorder dock to `window` (under the viewport). `presentFrame` reads the newest
    /// snapshot and shows it (the window's observer), while a recording waits for a new scene.
    RecordingController(QMainWindow& window, HapticSession& session, Viewport& viewport,
                        std::function<void()> presentFrame, QObject* parent = nullptr);

    /// The exercise runner: during an exercise, Add Mark without text is the trainee's mark.
    void setExercises(ExerciseController& exercises) { mExercises = &exercises; }
    /// The status bar's field: REC and its time, or the recording played back.
    void setStatusField(QLabel* field) { mStatusField = field; }
    /// Simulation > Record and Add Mark.
    void addMenuActions(QMenu* simulation);

    RecorderPanel* panel() const { return mPanel; }
    QDockWidget* dock() const { return mDock; }

    /// Records the live session into a new timestamped file in the recorder's folder. "" or why
    /// not, also shown in the dock and the status bar.
    QString startRecording();
    /// Stops recording and closes the file cleanly. "" or the write error (shown as above).
    QString stopRecording();
    /// Adds a mark (the dock's text, else "Mark N") at the recording's current tick; false when not recording.
    bool addMark(const QString& text = {});
    /// An exercise's own recording started or ended: the dock shows it like its own.
    void showExerciseRecording(bool recording, const QString& path);

    /// File > Open Recording…: the dock's file dialog.
    void openRecordingDialog();
    /// Opens a recording for playback (checked off the GUI thread); see MainWindow::openRecording.
    void openRecording(const QString& path);
    bool inPlayback() const { return mPlayback; }
    /// Leaves playback: the viewport shows the live session again.
    void backToLive();

    /// The recording's figures to the dock and the status bar; stops it on a write error.
    void update();

signals:
    /// A recording plays in the viewport. `fromLive`: the live session was showing until now (the
    /// window pauses it and keeps its state); false when one recording replaces another.
    void playbackStarted(const QString& path, bool fromLive);
    /// Playback ended: the window shows and runs the live session as before.
    void liveResumed();
    /// The status bar should show again (the mesh of the recording played back changed).
    void statusChanged();

private:
    void enterPlayback(const QString& path);
    void showError(const QString& message);
    void showMessage(const QString& text, int timeoutMs);

    QMainWindow& mWindow;
    HapticSession& mSession;
    Viewport& mViewport;
    std::function<void()> mPresentFrame;
    ExerciseController* mExercises = nullptr;
    RecorderPanel* mPanel = nullptr;  // owned by Qt (the dock's widget)
    QDockWidget* mDock = nullptr;     // owned by Qt (child of the window)
    QAction* mRecordAction = nullptr;
    QAction* mMarkAction = nullptr;
    QLabel* mStatusField = nullptr;
    bool mPlayback = false;
};

}  // namespace palpate
