#pragma once
// The OpenGL 3.3 core viewport: smooth-shaded tissue with normals recomputed from the deformed
// shape every frame, a wireframe overlay, and the shared QPainter markers on top. Only create it
// where ViewportFactory found a working 3.3 context.

#include "widgets/Viewport.h"

#include <QOpenGLBuffer>
#include <QOpenGLFunctions_3_3_Core>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QOpenGLWidget>

#include <glm/vec3.hpp>

#include <memory>
#include <vector>

namespace palpate {

class MeshViewport final : public QOpenGLWidget, public Viewport, protected QOpenGLFunctions_3_3_Core {
    Q_OBJECT
public:
    explicit MeshViewport(QWidget* parent = nullptr);
    ~MeshViewport() override;

    QWidget* widget() override { return this; }
    RendererKind kind() const override { return RendererKind::OpenGL; }
    QImage grabImage() override { return grabFramebuffer(); }

    QSize sizeHint() const override { return {800, 600}; }

protected:
    void sceneChanged(bool topologyChanged) override;
    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    void releaseGl();
    void uploadScene();

    std::unique_ptr<QOpenGLShaderProgram> mProgram;
    QOpenGLVertexArrayObject mVao;
    QOpenGLBuffer mPositionBuffer{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer mNormalBuffer{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer mPressedBuffer{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer mIndexBuffer{QOpenGLBuffer::IndexBuffer};
    int mIndexCount = 0;
    bool mTopologyDirty = true;
    bool mShapeDirty = true;
    bool mGlReady = false;  // false if the shaders failed: then only the markers are drawn
    std::vector<glm::vec3> mNormals;  // scratch, kept between frames
};

}  // namespace palpate
