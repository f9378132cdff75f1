#include "app/gui/MainWindow.h"

#include <QAction>
#include <QApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QKeySequence>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>

#include <glm/geometric.hpp>

namespace palpate {

MainWindow::MainWindow(RendererChoice renderer, QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(QStringLiteral("Palpate"));
    mViewport = createViewport(renderer, this, &mRendererReason);
    setCentralWidget(mViewport->widget());
    mStatusLabel = new QLabel(this);
    statusBar()->addWidget(mStatusLabel, 1);
    createMenus();

    // Stand-in for the haptic thread (a later issue): the GUI thread steps the deformer itself,
    // kTicksPerFrame ticks per frame, and then repaints. Once the engine runs its own 1 kHz loop,
    // this timer will only read the newest snapshot.
    mFrameTimer.setTimerType(Qt::PreciseTimer);
    mFrameTimer.setInterval(kFrameIntervalMs);
    connect(&mFrameTimer, &QTimer::timeout, this, [this] { advanceTicks(kTicksPerFrame); });
    showSimulationState();
}

MainWindow::~MainWindow() = default;

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
    mPlayAction = simulation->addAction(tr("&Play"), QKeySequence(Qt::Key_Space), this,
                                        [this](bool on) { setPlaying(on); });
    mPlayAction->setCheckable(true);
    simulation->addAction(tr("R&eset"), this, &MainWindow::resetSimulation);
}

QString MainWindow::loadMesh(const QString& path) {
    auto outcome = SceneSimulation::load(path.toStdString());
    if (!outcome.simulation) {
        const QString error = QString::fromStdString(outcome.error);
        // The engine's messages name the file; make sure ours always do.
        return error.contains(path) ? error : path + QStringLiteral(": ") + error;
    }
    mSimulation = std::move(outcome.simulation);
    mViewport->setMesh(mSimulation->mesh());
    setWindowTitle(QStringLiteral("Palpate - %1").arg(QFileInfo(path).fileName()));
    showSimulationState();
    return {};
}

void MainWindow::advanceTicks(int ticks) {
    if (!mSimulation) return;
    mSimulation->advance(ticks);
    showSimulationState();
}

void MainWindow::setPlaying(bool playing) {
    if (playing && mSimulation)
        mFrameTimer.start();
    else
        mFrameTimer.stop();
    mPlayAction->setChecked(mFrameTimer.isActive());
    mPlayAction->setText(mFrameTimer.isActive() ? tr("&Pause") : tr("&Play"));
}

void MainWindow::resetSimulation() {
    if (!mSimulation) return;
    mSimulation->reset();
    showSimulationState();
}

void MainWindow::openMeshDialog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Mesh"), QString(),
                                                      tr("Meshes (*.obj *.off *.ply *.stl *.om);;All files (*)"));
    if (path.isEmpty()) return;
    const QString error = loadMesh(path);
    // The error names the file and every problem found.
    if (!error.isEmpty()) QMessageBox::warning(this, tr("Cannot open mesh"), error);
}

void MainWindow::showSimulationState() {
    if (mSimulation) {
        mSimulation->fillSnapshot(mSnapshot);
        mViewport->setSnapshot(mSnapshot);
    }
    mStatusLabel->setText(statusText());
}

QString MainWindow::statusText() const {
    const QString renderer = rendererName(mViewport->kind());
    if (!mSimulation) return tr("No mesh   |   %1").arg(renderer);
    const TissueMesh& mesh = mSimulation->mesh();
    const TickResult& tick = mSimulation->lastTick();
    return tr("%1   |   %2 vertices, %3 triangles   |   %4   |   contact: %5   |   force %6 N")
        .arg(QFileInfo(QString::fromStdString(mSimulation->path())).fileName())
        .arg(mesh.vertexCount())
        .arg(mesh.triangleCount())
        .arg(renderer)
        .arg(tick.contact ? tr("yes") : tr("no"))
        .arg(double(glm::length(tick.forceN)), 0, 'f', 2);
}

}  // namespace palpate
