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

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <utility>

namespace palpate {

namespace {
enum Attribute : GLuint { kPositionAttribute = 0, kNormalAttribute = 1, kPressedAttribute = 2, kRingAttribute = 3 };

// The tissue's fill is pushed back by (1, 1) so that its wireframe wins. The ghost (drawn only on
// triangles with a moved corner) goes further back, so that where it still coincides with the tissue
// (the barely moved rim of a dent) the tissue wins: an edge's samples can lie half a pixel into the
// neighbouring triangle, whose plane differs by up to a pixel's depth slope, so the margin is in
// slope (factor) as well as in units.
constexpr float kGhostOffsetFactor = 3.0f;
constexpr float kGhostOffsetUnits = 8.0f;

std::unique_ptr<QOpenGLShaderProgram> buildProgram(std::initializer_list<std::pair<QOpenGLShader::ShaderType, QString>> stages) {
    auto program = std::make_unique<QOpenGLShaderProgram>();
    for (const auto& [type, file] : stages) {
        if (!program->addShaderFromSourceFile(type, file)) {
            qWarning("MeshViewport: %s does not build: %s", qPrintable(file), qPrintable(program->log()));
            return nullptr;
        }
    }
    if (!program->link()) {
        qWarning("MeshViewport: the shaders do not link: %s", qPrintable(program->log()));
        return nullptr;
    }
    return program;
}
}  // namespace

MeshViewport::MeshViewport(int samples, QWidget* parent) : QOpenGLWidget(parent), mRequestedSamples(std::max(samples, 0)) {
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setSamples(mRequestedSamples);
    setFormat(format);
    setFocusPolicy(Qt::StrongFocus);
    setContextMenuPolicy(Qt::PreventContextMenu);  // right-drag pans; no menu from the window either
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
    mGhostVao.destroy();
    mVertexBuffer.destroy();
    mRestBuffer.destroy();
    mIndexBuffer.destroy();
    mMeshProgram.reset();
    mFlatProgram.reset();
    mGlReady = false;
}

void MeshViewport::sceneChanged(bool topologyChanged) {
    mTopologyDirty = mTopologyDirty || topologyChanged;
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

    mMeshProgram = buildProgram({{QOpenGLShader::Vertex, QStringLiteral(":/shaders/mesh.vert")},
                                 {QOpenGLShader::Geometry, QStringLiteral(":/shaders/mesh.geom")},
                                 {QOpenGLShader::Fragment, QStringLiteral(":/shaders/mesh.frag")}});
    mFlatProgram = buildProgram({{QOpenGLShader::Vertex, QStringLiteral(":/shaders/flat.vert")},
                                 {QOpenGLShader::Fragment, QStringLiteral(":/shaders/flat.frag")}});
    if (!mMeshProgram || !mFlatProgram) {
        mMeshProgram.reset();
        mFlatProgram.reset();
        return;
    }
    mVao.create();
    mGhostVao.create();
    mVertexBuffer.create();
    mVertexBuffer.setUsagePattern(QOpenGLBuffer::DynamicDraw);  // kept, and rewritten in ranges
    mRestBuffer.create();
    mRestBuffer.setUsagePattern(QOpenGLBuffer::StaticDraw);
    mIndexBuffer.create();
    mIndexBuffer.setUsagePattern(QOpenGLBuffer::StaticDraw);

    // The VAOs record the attribute layouts and the index buffer once.
    {
        QOpenGLVertexArrayObject::Binder vaoBinder(&mVao);
        mVertexBuffer.bind();
        const GLsizei stride = sizeof(GpuVertex);
        glEnableVertexAttribArray(kPositionAttribute);
        glVertexAttribPointer(kPositionAttribute, 3, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(offsetof(GpuVertex, positionMm)));
        glEnableVertexAttribArray(kNormalAttribute);
        glVertexAttribPointer(kNormalAttribute, 3, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(offsetof(GpuVertex, normal)));
        glEnableVertexAttribArray(kPressedAttribute);
        glVertexAttribPointer(kPressedAttribute, 1, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(offsetof(GpuVertex, pressed)));
        glEnableVertexAttribArray(kRingAttribute);
        glVertexAttribIPointer(kRingAttribute, 1, GL_UNSIGNED_BYTE, stride,
                               reinterpret_cast<const void*>(offsetof(GpuVertex, ring)));
        mIndexBuffer.bind();
    }
    {
        // Rest positions, with the deformed vertices' pressed weights: only moved triangles show.
        QOpenGLVertexArrayObject::Binder vaoBinder(&mGhostVao);
        mRestBuffer.bind();
        glEnableVertexAttribArray(kPositionAttribute);
        glVertexAttribPointer(kPositionAttribute, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
        mVertexBuffer.bind();
        glEnableVertexAttribArray(kPressedAttribute);
        glVertexAttribPointer(kPressedAttribute, 1, GL_FLOAT, GL_FALSE, sizeof(GpuVertex),
                              reinterpret_cast<const void*>(offsetof(GpuVertex, pressed)));
        mIndexBuffer.bind();
    }
    mTopologyDirty = true;
    mGlReady = true;
}

void MeshViewport::fillVertex(VertexId v) {
    GpuVertex& g = mVertices[v];
    g.positionMm = mScene.positionsMm()[v];
    g.normal = mNormals[v];
    g.pressed = mScene.pressedWeights()[v];
    g.ring = mScene.rings()[v];
}

void MeshViewport::uploadScene() {
    mLastUpload = UploadStats{};
    const std::size_t n = mScene.vertexCount();
    bool full = mScene.allDirty();
    if (mTopologyDirty) {
        QOpenGLVertexArrayObject::Binder vaoBinder(&mVao);
        const auto indices = mScene.indices();
        mIndexBuffer.bind();
        mIndexBuffer.allocate(indices.data(), int(indices.size_bytes()));
        mIndexCount = int(indices.size());
        const auto rest = mScene.restPositionsMm();
        mRestBuffer.bind();
        mRestBuffer.allocate(rest.data(), int(rest.size_bytes()));
        mTopologyDirty = false;
        full = true;
    }
    constexpr int kStride = sizeof(GpuVertex);
    if (full) {
        mScene.computeVertexNormals(mNormals);
        mVertices.resize(n);
        for (VertexId v = 0; v < n; ++v) {
            mVertices[v] = GpuVertex{};
            fillVertex(v);
        }
        mVertexBuffer.bind();
        mVertexBuffer.allocate(mVertices.data(), int(n * kStride));
        mLastUpload = {true, n, 1, n * kStride};
        ++mFullUploads;
    } else if (!mScene.dirtyVertices().empty()) {
        // The changed vertices and the corners around them (their normals moved), in runs.
        mScene.updateVertexNormals(mNormals, mRecomputed);
        for (const VertexId v : mRecomputed) fillVertex(v);
        coalesceVertexRanges(mRecomputed, kMaxRangeGap, mRanges);
        mVertexBuffer.bind();
        for (const VertexRange& r : mRanges) {
            // Gap vertices inside a range are re-sent with their current (unchanged) values.
            mVertexBuffer.write(int(r.first * kStride), &mVertices[r.first], int(r.count * kStride));
            mLastUpload.vertices += r.count;
        }
        mLastUpload.ranges = mRanges.size();
        mLastUpload.bytes = mLastUpload.vertices * kStride;
    }
    mScene.clearDirty();
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
        // Open meshes are allowed: their inside must show. Seen from outside a closed, consistently
        // wound surface, only its front faces can be nearest: the back half is not drawn.
        if (mBackFaceCulling && mScene.closedAndConsistent() && mScene.outside(mCamera.eyeMm())) {
            glEnable(GL_CULL_FACE);
            glCullFace(GL_BACK);
            glFrontFace(mScene.outwardWinding() > 0 ? GL_CCW : GL_CW);
        } else {
            glDisable(GL_CULL_FACE);
        }
        mMeshProgram->bind();
        glUniformMatrix4fv(mMeshProgram->uniformLocation("uView"), 1, GL_FALSE, glm::value_ptr(view));
        glUniformMatrix4fv(mMeshProgram->uniformLocation("uProjection"), 1, GL_FALSE, glm::value_ptr(projection));
        const glm::vec3 light = glm::normalize(style::kLightDirView);
        mMeshProgram->setUniformValue("uTissueColor", style::kTissue.x, style::kTissue.y, style::kTissue.z);
        mMeshProgram->setUniformValue("uPressedColor", style::kPressed.x, style::kPressed.y, style::kPressed.z);
        mMeshProgram->setUniformValue("uLightDirView", light.x, light.y, light.z);
        mMeshProgram->setUniformValue("uAmbient", style::kAmbient);
        mMeshProgram->setUniformValue("uRingAmbient", style::kRingAmbient);
        mMeshProgram->setUniformValue("uSpecular", style::kSpecular);
        mMeshProgram->setUniformValue("uShininess", style::kShininess);
        glUniform3fv(mMeshProgram->uniformLocation("uRingColors"), GLsizei(style::kRingColours.size()),
                     glm::value_ptr(style::kRingColours[0]));

        const qreal scale = devicePixelRatioF();  // the framebuffer is in device pixels
        mMeshProgram->setUniformValue("uViewportPx", float(width() * scale), float(height() * scale));
        mMeshProgram->setUniformValue("uWireframe", mWireframe);
        mMeshProgram->setUniformValue("uWireColor", style::kWire.x, style::kWire.y, style::kWire.z, style::kWireAlpha);
        mMeshProgram->setUniformValue("uBackground", bg.x, bg.y, bg.z);
        mMeshProgram->setUniformValue("uOpacity", surfaceOpacity());

        // One pass: shading, ring colours and the wireframe (mesh.geom, mesh.frag). The fill is pushed
        // back a little so that the ghost's edges can be tested against it.
        QOpenGLVertexArrayObject::Binder vaoBinder(&mVao);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.0f, 1.0f);
        glDrawElements(GL_TRIANGLES, mIndexCount, GL_UNSIGNED_INT, nullptr);
        glDisable(GL_POLYGON_OFFSET_FILL);
        vaoBinder.release();
        mMeshProgram->release();

        glDisable(GL_CULL_FACE);
        if (mShowRestGhost) {
            mFlatProgram->bind();
            glUniformMatrix4fv(mFlatProgram->uniformLocation("uView"), 1, GL_FALSE, glm::value_ptr(view));
            glUniformMatrix4fv(mFlatProgram->uniformLocation("uProjection"), 1, GL_FALSE, glm::value_ptr(projection));
            glEnable(GL_BLEND);
            // Keep destination alpha at 1: the grabbed image must stay opaque.
            glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
            glDepthMask(GL_FALSE);
            // The rest shape, pushed back further than the tissue: where the two coincide the tissue
            // wins the depth test and the ghost vanishes; over a dent the rest surface is well in
            // front and shows, translucent.
            QOpenGLVertexArrayObject::Binder ghostBinder(&mGhostVao);
            glDepthFunc(GL_LESS);
            glPolygonOffset(kGhostOffsetFactor, kGhostOffsetUnits);
            mFlatProgram->setUniformValue("uOnlyMoved", true);  // only triangles with a moved corner
            glEnable(GL_POLYGON_OFFSET_FILL);
            glEnable(GL_POLYGON_OFFSET_LINE);
            mFlatProgram->setUniformValue("uColor", style::kGhost.x, style::kGhost.y, style::kGhost.z, style::kGhostFillAlpha);
            glDrawElements(GL_TRIANGLES, mIndexCount, GL_UNSIGNED_INT, nullptr);
            mFlatProgram->setUniformValue("uColor", style::kGhost.x, style::kGhost.y, style::kGhost.z, style::kGhostWireAlpha);
            glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
            glDrawElements(GL_TRIANGLES, mIndexCount, GL_UNSIGNED_INT, nullptr);
            glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
            glDisable(GL_POLYGON_OFFSET_LINE);
            glDisable(GL_POLYGON_OFFSET_FILL);
            glDepthFunc(GL_LEQUAL);
            glDepthMask(GL_TRUE);
            glDisable(GL_BLEND);
            mFlatProgram->release();
        }
        glDisable(GL_DEPTH_TEST);
    }
    // The markers: the same QPainter code as the software renderer, on top of the GL picture. Painted
    // through a paint device on the bound framebuffer rather than QPainter(this): when a parent is
    // grabbed (QWidget::grab), painting on the widget is redirected and the markers would be lost.
    const qreal dpr = devicePixelRatioF();
    QOpenGLPaintDevice device(QSize(qRound(width() * dpr), qRound(height() * dpr)));
    device.setDevicePixelRatio(dpr);
    QPainter painter(&device);
    paintExerciseMarkers(painter, mExerciseMarkers, mCamera, size());
    paintSceneOverlay(painter, mScene, mCamera, size(), mShowRestGhost);
    countFrame();
}

void MeshViewport::mousePressEvent(QMouseEvent* event) {
    if (handleMousePress(*event)) update();
}

void MeshViewport::mouseMoveEvent(QMouseEvent* event) {
    if (handleMouseMove(*event)) update();
}

void MeshViewport::mouseReleaseEvent(QMouseEvent* event) {
    if (handleMouseRelease(*event)) update();
}

void MeshViewport::wheelEvent(QWheelEvent* event) {
    if (handleWheel(*event)) update();
    event->accept();
}

}  // namespace palpate
