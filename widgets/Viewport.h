#pragma once
// The viewport behind one interface, with an OpenGL and a QPainter implementation (MeshViewport,
// SoftwareViewport): where there is no OpenGL (Qt's offscreen platform, tests) the same scene,
// camera and markers are drawn in software. The scene, camera and mouse handling live here, shared.

#include "widgets/ExerciseMarkers.h"
#include "widgets/OrbitCamera.h"
#include "widgets/RenderScene.h"

#include <QImage>
#include <QPoint>
#include <QPointF>
#include <QSize>
#include <QString>

#include <cstdint>
#include <functional>
#include <optional>

class QMouseEvent;
class QWheelEvent;
class QWidget;

namespace palpate {

enum class RendererKind { OpenGL, Software };

QString rendererName(RendererKind kind);

class Viewport {
public:
    virtual ~Viewport() = default;

    /// The widget to put in a layout; it owns this viewport (delete the widget, not the interface).
    virtual QWidget* widget() = 0;
    virtual RendererKind kind() const = 0;
    /// Renders the current scene into an image of the widget's size (what --screenshot saves).
    virtual QImage grabImage() = 0;

    /// Shows a new mesh at rest and frames it. The viewport keeps a copy; `mesh` may go away.
    void setMesh(const TissueMesh& mesh);
    void clearMesh();
    /// The newest simulation state: deformed positions, tool, contact, force.
    void setSnapshot(const SceneSnapshot& snapshot);

    void setWireframe(bool on);
    bool wireframe() const { return mWireframe; }
    /// Draws the rest shape as a translucent ghost where the tissue is pushed away from it.
    void setShowRestGhost(bool on);
    bool showRestGhost() const { return mShowRestGhost; }
    /// Default view angles, framing the mesh (undoes pans).
    void resetCamera();
    /// Frames the mesh from the current angles (undoes pans).
    void fitCamera();

    /// The vertex under `pixel` (widget coordinates, logical pixels): the nearest triangle the ray
    /// through the pixel's centre hits, and its corner nearest to the hit. The same camera and
    /// positions in both renderers, so both pick the same vertex. nullopt over the background.
    std::optional<VertexId> pickVertex(QPoint pixel);
    /// The same for a point in a viewport of `sizePx` (sub-pixel: no half-pixel shift is added).
    std::optional<VertexId> pickVertexAt(QPointF pointPx, QSize sizePx) const;

    /// Touch mode: the mouse steers the virtual tool. A left press or drag over the mesh calls
    /// TouchHandlers::moved with the vertex under the mouse (picked on the drawn, deformed positions),
    /// the left release calls released; right-drag orbits, middle-drag pans, the wheel changes the
    /// press depth (kTouchDepthStepMm a notch, forward is deeper) and Shift+wheel zooms.
    struct TouchHandlers {
        std::function<void(VertexId, QPointF)> moved;
        std::function<void()> released;
        std::function<void(double depthMm)> depthChanged;
    };
    static constexpr double kDefaultTouchDepthMm = 3.0;
    static constexpr double kMaxTouchDepthMm = 10.0;
    static constexpr double kTouchDepthStepMm = 0.5;
    void setTouchHandlers(TouchHandlers handlers) { mTouchHandlers = std::move(handlers); }
    /// Leaving touch mode while pressing releases the touch.
    void setTouchMode(bool on);
    bool touchMode() const { return mTouchMode; }
    /// The left button is down in touch mode.
    bool touching() const { return mTouching; }
    /// Clamped to 0..kMaxTouchDepthMm; calls depthChanged when the depth changes.
    void setTouchDepthMm(double depthMm);
    double touchDepthMm() const { return mTouchDepthMm; }

    /// An exercise's markers (targets, path, inclusion, the trainee's mark) drawn over the mesh.
    void setExerciseMarkers(ExerciseMarkers markers);
    const ExerciseMarkers& exerciseMarkers() const { return mExerciseMarkers; }
    /// The tissue surface's opacity: style::kSeeThroughOpacity while the markers show a lump inside
    /// the tissue (the instructor's see-through view), else 1.
    float surfaceOpacity() const;

    /// Click-to-place (the instructor's exercise editor): while a handler is set, a left click
    /// that does not drag (less than kClickSlopPx) picks the vertex under it and calls the handler
    /// with it; a drag still orbits. Touch mode takes precedence. An empty function turns it off.
    static constexpr double kClickSlopPx = 4.0;
    void setPickHandler(std::function<void(VertexId)> handler) { mPickHandler = std::move(handler); }
    bool pickHandlerSet() const { return bool(mPickHandler); }

    const OrbitCamera& camera() const { return mCamera; }
    const RenderScene& scene() const { return mScene; }
    /// Frames painted so far (on screen or grabbed): the window divides it by time for its fps.
    std::uint64_t framesDrawn() const { return mFramesDrawn; }

protected:
    /// Schedules a repaint. `topologyChanged`: the triangles changed (GPU buffers must be rebuilt).
    virtual void sceneChanged(bool topologyChanged) = 0;

    // Event helpers for the widgets: left-drag orbits, right- or middle-drag pans, the wheel zooms
    // (touch mode: see TouchHandlers). Each returns whether the view changed (the widget then repaints).
    bool handleMousePress(const QMouseEvent& event);
    bool handleMouseMove(const QMouseEvent& event);
    bool handleMouseRelease(const QMouseEvent& event);
    bool handleWheel(const QWheelEvent& event);

    /// The widgets call this once per painted frame.
    void countFrame() { ++mFramesDrawn; }

    RenderScene mScene;
    OrbitCamera mCamera;
    bool mWireframe = true;
    bool mShowRestGhost = false;
    ExerciseMarkers mExerciseMarkers;

private:
    void touchAt(QPointF pointPx);

    QPointF mLastDragPx;
    TouchHandlers mTouchHandlers;
    std::function<void(VertexId)> mPickHandler;
    QPointF mPressPx;
    bool mClickCandidate = false;  // a left press with a pick handler that has not dragged yet
    bool mTouchMode = false;
    bool mTouching = false;
    double mTouchDepthMm = kDefaultTouchDepthMm;
    std::uint64_t mFramesDrawn = 0;
};

}  // namespace palpate
