#include "app/gui/MainWindow.h"

#include "device/open/DeviceUri.h"
#include "device/SafetyFilter.h"
#include "engine/loop/HapticSnapshot.h"
#include "engine/scene/TissuePreset.h"
#include "engine/scoring/TargetReachability.h"
#include "base/resources/ShippedResources.h"
#include "app/gui/DeviceController.h"
#include "app/gui/ExerciseController.h"
#include "app/gui/FirstRun.h"
#include "app/gui/MeshOpener.h"
#include "app/gui/RecordingController.h"
#include "widgets/ChartsPanel.h"
#include "widgets/StiffeningPanel.h"
#include "widgets/FeelPanel.h"
#include "widgets/ExerciseEditorPanel.h"
#include "widgets/GuardedLoad.h"
#include "widgets/HistoryPanel.h"
#include "widgets/LodPanel.h"
#include "widgets/ClassDialog.h"
#include "results/ResultUploader.h"
#include "engine/accuracy/StiffeningCalibration.h"
#include "widgets/MeshSizeText.h"
#include "widgets/PreferencesDialog.h"
#include "widgets/ScoreCard.h"
#include "widgets/TraineePanel.h"
#include "widgets/DevicePanel.h"
#include "widgets/ParameterPanel.h"
#include "widgets/RecorderPanel.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QMimeData>
#include <QSettings>
#include <QUndoGroup>
#include <QUndoStack>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QKeySequence>
#include <QScrollArea>
#include <QLocale>
#include <QScrollBar>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>

#include <glm/geometric.hpp>

#include <stdexcept>

namespace palpate {

namespace {

/// `panel` in a frameless scroll area that resizes it: a dock of it can be shorter than the panel's
/// own minimum, so that the window's docks fit a 1280x800 screen (the panel scrolls instead).
QScrollArea* scrolled(QWidget* panel, QWidget* parent) {
    auto* scroll = new QScrollArea(parent);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(panel);
    return scroll;
}

bool isMeshFile(const QString& path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    return suffix == "obj" || suffix == "off" || suffix == "ply" || suffix == "stl" || suffix == "om";
}

bool isMouseUri(const std::string& uri) {
    DeviceUri parsed;
    std::string ignored;
    return (ignored = parseDeviceUri(uri, parsed)).empty() && parsed.kind == DeviceKind::Mouse;
}

/// A device that plays a script or a recording: nobody's hand is on it.
bool isScriptedUri(const std::string& uri) {
    DeviceUri parsed;
    std::string ignored;
    if (!(ignored = parseDeviceUri(uri, parsed)).empty()) return false;
    return parsed.kind == DeviceKind::SimPress || parsed.kind == DeviceKind::SimStroke ||
           parsed.kind == DeviceKind::SimScan || parsed.kind == DeviceKind::SimSine ||
           parsed.kind == DeviceKind::SimPath || parsed.kind == DeviceKind::Replay;
}

QLabel* addStatusField(QStatusBar* bar, const char* objectName, const QString& toolTip) {
    auto* label = new QLabel(bar);
    label->setObjectName(QLatin1String(objectName));
    label->setToolTip(toolTip);
    label->setContentsMargins(4, 0, 0, 0);
    // A narrow window clips these rather than the mesh field (its name, size and unit stay whole).
    label->setMinimumWidth(16);
    bar->addPermanentWidget(label);
    return label;
}

}  // namespace

MainWindow::MainWindow(RendererChoice renderer, LoopMode mode, const HapticLoopDef& loopDef, QWidget* parent)
    : QMainWindow(parent), mSession(std::make_unique<HapticSession>(mode, loopDef)) {
    setWindowTitle(QStringLiteral("Palpate"));
    mViewport = createViewport(renderer, this, &mRendererReason);
    setCentralWidget(mViewport->widget());
    Viewport::TouchHandlers touch;
    touch.moved = [this](VertexId v, QPointF) { touchVertex(v); };
    touch.released = [this] { releaseTouch(); };
    touch.depthChanged = [this](double depthMm) {
        if (mTouchVertex != kNoVertex) touchVertex(mTouchVertex);
        statusBar()->showMessage(tr("Touch depth %1 mm").arg(locale().toString(depthMm, 'f', 1)), 2000);
    };
    mViewport->setTouchHandlers(std::move(touch));
    createStatusBar();
    createDocks();
    createMenus();
    setAcceptDrops(true);
    restoreWindowState();

    // The observer: reads the newest snapshot (only if a new one was published) and repaints. In
    // stepped mode nothing ticks between advanceTicks() calls, which observe themselves.
    mFrameTimer.setTimerType(Qt::PreciseTimer);
    mFrameTimer.setInterval(kFrameIntervalMs);
    connect(&mFrameTimer, &QTimer::timeout, this, &MainWindow::observeFrame);
    if (mode == LoopMode::Threaded) mFrameTimer.start();
    mStatusTimer.setInterval(kStatusIntervalMs);
    connect(&mStatusTimer, &QTimer::timeout, this, &MainWindow::measureRates);
    mStatusTimer.start();
    showStatus();
}

MainWindow::~MainWindow() { shutDown(); }

void MainWindow::shutDown() {
    mDevices->waitForOpening();  // a device being opened: it is closed with the job
    // Docks hide and focus moves while the children are destroyed: the slots that react to it
    // must not run on a half-destroyed window.
    if (mEditorDock) mEditorDock->disconnect(this);
    if (mFocusConnection) QObject::disconnect(mFocusConnection);
    mFrameTimer.stop();
    mStatusTimer.stop();
    if (mSession->recording()) stopRecording();  // the file gets its end chunk and is closed cleanly
    mSession->stop();  // joins the haptic thread: from here on nothing runs behind our back
}

void MainWindow::closeEvent(QCloseEvent* event) {
    saveWindowState();
    shutDown();
    QMainWindow::closeEvent(event);
}

void MainWindow::createDocks() {
    setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);
    mParameterPanel = new ParameterPanel(this);
    mParameterPanel->setPreset(mSession->preset());
    // Calibrate slopes works on the mesh being drawn; the panel asks for it each time, never keeps it.
    mParameterPanel->setMeshProvider([this]() -> const TissueMesh* { return mSession->drawnMesh().get(); });
    // The shipped tissues (resources/presets/tissues/*.json), found through one of them.
    if (const std::string anchor = findResource("presets/tissues/phantom_gel.json"); !anchor.empty())
        mParameterPanel->setTissuePresetDirectory(QFileInfo(QString::fromStdString(anchor)).absolutePath());
    mParameterDock = new QDockWidget(tr("Parameters"), this);
    mParameterDock->setObjectName(QStringLiteral("parametersDock"));
    mParameterDock->setWidget(mParameterPanel);
    addDockWidget(Qt::RightDockWidgetArea, mParameterDock);
    connect(mParameterPanel, &ParameterPanel::applyRequested, this, [this](const TissuePreset& preset) {
        if (const QString error = applyPreset(preset); !error.isEmpty())
            QMessageBox::warning(this, tr("Parameters not applied"), error);
    });

    mDevicePanel = new DevicePanel(this);
    mDeviceDock = new QDockWidget(tr("Device"), this);
    mDeviceDock->setObjectName(QStringLiteral("deviceDock"));
    mDeviceDock->setWidget(scrolled(mDevicePanel, this));
    addDockWidget(Qt::RightDockWidgetArea, mDeviceDock);
    tabifyDockWidget(mParameterDock, mDeviceDock);
    mParameterDock->raise();

    mStatusDetails = new QLabel(this);
    mStatusDetails->setObjectName(QStringLiteral("statusDetails"));
    mStatusDetails->setTextFormat(Qt::PlainText);
    mStatusDetails->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    mStatusDetails->setMargin(6);
    mStatusDock = new QDockWidget(tr("Status"), this);
    mStatusDock->setObjectName(QStringLiteral("statusDock"));
    mStatusDock->setWidget(mStatusDetails);
    addDockWidget(Qt::RightDockWidgetArea, mStatusDock);

    mChartsPanel = new ChartsPanel(this);
    mChartsDock = new QDockWidget(tr("Charts"), this);
    mChartsDock->setObjectName(QStringLiteral("chartsDock"));
    mChartsDock->setWidget(mChartsPanel);
    addDockWidget(Qt::RightDockWidgetArea, mChartsDock);
    tabifyDockWidget(mDeviceDock, mChartsDock);
    mParameterDock->raise();
    // The committed sweep (docs/ beside resources/), shown without measuring again when the dock is
    // first shown; without it the chart says how to make one.
    mChartsPanel->setDefaultCsv(QString::fromStdString(findResource("../docs/bench/sweep.csv")));
    mChartsPanel->feelPanel()->setDefaultCsv(QString::fromStdString(findResource("../docs/bench/feel.csv")));
    connect(mChartsPanel->stiffeningPanel(), &StiffeningPanel::applyKnotsRequested, this,
            [this](const StiffeningCalibration& calibration) {
                const QString error = mParameterPanel->applyStiffeningKnots(calibration);
                statusBar()->showMessage(
                    error.isEmpty() ? tr("Stiffening knots applied to the tissue (undo them in Parameters, then Apply)")
                                    : error,
                    8000);
            });
    updateChartsConfiguration();
    mRecording = new RecordingController(
        *this, *mSession, *mViewport, [this] { present(mSession->observe()); }, this);
    mRecording->setStatusField(mRecordingLabel);
    connect(mRecording, &RecordingController::playbackStarted, this, &MainWindow::pauseForPlayback);
    connect(mRecording, &RecordingController::liveResumed, this, &MainWindow::resumeLive);
    connect(mRecording, &RecordingController::statusChanged, this, &MainWindow::showStatus);
    createExerciseDocks();
    mRecording->setExercises(*mExercises);
    createEditorDock();
    createLodDock();
    mMeshes = new MeshOpener(*this, *mSession, *mExercises, this);
    connect(mMeshes, &MeshOpener::loaded, this, &MainWindow::meshLoaded);
    mDevices = new DeviceController(*this, *mSession, *mDevicePanel, *mExercises, this);
    connect(mDevices, &DeviceController::switched, this, &MainWindow::deviceSwitched);
    mPanelSnapshot = std::make_unique<HapticSnapshot>();
}

QString MainWindow::applyPreset(const TissuePreset& preset) {
    const QString error = QString::fromStdString(mSession->applyPreset(preset));
    if (error.isEmpty()) mParameterPanel->showApplied(mSession->preset());  // clears its "Not applied" marks
    if (error.isEmpty()) updateChartsConfiguration();
    if (error.isEmpty() && mLodPanel) updateLodScene();
    return error;
}

void MainWindow::updateChartsConfiguration() {
    const TissuePreset& applied = mSession->preset();
    const auto& mesh = mSession->drawnMesh();
    mChartsPanel->setCurrentConfiguration(applied, ParameterPanel::toolContactOf(applied), mesh ? mesh->vertexCount() : 0);
}

QString MainWindow::loadPresetFile(const QString& path) {
    QString error;
    if (!mParameterPanel->loadPresetFile(path, &error)) return error.isEmpty() ? path + tr(": not loaded") : error;
    return applyPreset(mParameterPanel->preset());
}

void MainWindow::restoreWindowState() {
    QSettings settings;
    restoreGeometry(settings.value("window/geometry").toByteArray());
    restoreState(settings.value("window/state").toByteArray());
    setMode(settings.value("window/mode").toString() == QLatin1String("trainee") ? Mode::Trainee : Mode::Instructor);
}

void MainWindow::saveWindowState() {
    QSettings settings;
    settings.setValue("window/mode", mMode == Mode::Trainee ? QStringLiteral("trainee") : QStringLiteral("instructor"));
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    for (const QUrl& url : event->mimeData()->urls())
        if (url.isLocalFile() && isMeshFile(url.toLocalFile())) {
            event->acceptProposedAction();
            return;
        }
}

void MainWindow::dropEvent(QDropEvent* event) {
    for (const QUrl& url : event->mimeData()->urls()) {
        if (!url.isLocalFile() || !isMeshFile(url.toLocalFile())) continue;
        event->acceptProposedAction();
        mMeshes->openMeshFile(url.toLocalFile());
        return;
    }
}

void MainWindow::showAbout() {
    QMessageBox::about(
        this, tr("About Palpate"),
        tr("<h3>Palpate %1</h3>"
           "<p>Haptic soft-tissue deformation: the slope-ring method of Ahmad, Sulaiman and Rambli, "
           "made exact and measured.</p>"
           "<p>Built with these libraries (Debian 12 packages):</p><ul>"
           "<li>Qt %2 (Widgets, OpenGL): LGPL-3.0</li>"
           "<li>OpenMesh: BSD-3-Clause</li>"
           "<li>GLM: MIT (Happy Bunny licence)</li>"
           "<li>nlohmann/json: MIT</li>"
           "<li>GoogleTest and Google Benchmark (tests only): BSD-3-Clause, Apache-2.0</li></ul>")
            .arg(QStringLiteral(PALPATE_VERSION_STRING), QString::fromLatin1(qVersion())));
}

void MainWindow::updateDocks() {
    const ObservedLoop& o = mSession->observed();
    HapticSnapshot& s = *mPanelSnapshot;
    s.publishCount = o.publishCount;
    s.tick = o.tick;
    s.deviceState = o.deviceState;
    s.safetyPhase = o.safetyPhase;
    s.safetyFlags = o.safetyFlags;
    s.toolTipMm = o.toolTipMm;
    s.forceN = o.forceN;
    s.commandedForceN = o.commandedForceN;
    s.contact = o.contact;
    s.touched = o.touched;
    s.paused = o.paused;
    s.counters = o.counters;
    mDevicePanel->updateFromSnapshot(s);
    const LoopCounters& c = o.counters;
    mStatusDetails->setText(
        tr("Haptic rate: %1 Hz (loop says %2 Hz)\nTicks: %3\nMissed deadlines: %4\nOverruns: %5\n"
           "Tick compute: last %6 µs, max %7 µs\nJitter: last %8 µs, max %9 µs\nScheduling: %10\n"
           "GUI: %11 fps\nDisplaced vertices: %12\nPaused: %13")
            .arg(mHapticRateHz, 0, 'f', 0)
            .arg(c.achievedRateHz, 0, 'f', 0)
            .arg(c.ticks)
            .arg(c.missedDeadlines)
            .arg(c.overruns)
            .arg(QLocale().toString(c.lastComputeUs, 'f', 1), QLocale().toString(c.maxComputeUs, 'f', 1),
                 QLocale().toString(c.lastJitterUs, 'f', 1), QLocale().toString(c.maxJitterUs, 'f', 1))
            .arg(c.schedFifo ? tr("SCHED_FIFO") : tr("normal (SCHED_FIFO not permitted)"))
            .arg(mFrameRateFps, 0, 'f', 0)
            .arg(o.displacedTotal)
            .arg(o.paused ? tr("yes") : tr("no")));
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open = file->addAction(tr("&Open Mesh…"), mMeshes, &MeshOpener::openMeshDialog);
    open->setShortcut(QKeySequence::Open);
    open->setObjectName(QStringLiteral("openMeshAction"));
    mOpenMeshAction = open;
    // Ctrl+Shift+O is Open Preset's; Ctrl+I is free in every menu and dock.
    mImportMeshAction = file->addAction(tr("&Import Mesh…"), QKeySequence(Qt::CTRL | Qt::Key_I), this,
                                        [this] { mMeshes->openImportDialog(); });
    mImportMeshAction->setObjectName(QStringLiteral("importMeshAction"));
    mImportMeshAction->setStatusTip(tr("Open a mesh from another tool: its unit, repair, remeshing, previewed"));
    mMeshes->setRecentMenu(file->addMenu(tr("Open &Recent")));
    QAction* openRecording = file->addAction(tr("Open Recor&ding…"), mRecording,
                                             &RecordingController::openRecordingDialog);
    openRecording->setObjectName(QStringLiteral("openRecordingAction"));
    openRecording->setStatusTip(tr("Play a session recording back (the live session pauses meanwhile)"));
    file->addSeparator();
    QAction* openPreset = mParameterPanel->openPresetAction();
    openPreset->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O));
    file->addAction(openPreset);
    QAction* savePreset = mParameterPanel->savePresetAction();
    savePreset->setShortcut(QKeySequence::Save);
    file->addAction(savePreset);
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Q));  // QKeySequence::Quit is empty on some platforms

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    // One Undo/Redo for the window, on the stack of the panel last worked in: two actions with the
    // same shortcut would be ambiguous, and Qt would run neither.
    QAction* undo = mUndoGroup->createUndoAction(this, tr("&Undo"));
    QAction* redo = mUndoGroup->createRedoAction(this, tr("&Redo"));
    undo->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Z));
    redo->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z));
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addAction(tr("&Apply Parameters"), QKeySequence(Qt::CTRL | Qt::Key_Return), mParameterPanel,
                    &ParameterPanel::apply);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addAction(tr("&Reset Camera"), QKeySequence(Qt::Key_R), this, [this] { mViewport->resetCamera(); });
    view->addAction(tr("&Fit"), QKeySequence(Qt::Key_F), this, [this] { mViewport->fitCamera(); });
    mWireframeAction = view->addAction(tr("&Wireframe"), QKeySequence(Qt::Key_W), this,
                                       [this](bool on) { mViewport->setWireframe(on); });
    mWireframeAction->setCheckable(true);
    mWireframeAction->setChecked(mViewport->wireframe());
    QAction* ghost = view->addAction(tr("Rest Shape &Ghost"), QKeySequence(Qt::Key_G), this,
                                     [this](bool on) { mViewport->setShowRestGhost(on); });
    ghost->setCheckable(true);
    ghost->setChecked(mViewport->showRestGhost());
    // After a palpation exercise: the surface examined firmly enough, coloured by the largest force.
    QAction* heat = view->addAction(tr("&Coverage Heat Map"), QKeySequence(Qt::Key_C), this, [this](bool on) {
        if (mExercises) mExercises->setShowCoverageHeat(on);
    });
    heat->setObjectName(QStringLiteral("coverageHeatAction"));
    heat->setCheckable(true);
    heat->setChecked(true);
    heat->setStatusTip(tr("Show, after a palpation exercise, where the surface was examined and how firmly"));
    view->addSeparator();
    view->addAction(mParameterDock->toggleViewAction());
    view->addAction(mDeviceDock->toggleViewAction());
    view->addAction(mStatusDock->toggleViewAction());
    view->addAction(mChartsDock->toggleViewAction());
    view->addAction(mRecording->dock()->toggleViewAction());
    view->addAction(mEditorDock->toggleViewAction());
    view->addAction(mLodDock->toggleViewAction());
    view->addAction(mExerciseDock->toggleViewAction());
    view->addAction(mHistoryDock->toggleViewAction());

    QMenu* simulation = menuBar()->addMenu(tr("&Simulation"));
    // One meaning for the tick: paused (the text says what a click does, the tick what is).
    mPlayAction = simulation->addAction(tr("&Pause"), QKeySequence(Qt::Key_Space), this,
                                        [this](bool paused) { setPlaying(!paused); });
    mPlayAction->setObjectName(QStringLiteral("pauseAction"));
    mPlayAction->setCheckable(true);
    mPlayAction->setChecked(!isPlaying());
    mPlayAction->setStatusTip(tr("Pause the simulation (ticked: paused; the tissue relaxes and the force is zero)"));
    mRestartAction = simulation->addAction(tr("&Restart"), QKeySequence(Qt::CTRL | Qt::Key_R), this, [this] {
        if (const QString error = restartSimulation(); !error.isEmpty())
            QMessageBox::warning(this, tr("Cannot restart"), error);
    });

    mTouchAction = simulation->addAction(tr("&Touch Mode"), QKeySequence(Qt::Key_T), this,
                                         [this](bool on) { setTouchMode(on); });
    mTouchAction->setCheckable(true);
    mTouchAction->setStatusTip(tr("The mouse steers the tool: left-drag presses the tissue, the wheel sets the "
                                  "depth; right-drag orbits, middle-drag pans, Shift+wheel zooms"));
    mTouchAction->setChecked(isMouseUri(mSession->deviceUri()));
    mViewport->setTouchMode(mTouchAction->isChecked());

    simulation->addSeparator();
    mRecording->addMenuActions(simulation);
    mDevices->addDeviceMenu(simulation);

    createExerciseMenu();

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About Palpate"), this, &MainWindow::showAbout);
    help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
    installFirstRunActions(*this, edit, help);  // Edit > Preferences…, Help > User Guide (F1), Welcome
}

void MainWindow::createStatusBar() {
    QStatusBar* bar = statusBar();
    mMeshLabel = new QLabel(bar);
    mMeshLabel->setObjectName(QStringLiteral("meshStatus"));
    bar->addWidget(mMeshLabel, 1);
    mRateLabel = addStatusField(bar, "hapticRateStatus", tr("Haptic ticks per second achieved by the loop thread"));
    mComputeLabel = addStatusField(bar, "tickComputeStatus", tr("Time spent in a haptic tick: the last one / the longest"));
    mJitterLabel = addStatusField(bar, "jitterStatus", tr("Lateness of the haptic thread's wake-up after its deadline: the last / the worst"));
    mOverrunLabel = addStatusField(bar, "overrunStatus",
                                   tr("Ticks that finished after the next deadline (and the deadlines skipped)"));
    mFifoLabel = addStatusField(bar, "schedFifoStatus", tr("Whether the haptic thread runs with SCHED_FIFO priority"));
    mFpsLabel = addStatusField(bar, "frameRateStatus", tr("Frames the viewport painted per second"));
    mDeviceLabel = addStatusField(bar, "deviceStatus", tr("The device URI and its state"));
    mContactLabel = addStatusField(bar, "contactStatus", tr("The tool is pressing the tissue"));
    mForceLabel = addStatusField(bar, "forceStatus", tr("Force sent to the device (after the safety filter)"));
    mRecordingLabel = addStatusField(bar, "recordingStatusField", tr("The session is being recorded, or a recording is played back"));
    mRecordingLabel->hide();
    mResultsLabel = addStatusField(bar, "resultsServerStatus",
                                   tr("Results kept on this workstation and copied to the class's server (Preferences)"));
    mResultsLabel->hide();
}

QString MainWindow::loadMesh(const QString& path, bool* deviceFailed) { return mMeshes->loadMesh(path, deviceFailed); }

std::optional<MeshUnit> MainWindow::rememberedMeshUnit(const QString& path) {
    return MeshOpener::rememberedMeshUnit(path);
}

void MainWindow::rememberMeshUnit(const QString& path, const MeshUnit& unit) {
    MeshOpener::rememberMeshUnit(path, unit);
}

QString MainWindow::openMeshFile(const QString& path) { return mMeshes->openMeshFile(path); }

MeshImportDialog* MainWindow::openImportDialog(const QString& path) { return mMeshes->openImportDialog(path); }

MeshImportDialog* MainWindow::importDialog() const { return mMeshes->importDialog(); }

QString MainWindow::meshDialogFolder() const { return MeshOpener::meshDialogFolder(); }

QStringList MainWindow::recentFiles() const { return MeshOpener::recentFiles(); }

void MainWindow::meshLoaded(const QString& path) {
    mTouchVertex = kNoVertex;  // a fresh device on another mesh: nothing is pressed
    // Another mesh than the level of detail's scene: its rings and knots were chosen for that
    // scene, and stay with it.
    if (mBeforeLodUse && !inLodScene(QFileInfo(path).absoluteFilePath()) && !inLodScene(path)) {
        const SlopeRingParams& before = mBeforeLodUse->preset.model.slopeRing;
        TissuePreset preset = mParameterPanel->preset();
        const int ringsUsed = preset.model.slopeRing.ringCount;
        preset.model.slopeRing.ringCount = before.ringCount;
        preset.model.slopeRing.stiffeningKnots = before.stiffeningKnots;
        preset.model.slopeRing.stiffeningForceN = before.stiffeningForceN;
        preset.model.slopeRing.stiffeningCompliance = before.stiffeningCompliance;
        mBeforeLodUse.reset();
        mLodPanel->setUseUndoable(false);
        mParameterPanel->setPreset(preset);
        if (applyPreset(preset).isEmpty() && ringsUsed != before.ringCount)
            statusBar()->showMessage(tr("Another mesh: the level of detail's %1 rings stay with its scene; %2 rings "
                                        "again")
                                         .arg(ringsUsed)
                                         .arg(before.ringCount),
                                     8000);
    }
    if (!mDevicePanel->isConnected()) {
        const QString uri = QString::fromStdString(mSession->deviceUri());
        std::string ignored;
        const auto device = createDeviceFromUri(mSession->deviceUri(), ignored);  // for its spec only
        mDevicePanel->setConnected(uri, device ? device->spec() : DeviceSpec{});
    }
    showDrawnMesh();  // the first mesh is drawn at once; a later one once the loop runs it
    showStatus();
}

QString MainWindow::startSession(const QString& meshPath, const QString& deviceUri, const QString& fallbackUri,
                                 QString& deviceProblem) {
    deviceProblem.clear();
    QString deviceError = setDeviceUri(deviceUri);  // before the first mesh the URI is only checked ...
    if (deviceError.isEmpty()) {
        bool deviceFailed = false;
        const QString error = loadMesh(meshPath, &deviceFailed);  // ... and the first mesh opens it
        if (error.isEmpty()) return {};
        if (!deviceFailed) return error;
        deviceError = error;
    }
    if (const QString error = setDeviceUri(fallbackUri); !error.isEmpty()) return error;
    if (const QString error = loadMesh(meshPath); !error.isEmpty()) return error;
    deviceProblem = tr("Cannot open the device %1: %2\nRunning with %3 instead: choose another in the Device dock or "
                       "in Edit > Preferences.")
                        .arg(deviceUri, deviceError, fallbackUri);
    mDevicePanel->showError(deviceProblem);
    mDeviceDock->show();
    mDeviceDock->raise();
    // Once the window is shown: a message shown before would be drawn over the mesh field, which only
    // a visible status bar hides for it.
    QTimer::singleShot(0, this, [this, deviceUri, fallbackUri] {
        statusBar()->showMessage(tr("Cannot open %1; running with %2").arg(deviceUri, fallbackUri), 30000);
    });
    return {};
}

QString MainWindow::setDeviceUri(const QString& uri) { return mDevices->setDeviceUri(uri); }

bool MainWindow::deviceOpening() const { return mDevices->opening(); }

void MainWindow::deviceSwitched(const QString& uri, bool ok) {
    if (ok) {
        mTouchVertex = kNoVertex;  // a fresh device: nothing is pressed
        setTouchMode(isMouseUri(uri.toStdString()));
    }
    showStatus();
}

QString MainWindow::restartSimulation() {
    mTouchVertex = kNoVertex;  // the fresh device's tool starts off the tissue
    return QString::fromStdString(mSession->restart());
}

void MainWindow::setTouchMode(bool on) {
    // Touch mode takes the left button back from the editor's placing (which then ends).
    if (on && mEditor && mEditor->placing() != ExerciseEditorPanel::Placing::None)
        mEditor->setPlacing(ExerciseEditorPanel::Placing::None);
    mViewport->setTouchMode(on);  // releases a touch in progress when turned off
    if (mTouchAction) mTouchAction->setChecked(on);
}

void MainWindow::touchVertex(VertexId v) {
    const auto& mesh = mSession->drawnMesh();
    if (!mSession->touchAvailable() || !mesh || v >= mesh->vertexCount()) return;
    mTouchVertex = v;
    // The editor's reachability check presses the same way (touchToolPositionMm).
    mSession->setTouchTarget(touchToolPositionMm(mesh->restPositionsMm()[v], mesh->restNormals()[v],
                                                 float(mSession->toolRadiusMm()), float(touchDepthMm())));
}

void MainWindow::releaseTouch() {
    mTouchVertex = kNoVertex;
    mSession->releaseTouch();
}

void MainWindow::advanceTicks(int ticks) {
    // An exercise starts its recording once the loop runs its scene: step to that tick first, so
    // that the ticks asked for are all recorded and scored.
    if (mExercises->phase() == ExerciseController::Phase::Starting && ticks > 0) {
        mSession->step(1);
        present(mSession->observe());
        mExercises->poll();
        --ticks;
    }
    mSession->step(ticks);
    present(mSession->observe());
    mExercises->poll();
    mSession->collectRetired();
    showStatus();
}

void MainWindow::setPlaying(bool playing) {
    mSession->setPaused(!playing);
    mPlayAction->setChecked(!playing);
}

void MainWindow::observeFrame() {
    present(mSession->observe());
    mExercises->poll();
}

void MainWindow::present(HapticSession::Observation observation) {
    if (observation == HapticSession::Observation::Nothing) return;
    if (mRecording->inPlayback()) return;  // the viewport shows the recording; backToLive() draws the live state again
    // A switch, or the first scene of a loop that an exercise (not loadMesh) created.
    if (observation == HapticSession::Observation::SceneSwitched || mSession->drawnMesh() != mShownMesh) showDrawnMesh();
    mViewport->setSnapshot(mSession->view());  // schedules the repaint
}

void MainWindow::showDrawnMesh() {
    if (mRecording->inPlayback()) return;  // the viewport shows the recording; backToLive() comes back here
    const auto& mesh = mSession->drawnMesh();
    if (!mesh || mesh == mShownMesh) return;  // a restart keeps the mesh: keep the camera too
    mShownMesh = mesh;
    mViewport->setMesh(*mesh);
    if (mEditor) mEditor->setDrawnMesh(mesh, QString::fromStdString(mSession->drawnPath()));
    mParameterPanel->refreshStabilityMargin();  // a mass-spring margin depends on the mesh
    updateLodScene();
    // Markers of another mesh mean nothing here: a running exercise sets its own again.
    if (!mExercises->running()) {
        mViewport->setExerciseMarkers({});
        showEditorMarkers();
        mExercises->followMesh(QString::fromStdString(mSession->drawnPath()));
    }
    updateChartsConfiguration();  // the highlight follows the mesh size
    setWindowTitle(QStringLiteral("Palpate - %1").arg(QFileInfo(QString::fromStdString(mSession->drawnPath())).fileName()));
}

void MainWindow::measureRates() {
    const ObservedLoop& o = mSession->observed();
    const std::uint64_t frames = mViewport->framesDrawn();
    if (mHaveRateBaseline) {
        const double tickSeconds = std::chrono::duration<double>(o.readAt - mRateBaselineReadAt).count();
        if (tickSeconds > 0.0) mHapticRateHz = double(o.counters.ticks - mRateBaselineTicks) / tickSeconds;
        const double frameSeconds = double(mFrameClock.nsecsElapsed()) * 1e-9;
        if (frameSeconds > 0.0) mFrameRateFps = double(frames - mRateBaselineFrames) / frameSeconds;
    } else {
        mHapticRateHz = o.counters.achievedRateHz;  // the loop's own average so far
    }
    mHaveRateBaseline = o.publishCount > 0;
    mRateBaselineTicks = o.counters.ticks;
    mRateBaselineReadAt = o.readAt;
    mRateBaselineFrames = frames;
    mFrameClock.restart();
    mSession->collectRetired();
    showStatus();
}

void MainWindow::showStatus() {
    updateDocks();
    mRecording->update();
    const QString renderer = rendererName(mViewport->kind());
    // In playback the viewport shows the recording's mesh: so does the status bar.
    const RecorderPanel& recorder = *mRecording->panel();
    const bool replayed = mRecording->inPlayback() && recorder.playbackMesh();
    const TissueMesh* mesh = replayed ? recorder.playbackMesh() : mSession->drawnMesh().get();
    if (!mesh) {
        mMeshLabel->setText(tr("No mesh, %1").arg(renderer));
        mMeshLabel->setMinimumWidth(0);
    } else {
        const QString path = replayed ? recorder.playbackMeshPath() : QString::fromStdString(mSession->drawnPath());
        // Name, size in mm and the file's unit: a mesh opened in the wrong unit shows at once.
        const MeshReport& report = mesh->report();
        QString shown = tr("%1 · %2").arg(QFileInfo(path).fileName(), meshSizeText(report.sizeMm));
        if (!report.unit.isMillimetres()) shown = tr("%1 · file in %2").arg(shown, QString::fromStdString(report.unit.text()));
        // Most important first: a narrow window cuts the end off, never the name, size and unit
        // (the loop's figures beside them are in the Status dock too).
        mMeshLabel->setText(tr("%1 · %2 vertices · %3").arg(shown).arg(mesh->vertexCount()).arg(renderer));
        mMeshLabel->setMinimumWidth(mMeshLabel->fontMetrics().horizontalAdvance(shown) + 8);
        mMeshLabel->setToolTip(tr("%1\n%2\n%3 vertices, %4 triangles\n%5 renderer")
                                   .arg(path, QString::fromStdString(report.unit.description()))
                                   .arg(mesh->vertexCount())
                                   .arg(mesh->triangleCount())
                                   .arg(renderer));
    }
    const ObservedLoop& o = mSession->observed();
    const LoopCounters& c = o.counters;
    const bool observed = o.publishCount > 0;
    // The loop's divergence guard zeroed the force and reset the tissue (docs/stability.md): say
    // what happened and what to change (the recording gets the event from the tick itself).
    if (c.divergences < mSeenDivergences) mSeenDivergences = 0;  // a new loop counts from zero
    if (c.divergences > mSeenDivergences) {
        mSeenDivergences = c.divergences;
        const QString what = tr("The tissue model diverged (%1) at tick %2: the force was zeroed and the tissue reset. %3")
                                 .arg(QString::fromUtf8(divergenceKindName(c.lastDivergence)))
                                 .arg(c.lastDivergenceTick)
                                 .arg(QString::fromUtf8(divergenceAdvice(c.lastDivergence)));
        statusBar()->showMessage(what, 20000);
    }
    if (!observed)
        mRateLabel->setText(tr("haptic -"));
    else if (mSession->mode() == LoopMode::Stepped)
        mRateLabel->setText(tr("haptic stepped (%1 Hz virtual)").arg(c.achievedRateHz, 0, 'f', 0));
    else
        mRateLabel->setText(tr("haptic %1 Hz").arg(mHapticRateHz, 0, 'f', 0));
    // Last/max, compact: the status bar is crowded. One decimal only where it says something.
    auto us = [](double v) { return QLocale().toString(v, 'f', v < 100.0 ? 1 : 0); };
    mComputeLabel->setText(tr("tick %1/%2 µs").arg(us(c.lastComputeUs), us(c.maxComputeUs)));
    mJitterLabel->setText(tr("jitter %1/%2 µs").arg(us(c.lastJitterUs), us(c.maxJitterUs)));
    mOverrunLabel->setText(tr("overruns %1 (missed %2)").arg(c.overruns).arg(c.missedDeadlines));
    mFifoLabel->setText(tr("SCHED_FIFO %1").arg(c.schedFifo ? tr("yes") : tr("no")));
    mFpsLabel->setText(tr("GUI %1 fps").arg(mFrameRateFps, 0, 'f', 0));
    // "mouse: Ready", not "mouse:: Ready": a URI's own trailing colon goes; the state in the
    // language the Device dock shows it in.
    QString uri = QString::fromStdString(mSession->deviceUri());
    if (uri.endsWith(QLatin1Char(':'))) uri.chop(1);
    mDeviceLabel->setText(tr("%1: %2").arg(uri, observed ? QCoreApplication::translate("palpate::DevicePanel",
                                                                                       deviceStateName(o.deviceState))
                                                         : tr("not started")));
    mContactLabel->setText(tr("contact: %1").arg(o.contact ? tr("yes") : tr("no")));
    // N or gf (Preferences); clamped to the device's maximum, the force felt is not the model's (docs/devices.md).
    mForceLabel->setText((o.safetyFlags & kSafetyClamped ? tr("force %1 (clipped at device max)") : tr("force %1"))
                             .arg(formatForce(double(glm::length(o.forceN)))));
}

QString MainWindow::statusText() const {
    QStringList parts{mMeshLabel->text()};
    for (const QLabel* label : {mRateLabel, mComputeLabel, mJitterLabel, mOverrunLabel, mFifoLabel, mFpsLabel,
                                mDeviceLabel, mContactLabel, mForceLabel})
        parts << label->text();
    return parts.join(QStringLiteral("   |   "));
}

RecorderPanel* MainWindow::recorderPanel() const { return mRecording->panel(); }

QString MainWindow::startRecording() { return mRecording->startRecording(); }

QString MainWindow::stopRecording() { return mRecording->stopRecording(); }

bool MainWindow::isRecording() const { return mSession->recording(); }

bool MainWindow::addRecordingMark(const QString& text) { return mRecording->addMark(text); }

void MainWindow::openRecording(const QString& path) { mRecording->openRecording(path); }

bool MainWindow::inPlayback() const { return mRecording->inPlayback(); }

void MainWindow::backToLive() { mRecording->backToLive(); }

void MainWindow::pauseForPlayback(const QString& path, bool fromLive) {
    if (fromLive) {
        mPlayingBeforePlayback = isPlaying();
        mTouchBeforePlayback = touchMode();
        setPlaying(false);  // the live session waits: the tissue relaxes and the force is zero
        setTouchMode(false);
    }
    mPlayAction->setEnabled(false);  // Space belongs to the recording now (on the dock's timeline)
    mTouchAction->setEnabled(false);
    mShownMesh.reset();  // backToLive() draws the live mesh again
    setWindowTitle(tr("Palpate - playing %1").arg(QFileInfo(path).fileName()));
}

void MainWindow::resumeLive() {
    mPlayAction->setEnabled(true);
    mTouchAction->setEnabled(true);
    setPlaying(mPlayingBeforePlayback);
    setTouchMode(mTouchBeforePlayback && mSession->touchAvailable());
    showDrawnMesh();
    mViewport->setSnapshot(mSession->view());
    if (!mSession->drawnMesh()) mViewport->clearMesh();
    showStatus();
}

void MainWindow::createExerciseDocks() {
    mTraineePanel = new TraineePanel(this);
    QScrollArea* scroll = scrolled(mTraineePanel, this);
    // Wrap, never clip: the panel is laid out to the dock's width (its labels wrap), and the dock
    // is never narrower than what the panel needs beside its scroll bar.
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);  // TraineePanel::event keeps it wide enough
    mExerciseDock = new QDockWidget(tr("Exercise"), this);
    mExerciseDock->setObjectName(QStringLiteral("exerciseDock"));
    mExerciseDock->setWidget(scroll);
    addDockWidget(Qt::LeftDockWidgetArea, mExerciseDock);

    mHistoryPanel = new HistoryPanel(this);
    mHistoryDock = new QDockWidget(tr("History"), this);
    mHistoryDock->setObjectName(QStringLiteral("historyDock"));
    mHistoryDock->setWidget(scrolled(mHistoryPanel, this));
    addDockWidget(Qt::LeftDockWidgetArea, mHistoryDock);
    tabifyDockWidget(mExerciseDock, mHistoryDock);
    mExerciseDock->raise();

    mExercises = new ExerciseController(
        *mSession, *mViewport, *mTraineePanel, *mHistoryPanel,
        [this] { return mRecording->panel()->recordingFolder(); }, this);
    connect(mExercises, &ExerciseController::runningChanged, this, &MainWindow::setExerciseRunning);
    connect(mExercises, &ExerciseController::message, this, [this](const QString& text) { statusBar()->showMessage(text, 8000); });
    connect(mExercises, &ExerciseController::finished, this, [this] {
        mExerciseDock->show();
        mExerciseDock->raise();
    });
    connect(mExercises, &ExerciseController::recordingStateChanged, mRecording,
            &RecordingController::showExerciseRecording);
    connect(mTraineePanel, &TraineePanel::newTraineeRequested, this, &MainWindow::newTraineeDialog);
    connect(mTraineePanel, &TraineePanel::openExerciseRequested, this, &MainWindow::openExerciseDialog);
    connect(mTraineePanel->scoreCard(), &ScoreCard::exportPdfRequested, this, &MainWindow::exportScorePdfDialog);
    connect(mTraineePanel->scoreCard(), &ScoreCard::historyRequested, this, [this] {
        mHistoryDock->show();
        mHistoryDock->raise();
    });
    connect(mHistoryPanel, &HistoryPanel::reportRequested, this, &MainWindow::exportResultPdfDialog);
    connect(mHistoryPanel, &HistoryPanel::replayRequested, this, [this](const QString& path) { openRecording(path); });

    mExercises->listExampleExercises();
    // The results database in the data folder; a failure is shown in the dock and nothing else
    // breaks (exercises still run and score; results are not kept).
    mExercises->openDatabase(ExerciseController::defaultDatabasePath());

    // The class's server (docs/results-store.md): each stored result is copied when it answers.
    mUploader = new ResultUploader(this);
    connect(mUploader, &ResultUploader::changed, this, [this] {
        const QString text = mUploader->statusText();
        mResultsLabel->setText(text);
        mResultsLabel->setVisible(!text.isEmpty());
        const SyncReport& last = mUploader->lastReport();
        // Who the server takes this workstation for (its role and class) and whether it is encrypted.
        QString tip = last.error.isEmpty()
                          ? tr("Results kept on this workstation and copied to %1 (%2)")
                                .arg(mUploader->serverUrl(), last.connection)
                          : tr("The last copy to %1 stopped: %2").arg(mUploader->serverUrl(), last.error);
        if (!last.refused.empty()) tip += QLatin1Char('\n') + last.refusedText();
        mResultsLabel->setToolTip(tip);
    });
    connect(mExercises, &ExerciseController::resultStored, mUploader, &ResultUploader::syncNow);
}

void MainWindow::createEditorDock() {
    mEditor = new ExerciseEditorPanel(findResource, this);
    mEditorDock = new QDockWidget(tr("Exercise Editor"), this);
    mEditorDock->setObjectName(QStringLiteral("exerciseEditorDock"));
    mEditorDock->setWidget(mEditor);
    addDockWidget(Qt::RightDockWidgetArea, mEditorDock);
    tabifyDockWidget(mChartsDock, mEditorDock);
    mParameterDock->raise();
    if (mSession->drawnMesh()) mEditor->setDrawnMesh(mSession->drawnMesh(), QString::fromStdString(mSession->drawnPath()));

    // The window's File menu owns Ctrl+O / Ctrl+S and Edit owns Ctrl+Z: the editor's own copies
    // would make those keys ambiguous. Its actions are in the Exercise menu instead.
    for (QAction* a : {mEditor->openAction(), mEditor->saveAction(), mEditor->saveAsAction(), mEditor->undoAction(),
                       mEditor->redoAction()})
        a->setShortcuts({});
    mEditor->saveAction()->setShortcut(QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_S));
    mEditor->saveAction()->setShortcutContext(Qt::WindowShortcut);

    mUndoGroup = new QUndoGroup(this);
    mUndoGroup->addStack(mParameterPanel->undoStack());
    mUndoGroup->addStack(mEditor->undoStack());
    mUndoGroup->setActiveStack(mParameterPanel->undoStack());
    mParameterPanel->undoAction()->setShortcuts({});
    mParameterPanel->redoAction()->setShortcuts({});
    // The stack of the panel the user works in is the one Edit > Undo acts on.
    mFocusConnection = connect(qApp, &QApplication::focusChanged, this, [this](QWidget*, QWidget* now) {
        for (QWidget* w = now; w; w = w->parentWidget()) {
            if (w == mEditor) return mUndoGroup->setActiveStack(mEditor->undoStack());
            if (w == mParameterPanel) return mUndoGroup->setActiveStack(mParameterPanel->undoStack());
        }
    });
    connect(mEditorDock, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible) mUndoGroup->setActiveStack(mEditor->undoStack());
        showEditorMarkers();
    });

    connect(mEditor, &ExerciseEditorPanel::placingChanged, this, [this](bool clickToPlace) {
        // Touch mode would take the left clicks (docs/user-guide.md): it waits while the editor
        // places points, and comes back after.
        if (clickToPlace) {
            mTouchBeforePlacing = touchMode();
            setTouchMode(false);
            mViewport->setPickHandler([this](VertexId v) { mEditor->vertexPicked(v); });
            statusBar()->showMessage(tr("Click the tissue to place; drag orbits; Esc stops placing"), 6000);
        } else {
            mViewport->setPickHandler({});
            setTouchMode(mTouchBeforePlacing && mSession->touchAvailable() && !mRecording->inPlayback());
        }
    });
    connect(mEditor, &ExerciseEditorPanel::markersChanged, this, [this](const ExerciseMarkers&) { showEditorMarkers(); });
    connect(mEditor, &ExerciseEditorPanel::meshRequested, this, [this](const QString& path) {
        if (mExercises->running()) {
            statusBar()->showMessage(tr("An exercise is running: the mesh cannot change now."), 6000);
            return;
        }
        // In the exercise's own unit (its "mesh_unit"), not the one remembered for the file.
        const QString error = mMeshes->finishLoad(path,
                                                  mSession->loadMesh(path.toStdString(), mEditor->exercise().meshUnit));
        if (!error.isEmpty()) QMessageBox::warning(this, tr("Cannot open mesh"), error);
    });
    connect(mEditor, &ExerciseEditorPanel::previewRequested, this, [this](const Exercise& exercise) {
        // Trying it is pressing as a trainee would: with the mouse in touch mode, unless a device
        // in someone's hand is connected (a script would press on its own).
        if (isScriptedUri(mSession->deviceUri()))
            if (const QString error = setDeviceUri(QLatin1String(HapticSession::kInteractiveDeviceUri)); !error.isEmpty())
                statusBar()->showMessage(error, 8000);
        if (const QString error = mExercises->startPreview(exercise); !error.isEmpty()) {
            QMessageBox::warning(this, tr("Cannot try the exercise"), error);
            return;
        }
        if (mSession->touchAvailable()) setTouchMode(true);
        // The instructor tries it beside the editor, in its tab group: a column of its own would
        // take a third of the viewport (docs/user-guide.md, "Try it").
        if (mMode == Mode::Instructor && mExerciseDock->isHidden() && !mEditorDock->isHidden()
            && !mEditorDock->isFloating())
            tabifyDockWidget(mEditorDock, mExerciseDock);
        mExerciseDock->show();
        mExerciseDock->raise();
    });
}

void MainWindow::showEditorMarkers() {
    // A running exercise (or its score) owns the markers; otherwise the editor's, while it shows.
    if (!mEditor || mExercises->running()) return;
    if (mEditorDock->isVisible())
        mViewport->setExerciseMarkers(mEditor->markers());
    else if (mExercises->phase() != ExerciseController::Phase::Finished)
        mViewport->setExerciseMarkers({});  // a finished exercise's markers stay beside its score card
}

void MainWindow::createLodDock() {
    mLodPanel = new LodPanel(this);
    mLodDock = new QDockWidget(tr("Level of Detail"), this);
    mLodDock->setObjectName(QStringLiteral("levelOfDetailDock"));
    mLodDock->setWidget(scrolled(mLodPanel, this));
    addDockWidget(Qt::RightDockWidgetArea, mLodDock);
    tabifyDockWidget(mChartsDock, mLodDock);
    mParameterDock->raise();
    connect(mLodPanel, &LodPanel::useRequested, this, [this](const QString& levelPath, int rings, bool overridden) {
        if (mExercises->running()) {
            statusBar()->showMessage(tr("An exercise is running: the model cannot change now."), 6000);
            return;
        }
        // The level's mesh (or the source again) and the ring count, as one new scene; what was
        // there before the first Use is kept for Undo use.
        const QString meshPath = levelPath.isEmpty() ? mLodPanel->meshPath() : levelPath;
        const QString meshBefore = QString::fromStdString(mSession->drawnPath());
        const std::size_t verticesBefore = mSession->drawnMesh() ? mSession->drawnMesh()->vertexCount() : 0;
        const TissuePreset presetBefore = mSession->preset();
        if (!mBeforeLodUse) mBeforeLodUse = BeforeLodUse{meshBefore, presetBefore, mLodPanel->meshPath()};
        if (QString::fromStdString(mSession->drawnPath()) != meshPath)
            if (const QString error = loadMesh(meshPath); !error.isEmpty()) {
                QMessageBox::warning(this, tr("Cannot use this level"), error);
                return;
            }
        TissuePreset preset = mParameterPanel->preset();
        preset.model.slopeRing.ringCount = rings;
        // Linear or stiffening tissue as the plan decided (docs/lod.md): the knots fitted to this
        // preset's |m1|, or none.
        QString tissue;
        if (const auto& choice = mLodPanel->stiffeningChoice(); choice && choice->error.empty() && mLodPanel->stiffeningReference()) {
            if (choice->nonlinear) {
                try {
                    applyStiffening(knotsFromCurve(mLodPanel->stiffeningReference()->curve, preset.model.slopeRing.slopeMagnitudeMmPerN[0]),
                                    preset.model.slopeRing);
                    tissue = tr(", %1 stiffening knots").arg(preset.model.slopeRing.stiffeningKnots);
                } catch (const std::invalid_argument& e) {
                    tissue = tr(", linear tissue (the knots do not fit this preset: %1)").arg(QString::fromUtf8(e.what()));
                }
            } else {
                preset.model.slopeRing.stiffeningKnots = 0;
                tissue = tr(", linear tissue");
            }
        }
        mParameterPanel->setPreset(preset);
        if (const QString error = applyPreset(preset); !error.isEmpty()) {
            QMessageBox::warning(this, tr("Cannot use this level"), error);
            return;
        }
        statusBar()->showMessage(overridden ? tr("Using your choice: %1, %2 rings (overrides the plan)")
                                                       .arg(QFileInfo(meshPath).fileName())
                                                       .arg(rings) + tissue
                                            : tr("Using the plan's choice: %1, %2 rings").arg(QFileInfo(meshPath).fileName()).arg(rings) +
                                                  tissue,
                                 8000);
        // What changed, said where it was asked for: mesh, rings, stiffening.
        QStringList changed;
        const std::size_t verticesNow = mSession->drawnMesh() ? mSession->drawnMesh()->vertexCount() : 0;
        if (meshPath != meshBefore)
            changed << tr("mesh %1 (%2 vertices) instead of %3 (%4)")
                           .arg(QFileInfo(meshPath).fileName())
                           .arg(verticesNow)
                           .arg(QFileInfo(meshBefore).fileName())
                           .arg(verticesBefore);
        if (rings != presetBefore.model.slopeRing.ringCount)
            changed << tr("%1 rings instead of %2").arg(rings).arg(presetBefore.model.slopeRing.ringCount);
        if (preset.model.slopeRing.stiffeningKnots != presetBefore.model.slopeRing.stiffeningKnots)
            changed << tr("%1 stiffening knots instead of %2")
                           .arg(preset.model.slopeRing.stiffeningKnots)
                           .arg(presetBefore.model.slopeRing.stiffeningKnots);
        mLodPanel->setUseUndoable(true, changed.isEmpty() ? tr("Nothing changed: the scene already ran this.")
                                                          : tr("Changed: %1. Undo use goes back; opening another "
                                                               "mesh drops these rings and knots.")
                                                                .arg(changed.join(QStringLiteral("; "))));
    });
    connect(mLodPanel, &LodPanel::undoUseRequested, this, &MainWindow::undoLodUse);
    connect(mLodPanel, &LodPanel::storeNeedsRequested, this, [this](const LodNeeds& needs) {
        TissuePreset preset = mParameterPanel->preset();
        preset.needs = needs;
        mParameterPanel->setPreset(preset);
        statusBar()->showMessage(tr("Targets stored in the preset: save it (File > Save Preset) to keep them"), 8000);
    });
    updateLodScene();
}

bool MainWindow::inLodScene(const QString& path) const {
    if (!mBeforeLodUse || mBeforeLodUse->lodSource.isEmpty()) return false;
    return path == mBeforeLodUse->lodSource || path.startsWith(mBeforeLodUse->lodSource + QStringLiteral(".levels/"));
}

void MainWindow::undoLodUse() {
    if (!mBeforeLodUse) return;
    if (mExercises->running()) {
        statusBar()->showMessage(tr("An exercise is running: the model cannot change now."), 6000);
        return;
    }
    const BeforeLodUse before = *mBeforeLodUse;
    if (QString::fromStdString(mSession->drawnPath()) != before.meshPath && !before.meshPath.isEmpty())
        if (const QString error = loadMesh(before.meshPath); !error.isEmpty()) {
            QMessageBox::warning(this, tr("Cannot undo the use"), error);
            return;
        }
    mBeforeLodUse.reset();
    mParameterPanel->setPreset(before.preset);
    if (const QString error = applyPreset(before.preset); !error.isEmpty()) {
        QMessageBox::warning(this, tr("Cannot undo the use"), error);
        return;
    }
    mLodPanel->setUseUndoable(false);
    statusBar()->showMessage(tr("Back to %1 with %2 rings, as before the level of detail was used")
                                 .arg(QFileInfo(before.meshPath).fileName())
                                 .arg(before.preset.model.slopeRing.ringCount),
                             8000);
}

void MainWindow::updateLodScene() {
    if (!mLodPanel) return;
    const auto& mesh = mSession->drawnMesh();
    const QString path = QString::fromStdString(mSession->drawnPath());
    // A level the panel made (in "<source>.levels/") is a choice within the panel's scene, not a new scene.
    const bool ownLevel = !mLodPanel->meshPath().isEmpty() &&
                          path.startsWith(mLodPanel->meshPath() + QStringLiteral(".levels/"));
    std::optional<LodNeeds> needs = mSession->preset().needs;
    QString source = needs ? tr("the tissue preset") : QString();
    const ExerciseAssets* exercise = mExercises && mExercises->assets() ? &*mExercises->assets() : nullptr;
    if (exercise && exercise->exercise.needs && mSession->exercisePhysics() == exercise->geometry) {
        needs = exercise->exercise.needs;
        source = tr("exercise '%1'").arg(QString::fromStdString(exercise->exercise.name));
    }
    mLodPanel->setToolContact(ParameterPanel::toolContactOf(mSession->preset()));
    mLodPanel->setSceneDemands(exercise && mSession->exercisePhysics() == exercise->geometry ? exerciseDemands(exercise->exercise)
                                                                                           : std::vector<ExerciseDemand>{});
    if (!ownLevel && mesh) mLodSceneMesh = mesh;  // the source the levels are made from
    mLodPanel->setScene(ownLevel || !mesh ? mLodPanel->meshPath() : path, mLodSceneMesh, needs, source);
}

void MainWindow::createExerciseMenu() {
    QMenu* menu = menuBar()->addMenu(tr("E&xercise"));
    menu->addAction(tr("&Start"), QKeySequence(Qt::Key_F6), this, [this] {
        if (const QString error = mExercises->start(); !error.isEmpty()) {
            mTraineePanel->setMessage(error);
            statusBar()->showMessage(error, 8000);
        }
    });
    menu->addAction(tr("S&top"), QKeySequence(Qt::SHIFT | Qt::Key_F6), this, [this] { mExercises->stop(); });
    menu->addAction(tr("&Finish Examination"), QKeySequence(Qt::Key_F7), this, [this] {
        if (!mExercises->finishExamination())
            statusBar()->showMessage(tr("Finish ends a running detect-lumps examination"), 4000);
    });
    menu->addSeparator();
    menu->addAction(tr("&Open Exercise…"), this, &MainWindow::openExerciseDialog);
    menu->addAction(tr("&New Trainee…"), this, &MainWindow::newTraineeDialog);
    menu->addAction(tr("&Export Score Report (PDF)…"), this, &MainWindow::exportScorePdfDialog);
    menu->addAction(tr("&Class View…"), this, [this] {
        // Every trainee of the class: this workstation's results, or the class's server's.
        auto* dialog = new ClassDialog(mExercises->database().path(), Preferences::load().resultsServer,
                                       QFileInfo(QString::fromStdString(findResource("exercises/press_targets.json")))
                                           .absolutePath(),
                                       this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->show();
    });
    menu->addAction(tr("&History"), QKeySequence(Qt::CTRL | Qt::Key_H), this, [this] {
        mHistoryDock->show();
        mHistoryDock->raise();
    });
    menu->addSeparator();
    QMenu* author = menu->addMenu(tr("&Author"));
    author->addActions(mEditor->editorActions());
    menu->addSeparator();
    mModeGroup = new QActionGroup(this);
    mInstructorAction = menu->addAction(tr("&Instructor Mode"), QKeySequence(Qt::CTRL | Qt::Key_1), this,
                                        [this] { setMode(Mode::Instructor); });
    mTraineeAction = menu->addAction(tr("&Trainee Mode"), QKeySequence(Qt::CTRL | Qt::Key_2), this,
                                     [this] { setMode(Mode::Trainee); });
    for (QAction* a : {mInstructorAction, mTraineeAction}) {
        a->setCheckable(true);
        mModeGroup->addAction(a);
    }
    mInstructorAction->setChecked(mMode == Mode::Instructor);
    mTraineeAction->setChecked(mMode == Mode::Trainee);
}

void MainWindow::setMode(Mode mode) {
    mMode = mode;
    const bool instructor = mode == Mode::Instructor;
    // A trainee's Exercise dock is beside History, where Try it may have taken it from.
    if (!instructor && tabifiedDockWidgets(mExerciseDock).contains(mEditorDock)) {
        addDockWidget(Qt::LeftDockWidgetArea, mExerciseDock);
        tabifyDockWidget(mExerciseDock, mHistoryDock);
    }
    // Trainees get the exercise and their history; the tissue's parameters and the charts are the
    // instructor's (a trainee must not make the task easier).
    mParameterDock->setVisible(instructor);
    mChartsDock->setVisible(instructor);
    mEditorDock->setVisible(instructor);
    mLodDock->setVisible(instructor);
    // The Exercise dock is the trainee's; an instructor sees it while trying an exercise (Try it).
    mExerciseDock->setVisible(!instructor || mExercises->running());
    mHistoryDock->setVisible(!instructor);
    if (!instructor) mExerciseDock->raise();
    else mParameterDock->raise();  // the instructor's first tool
    if (mInstructorAction) mInstructorAction->setChecked(instructor);
    if (mTraineeAction) mTraineeAction->setChecked(!instructor);
    // Another person at the window: the instructor's draft (its lumps, its targets) is never shown
    // to a trainee, nor a finished exercise's overlay (revealed lumps, heat map) to the next one.
    if (!mExercises->running())
        mViewport->setExerciseMarkers(instructor && mEditor && mEditorDock->isVisible() ? mEditor->markers()
                                                                                        : ExerciseMarkers{});
}

void MainWindow::setExerciseRunning(bool running) {
    mParameterPanel->setEnabled(!running);
    mDevices->setSwitchingEnabled(!running);
    if (mOpenMeshAction) mOpenMeshAction->setEnabled(!running);
    if (mImportMeshAction) mImportMeshAction->setEnabled(!running);
    if (mRestartAction) mRestartAction->setEnabled(!running);
    if (running) {
        // The panel shows the exercise's tissue (it cannot be changed until the end).
        mParameterPanel->setPreset(mSession->preset());
        updateChartsConfiguration();
    }
    mRecording->update();
}

void MainWindow::newTraineeDialog() {
    bool ok = false;
    const QString name = QInputDialog::getText(this, tr("New Trainee"), tr("Name:"), QLineEdit::Normal, QString(), &ok);
    if (!ok || name.trimmed().isEmpty()) return;
    if (const QString error = mExercises->addTrainee(name); !error.isEmpty())
        QMessageBox::warning(this, tr("Trainee not added"), error);
}

void MainWindow::openExerciseDialog() {
    const QString start = QFileInfo(QString::fromStdString(findResource("exercises/press_targets.json"))).absolutePath();
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Exercise"), start,
                                                      tr("Exercises and bundles (*.json *.palpex)"));
    if (path.isEmpty()) return;
    if (const QString error = mExercises->addExerciseFile(path); !error.isEmpty())
        QMessageBox::warning(this, tr("Not an exercise"), error);
}

void MainWindow::exportScorePdfDialog() {
    if (!mExercises->lastReport()) {
        statusBar()->showMessage(tr("There is no score to export yet: run an exercise first."), 5000);
        return;
    }
    const QString suggested = QDir(mRecording->panel()->recordingFolder())
                                  .filePath(QFileInfo(mExercises->lastRecordingPath()).completeBaseName() +
                                            QStringLiteral(".pdf"));
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Score Report"), suggested, tr("PDF (*.pdf)"));
    if (path.isEmpty()) return;
    if (const QString error = mExercises->exportLastReportPdf(path); !error.isEmpty())
        QMessageBox::warning(this, tr("Report not written"), error);
    else
        statusBar()->showMessage(tr("Report written: %1").arg(QDir::toNativeSeparators(path)), 8000);
}

void MainWindow::exportResultPdfDialog(const ResultRecord& result) {
    const QString suggested = QFileInfo(result.recordingPath).absoluteDir().filePath(
        QFileInfo(result.recordingPath).completeBaseName() + QStringLiteral(".pdf"));
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Score Report"), suggested, tr("PDF (*.pdf)"));
    if (path.isEmpty()) return;
    if (const QString error = mExercises->exportResultPdf(result, path); !error.isEmpty())
        QMessageBox::warning(this, tr("Report not written"), error);
    else
        statusBar()->showMessage(tr("Report written: %1").arg(QDir::toNativeSeparators(path)), 8000);
}

QString MainWindow::runExercise(const QString& path, const QString& trainee) {
    // Every message names its file: the exercise's, or the results database's (addTrainee).
    const auto naming = [&path](const QString& error) {
        return error.isEmpty() || error.contains(path) ? error : path + QStringLiteral(": ") + error;
    };
    if (!trainee.trimmed().isEmpty()) {
        if (QString error = mExercises->addExerciseFile(path); !error.isEmpty()) return naming(error);
        if (QString error = mExercises->addTrainee(trainee); !error.isEmpty()) return error;
        return naming(mExercises->start());
    }
    const auto loaded = guardedLoad(path.toStdString(), [&] { return loadExercise(path.toStdString()); });
    if (!loaded.exercise) {
        QStringList errors;
        for (const auto& e : loaded.errors) errors << QString::fromStdString(e);
        return naming(errors.join(QLatin1Char('\n')));
    }
    return naming(mExercises->startPreview(*loaded.exercise));
}

}  // namespace palpate
