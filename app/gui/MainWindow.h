#pragma once
// The main window: the viewport in the centre, menus, and a status bar with the mesh, the haptic
// loop's health (rate, tick time, jitter, overruns, SCHED_FIFO), the GUI's frame rate, the device,
// the contact and the force. The haptic loop runs the model; this window only observes its
// snapshots (docs/architecture.md) and sends it commands. Three concerns have controllers of their
// own: recording and playback (RecordingController), opening meshes (MeshOpener) and switching the
// device (DeviceController); the window's public API forwards to them.

#include "app/gui/HapticSession.h"
#include "results/ResultsDatabase.h"
#include "widgets/ViewportFactory.h"

#include <QElapsedTimer>
#include <QMainWindow>
#include <QString>
#include <QTimer>

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>

class QAction;
class QActionGroup;
class QDockWidget;
class QLabel;
class QUndoGroup;

namespace palpate {

class ResultUploader;

class ChartsPanel;
class DeviceController;
class DevicePanel;
class ExerciseController;
class ExerciseEditorPanel;
class HistoryPanel;
class LodPanel;
class MeshImportDialog;
class MeshOpener;
class TraineePanel;
class ParameterPanel;
class RecorderPanel;
class RecordingController;
struct HapticSnapshot;
struct TissuePreset;

class MainWindow final : public QMainWindow {
    Q_OBJECT
public:
    /// The observer reads the newest snapshot and repaints at about 60 Hz ...
    static constexpr int kFrameIntervalMs = 16;
    /// ... and the status bar's figures change at about 4 Hz, slow enough to read.
    static constexpr int kStatusIntervalMs = 250;

    /// `mode`: Threaded runs the haptic loop's real-time thread (the interactive window); Stepped
    /// runs ticks only in advanceTicks(), on the GUI thread (screenshots, tests: deterministic).
    /// `loopDef`: the haptic loop's definition (e.g. trySchedFifo off, as for a desktop user
    /// without real-time rights: `palpate --no-fifo`).
    MainWindow(RendererChoice renderer, LoopMode mode, const HapticLoopDef& loopDef = {}, QWidget* parent = nullptr);
    /// Stops the haptic thread before anything is destroyed.
    ~MainWindow() override;

    /// Loads `path` (on this thread, not the haptic one) and makes it the loop's scene. On failure
    /// the current scene stays and the error (naming the file and the problem) is returned; "" on
    /// success. Shows no dialog. The first mesh is drawn at once, later ones once the loop runs them.
    /// `deviceFailed` (if given): set when the failure was the device's (HapticSession::loadMesh).
    QString loadMesh(const QString& path, bool* deviceFailed = nullptr);
    /// What a start-up with no mesh yet is (main): the device `deviceUri` (--device or Preferences)
    /// and the mesh. A device that cannot be created or opened (not plugged in, a typo, a bad
    /// recording) never stops the window from starting, or Preferences could not be reached to
    /// choose another: `fallbackUri` runs instead, and `deviceProblem` says what could not be opened,
    /// why and what runs instead (also shown in the Device dock and the status bar). Returns the
    /// error that does stop it (the mesh's, naming the file), "" once the window can start.
    QString startSession(const QString& meshPath, const QString& deviceUri, const QString& fallbackUri,
                         QString& deviceProblem);
    /// Switches the device (a URI, see device/open/DeviceUri.h). "" or an error naming the URI; no dialog.
    /// Real hardware (HapticSession::opensSlowly) is opened on a worker thread while the loop runs:
    /// then "" means "opening"; the device arrives later (deviceOpening() until then) and an error
    /// is shown in the Device dock and the status bar.
    QString setDeviceUri(const QString& uri);
    bool deviceOpening() const;
    /// A fresh device of the same URI and a fresh scene of the same mesh. "" or why not.
    QString restartSimulation();
    /// Stepped mode: runs `ticks` haptic ticks now, then shows the newest snapshot (what --ticks does).
    void advanceTicks(int ticks);
    /// Loads a tissue preset into the Parameters panel and applies it. "" or the error (naming the key).
    QString loadPresetFile(const QString& path);
    /// Sends a validated preset to the loop (what the Parameters panel's Apply does). "" or why not.
    QString applyPreset(const TissuePreset& preset);
    ParameterPanel* parameterPanel() const { return mParameterPanel; }
    DevicePanel* devicePanel() const { return mDevicePanel; }
    /// The Charts dock's content (speed against accuracy, the applied configuration highlighted).
    ChartsPanel* chartsPanel() const { return mChartsPanel; }
    /// The Recorder dock's content: recording the live session, playing recordings back.
    RecorderPanel* recorderPanel() const;
    /// Records the live session into a new timestamped file in the recorder's folder (the dock's
    /// Record, Simulation > Record). "" or why not, also shown in the dock and the status bar.
    QString startRecording();
    /// Stops recording and closes the file cleanly. "" or the write error (shown as above).
    QString stopRecording();
    bool isRecording() const;
    /// Adds a mark (the dock's text, else "Mark N") at the recording's current tick; false when not recording.
    bool addRecordingMark(const QString& text = {});
    /// Opens a recording for playback (checked off the GUI thread). Once it opened, the live
    /// session pauses and the viewport shows the replay; garbage leaves the live session alone.
    void openRecording(const QString& path);
    /// Playing a recording back (the viewport shows it; the live session is paused).
    bool inPlayback() const;
    /// Leaves playback: the viewport shows the live session again, which runs as before.
    void backToLive();
    /// Trainee mode: the Exercise dock's content, the History dock's, and what runs exercises and
    /// keeps results (ExerciseController).
    TraineePanel* traineePanel() const { return mTraineePanel; }
    /// Instructor mode's exercise editor (click the mesh to place targets, path, inclusion).
    ExerciseEditorPanel* exerciseEditor() const { return mEditor; }
    /// The Level of Detail dock: which mesh level and ring count meet the scene's needs.
    LodPanel* lodPanel() const { return mLodPanel; }
    /// Edit > Undo/Redo act on the stack of the panel last focused (parameters or exercise editor).
    QUndoGroup* undoGroup() const { return mUndoGroup; }
    HistoryPanel* historyPanel() const { return mHistoryPanel; }
    ExerciseController& exercises() { return *mExercises; }
    /// Copies the stored results to the class's server (Preferences, docs/results-store.md).
    ResultUploader* resultUploader() const { return mUploader; }
    /// Instructor mode shows the tools that shape the tissue and the exercises (parameters,
    /// charts, the exercise editor); trainee mode the Exercise and History docks. Kept in QSettings.
    enum class Mode { Instructor, Trainee };
    void setMode(Mode mode);
    Mode mode() const { return mMode; }
    /// Starts the exercise in `path` for `trainee` (created if new); an empty trainee runs it as a
    /// preview (nothing stored). What --exercise does. "" or why not.
    QString runExercise(const QString& path, const QString& trainee);

    /// What File > Open Mesh…, Open Recent and a drop do with a mesh file: loads it in the unit
    /// remembered for it (rememberedMeshUnit). The first time, when its size is implausible in mm
    /// (suggestMeshUnit, docs/meshes.md "Units"), asks once with the reason: open it in the unit
    /// suggested, as mm, or import it (the Import Mesh dialog with the file); the answer is
    /// remembered. A mesh refused for its faults offers Import… too. "" when it opened (or the
    /// import dialog did, or the question was cancelled), else the error (also shown).
    QString openMeshFile(const QString& path);
    /// File > Import Mesh…: the dialog (one per window, kept), with `path` previewed if given.
    MeshImportDialog* openImportDialog(const QString& path = {});
    /// The import dialog once opened (null before).
    MeshImportDialog* importDialog() const;
    /// The unit a mesh file is read in, as chosen for it before (QSettings "meshUnits", by
    /// absolute path); nullopt when never asked.
    static std::optional<MeshUnit> rememberedMeshUnit(const QString& path);
    static void rememberMeshUnit(const QString& path, const MeshUnit& unit);

    /// Where File > Open Mesh… starts: the folder a mesh was last opened from with it (QSettings
    /// "meshes/lastFolder"), else the bundled meshes.
    QString meshDialogFolder() const;
    /// Recent mesh files, newest first (kept in QSettings).
    QStringList recentFiles() const;
    /// Play/Pause: resumes or pauses the loop (paused, the tissue relaxes and the force is zero).
    void setPlaying(bool playing);
    bool isPlaying() const { return !mSession->pauseRequested(); }

    /// Touch mode: the viewport's left button steers the mouse: device's tool (Viewport::TouchHandlers).
    /// Switching to mouse: turns it on, to any other device off. The Simulation menu's "Touch Mode" (T).
    void setTouchMode(bool on);
    bool touchMode() const { return mViewport->touchMode(); }
    /// A touch on vertex `v` of the drawn mesh: the tool goes to its rest position, touchDepthMm()
    /// in along its rest normal. Does nothing without a mouse device or for an unknown vertex.
    void touchVertex(VertexId v);
    /// Lifts the tool off the tissue (the left button's release).
    void releaseTouch();
    /// The press depth (mm, 0..10; the wheel in touch mode). Re-aims a touch in progress.
    void setTouchDepthMm(double depthMm) { mViewport->setTouchDepthMm(depthMm); }
    double touchDepthMm() const { return mViewport->touchDepthMm(); }
    QAction* touchModeAction() const { return mTouchAction; }

    Viewport* viewport() const { return mViewport; }
    HapticSession& session() { return *mSession; }
    const HapticSession& session() const { return *mSession; }
    /// Why this renderer was chosen (for the log).
    const QString& rendererReason() const { return mRendererReason; }
    /// Everything the status bar shows, on one line.
    QString statusText() const;
    /// Haptic rate and GUI frame rate as last shown (measured over the last status period).
    double hapticRateHz() const { return mHapticRateHz; }
    double frameRateFps() const { return mFrameRateFps; }

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private slots:
    void observeFrame();
    void measureRates();

private:
    void createDocks();
    void createMenus();
    void restoreWindowState();
    void saveWindowState();
    void showAbout();
    void updateDocks();
    /// Tells the Charts panel the applied preset and the drawn mesh's size (its highlight).
    void updateChartsConfiguration();
    /// The session has a new mesh (MeshOpener::loaded): nothing is pressed, the device panel, the mesh drawn.
    void meshLoaded(const QString& path);
    void createStatusBar();
    void present(HapticSession::Observation observation);
    void showDrawnMesh();
    void showStatus();
    void shutDown();
    /// A recording plays (RecordingController::playbackStarted): the live session waits, its
    /// Play/Pause and touch mode kept for backToLive.
    void pauseForPlayback(const QString& path, bool fromLive);
    /// Playback ended (RecordingController::liveResumed): the live session runs and shows again.
    void resumeLive();
    void createExerciseDocks();
    void createEditorDock();
    void createLodDock();
    /// After a device switch (DeviceController::switched): touch mode, the status bar.
    void deviceSwitched(const QString& uri, bool ok);
    /// The Level of Detail panel's scene: the drawn mesh (unless it is one of its own levels) and
    /// the needs of the running exercise or the preset.
    void updateLodScene();
    /// The editor's markers on the viewport (instructor mode, no exercise running).
    void showEditorMarkers();
    void createExerciseMenu();
    /// During an exercise the tissue, mesh and device stay as the exercise set them.
    void setExerciseRunning(bool running);
    void newTraineeDialog();
    void openExerciseDialog();
    void exportScorePdfDialog();
    void exportResultPdfDialog(const ResultRecord& result);

    Viewport* mViewport = nullptr;  // owned by Qt as the central widget
    QString mRendererReason;
    std::unique_ptr<HapticSession> mSession;
    std::shared_ptr<const TissueMesh> mShownMesh;  // what the viewport was given last
    QTimer mFrameTimer;
    QTimer mStatusTimer;

    // Rate measurement between status updates: ticks against the times their snapshots were read,
    // frames against the GUI's clock.
    bool mHaveRateBaseline = false;
    std::uint64_t mRateBaselineTicks = 0;
    std::chrono::steady_clock::time_point mRateBaselineReadAt{};
    QElapsedTimer mFrameClock;
    std::uint64_t mRateBaselineFrames = 0;
    std::uint64_t mSeenDivergences = 0;  ///< divergence-guard events already reported to the user
    double mHapticRateHz = 0.0;
    double mFrameRateFps = 0.0;

    QLabel* mMeshLabel = nullptr;
    QLabel* mRateLabel = nullptr;
    QLabel* mComputeLabel = nullptr;
    QLabel* mJitterLabel = nullptr;
    QLabel* mOverrunLabel = nullptr;
    QLabel* mFifoLabel = nullptr;
    QLabel* mFpsLabel = nullptr;
    QLabel* mDeviceLabel = nullptr;
    QLabel* mContactLabel = nullptr;
    QLabel* mForceLabel = nullptr;
    QLabel* mResultsLabel = nullptr;
    ResultUploader* mUploader = nullptr;  // owned by Qt (child of this window)
    QAction* mPlayAction = nullptr;
    QAction* mWireframeAction = nullptr;
    QAction* mTouchAction = nullptr;
    VertexId mTouchVertex = kNoVertex;  // the vertex being pressed (touch mode), else kNoVertex
    ParameterPanel* mParameterPanel = nullptr;
    DevicePanel* mDevicePanel = nullptr;
    QLabel* mStatusDetails = nullptr;
    QDockWidget* mParameterDock = nullptr;
    QDockWidget* mDeviceDock = nullptr;
    QDockWidget* mStatusDock = nullptr;
    ChartsPanel* mChartsPanel = nullptr;
    QDockWidget* mChartsDock = nullptr;
    RecordingController* mRecording = nullptr;  // owned by Qt (child of this window)
    MeshOpener* mMeshes = nullptr;              // owned by Qt (child of this window)
    DeviceController* mDevices = nullptr;       // owned by Qt (child of this window)
    QLabel* mRecordingLabel = nullptr;          // status bar: REC and its time, or the recording played back
    bool mPlayingBeforePlayback = true;  // the live session's state to go back to
    bool mTouchBeforePlayback = false;
    bool mTouchBeforePlacing = false;  // touch mode waits while the exercise editor places points
    std::unique_ptr<HapticSnapshot> mPanelSnapshot;  // what the Device panel reads (large: on the heap)
    TraineePanel* mTraineePanel = nullptr;
    ExerciseEditorPanel* mEditor = nullptr;
    QDockWidget* mEditorDock = nullptr;
    QUndoGroup* mUndoGroup = nullptr;
    LodPanel* mLodPanel = nullptr;
    QDockWidget* mLodDock = nullptr;
    std::shared_ptr<const TissueMesh> mLodSceneMesh;  // the Level of Detail panel's source mesh
    /// Before the first "Use" of a level of detail: the mesh, the tissue and the panel's source,
    /// for Undo use, and to drop the level's rings and knots when another mesh is opened.
    struct BeforeLodUse {
        QString meshPath;
        TissuePreset preset;
        QString lodSource;
    };
    std::optional<BeforeLodUse> mBeforeLodUse;
    /// Whether `path` is the Level of Detail source a Use was made in, or one of its levels.
    bool inLodScene(const QString& path) const;
    void undoLodUse();
    QMetaObject::Connection mFocusConnection;         // Edit > Undo follows the focused panel
    HistoryPanel* mHistoryPanel = nullptr;
    QDockWidget* mExerciseDock = nullptr;
    QDockWidget* mHistoryDock = nullptr;
    ExerciseController* mExercises = nullptr;  // owned by Qt (child of this window)
    Mode mMode = Mode::Instructor;
    QActionGroup* mModeGroup = nullptr;
    QAction* mInstructorAction = nullptr;
    QAction* mTraineeAction = nullptr;
    QAction* mOpenMeshAction = nullptr;
    QAction* mImportMeshAction = nullptr;
    QAction* mRestartAction = nullptr;
};

}  // namespace palpate
