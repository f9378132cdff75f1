#pragma once
// The OpenGL 3.3 core viewport: smooth-shaded tissue with each ring of the touched vertex in its own
// colour (a geometry shader gives each triangle its lowest ring's colour), a wireframe overlay, the
// rest-shape ghost on request, and the shared QPainter markers on top. Only create it where
// ViewportFactory found a working 3.3 context.
//
// Uploads: the vertex buffer (position, normal, pressed weight, ring: 32 bytes per vertex) stays on
// the GPU. Each frame only the vertices that changed since the last frame are sent, with one
// glBufferSubData per run of neighbouring ids (vertices are Morton-ordered, so a deformed region is
// a few runs). A moved vertex changes the normals of the corners of its triangles too: those are
// recomputed on the CPU and sent with it. A new mesh or a new context sends everything.

#include "widgets/RenderScene.h"
#include "widgets/Viewport.h"

#include <QOpenGLBuffer>
#include <QOpenGLFunctions_3_3_Core>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QOpenGLWidget>

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace palpate {

class MeshViewport final : public QOpenGLWidget, public Viewport, protected QOpenGLFunctions_3_3_Core {
    Q_OBJECT
public:
    /// Runs of changed vertices closer than this are sent as one range.
    static constexpr std::uint32_t kMaxRangeGap = 16;

    /// What the last painted frame sent to the vertex buffer.
    struct UploadStats {
        bool full = false;          ///< the whole buffer (new mesh, new context)
        std::size_t vertices = 0;   ///< vertices sent (with the gaps merged into ranges)
        std::size_t ranges = 0;     ///< glBufferSubData calls for the vertex buffer
        std::size_t bytes = 0;
    };

    /// `samples`: the multisampling to ask for (0: none; ViewportFactory picks it per GL_RENDERER).
    explicit MeshViewport(int samples = 4, QWidget* parent = nullptr);
    ~MeshViewport() override;

    QWidget* widget() override { return this; }
    RendererKind kind() const override { return RendererKind::OpenGL; }
    QImage grabImage() override { return grabFramebuffer(); }

    QSize sizeHint() const override { return {800, 600}; }

    /// False when the shaders did not build (then only the markers are drawn); set by the first paint.
    bool glReady() const { return mGlReady; }
    const UploadStats& lastUpload() const { return mLastUpload; }
    /// Skipping the back faces of a closed mesh seen from outside (on by default). Off, every
    /// triangle is drawn: the same picture, slower (the tests compare the two).
    void setBackFaceCulling(bool on) {
        mBackFaceCulling = on;
        update();
    }

    /// The multisampling asked for at construction (the context may give more or fewer).
    int requestedSamples() const { return mRequestedSamples; }
    /// Whole-buffer uploads so far (one per mesh or context, when all is well).
    std::uint64_t fullUploadCount() const { return mFullUploads; }

protected:
    void sceneChanged(bool topologyChanged) override;
    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    /// One vertex in the GPU buffer.
    struct GpuVertex {
        glm::vec3 positionMm;
        glm::vec3 normal;
        float pressed;
        std::uint8_t ring;
        std::uint8_t padding[3];
    };
    static_assert(sizeof(GpuVertex) == 32);

    void releaseGl();
    void uploadScene();
    void fillVertex(VertexId v);

    std::unique_ptr<QOpenGLShaderProgram> mMeshProgram;  // shaded surface, ring colours
    std::unique_ptr<QOpenGLShaderProgram> mFlatProgram;  // one colour: wireframe, ghost
    QOpenGLVertexArrayObject mVao;       // the deformed surface
    QOpenGLVertexArrayObject mGhostVao;  // the rest shape
    QOpenGLBuffer mVertexBuffer{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer mRestBuffer{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer mIndexBuffer{QOpenGLBuffer::IndexBuffer};
    int mIndexCount = 0;
    int mRequestedSamples = 0;
    bool mBackFaceCulling = true;
    bool mTopologyDirty = true;
    bool mGlReady = false;  // false if the shaders failed: then only the markers are drawn

    // CPU copies and scratch, kept between frames so that a frame does not allocate.
    std::vector<GpuVertex> mVertices;
    std::vector<glm::vec3> mNormals;
    std::vector<VertexId> mRecomputed;
    std::vector<VertexRange> mRanges;
    UploadStats mLastUpload;
    std::uint64_t mFullUploads = 0;
};

}  // namespace palpate
