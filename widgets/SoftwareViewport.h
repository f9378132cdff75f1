#pragma once
// The viewport drawn on the CPU without OpenGL: a small z-buffered rasteriser into an image, with
// per-vertex normals (recomputed only around the vertices that moved, as the OpenGL viewport does)
// so that a dent shades as a dent, each triangle in the colour of its lowest ring, the wireframe
// blended in near the edges, the rest-shape ghost on request, and the same camera, colours,
// markers and picking as MeshViewport. Used where OpenGL is missing (Qt's offscreen platform,
// widget tests, remote sessions), where OpenGL is itself a software rasteriser and this is faster
// (ViewportFactory), or when --software-render is given.
//
// A whole frame transforms every vertex once and fills every front-facing triangle once against the
// depth buffer (a closed mesh seen from outside: its back faces are skipped), scanning each row only
// over the triangle's span: no sort, no QPainter call per triangle. While only a dent changes (same
// camera, size and options), only the rectangle around the changed triangles is cleared and drawn
// again, from the kept picture and depth buffer (docs/bench/README.md, "Viewport").

#include "widgets/Viewport.h"

#include <QImage>
#include <QRect>
#include <QWidget>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace palpate {

class SoftwareViewport final : public QWidget, public Viewport {
    Q_OBJECT
public:
    explicit SoftwareViewport(QWidget* parent = nullptr);

    QWidget* widget() override { return this; }
    RendererKind kind() const override { return RendererKind::Software; }
    QImage grabImage() override;

    QSize sizeHint() const override { return {800, 600}; }

    /// Skipping the back faces of a closed mesh seen from outside (on by default). Off, every
    /// triangle is filled: the same picture, slower (the tests compare the two).
    void setBackFaceCulling(bool on) {
        mBackFaceCulling = on;
        update();
    }

    /// What the last frame drew: the whole picture, or only the rectangle around what changed.
    struct RasterStats {
        bool whole = false;
        std::size_t regionPx = 0;   ///< pixels cleared and drawn again (0: the picture was kept)
        std::size_t triangles = 0;  ///< triangles filled (before back faces are skipped)
    };
    const RasterStats& lastRaster() const { return mLastRaster; }

    /// Per-vertex normals as last drawn (the shape's, area-weighted; RenderScene::computeVertexNormals).
    const std::vector<glm::vec3>& vertexNormals() const { return mNormals; }

protected:
    void sceneChanged(bool topologyChanged) override;
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    /// Draws the scene (not the markers) into mFrame, of `sizePx` device pixels.
    void rasterScene(QSize sizePx, float devicePixelRatio);
    void paintAll(QPainter& painter, QSize logicalSize, float devicePixelRatio);

    // Kept between frames so that painting does not allocate.
    struct ProjectedVertex {
        float xPx, yPx;
        float invDepth;  // 1 / (distance along the view axis, mm): linear across the screen
        float diffuse;   // key light on the vertex normal, turned towards the eye
        float specular;  // its highlight
        bool inFront;    // in front of the near plane
    };
    std::vector<ProjectedVertex> mProjected;
    std::vector<glm::vec3> mNormals;
    std::vector<VertexId> mRecomputed;
    std::vector<float> mDepth;  // per pixel: invDepth of the nearest surface, 0 for none
    QImage mFrame;
    bool mFrameValid = false;
    bool mBackFaceCulling = true;
    /// What the picture in mFrame depends on besides the scene: when it changes, all is drawn again.
    struct FrameKey {
        QSize sizePx;
        glm::mat4 view{1.0f}, projection{1.0f};
        bool wireframe = false, ghost = false;
        int backSign = 0;
        float opacity = 1.0f;
        bool operator==(const FrameKey&) const = default;
    };
    FrameKey mLastKey;
    RasterStats mLastRaster;

    /// The camera of one frame: what projects a vertex to the frame's device pixels.
    struct FrameCamera {
        glm::mat4 view{1.0f}, projection{1.0f};
        glm::mat3 rotation{1.0f};  ///< the view's: maps normals
        glm::vec3 light{0.0f};     ///< the key light's direction, in view space
        glm::vec2 sizePx{0.0f};
    };
    static ProjectedVertex projectVertex(const FrameCamera& camera, const glm::vec3& pointMm, const glm::vec3& normal);
    /// After a partial change: projects the vertices whose normals changed again; the rectangle
    /// (device pixels) their triangles covered before and cover now, the whole frame when one is
    /// behind the eye.
    QRect reprojectChanged(const FrameCamera& camera, QSize sizePx);
    /// The rest shape of every displaced triangle, translucent, over the tissue drawn in `rect`.
    void drawRestGhost(const FrameCamera& camera, const QRect& rect);
};

}  // namespace palpate
