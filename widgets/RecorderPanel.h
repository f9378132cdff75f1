#pragma once
// The Recorder dock (docs/recording.md): records the live session and plays recordings
// back. Recording: the main window owns the haptic session and its RecordingSession; this panel
// asks (recordRequested, stopRequested, markRequested), names the file (a timestamped name in the
// recordings folder) and shows what it is told (started, stats about 4 times a second, stopped,
// errors). Playback: the panel owns the RecordingReader and the stepped RecordingPlayer. Opening a
// file and long seeks (backwards means replaying from the start) run on a worker thread with a
// progress bar, so the GUI never waits for them; playing steps the player on the GUI thread at
// display rate within a time budget. The replayed scene goes out as signals for the viewport.

#include "engine/record/RecordingReader.h"
#include "engine/record/RecordingWriter.h"
#include "widgets/SceneSnapshot.h"

#include <QElapsedTimer>
#include <QString>
#include <QTimer>
#include <QWidget>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QThread;

namespace palpate {

class RecordingPlayer;
class RecordingTimeline;
class TissueMesh;

class RecorderPanel final : public QWidget {
    Q_OBJECT
public:
    /// Playback speeds the combo offers.
    static constexpr double kSpeeds[] = {0.25, 0.5, 1.0, 2.0, 4.0};
    /// The frame timer's interval (about 60 Hz, as the viewport's).
    static constexpr int kFrameIntervalMs = 16;

    explicit RecorderPanel(QWidget* parent = nullptr);
    /// Stops a worker job (a seek stops within a few ms; an open runs to its end) before going.
    ~RecorderPanel() override;

    // --- recording: the main window answers the requests ---
    /// Where new recordings go: the folder chosen with Folder… (kept in QSettings), else
    /// defaultRecordingFolder().
    QString recordingFolder() const { return mFolder; }
    /// `persist`: keep it in QSettings for the next run (the Folder… button does).
    void setRecordingFolder(const QString& folder, bool persist = false);
    /// QStandardPaths::AppDataLocation/recordings.
    static QString defaultRecordingFolder();
    /// A new file in the folder, named by the time (palpate-20240131-142501.palprec), the folder
    /// created if need be. "" and `error` (naming the folder) when it cannot be created.
    QString newRecordingPath(QString* error) const;
    /// The text of the next mark: the mark field, else "Mark N".
    QString nextMarkText() const;

    void setRecordingStarted(const QString& path);
    /// `error`: "" for a clean close, else why the recording ended (shown in red, kept).
    void setRecordingStopped(const QString& error);
    /// The status line: elapsed, ticks, bytes, bytes/tick, drops and gaps.
    void showRecordingStats(const RecordingStats& stats);
    /// A recording problem (cannot create the file, write error), shown in red until the next start.
    void showRecordingError(const QString& message);
    /// The mark was written: clears the field and says so.
    void noteMarkAdded(const QString& text);
    bool isRecording() const { return mRecording; }
    const QString& recordingPath() const { return mRecordingPath; }
    QString recordingStatusText() const;
    QString recordingErrorText() const;
    /// Record is refused while playing back (Back to live first).
    void setRecordingAllowed(bool allowed);

    // --- playback: the panel owns the reader and the player ---
    /// Opens `path` on a worker thread: checked with RecordingReader (a damaged file opens with a
    /// warning, garbage gives an error naming the file), then a player is built (mesh loaded,
    /// scene rebuilt). On success playbackStarted, then the mesh and the first tick. False when an
    /// open is already running.
    bool openRecording(const QString& path);
    /// The file dialog, then openRecording. It starts in the folder a recording was last chosen
    /// from (QSettings "recorder/openFolder"), else in the recordings folder.
    void chooseRecording();
    /// Where chooseRecording's dialog starts.
    QString openDialogFolder() const;
    /// Drops the player and the reader (a running seek is stopped first, a file being opened is
    /// dropped when it arrives). Emits nothing.
    void closePlayback();
    bool inPlayback() const { return mPlayer != nullptr; }
    /// A job (open, seek) is running on the worker thread.
    bool isBusy() const { return mWorker != nullptr; }

    /// Moves playback to `tick` (clamped to the replayable ticks). Cheap seeks run here; one that
    /// would take more than a frame's time runs on the worker (scrubbing keeps retargeting it).
    bool seekTo(std::uint64_t tick);
    /// Seeks predicted to take longer than this run on the worker (default kSyncSeekBudgetUs, a
    /// frame and a half; 0 sends every seek there, as tests do to exercise that path).
    void setSyncSeekBudgetUs(double us) { mSyncSeekBudgetUs = us; }
    static constexpr double kSyncSeekBudgetUs = 25'000.0;
    void setPlaying(bool playing);
    bool isPlaying() const { return mPlaying; }
    /// One of kSpeeds (others are taken as the nearest).
    void setSpeed(double speed);
    double speed() const;
    /// One display frame of playback, `elapsedS` after the previous one: steps rate*elapsed*speed
    /// ticks (carrying fractions; at most a frame's time budget). The frame timer calls it with the
    /// measured time; tests call it with a fixed one.
    void advanceFrame(double elapsedS);
    /// Display frames played so far (timer or advanceFrame).
    std::uint64_t framesPlayed() const { return mFramesPlayed; }

    /// Null outside playback or while a seek runs on the worker.
    RecordingPlayer* player() { return mJob == Job::Seek ? nullptr : mPlayer.get(); }
    const RecordingReader* reader() const { return mReader.get(); }
    RecordingTimeline* timeline() const { return mTimeline; }
    /// The mesh the replay shows (null outside playback, before its first frame), and its file as
    /// the recording names it (the header's, or that of the last scene switch replayed).
    const TissueMesh* playbackMesh() const { return mPlayer ? mShownMesh.get() : nullptr; }
    QString playbackMeshPath() const;
    /// The player's tick (0 outside playback).
    std::uint64_t currentTick() const;
    const SceneSnapshot& frame() const { return mFrame; }
    QString playbackErrorText() const;
    QString playbackWarningText() const;
    /// The replay's verdict once it reached the end ("" before).
    QString verdictText() const;
    QString timeText() const;

signals:
    void recordRequested();
    void stopRequested();
    void markRequested(const QString& text);
    /// A recording opened: from now on the viewport shows the replay (pause the live session).
    void playbackStarted(const QString& path);
    /// The replayed mesh (on open, and when the recording switched scenes).
    void playbackMeshChanged(const TissueMesh& mesh);
    /// The replayed state at the current tick, for the viewport.
    void playbackFrame(const SceneSnapshot& frame);
    /// Back to live: the main window closes playback and resumes the live session.
    void backToLiveRequested();
    /// Opening failed (the message names the file); the live session was left alone.
    void openFailed(const QString& error);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    struct OpenResult;
    void buildRecordingBox(QWidget* box);
    void buildPlaybackBox(QWidget* box);
    void chooseFolder();
    void updateButtons();

    void startWorker(std::function<void()> work);
    void onOpenFinished(const std::shared_ptr<OpenResult>& result);
    void onSeekFinished(std::optional<std::uint64_t> reachedTick);
    void finishWorker();
    void pollProgress();
    void startSeekJob(std::uint64_t tick);
    void onFrameTimer();
    /// Steps up to `ticks` within the frame budget; returns how many ran.
    std::uint64_t stepBudgeted(std::uint64_t ticks);
    void presentFrame();
    void updateTimeLabels();
    void updateVerdict();
    void setPlaybackError(const QString& text);
    void setPlaybackWarning(const QString& text);
    double timeOfTick(std::uint64_t tick) const;

    // Recording.
    QPushButton* mRecordButton = nullptr;
    QPushButton* mStopButton = nullptr;
    QPushButton* mFolderButton = nullptr;
    QLabel* mRecordStatus = nullptr;
    QLabel* mRecordError = nullptr;
    QLineEdit* mMarkEdit = nullptr;
    QPushButton* mMarkButton = nullptr;
    QString mFolder;
    bool mRecording = false;
    bool mRecordingAllowed = true;
    QString mRecordingPath;
    int mMarksAdded = 0;

    // Playback widgets.
    QPushButton* mOpenButton = nullptr;
    QLabel* mFileLabel = nullptr;
    QLabel* mPlaybackError = nullptr;
    QLabel* mPlaybackWarning = nullptr;
    RecordingTimeline* mTimeline = nullptr;
    QPushButton* mPlayButton = nullptr;
    QComboBox* mSpeedCombo = nullptr;
    QLabel* mTimeLabel = nullptr;
    QPushButton* mLiveButton = nullptr;
    QProgressBar* mProgress = nullptr;
    QLabel* mVerdictLabel = nullptr;

    // Playback state. While mWorker runs, only the worker touches mReader/mPlayer (or, opening, its
    // own new ones); the GUI reads the atomics below.
    std::shared_ptr<const RecordingReader> mReader;
    std::unique_ptr<RecordingPlayer> mPlayer;
    QString mPlaybackPath;
    QThread* mWorker = nullptr;
    enum class Job { None, Open, Seek } mJob = Job::None;
    std::atomic<bool> mCancel{false};
    std::atomic<std::uint64_t> mSeekTarget{0};
    std::atomic<std::uint64_t> mSeekFrom{0};
    std::atomic<std::uint64_t> mSeekReached{0};
    QElapsedTimer mJobClock;
    QTimer mProgressTimer;
    bool mBusyCursor = false;

    QTimer mFrameTimer;
    QElapsedTimer mFrameClock;
    bool mPlaying = false;
    double mRateHz = 1000.0;
    double mTickCarry = 0.0;
    double mSyncSeekBudgetUs = kSyncSeekBudgetUs;
    double mUsPerTick = 10.0;     ///< measured replay cost, to decide which seeks run here
    std::uint64_t mFramesPlayed = 0;
    double mStartTimeS = 0.0;     ///< loop clock at the first recovered tick
    std::vector<ChunkInfo> mTimeChunks;  ///< data chunks by tick: loop time of any tick
    std::uint64_t mShownSceneId = 0;     ///< the replayed scene of the last frame
    QString mShownMeshPath;  ///< its file, as the recording names it
    std::unique_ptr<TissueMesh> mShownMesh;  ///< copy of the mesh last emitted (a restart rebuilds the scene)
    SceneSnapshot mFrame;
};

}  // namespace palpate
