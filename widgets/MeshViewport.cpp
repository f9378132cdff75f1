#include "widgets/MeshViewport.h"

#include "widgets/SceneOverlay.h"
#include "widgets/SceneStyle.h"

#include <QMouseEvent>
#include <QOpenGLPaintDevice>
#include <QPainter>
#include <QWheelEvent>
#include <QtDebug>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace palpate {

namespace {
enum Attribute : GLuint { kPositionAttribute = 0, kNormalAttribute = 1, kPressedAttribute = 2 };
}

MeshViewport::MeshViewport(QWidget* parent) : QOpenGLWidget(parent) {
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setSamples(4);
    setFormat(format);
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(160, 120);
}

MeshViewport::~MeshViewport() {
    // GL objects belong to this widget's context: delete them while it is current, and stop the
    // context's destruction (in ~QOpenGLWidget) from calling back into this half-destroyed object.
    if (context()) disconnect(context(), nullptr, this, nullptr);
    makeCurrent();
    releaseGl();
    doneCurrent();
}

void MeshViewport::releaseGl() {
    mVao.destroy();
    mPositionBuffer.destroy();
    mNormalBuffer.destroy();
    mPressedBuffer.destroy();
    mIndexBuffer.destroy();
    mProgram.reset();
    mGlReady = false;
}

void MeshViewport::sceneChanged(bool topologyChanged) {
    mTopologyDirty = mTopologyDirty || topologyChanged;
    mShapeDirty = true;
    update();
}

void MeshViewport::initializeGL() {
    // The context is recreated when the widget moves to another top-level window.
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, [this] {
        makeCurrent();
        releaseGl();
        doneCurrent();
    });
    initializeOpenGLFunctions();

    mProgram = std::make_unique<QOpenGLShaderProgram>();
    if (!mProgram->addShaderFromSourceFile(QOpenGLShader::Vertex, QStringLiteral(":/shaders/mesh.vert")) ||
        !mProgram->addShaderFromSourceFile(QOpenGLShader::Fragment, QStringLiteral(":/shaders/mesh.frag")) ||
        !mProgram->link()) {
        qWarning("MeshViewport: the mesh shaders do not build: %s", qPrintable(mProgram->log()));
        mProgram.reset();
        return;
    }
    mVao.create();
    for (QOpenGLBuffer* buffer : {&mPositionBuffer, &mNormalBuffer, &mPressedBuffer, &mIndexBuffer}) {
        buffer->create();
        buffer->setUsagePattern(buffer == &mIndexBuffer ? QOpenGLBuffer::StaticDraw : QOpenGLBuffer::StreamDraw);
    }
    // The VAO records the attribute layout and the index buffer once.
    QOpenGLVertexArrayObject::Binder vaoBinder(&mVao);
    mPositionBuffer.bind();
    glEnableVertexAttribArray(kPositionAttribute);
    glVertexAttribPointer(kPositionAttribute, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    mNormalBuffer.bind();
    glEnableVertexAttribArray(kNormalAttribute);
    glVertexAttribPointer(kNormalAttribute, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    mPressedBuffer.bind();
    glEnableVertexAttribArray(kPressedAttribute);
    glVertexAttribPointer(kPressedAttribute, 1, GL_FLOAT, GL_FALSE, sizeof(float), nullptr);
    mIndexBuffer.bind();
    mTopologyDirty = mShapeDirty = true;
    mGlReady = true;
}

void MeshViewport::uploadScene() {
    QOpenGLVertexArrayObject::Binder vaoBinder(&mVao);
    if (mTopologyDirty) {
        const auto indices = mScene.indices();
        mIndexBuffer.bind();
        mIndexBuffer.allocate(indices.data(), int(indices.size_bytes()));
        mIndexCount = int(indices.size());
        mTopologyDirty = false;
    }
    if (mShapeDirty) {
        const auto positions = mScene.positionsMm();
        const auto pressed = mScene.pressedWeights();
        mScene.computeVertexNormals(mNormals);
        // allocate() orphans the old storage, so the driver need not wait for the previous frame.
        mPositionBuffer.bind();
        mPositionBuffer.allocate(positions.data(), int(positions.size_bytes()));
        mNormalBuffer.bind();
        mNormalBuffer.allocate(mNormals.data(), int(mNormals.size() * sizeof(glm::vec3)));
        mPressedBuffer.bind();
        mPressedBuffer.allocate(pressed.data(), int(pressed.size_bytes()));
        mShapeDirty = false;
    }
}

void MeshViewport::paintGL() {
    const glm::vec3& bg = style::kBackground;
    glClearColor(bg.x, bg.y, bg.z, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (mGlReady && !mScene.empty()) {
        uploadScene();
        const float aspect = float(width()) / float(std::max(height(), 1));
        const glm::mat4 view = mCamera.view();
        const glm::mat4 projection = mCamera.projection(aspect);

        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glDisable(GL_CULL_FACE);  // open meshes are allowed: their inside must show
        mProgram->bind();
        glUniformMatrix4fv(mProgram->uniformLocation("uView"), 1, GL_FALSE, glm::value_ptr(view));
        glUniformMatrix4fv(mProgram->uniformLocation("uProjection"), 1, GL_FALSE, glm::value_ptr(projection));
        const glm::vec3 light = glm::normalize(style::kLightDirView);
        mProgram->setUniformValue("uTissueColor", style::kTissue.x, style::kTissue.y, style::kTissue.z);
        mProgram->setUniformValue("uPressedColor", style::kPressed.x, style::kPressed.y, style::kPressed.z);
        mProgram->setUniformValue("uLightDirView", light.x, light.y, light.z);
        mProgram->setUniformValue("uAmbient", style::kAmbient);
        mProgram->setUniformValue("uWireColor", style::kWire.x, style::kWire.y, style::kWire.z, style::kWireAlpha);

        QOpenGLVertexArrayObject::Binder vaoBinder(&mVao);
        // Fill pushed back a little so that the wire pass on the same triangles wins the depth test.
        mProgram->setUniformValue("uWirePass", false);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.0f, 1.0f);
        glDrawElements(GL_TRIANGLES, mIndexCount, GL_UNSIGNED_INT, nullptr);
        glDisable(GL_POLYGON_OFFSET_FILL);
        if (mWireframe) {
            mProgram->setUniformValue("uWirePass", true);
            glEnable(GL_BLEND);
            // Keep destination alpha at 1: the grabbed image must stay opaque.
            glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
            glDepthMask(GL_FALSE);
            glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
            glDrawElements(GL_TRIANGLES, mIndexCount, GL_UNSIGNED_INT, nullptr);
            glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
            glDepthMask(GL_TRUE);
            glDisable(GL_BLEND);
        }
        vaoBinder.release();
        mProgram->release();
        glDisable(GL_DEPTH_TEST);
    }
    // The markers: the same QPainter code as the software renderer, on top of the GL picture. Painted
    // through a paint device on the bound framebuffer rather than QPainter(this): when a parent is
    // grabbed (QWidget::grab), painting on the widget is redirected and the markers would be lost.
    const qreal dpr = devicePixelRatioF();
    QOpenGLPaintDevice device(QSize(qRound(width() * dpr), qRound(height() * dpr)));
    device.setDevicePixelRatio(dpr);
    QPainter painter(&device);
    paintSceneOverlay(painter, mScene, mCamera, size());
    countFrame();
}

void MeshViewport::mousePressEvent(QMouseEvent* event) {
    if (handleMousePress(*event)) update();
}

void MeshViewport::mouseMoveEvent(QMouseEvent* event) {
    if (handleMouseMove(*event)) update();
}

void MeshViewport::wheelEvent(QWheelEvent* event) {
    if (handleWheel(*event)) update();
    event->accept();
}

}  // namespace palpate
