// The OpenGL viewport through the real GL path: run under Xvfb with the xcb platform (ctest runs it
// with `xvfb-run -a`; Mesa's llvmpipe gives OpenGL 4.5). Not under Qt's offscreen platform, which
// has no OpenGL for widgets (docs/architecture.md). Every test skips, saying why, when no OpenGL 3.3
// core context can be created. The scene is the default one stepped into contact (deterministic).
#include "ImageChecks.h"
#include "LumpMarker.h"

#include "base/resources/ShippedResources.h"
#include "app/gui/HapticSession.h"
#include "app/gui/ViewportBenchmark.h"
#include "widgets/MeshViewport.h"
#include "widgets/SceneOverlay.h"
#include "widgets/SceneStyle.h"
#include "widgets/SoftwareViewport.h"
#include "widgets/ViewportFactory.h"

#include <QApplication>
#include <QDir>
#include <QImage>
#include <QMouseEvent>
#include <QTest>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdlib>
#include <memory>

using namespace palpate;
using namespace palpate::test;

namespace {

constexpr int kTicksIntoContact = 1500;
constexpr int kWidthPx = 640;
constexpr int kHeightPx = 480;

QString defaultMeshPath() { return QString::fromStdString(findResource(kDefaultMesh)); }

/// Saves a picture next to the test's working directory for a look when a check fails.
void keep(const QImage& image, const char* name) {
    image.save(QDir::current().filePath(QStringLiteral("gl_viewport_%1.png").arg(QLatin1String(name))));
}

class GlViewport : public ::testing::Test {
protected:
    void SetUp() override {
        QString whyNot;
        if (!openGl33Available(&whyNot))
            GTEST_SKIP() << "no OpenGL 3.3 core context here (" << whyNot.toStdString()
                         << "); run under xvfb-run with the xcb platform";
        mSession = std::make_unique<HapticSession>(LoopMode::Stepped);
        ASSERT_EQ(mSession->loadMesh(defaultMeshPath().toStdString()), "");
    }

    /// A shown GL viewport of the test size with the session's mesh (and the session's current
    /// state, if `withSnapshot`, before the first frame).
    std::unique_ptr<MeshViewport> makeViewport(bool withSnapshot = false) {
        auto viewport = std::make_unique<MeshViewport>(viewportSamplesFor(probeOpenGl33().renderer));
        viewport->resize(kWidthPx, kHeightPx);
        viewport->setMesh(*mSession->drawnMesh());
        if (withSnapshot) viewport->setSnapshot(mSession->view());
        viewport->show();
        EXPECT_TRUE(QTest::qWaitForWindowExposed(viewport.get()));
        return viewport;
    }

    void stepTo(int ticks) {
        mSession->step(ticks);
        mSession->observe();
    }

    std::unique_ptr<HapticSession> mSession;
};

}  // namespace

TEST_F(GlViewport, TheFactoryPicksOpenGlOnAGpuAndTheSoftwareRendererOnACpuRasteriser) {
    ASSERT_NE(QGuiApplication::platformName(), QStringLiteral("offscreen"));
    const GlProbe probe = probeOpenGl33();
    ASSERT_TRUE(probe.available);
    EXPECT_FALSE(probe.renderer.isEmpty()) << "GL_RENDERER was read";
    const bool cpu = isSoftwareGlRenderer(probe.renderer);
    QWidget parent;
    QString reason;
    Viewport* viewport = createViewport(RendererChoice::Auto, &parent, &reason);
    EXPECT_EQ(viewport->kind(), cpu ? RendererKind::Software : RendererKind::OpenGL) << reason.toStdString();
    EXPECT_TRUE(reason.contains(probe.renderer)) << reason.toStdString();
    // --opengl-render: OpenGL whatever the rasteriser, without multisampling on a CPU one.
    auto* forced = dynamic_cast<MeshViewport*>(createViewport(RendererChoice::OpenGL, &parent, &reason));
    ASSERT_NE(forced, nullptr);
    EXPECT_EQ(forced->requestedSamples(), cpu ? 0 : 4) << reason.toStdString();
    EXPECT_EQ(forced->format().samples() > 0, !cpu) << "the widget asks its context for " << forced->format().samples();
    // --software-render still gives the software one.
    EXPECT_EQ(createViewport(RendererChoice::Software, &parent)->kind(), RendererKind::Software);
}

TEST_F(GlViewport, DrawsTheTissueAndColoursTheTouchedVertexAndEachRing) {
    auto viewport = makeViewport();
    const QImage atRest = viewport->grabImage();
    ASSERT_TRUE(viewport->glReady()) << "the shaders did not build (see the warnings above)";
    ASSERT_EQ(atRest.size(), QSize(kWidthPx, kHeightPx));
    keep(atRest, "rest");
    const QRgb background = toQColor(style::kBackground).rgb();
    // The mesh fills a good part of the picture; the corner is background.
    EXPECT_GT(countNotNear(atRest, background, 6), kWidthPx * kHeightPx / 5);
    EXPECT_TRUE(nearRgb(atRest.pixel(2, 2), background, 2));
    for (std::size_t r = 0; r < 3; ++r)
        EXPECT_EQ(countChromaticity(atRest, style::kRingColours[r]), 0) << "ring " << r << " coloured at rest";

    stepTo(kTicksIntoContact);
    ASSERT_TRUE(mSession->view().contact);
    viewport->setSnapshot(mSession->view());
    const QImage pressed = viewport->grabImage();
    keep(pressed, "pressed");
    EXPECT_GT(countNotNear(pressed, background, 6), kWidthPx * kHeightPx / 5);
    const QRectF legend = sceneLegendRect(viewport->scene(), viewport->size());
    ASSERT_FALSE(legend.isEmpty());
    // The rings on the tissue itself (the legend's swatches left out), shaded but in their hue.
    const int touched = countChromaticity(pressed, style::kRingColours[0], legend);
    const int ring1 = countChromaticity(pressed, style::kRingColours[1], legend);
    const int ring2 = countChromaticity(pressed, style::kRingColours[2], legend);
    EXPECT_GT(touched, 20) << "touched vertex";
    EXPECT_GT(ring1, 60) << "ring 1";
    EXPECT_GT(ring2, 100) << "ring 2";
    EXPECT_GT(ring2, ring1);
    EXPECT_EQ(countChromaticity(pressed, style::kRingColours[3], legend), 0) << "ring 3 is not in the model";
    // The overlay on top of the GL picture: the touched marker in its exact colour.
    int marker = 0;
    const QRgb highlight = toQColor(style::kTouchedHighlight).rgb();
    for (int y = 0; y < pressed.height(); ++y)
        for (int x = 0; x < pressed.width(); ++x)
            if (nearRgb(pressed.pixel(x, y), highlight, 10)) ++marker;
    EXPECT_GT(marker, 20);
}

TEST_F(GlViewport, PartialUploadsDrawTheSamePictureAsAWholeUpload) {
    auto incremental = makeViewport();
    (void)incremental->grabImage();
    EXPECT_EQ(incremental->fullUploadCount(), 1u) << "a new mesh is sent whole, once";
    const std::size_t vertexCount = incremental->scene().vertexCount();

    // Every snapshot from before the press until deep in it, each drawn: only changes are sent.
    stepTo(700);
    incremental->setSnapshot(mSession->view());
    (void)incremental->grabImage();
    std::size_t partialFrames = 0, maxVertices = 0;
    for (int frame = 0; frame < 80; ++frame) {
        stepTo(10);
        incremental->setSnapshot(mSession->view());
        (void)incremental->grabImage();
        const auto& upload = incremental->lastUpload();
        EXPECT_FALSE(upload.full) << "frame " << frame;
        if (upload.vertices > 0) {
            ++partialFrames;
            EXPECT_GE(upload.ranges, 1u);
            maxVertices = std::max(maxVertices, upload.vertices);
        }
    }
    ASSERT_TRUE(mSession->view().contact);
    EXPECT_EQ(incremental->fullUploadCount(), 1u);
    EXPECT_GT(partialFrames, 40u);
    EXPECT_LT(maxVertices, vertexCount / 4) << "a press changes a small part of the mesh";
    // Nothing new: nothing sent.
    incremental->setSnapshot(mSession->view());
    (void)incremental->grabImage();
    EXPECT_EQ(incremental->lastUpload().vertices, 0u);

    // A fresh viewport sent the same state whole draws the same picture.
    const QImage fromRanges = incremental->grabImage();
    auto whole = makeViewport(true);
    const QImage fromWhole = whole->grabImage();
    EXPECT_EQ(whole->fullUploadCount(), 1u);
    keep(fromRanges, "ranges");
    keep(fromWhole, "whole");
    EXPECT_EQ(countDifferent(fromRanges, fromWhole, 0), 0) << "partial uploads left stale vertices or normals";
}

TEST_F(GlViewport, SkippingTheBackFacesOfAClosedMeshDrawsTheSamePicture) {
    stepTo(kTicksIntoContact);
    auto viewport = makeViewport(true);
    ASSERT_TRUE(viewport->scene().closedAndConsistent());
    const QImage culled = viewport->grabImage();
    viewport->setBackFaceCulling(false);
    const QImage all = viewport->grabImage();
    keep(culled, "culled");
    // Along the silhouette a back face's wire can win the LEQUAL depth test by a hair: a thin line
    // of pixels at most (a wrong winding would differ over the whole organ).
    EXPECT_LE(countDifferent(culled, all, 2), 300);
    EXPECT_GT(countNotNear(culled, toQColor(style::kBackground).rgb(), 6), kWidthPx * kHeightPx / 5);
}

TEST_F(GlViewport, ShowsTheRestGhostOverTheDentOnly) {
    auto viewport = makeViewport();
    const QImage plain = viewport->grabImage();
    viewport->setShowRestGhost(true);
    const QImage ghostAtRest = viewport->grabImage();
    keep(ghostAtRest, "ghost_rest");
    const QRectF legendAtRest = sceneLegendRect(viewport->scene(), viewport->size(), true);
    // At rest the ghost coincides with the tissue and loses the depth test everywhere.
    EXPECT_LE(countDifferent(plain, ghostAtRest, 2, legendAtRest), 10);

    stepTo(kTicksIntoContact);
    viewport->setSnapshot(mSession->view());
    const QImage withGhost = viewport->grabImage();
    viewport->setShowRestGhost(false);
    const QImage withoutGhost = viewport->grabImage();
    keep(withGhost, "ghost");
    const QRectF legend = sceneLegendRect(viewport->scene(), viewport->size(), true);
    EXPECT_GT(countDifferent(withGhost, withoutGhost, 3, legend), 50) << "the ghost shows over the dent";
    const auto centre = viewport->camera().projectToPixel(viewport->scene().positionsMm()[mSession->view().touched],
                                                          glm::vec2(float(kWidthPx), float(kHeightPx)));
    ASSERT_TRUE(centre);
    const QRectF around(centre->x - 120.0, centre->y - 120.0, 240.0, 240.0);
    int awayFromDent = 0;
    for (int y = 0; y < withGhost.height(); ++y)
        for (int x = 0; x < withGhost.width(); ++x) {
            const QPointF p(x + 0.5, y + 0.5);
            if (!around.contains(p) && !legend.contains(p) && !nearRgb(withGhost.pixel(x, y), withoutGhost.pixel(x, y), 3))
                ++awayFromDent;
        }
    EXPECT_LE(awayFromDent, 10) << "ghost drawn away from the dent";
}

// The see-through view in OpenGL: the surface faded towards the background as the software renderer
// fades it (mesh.frag), away from the markers.
TEST_F(GlViewport, ALumpShownInsideTheTissueDrawsTheSurfaceSeeThrough) {
    auto viewport = makeViewport();
    const QImage plain = viewport->grabImage();
    ExerciseMarkers markers;
    markers.markers.push_back(lumpMarkerFacingTheCamera(*viewport));
    viewport->setExerciseMarkers(markers);
    const QImage seeThrough = viewport->grabImage();
    keep(seeThrough, "see_through");
    const auto centre = viewport->camera().projectToPixel(markers.markers[0].positionMm,
                                                          glm::vec2(float(kWidthPx), float(kHeightPx)));
    ASSERT_TRUE(centre);
    const QRectF markerArea(centre->x - 80.0, centre->y - 80.0, 160.0, 160.0);
    const FadedCount faded = countFaded(plain, seeThrough, toQColor(style::kBackground).rgb(),
                                        style::kSeeThroughOpacity, markerArea, 3);
    EXPECT_GT(faded.surface, kWidthPx * kHeightPx / 8);
    EXPECT_GE(faded.faded, faded.surface * 98 / 100) << faded.faded << " of " << faded.surface;
}

TEST_F(GlViewport, PicksAndPansLikeTheSoftwareViewport) {
    stepTo(kTicksIntoContact);
    auto gl = makeViewport();
    gl->setSnapshot(mSession->view());
    SoftwareViewport software;
    software.resize(kWidthPx, kHeightPx);
    software.setMesh(*mSession->drawnMesh());
    software.setSnapshot(mSession->view());

    // Right-drag pans the GL viewport as it does the software one.
    for (Viewport* v : {static_cast<Viewport*>(gl.get()), static_cast<Viewport*>(&software)}) {
        QWidget* w = v->widget();
        const QPointF from(300, 200), to(330, 215);
        QMouseEvent press(QEvent::MouseButtonPress, from, w->mapToGlobal(from), Qt::RightButton, Qt::RightButton, Qt::NoModifier);
        QApplication::sendEvent(w, &press);
        QMouseEvent move(QEvent::MouseMove, to, w->mapToGlobal(to), Qt::NoButton, Qt::RightButton, Qt::NoModifier);
        QApplication::sendEvent(w, &move);
        QMouseEvent release(QEvent::MouseButtonRelease, to, w->mapToGlobal(to), Qt::RightButton, Qt::NoButton, Qt::NoModifier);
        QApplication::sendEvent(w, &release);
    }
    EXPECT_EQ(gl->camera().targetMm(), software.camera().targetMm());
    EXPECT_EQ(gl->camera().yawDeg(), software.camera().yawDeg());

    // The same camera and positions: every pixel picks the same vertex in both.
    int hits = 0;
    for (int y = 10; y < kHeightPx; y += 37)
        for (int x = 10; x < kWidthPx; x += 41) {
            const auto a = gl->pickVertex(QPoint(x, y));
            EXPECT_EQ(a, software.pickVertex(QPoint(x, y))) << x << "," << y;
            if (a) ++hits;
        }
    EXPECT_GT(hits, 20);
    // The touched vertex is picked where it is drawn.
    const VertexId touched = mSession->view().touched;
    const auto p = gl->camera().projectToPixel(gl->scene().positionsMm()[touched], glm::vec2(float(kWidthPx), float(kHeightPx)));
    ASSERT_TRUE(p);
    EXPECT_EQ(gl->pickVertex(QPoint(int(std::floor(p->x)), int(std::floor(p->y)))), touched);
    // And the picture after the pan is still the mesh, drawn.
    EXPECT_GT(countNotNear(gl->grabImage(), toQColor(style::kBackground).rgb(), 6), kWidthPx * kHeightPx / 5);
}

TEST_F(GlViewport, TheBenchmarkPrintsFpsWithOpenGlForced) {
    testing::internal::CaptureStdout();
    const int code = runViewportBenchmark(QStringLiteral("0.5"), defaultMeshPath(), RendererChoice::OpenGL);
    const std::string out = testing::internal::GetCapturedStdout();
    EXPECT_EQ(code, 0) << out;
    EXPECT_NE(out.find("fps="), std::string::npos) << out;
    EXPECT_NE(out.find("renderer=OpenGL"), std::string::npos) << out;
    const bool cpu = isSoftwareGlRenderer(probeOpenGl33().renderer);
    EXPECT_NE(out.find(cpu ? "samples=0" : "samples=4"), std::string::npos) << out;
}

int main(int argc, char** argv) {
    // Real GL needs a display (xvfb-run gives one, with the xcb platform). Without one Qt would abort
    // on xcb: use offscreen instead, where every test skips.
    if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    else if (qgetenv("QT_QPA_PLATFORM") == "offscreen")
        std::fprintf(stderr, "gl_viewport_tests: QT_QPA_PLATFORM=offscreen has no OpenGL: the tests will skip\n");
    QApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
