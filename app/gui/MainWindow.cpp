#include "app/gui/MainWindow.h"

#include "device/DeviceUri.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QKeySequence>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>

namespace palpate {

namespace {

/// The simulated devices the Device menu offers (listDeviceSchemes() also has forms that need an
/// argument, or a viewport that steers them).
constexpr std::array<const char*, 4> kMenuDevices = {"sim:press", "sim:stroke", "sim:scan", "sim:sine"};

QLabel* addStatusField(QStatusBar* bar, const char* objectName, const QString& toolTip) {
    auto* label = new QLabel(bar);
    label->setObjectName(QLatin1String(objectName));
    label->setToolTip(toolTip);
    label->setContentsMargins(4, 0, 0, 0);
    bar->addPermanentWidget(label);
    return label;
}

}  // namespace

MainWindow::MainWindow(RendererChoice renderer, LoopMode mode, QWidget* parent)
    : QMainWindow(parent), mSession(std::make_unique<HapticSession>(mode)) {
    setWindowTitle(QStringLiteral("Palpate"));
    mViewport = createViewport(renderer, this, &mRendererReason);
    setCentralWidget(mViewport->widget());
    createStatusBar();
    createMenus();

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
    mFrameTimer.stop();
    mStatusTimer.stop();
    mSession->stop();  // joins the haptic thread: from here on nothing runs behind our back
}

void MainWindow::closeEvent(QCloseEvent* event) {
    shutDown();
    QMainWindow::closeEvent(event);
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open = file->addAction(tr("&Open Mesh…"), this, &MainWindow::openMeshDialog);
    open->setShortcut(QKeySequence::Open);
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Q));  // QKeySequence::Quit is empty on some platforms

    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addAction(tr("&Reset Camera"), QKeySequence(Qt::Key_R), this, [this] { mViewport->resetCamera(); });
    view->addAction(tr("&Fit"), QKeySequence(Qt::Key_F), this, [this] { mViewport->fitCamera(); });
    mWireframeAction = view->addAction(tr("&Wireframe"), QKeySequence(Qt::Key_W), this,
                                       [this](bool on) { mViewport->setWireframe(on); });
    mWireframeAction->setCheckable(true);
    mWireframeAction->setChecked(mViewport->wireframe());

    QMenu* simulation = menuBar()->addMenu(tr("&Simulation"));
    mPlayAction = simulation->addAction(tr("&Pause"), QKeySequence(Qt::Key_Space), this,
                                        [this](bool on) { setPlaying(on); });
    mPlayAction->setCheckable(true);
    mPlayAction->setChecked(isPlaying());
    simulation->addAction(tr("&Restart"), QKeySequence(Qt::CTRL | Qt::Key_R), this, [this] {
        if (const QString error = restartSimulation(); !error.isEmpty())
            QMessageBox::warning(this, tr("Cannot restart"), error);
    });

    QMenu* devices = simulation->addMenu(tr("&Device"));
    mDeviceGroup = new QActionGroup(this);
    mDeviceGroup->setExclusive(true);
    for (const DeviceSchemeInfo& scheme : listDeviceSchemes()) {
        if (std::find(kMenuDevices.begin(), kMenuDevices.end(), scheme.uri) == kMenuDevices.end()) continue;
        const QString uri = QString::fromStdString(scheme.uri);
        QAction* action = devices->addAction(uri);
        action->setCheckable(true);
        action->setData(uri);
        action->setStatusTip(QString::fromStdString(scheme.description));
        action->setToolTip(QString::fromStdString(scheme.description));
        mDeviceGroup->addAction(action);
        connect(action, &QAction::triggered, this, [this, uri] {
            if (const QString error = setDeviceUri(uri); !error.isEmpty()) {
                QMessageBox::warning(this, tr("Cannot switch the device"), error);
                checkCurrentDevice();
            }
        });
    }
    checkCurrentDevice();
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
}

void MainWindow::checkCurrentDevice() {
    const QString current = QString::fromStdString(mSession->deviceUri());
    // None is checked for a URI the menu does not list (e.g. sim:path:FILE from --device).
    for (QAction* action : mDeviceGroup->actions()) action->setChecked(action->data().toString() == current);
}

QString MainWindow::loadMesh(const QString& path) {
    const std::string error = mSession->loadMesh(path.toStdString());
    if (!error.empty()) return QString::fromStdString(error);
    showDrawnMesh();  // the first mesh is drawn at once; a later one once the loop runs it
    showStatus();
    return {};
}

QString MainWindow::setDeviceUri(const QString& uri) {
    const std::string error = mSession->setDevice(uri.toStdString());
    checkCurrentDevice();
    showStatus();
    return QString::fromStdString(error);
}

QString MainWindow::restartSimulation() { return QString::fromStdString(mSession->restart()); }

void MainWindow::advanceTicks(int ticks) {
    mSession->step(ticks);
    present(mSession->observe());
    mSession->collectRetired();
    showStatus();
}

void MainWindow::setPlaying(bool playing) {
    mSession->setPaused(!playing);
    mPlayAction->setChecked(playing);
    mPlayAction->setText(playing ? tr("&Pause") : tr("&Play"));
}

void MainWindow::observeFrame() { present(mSession->observe()); }

void MainWindow::present(HapticSession::Observation observation) {
    if (observation == HapticSession::Observation::Nothing) return;
    if (observation == HapticSession::Observation::SceneSwitched) showDrawnMesh();
    mViewport->setSnapshot(mSession->view());  // schedules the repaint
}

void MainWindow::showDrawnMesh() {
    const auto& mesh = mSession->drawnMesh();
    if (!mesh || mesh == mShownMesh) return;  // a restart keeps the mesh: keep the camera too
    mShownMesh = mesh;
    mViewport->setMesh(*mesh);
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
    const QString renderer = rendererName(mViewport->kind());
    const auto& mesh = mSession->drawnMesh();
    if (!mesh) {
        mMeshLabel->setText(tr("No mesh, %1").arg(renderer));
    } else {
        const QString path = QString::fromStdString(mSession->drawnPath());
        mMeshLabel->setText(
            tr("%1, %2 vertices, %3").arg(QFileInfo(path).fileName()).arg(mesh->vertexCount()).arg(renderer));
        mMeshLabel->setToolTip(tr("%1\n%2 vertices, %3 triangles\n%4 renderer")
                                   .arg(path)
                                   .arg(mesh->vertexCount())
                                   .arg(mesh->triangleCount())
                                   .arg(renderer));
    }
    const ObservedLoop& o = mSession->observed();
    const LoopCounters& c = o.counters;
    const bool observed = o.publishCount > 0;
    if (!observed)
        mRateLabel->setText(tr("haptic -"));
    else if (mSession->mode() == LoopMode::Stepped)
        mRateLabel->setText(tr("haptic stepped (%1 Hz virtual)").arg(c.achievedRateHz, 0, 'f', 0));
    else
        mRateLabel->setText(tr("haptic %1 Hz").arg(mHapticRateHz, 0, 'f', 0));
    // Last/max, compact: the status bar is crowded. One decimal only where it says something.
    auto us = [](double v) { return QString::number(v, 'f', v < 100.0 ? 1 : 0); };
    mComputeLabel->setText(tr("tick %1/%2 µs").arg(us(c.lastComputeUs), us(c.maxComputeUs)));
    mJitterLabel->setText(tr("jitter %1/%2 µs").arg(us(c.lastJitterUs), us(c.maxJitterUs)));
    mOverrunLabel->setText(tr("overruns %1 (missed %2)").arg(c.overruns).arg(c.missedDeadlines));
    mFifoLabel->setText(tr("SCHED_FIFO %1").arg(c.schedFifo ? tr("yes") : tr("no")));
    mFpsLabel->setText(tr("GUI %1 fps").arg(mFrameRateFps, 0, 'f', 0));
    mDeviceLabel->setText(tr("%1: %2")
                              .arg(QString::fromStdString(mSession->deviceUri()),
                                   observed ? QString::fromLatin1(deviceStateName(o.deviceState)) : tr("not started")));
    mContactLabel->setText(tr("contact: %1").arg(o.contact ? tr("yes") : tr("no")));
    mForceLabel->setText(tr("force %1 N").arg(double(glm::length(o.forceN)), 0, 'f', 2));
}

QString MainWindow::statusText() const {
    QStringList parts{mMeshLabel->text()};
    for (const QLabel* label : {mRateLabel, mComputeLabel, mJitterLabel, mOverrunLabel, mFifoLabel, mFpsLabel,
                                mDeviceLabel, mContactLabel, mForceLabel})
        parts << label->text();
    return parts.join(QStringLiteral("   |   "));
}

void MainWindow::openMeshDialog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Mesh"), QString(),
                                                      tr("Meshes (*.obj *.off *.ply *.stl *.om);;All files (*)"));
    if (path.isEmpty()) return;
    const QString error = loadMesh(path);
    // The error names the file and every problem found.
    if (!error.isEmpty()) QMessageBox::warning(this, tr("Cannot open mesh"), error);
}

}  // namespace palpate
