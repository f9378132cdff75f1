#pragma once
// The milestone's main window: the viewport in the centre, menus, and a status bar with the mesh,
// the renderer, the contact and the force. Docks (parameters, device, recorder...) come later.

#include "app/gui/SceneSimulation.h"
#include "widgets/ViewportFactory.h"

#include <QMainWindow>
#include <QString>
#include <QTimer>

#include <memory>

class QAction;
class QLabel;

namespace palpate {

class MainWindow final : public QMainWindow {
    Q_OBJECT
public:
    /// Haptic ticks simulated per displayed frame: 16 ticks of 1 ms at ~60 frames per second keeps
    /// the scripted tool moving at about real time.
    static constexpr int kTicksPerFrame = 16;
    static constexpr int kFrameIntervalMs = 16;

    explicit MainWindow(RendererChoice renderer, QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Loads `path` and makes it the scene. On failure the current scene stays and the error (naming
    /// the file and the problem) is returned; "" on success. Shows no dialog.
    QString loadMesh(const QString& path);
    /// Runs `ticks` simulation ticks now and shows the result (what the frame timer does, and --ticks).
    void advanceTicks(int ticks);
    void setPlaying(bool playing);
    bool isPlaying() const { return mFrameTimer.isActive(); }

    Viewport* viewport() const { return mViewport; }
    /// Why this renderer was chosen (for the log).
    const QString& rendererReason() const { return mRendererReason; }
    QString statusText() const;

private slots:
    void openMeshDialog();
    void resetSimulation();

private:
    void createMenus();
    void showSimulationState();

    Viewport* mViewport = nullptr;  // owned by Qt as the central widget
    QString mRendererReason;
    std::unique_ptr<SceneSimulation> mSimulation;
    SceneSnapshot mSnapshot;  // reused every frame
    QTimer mFrameTimer;
    QLabel* mStatusLabel = nullptr;
    QAction* mPlayAction = nullptr;
    QAction* mWireframeAction = nullptr;
};

}  // namespace palpate
