// The viewport's features under QT_QPA_PLATFORM=offscreen (the software renderer): ring colours and
// their legend, the rest-shape ghost, pan, picking, and the bookkeeping behind partial uploads (the
// observer's changed vertices and versions, the scene's dirty vertices, ranges and normals).
#include "ImageChecks.h"
#include "LumpMarker.h"

#include "base/resources/ShippedResources.h"
#include "app/gui/HapticSession.h"
#include "app/gui/MainWindow.h"
#include "app/gui/SnapshotObserver.h"
#include "widgets/OrbitCamera.h"
#include "widgets/RenderScene.h"
#include "widgets/SceneOverlay.h"
#include "widgets/SceneStyle.h"
#include "widgets/SoftwareViewport.h"

#include <QApplication>
#include <QStandardPaths>
#include <QImage>
#include <QMouseEvent>
#include <QTest>
#include <QWheelEvent>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <set>

using namespace palpate;
using namespace palpate::test;

namespace {

constexpr int kTicksIntoContact = 1500;  // the scripted stroke presses (what --screenshot --ticks 1500 shows)

QString defaultMeshPath() { return QString::fromStdString(findResource(kDefaultMesh)); }

/// A stepped session on the default mesh, `ticks` ticks in, the newest snapshot applied.
std::unique_ptr<HapticSession> steppedSession(int ticks) {
    auto session = std::make_unique<HapticSession>(LoopMode::Stepped);
    EXPECT_EQ(session->loadMesh(defaultMeshPath().toStdString()), "");
    session->step(ticks);
    session->observe();
    return session;
}

/// The vertex nearest to the camera's eye: on a closed organ it faces the camera, unhidden.
VertexId vertexNearestTheEye(const RenderScene& scene, const OrbitCamera& camera) {
    const auto positions = scene.positionsMm();
    VertexId best = 0;
    for (VertexId v = 1; v < positions.size(); ++v)
        if (glm::length(positions[v] - camera.eyeMm()) < glm::length(positions[best] - camera.eyeMm())) best = v;
    return best;
}

void sendMouse(QWidget& widget, QEvent::Type type, QPointF at, Qt::MouseButton button, Qt::MouseButtons buttons) {
    QMouseEvent event(type, at, widget.mapToGlobal(at), button, buttons, Qt::NoModifier);
    QApplication::sendEvent(&widget, &event);
}

void drag(QWidget& widget, Qt::MouseButton button, QPointF from, QPointF to) {
    sendMouse(widget, QEvent::MouseButtonPress, from, button, button);
    sendMouse(widget, QEvent::MouseMove, (from + to) / 2, Qt::NoButton, button);
    sendMouse(widget, QEvent::MouseMove, to, Qt::NoButton, button);
    sendMouse(widget, QEvent::MouseButtonRelease, to, button, Qt::NoButton);
}

}  // namespace

// --- the snapshot observer: rings, changed vertices, versions ---

TEST(SnapshotObserverRings, CarriesRingsAndListsOnlyTheVerticesThatChanged) {
    const std::vector<glm::vec3> rest = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
    SnapshotObserver observer;
    observer.setRestPositions(rest);
    EXPECT_EQ(observer.view().rings, std::vector<std::uint8_t>(5, kNoRing));
    const std::uint64_t atRest = observer.view().version;
    EXPECT_GT(atRest, 0u);

    auto snapshot = std::make_unique<HapticSnapshot>();
    snapshot->displacedCount = 2;
    snapshot->displacedIds[0] = 1;
    snapshot->displacedPositionsMm[0] = {1, 0, -1};
    snapshot->displacedRings[0] = 0;
    snapshot->displacedIds[1] = 2;
    snapshot->displacedPositionsMm[1] = {2, 0, -0.5f};
    snapshot->displacedRings[1] = 1;
    observer.apply(*snapshot);
    EXPECT_EQ(observer.view().version, atRest + 1);
    EXPECT_EQ(observer.view().rings, (std::vector<std::uint8_t>{kNoRing, 0, 1, kNoRing, kNoRing}));
    EXPECT_EQ(std::set<VertexId>(observer.view().changed.begin(), observer.view().changed.end()),
              (std::set<VertexId>{1, 2}));

    // 2 listed again unchanged, 3 new and relaxing, 1 back at rest: 1 and 3 changed, 2 did not.
    snapshot->displacedCount = 2;
    snapshot->displacedIds[0] = 2;
    snapshot->displacedPositionsMm[0] = {2, 0, -0.5f};
    snapshot->displacedRings[0] = 1;
    snapshot->displacedIds[1] = 3;
    snapshot->displacedPositionsMm[1] = {3, 0, -0.1f};
    snapshot->displacedRings[1] = kRelaxingRing;
    observer.apply(*snapshot);
    EXPECT_EQ(observer.view().version, atRest + 2);
    EXPECT_EQ(observer.view().rings, (std::vector<std::uint8_t>{kNoRing, kNoRing, 1, kNoRing, kNoRing}));
    EXPECT_EQ(std::set<VertexId>(observer.view().changed.begin(), observer.view().changed.end()),
              (std::set<VertexId>{1, 3}));
    EXPECT_EQ(observer.view().positionsMm[1], rest[1]);

    // The same again: nothing changed, the version stays.
    observer.apply(*snapshot);
    EXPECT_EQ(observer.view().version, atRest + 2);
    EXPECT_TRUE(observer.view().changed.empty());

    // A ring change alone is a change.
    snapshot->displacedRings[0] = 0;
    observer.apply(*snapshot);
    EXPECT_EQ(observer.view().version, atRest + 3);
    EXPECT_EQ(observer.view().changed, (std::vector<VertexId>{2}));

    // A new scene is a new version, all at rest and in no ring.
    observer.setRestPositions(rest);
    EXPECT_GT(observer.view().version, atRest + 3);
    EXPECT_EQ(observer.view().rings, std::vector<std::uint8_t>(5, kNoRing));
    EXPECT_EQ(observer.view().positionsMm, rest);
}

// --- the render scene: incremental updates, dirty vertices, normals, ranges ---

TEST(RenderSceneUpdates, IncrementalSnapshotsGiveTheSameSceneAsWholeOnesAndMarkOnlyWhatChanged) {
    HapticSession session(LoopMode::Stepped);
    ASSERT_EQ(session.loadMesh(defaultMeshPath().toStdString()), "");
    const TissueMesh& mesh = *session.drawnMesh();
    RenderScene incremental;
    incremental.setMesh(mesh);
    std::vector<glm::vec3> normals;
    std::vector<VertexId> recomputed;
    incremental.computeVertexNormals(normals);
    incremental.clearDirty();
    EXPECT_FALSE(incremental.allDirty());

    std::size_t maxDirty = 0, framesWithChanges = 0;
    for (int frame = 0; frame < 150; ++frame) {
        session.step(10);
        session.observe();
        incremental.setSnapshot(session.view());  // consecutive versions: only `changed` is read
        EXPECT_FALSE(incremental.allDirty()) << "frame " << frame;
        const std::size_t dirty = incremental.dirtyVertices().size();
        maxDirty = std::max(maxDirty, dirty);
        if (dirty > 0) ++framesWithChanges;
        incremental.updateVertexNormals(normals, recomputed);
        // Every dirty vertex is among those recomputed (and so uploaded).
        const std::set<VertexId> recomputedSet(recomputed.begin(), recomputed.end());
        EXPECT_EQ(recomputedSet.size(), recomputed.size()) << "listed twice";
        for (const VertexId v : incremental.dirtyVertices()) EXPECT_TRUE(recomputedSet.count(v)) << v;
        incremental.clearDirty();
    }
    ASSERT_TRUE(session.view().contact);
    EXPECT_GT(framesWithChanges, 50u);
    EXPECT_GT(maxDirty, 0u);
    EXPECT_LT(maxDirty, mesh.vertexCount() / 4) << "a press should change a small part of the mesh";

    // The same state read whole (an unversioned copy).
    SceneSnapshot copy = session.view();
    copy.version = 0;
    copy.changed.clear();
    RenderScene whole;
    whole.setMesh(mesh);
    whole.setSnapshot(copy);
    ASSERT_EQ(whole.vertexCount(), incremental.vertexCount());
    EXPECT_TRUE(std::equal(whole.positionsMm().begin(), whole.positionsMm().end(), incremental.positionsMm().begin()));
    EXPECT_TRUE(std::equal(whole.rings().begin(), whole.rings().end(), incremental.rings().begin()));
    EXPECT_TRUE(std::equal(whole.pressedWeights().begin(), whole.pressedWeights().end(),
                           incremental.pressedWeights().begin()));
    for (int r = 0; r < 256; ++r)
        EXPECT_EQ(whole.ringVertexCount(std::uint8_t(r)), incremental.ringVertexCount(std::uint8_t(r))) << r;
    EXPECT_EQ(incremental.highestRing(), 2) << "the default model has the touched vertex and two rings";
    EXPECT_EQ(incremental.ringVertexCount(0), 1u);

    // The normals kept up around the changes equal a fresh computation, bit for bit.
    std::vector<glm::vec3> fresh;
    incremental.computeVertexNormals(fresh);
    ASSERT_EQ(fresh.size(), normals.size());
    EXPECT_EQ(std::memcmp(fresh.data(), normals.data(), fresh.size() * sizeof(glm::vec3)), 0);

    // A version gap (frames missed) reads the snapshot whole, still marking only what differs.
    session.step(30);
    session.observe();
    session.step(1);
    session.observe();
    incremental.setSnapshot(session.view());
    EXPECT_FALSE(incremental.allDirty());
    EXPECT_LT(incremental.dirtyVertices().size(), mesh.vertexCount() / 4);
}

TEST(RenderSceneUpdates, CoalescesChangedVerticesIntoRanges) {
    std::vector<VertexRange> ranges;
    std::vector<VertexId> ids = {5, 3, 4, 10, 11, 30, 4};
    coalesceVertexRanges(ids, 0, ranges);
    EXPECT_EQ(ranges, (std::vector<VertexRange>{{3, 3}, {10, 2}, {30, 1}}));
    ids = {5, 3, 4, 10, 11, 30, 4};
    coalesceVertexRanges(ids, 4, ranges);  // 5 -> 10 is a gap of 4 ids: merged
    EXPECT_EQ(ranges, (std::vector<VertexRange>{{3, 9}, {30, 1}}));
    ids.clear();
    coalesceVertexRanges(ids, 16, ranges);
    EXPECT_TRUE(ranges.empty());
}

TEST(RenderSceneUpdates, PicksTheNearestTriangleAndItsNearestCorner) {
    // Two parallel triangles facing +z; the ray from +z hits the upper one first.
    const auto loaded = TissueMesh::fromTriangles(
        {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 0, 5}, {10, 0, 5}, {0, 10, 5}}, {{0, 1, 2}, {3, 4, 5}},
        "two triangles");
    if (!loaded.mesh) GTEST_SKIP() << "the validator refuses two loose triangles";
    RenderScene scene;
    scene.setMesh(*loaded.mesh);
    const auto positions = scene.positionsMm();
    const auto hit = scene.pick({1.0f, 1.0f, 20.0f}, {0.0f, 0.0f, -1.0f});
    ASSERT_TRUE(hit);
    EXPECT_EQ(positions[*hit], glm::vec3(0, 0, 5));
    const auto corner = scene.pick({8.0f, 1.0f, 20.0f}, {0.0f, 0.0f, -1.0f});
    ASSERT_TRUE(corner);
    EXPECT_EQ(positions[*corner], glm::vec3(10, 0, 5));
    EXPECT_FALSE(scene.pick({20.0f, 20.0f, 20.0f}, {0.0f, 0.0f, -1.0f}));
}

// --- the camera: pan ---

TEST(OrbitCameraPan, WhatLiesAtTheTargetFollowsTheMouseAndResetUndoesIt) {
    const std::vector<glm::vec3> box = {{-50, -20, -30}, {50, 20, 30}};
    OrbitCamera camera;
    camera.reset(box);
    const glm::vec2 size(640.0f, 480.0f);
    const glm::vec3 target = camera.targetMm();
    const float yaw = camera.yawDeg(), pitch = camera.pitchDeg(), distance = camera.distanceMm();
    const auto before = camera.projectToPixel(target, size);
    ASSERT_TRUE(before);
    EXPECT_NEAR(before->x, 320.0f, 0.01f);
    EXPECT_NEAR(before->y, 240.0f, 0.01f);

    camera.pan(40.0f, -25.0f, size);
    const auto after = camera.projectToPixel(target, size);
    ASSERT_TRUE(after);
    EXPECT_NEAR(after->x, 360.0f, 0.05f);
    EXPECT_NEAR(after->y, 215.0f, 0.05f);
    EXPECT_EQ(camera.yawDeg(), yaw);
    EXPECT_EQ(camera.pitchDeg(), pitch);
    EXPECT_EQ(camera.distanceMm(), distance);
    EXPECT_NE(camera.targetMm(), target);

    // Tall viewports give the field of view to the width: the pan still follows the mouse.
    const glm::vec2 tall(300.0f, 700.0f);
    const auto tallBefore = camera.projectToPixel(target, tall);
    camera.pan(-30.0f, 10.0f, tall);
    const auto tallAfter = camera.projectToPixel(target, tall);
    ASSERT_TRUE(tallBefore && tallAfter);
    EXPECT_NEAR(tallAfter->x - tallBefore->x, -30.0f, 0.05f);
    EXPECT_NEAR(tallAfter->y - tallBefore->y, 10.0f, 0.05f);

    camera.reset(box);
    EXPECT_LT(glm::length(camera.targetMm() - target), 1e-3f);
}

TEST(OrbitCameraPan, RaysThroughPixelsHitWhatProjectsThere) {
    const std::vector<glm::vec3> box = {{-50, -20, -30}, {50, 20, 30}};
    OrbitCamera camera;
    camera.reset(box);
    camera.orbit(35.0f, -12.0f);
    camera.pan(12.0f, 7.0f, {640.0f, 480.0f});
    const glm::vec2 size(640.0f, 480.0f);
    for (const glm::vec3 point : {glm::vec3(10, 5, -3), glm::vec3(-40, 15, 20), glm::vec3(0, 0, 0)}) {
        const auto pixel = camera.projectToPixel(point, size);
        ASSERT_TRUE(pixel);
        const auto ray = camera.rayThroughPixel(*pixel, size);
        // The point lies on the ray: its distance from the line is ~0.
        const glm::vec3 toPoint = point - ray.originMm;
        const float off = glm::length(toPoint - glm::dot(toPoint, ray.direction) * ray.direction);
        EXPECT_LT(off, 1e-3f * glm::length(toPoint));
        EXPECT_GT(glm::dot(toPoint, ray.direction), 0.0f);
    }
}

// --- the software viewport ---

TEST(SoftwareViewportFeatures, ColoursTheTouchedVertexAndEachRingAndShowsALegend) {
    auto session = steppedSession(kTicksIntoContact);
    ASSERT_TRUE(session->view().contact);
    SoftwareViewport viewport;
    viewport.resize(640, 480);
    viewport.setMesh(*session->drawnMesh());

    // At rest: no ring colour on the tissue, and no legend.
    const QImage atRest = viewport.grabImage();
    EXPECT_TRUE(sceneLegendRect(viewport.scene(), viewport.size()).isEmpty());
    for (std::size_t r = 0; r < 3; ++r)
        EXPECT_EQ(countChromaticity(atRest, style::kRingColours[r]), 0) << "ring " << r << " coloured at rest";

    viewport.setSnapshot(session->view());
    ASSERT_EQ(viewport.scene().highestRing(), 2);
    const QImage pressed = viewport.grabImage();
    const QRectF legend = sceneLegendRect(viewport.scene(), viewport.size());
    ASSERT_FALSE(legend.isEmpty());
    EXPECT_LT(legend.right(), 160.0);
    EXPECT_GT(legend.top(), 400.0) << "bottom left";
    // On the tissue (outside the legend): each ring's colour, shaded.
    const int touched = countChromaticity(pressed, style::kRingColours[0], legend);
    const int ring1 = countChromaticity(pressed, style::kRingColours[1], legend);
    const int ring2 = countChromaticity(pressed, style::kRingColours[2], legend);
    EXPECT_GT(touched, 20);
    EXPECT_GT(ring1, 60);
    EXPECT_GT(ring2, 100) << "the outer ring is the largest band";
    EXPECT_GT(ring2, ring1);
    EXPECT_EQ(countChromaticity(pressed, style::kRingColours[3], legend), 0) << "ring 3 is not in the model";
    // The legend: one unshaded swatch per ring, in its exact colour.
    for (std::size_t r = 0; r < 3; ++r) {
        const QColor swatch = toQColor(style::kRingColours[r]);
        int exact = 0;
        for (int y = int(legend.top()); y < int(legend.bottom()); ++y)
            for (int x = int(legend.left()); x < int(legend.right()); ++x)
                if (nearRgb(pressed.pixel(x, y), swatch.rgb(), 2)) ++exact;
        EXPECT_GE(exact, style::kLegendSwatchPx * style::kLegendSwatchPx / 2) << "swatch of ring " << r;
    }
    EXPECT_EQ(ringLegendLabel(0), QStringLiteral("touched"));
    EXPECT_EQ(ringLegendLabel(2), QStringLiteral("ring 2"));
}

TEST(SoftwareViewportFeatures, ShowsTheRestGhostOnlyWhereTheTissueMoved) {
    auto session = steppedSession(kTicksIntoContact);
    SoftwareViewport viewport;
    viewport.resize(640, 480);
    viewport.setMesh(*session->drawnMesh());

    // At rest the ghost coincides with the tissue: nothing is drawn for it but its legend row.
    const QImage plain = viewport.grabImage();
    viewport.setShowRestGhost(true);
    EXPECT_TRUE(viewport.showRestGhost());
    const QImage ghostAtRest = viewport.grabImage();
    const QRectF legendAtRest = sceneLegendRect(viewport.scene(), viewport.size(), true);
    EXPECT_FALSE(legendAtRest.isEmpty()) << "the ghost has a legend row";
    EXPECT_EQ(countDifferent(plain, ghostAtRest, 0, legendAtRest), 0);

    viewport.setSnapshot(session->view());
    const QImage withGhost = viewport.grabImage();
    viewport.setShowRestGhost(false);
    const QImage withoutGhost = viewport.grabImage();
    const QRectF legend = sceneLegendRect(viewport.scene(), viewport.size(), true);
    const int different = countDifferent(withGhost, withoutGhost, 3, legend);
    EXPECT_GT(different, 50) << "the ghost shows over the dent";
    // ... and only around the dent: near the touched vertex.
    const auto centre = viewport.camera().projectToPixel(viewport.scene().positionsMm()[session->view().touched],
                                                         glm::vec2(640.0f, 480.0f));
    ASSERT_TRUE(centre);
    const QRectF around(centre->x - 120.0, centre->y - 120.0, 240.0, 240.0);
    QImage masked = withGhost;
    for (int y = 0; y < masked.height(); ++y)
        for (int x = 0; x < masked.width(); ++x)
            if (around.contains(QPointF(x + 0.5, y + 0.5))) masked.setPixel(x, y, withoutGhost.pixel(x, y));
    EXPECT_EQ(countDifferent(masked, withoutGhost, 3, legend), 0) << "ghost drawn away from the dent";
}

// The instructor's see-through view: while a lump inside the tissue is shown, the surface is drawn
// faded towards the background (style::kSeeThroughOpacity), everywhere but where the markers paint;
// without the lump the picture is the plain one again.
TEST(SoftwareViewportFeatures, ALumpShownInsideTheTissueDrawsTheSurfaceSeeThrough) {
    auto session = steppedSession(0);
    SoftwareViewport viewport;
    viewport.resize(640, 480);
    viewport.setMesh(*session->drawnMesh());
    const QImage plain = viewport.grabImage();
    EXPECT_EQ(viewport.surfaceOpacity(), 1.0f);

    ExerciseMarkers markers;
    markers.markers.push_back(lumpMarkerFacingTheCamera(viewport));
    viewport.setExerciseMarkers(markers);
    EXPECT_EQ(viewport.surfaceOpacity(), style::kSeeThroughOpacity);
    const QImage seeThrough = viewport.grabImage();

    const auto centre = viewport.camera().projectToPixel(markers.markers[0].positionMm, glm::vec2(640.0f, 480.0f));
    ASSERT_TRUE(centre);
    const QRectF markerArea(centre->x - 80.0, centre->y - 80.0, 160.0, 160.0);
    const QRgb background = toQColor(style::kBackground).rgb();
    const FadedCount faded = countFaded(plain, seeThrough, background, style::kSeeThroughOpacity, markerArea, 2);
    EXPECT_GT(faded.surface, 640 * 480 / 8);
    EXPECT_GE(faded.faded, faded.surface * 99 / 100) << faded.faded << " of " << faded.surface;

    // A surface marker alone (a target) keeps the surface opaque.
    markers.markers[0].bodyRadiusMm = 0.0;
    viewport.setExerciseMarkers(markers);
    EXPECT_EQ(countDifferent(viewport.grabImage(), plain, 0, markerArea), 0);
}

TEST(SoftwareViewportFeatures, ShadesTheDentWithNormalsRecomputedAroundIt) {
    auto session = steppedSession(0);
    SoftwareViewport viewport;
    viewport.resize(640, 480);
    viewport.setMesh(*session->drawnMesh());
    (void)viewport.grabImage();
    const std::vector<glm::vec3> atRest = viewport.vertexNormals();
    ASSERT_EQ(atRest.size(), viewport.scene().vertexCount());

    const float kCos5Deg = std::cos(5.0f * 3.14159265f / 180.0f);
    // Several frames into the press, each taking only the vertices that changed.
    for (int frame = 0; frame < 10; ++frame) {
        session->step(kTicksIntoContact / 10);
        session->observe();
        viewport.setSnapshot(session->view());
        (void)viewport.grabImage();
    }
    ASSERT_TRUE(session->view().contact);
    const VertexId touched = session->view().touched;
    // The drawn normals are the deformed shape's, everywhere (as if all were recomputed) ...
    std::vector<glm::vec3> expected;
    viewport.scene().computeVertexNormals(expected);
    ASSERT_EQ(viewport.vertexNormals().size(), expected.size());
    std::size_t turned = 0;
    for (VertexId v = 0; v < expected.size(); ++v) {
        ASSERT_EQ(viewport.vertexNormals()[v], expected[v]) << "vertex " << v;
        if (glm::dot(expected[v], atRest[v]) < kCos5Deg) ++turned;
    }
    // ... so in the dent they turned away from the rest normals: the dent shades as a dent.
    EXPECT_GT(turned, 5u);
    bool ringTurned = false;
    for (const std::uint32_t t : viewport.scene().vertexTriangles(touched))
        for (int k = 0; k < 3; ++k) {
            const VertexId w = viewport.scene().indices()[3 * t + k];
            if (glm::dot(expected[w], atRest[w]) < kCos5Deg) ringTurned = true;
        }
    EXPECT_TRUE(ringTurned) << "the normals around the touched vertex";
}

TEST(SoftwareViewportFeatures, SkippingTheBackFacesOfAClosedMeshDrawsTheSamePicture) {
    auto session = steppedSession(kTicksIntoContact);
    SoftwareViewport viewport;
    viewport.resize(640, 480);
    viewport.setMesh(*session->drawnMesh());
    ASSERT_TRUE(viewport.scene().closedAndConsistent()) << "the default organ is a closed surface";
    EXPECT_NE(viewport.scene().outwardWinding(), 0);
    EXPECT_TRUE(viewport.scene().outside(viewport.camera().eyeMm()));
    viewport.setSnapshot(session->view());
    for (const bool wireframe : {true, false}) {
        viewport.setWireframe(wireframe);
        viewport.setBackFaceCulling(true);
        const QImage culled = viewport.grabImage();
        viewport.setBackFaceCulling(false);
        const QImage all = viewport.grabImage();
        // Pixel centres exactly on a silhouette edge may pick the other face: a handful at most.
        EXPECT_LE(countDifferent(culled, all, 2), 20) << "wireframe " << wireframe;
        EXPECT_GT(countNotNear(culled, toQColor(style::kBackground).rgb(), 6), 640 * 480 / 5);
    }
    // An open surface (two triangles) is not closed: both its sides are drawn.
    auto open = TissueMesh::fromTriangles({{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {10, 10, 0}}, {{0, 1, 2}, {1, 3, 2}}, "open");
    ASSERT_TRUE(open.mesh) << open.report.text();
    RenderScene openScene;
    openScene.setMesh(*open.mesh);
    EXPECT_FALSE(openScene.closedAndConsistent());
    EXPECT_EQ(openScene.outwardWinding(), 0);
}

TEST(SoftwareViewportFeatures, RedrawingOnlyAroundTheDentGivesTheSamePictureAsAWholeFrame) {
    auto session = steppedSession(kTicksIntoContact / 2);
    SoftwareViewport incremental;
    incremental.resize(640, 480);
    incremental.setMesh(*session->drawnMesh());
    incremental.setSnapshot(session->view());
    (void)incremental.grabImage();
    EXPECT_TRUE(incremental.lastRaster().whole) << "a new mesh is drawn whole";
    std::size_t partialFrames = 0;
    for (int frame = 0; frame < 20; ++frame) {
        session->step(kTicksIntoContact / 20);
        session->observe();
        incremental.setSnapshot(session->view());
        (void)incremental.grabImage();
        if (!incremental.lastRaster().whole) {
            ++partialFrames;
            EXPECT_LT(incremental.lastRaster().regionPx, std::size_t(640 * 480 / 4)) << "frame " << frame;
        }
    }
    EXPECT_GT(partialFrames, 15u) << "while only the dent changes, only its rectangle is drawn again";
    ASSERT_TRUE(session->view().contact);

    SoftwareViewport whole;
    whole.resize(640, 480);
    whole.setMesh(*session->drawnMesh());
    whole.setSnapshot(session->view());
    const QImage expected = whole.grabImage();
    EXPECT_TRUE(whole.lastRaster().whole);
    EXPECT_EQ(countDifferent(incremental.grabImage(), expected, 0), 0);
    // Nothing new: the picture is kept, nothing is drawn again.
    (void)incremental.grabImage();
    EXPECT_EQ(incremental.lastRaster().regionPx, 0u);
    // A camera move draws all again.
    incremental.resetCamera();
    incremental.fitCamera();
    QWheelEvent wheel(QPointF(320, 240), QPointF(320, 240), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(&incremental, &wheel);
    (void)incremental.grabImage();
    EXPECT_TRUE(incremental.lastRaster().whole);
}

TEST(SoftwareViewportFeatures, TheForceLabelSitsOnAnOpaquePlateWithReadableContrast) {
    auto session = steppedSession(kTicksIntoContact);
    SoftwareViewport viewport;
    viewport.resize(640, 480);
    viewport.setMesh(*session->drawnMesh());
    viewport.setSnapshot(session->view());
    ASSERT_GT(glm::length(viewport.scene().forceN()), 0.0f);
    const QImage image = viewport.grabImage();
    const QRectF plate = forceLabelRect(viewport.scene(), viewport.camera(), viewport.size());
    ASSERT_FALSE(plate.isEmpty());
    EXPECT_TRUE(QRectF(0, 0, 640, 480).contains(plate)) << "kept inside the viewport";
    EXPECT_GE(plate.height(), double(style::kLabelFontPx)) << "a larger font than the legend's";
    // The plate is opaque: its colour whatever lies under it (tissue, rings, background).
    const QColor plateColour = toQColor(style::kLabelPlate);
    const QRect inner = plate.toAlignedRect().adjusted(2, 2, -2, -2);
    int platePixels = 0, all = 0;
    double bestContrast = 1.0;
    for (int y = inner.top(); y <= inner.bottom(); ++y)
        for (int x = inner.left(); x <= inner.right(); ++x) {
            ++all;
            const QRgb pixel = image.pixel(x, y);
            if (nearRgb(pixel, plateColour.rgb(), 2)) ++platePixels;
            bestContrast = std::max(bestContrast, contrastRatio(QColor(pixel), plateColour));
        }
    EXPECT_GT(platePixels, all / 2) << "the plate shows between the letters";
    // The text on it: the pixels most unlike the plate are the letters' cores.
    EXPECT_GE(bestContrast, 4.5);
    EXPECT_GE(contrastRatio(toQColor(style::kForceArrow), plateColour), 4.5);
    // The formula itself: black on white is 21, a colour against itself 1.
    EXPECT_NEAR(contrastRatio(Qt::black, Qt::white), 21.0, 1e-9);
    EXPECT_NEAR(contrastRatio(plateColour, plateColour), 1.0, 1e-9);
}

TEST(SoftwareViewportFeatures, TheForceLabelStaysOffTheDentWhenTheForcePointsAtTheViewer) {
    auto session = steppedSession(kTicksIntoContact);
    SoftwareViewport viewport;
    viewport.resize(640, 480);
    viewport.setMesh(*session->drawnMesh());
    viewport.setSnapshot(session->view());
    // The same press with the force turned towards the eye: its arrow is seen end-on, a few pixels.
    SceneSnapshot towards = session->view();
    const glm::vec3 at = towards.toolRadiusMm > 0.0f ? towards.proxyMm : towards.toolTipMm;
    towards.forceN = 2.0f * glm::normalize(viewport.camera().eyeMm() - at);
    viewport.setSnapshot(towards);
    const QRectF patch = displacedPatchRect(viewport.scene(), viewport.camera(), viewport.size());
    const QRectF label = forceLabelRect(viewport.scene(), viewport.camera(), viewport.size());
    ASSERT_FALSE(patch.isEmpty());
    ASSERT_FALSE(label.isEmpty());
    EXPECT_FALSE(label.intersects(patch)) << "label (" << label.x() << ", " << label.y() << ", " << label.width() << " x "
                                          << label.height() << ") over the dent (" << patch.x() << ", " << patch.y()
                                          << ", " << patch.width() << " x " << patch.height() << ")";
    EXPECT_TRUE(QRectF(0, 0, 640, 480).contains(label));
}

TEST(SoftwareViewportFeatures, OutlinesTheDisplacedPatchAndMarksItWhenSmall) {
    auto session = steppedSession(kTicksIntoContact);
    SoftwareViewport viewport;
    viewport.resize(640, 480);
    viewport.setMesh(*session->drawnMesh());
    const QRgb outline = toQColor(style::kPatchOutline).rgb();
    auto outlinePixels = [&](const QImage& image, const QRectF& exclude) {
        int count = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                if (!exclude.contains(QPointF(x + 0.5, y + 0.5)) && nearRgb(image.pixel(x, y), outline, 12)) ++count;
        return count;
    };
    EXPECT_EQ(outlinePixels(viewport.grabImage(), {}), 0) << "no outline at rest";

    viewport.setSnapshot(session->view());
    const QRectF legend = sceneLegendRect(viewport.scene(), viewport.size());
    const int near = outlinePixels(viewport.grabImage(), legend);
    EXPECT_GT(near, 40) << "the patch's border";
    EXPECT_GT(deepestDisplacementMm(viewport.scene()), style::kOutlineDisplacementMm);

    // Far away (as a fine mesh's patch looks) the patch is a few pixels: a circle still marks it.
    viewport.resetCamera();
    for (int step = 0; step < 12; ++step) {
        QWheelEvent wheel(QPointF(320, 240), QPointF(320, 240), QPoint(), QPoint(0, -120), Qt::NoButton, Qt::NoModifier,
                          Qt::NoScrollPhase, false);
        QApplication::sendEvent(&viewport, &wheel);
    }
    const int far = outlinePixels(viewport.grabImage(), sceneLegendRect(viewport.scene(), viewport.size()));
    EXPECT_GT(far, int(style::kPatchMarkerMinRadiusPx * 2.0f)) << "a circle of at least the minimum radius";
}

TEST(SoftwareViewportFeatures, RightAndMiddleDragPanLeftDragOrbits) {
    auto session = steppedSession(0);
    SoftwareViewport viewport;
    viewport.resize(640, 480);
    viewport.setMesh(*session->drawnMesh());
    viewport.show();
    EXPECT_EQ(viewport.contextMenuPolicy(), Qt::PreventContextMenu);

    const OrbitCamera start = viewport.camera();
    drag(viewport, Qt::RightButton, {300, 200}, {340, 230});
    EXPECT_NE(viewport.camera().targetMm(), start.targetMm()) << "right-drag pans";
    EXPECT_EQ(viewport.camera().yawDeg(), start.yawDeg());
    EXPECT_EQ(viewport.camera().pitchDeg(), start.pitchDeg());
    // The point that was at the centre moved with the mouse.
    const auto moved = viewport.camera().projectToPixel(start.targetMm(), glm::vec2(640.0f, 480.0f));
    ASSERT_TRUE(moved);
    EXPECT_NEAR(moved->x, 360.0f, 0.1f);
    EXPECT_NEAR(moved->y, 270.0f, 0.1f);

    const glm::vec3 afterRight = viewport.camera().targetMm();
    drag(viewport, Qt::MiddleButton, {300, 200}, {280, 200});
    EXPECT_NE(viewport.camera().targetMm(), afterRight) << "middle-drag pans";

    const glm::vec3 afterMiddle = viewport.camera().targetMm();
    drag(viewport, Qt::LeftButton, {300, 200}, {350, 200});
    EXPECT_EQ(viewport.camera().targetMm(), afterMiddle) << "left-drag orbits about the target";
    EXPECT_NE(viewport.camera().yawDeg(), start.yawDeg());

    viewport.resetCamera();
    EXPECT_LT(glm::length(viewport.camera().targetMm() - start.targetMm()), 1e-3f);
    EXPECT_EQ(viewport.camera().yawDeg(), start.yawDeg());
    viewport.fitCamera();
    EXPECT_LT(glm::length(viewport.camera().targetMm() - start.targetMm()), 1e-3f);
}

TEST(SoftwareViewportFeatures, PicksTheVertexUnderTheMouse) {
    auto session = steppedSession(kTicksIntoContact);
    SoftwareViewport viewport;
    viewport.resize(640, 480);
    viewport.setMesh(*session->drawnMesh());
    viewport.setSnapshot(session->view());
    const glm::vec2 size(640.0f, 480.0f);

    auto pickAtVertex = [&](VertexId v) -> std::optional<VertexId> {
        const auto p = viewport.camera().projectToPixel(viewport.scene().positionsMm()[v], size);
        if (!p) return std::nullopt;
        return viewport.pickVertex(QPoint(int(std::floor(p->x)), int(std::floor(p->y))));
    };
    const VertexId nearest = vertexNearestTheEye(viewport.scene(), viewport.camera());
    EXPECT_EQ(pickAtVertex(nearest), nearest);
    // The touched vertex, pressed in, is still picked (picking uses the deformed positions).
    const VertexId touched = session->view().touched;
    ASSERT_NE(touched, kNoVertex);
    EXPECT_EQ(pickAtVertex(touched), touched);
    // Over the background: nothing.
    EXPECT_FALSE(viewport.pickVertex(QPoint(2, 2)));

    // After orbiting and panning the same holds: the same camera draws and picks.
    viewport.widget()->resize(500, 400);
    drag(viewport, Qt::LeftButton, {200, 200}, {260, 180});
    drag(viewport, Qt::RightButton, {200, 200}, {230, 220});
    const VertexId nearestNow = vertexNearestTheEye(viewport.scene(), viewport.camera());
    const auto p = viewport.camera().projectToPixel(viewport.scene().positionsMm()[nearestNow], glm::vec2(500.0f, 400.0f));
    ASSERT_TRUE(p);
    EXPECT_EQ(viewport.pickVertex(QPoint(int(std::floor(p->x)), int(std::floor(p->y)))), nearestNow);
}

// --- through the window: the observer's rings reach the viewport ---

TEST(MainWindowRings, TheViewportGetsTheRingsOfEachSnapshot) {
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    ASSERT_EQ(window.loadMesh(defaultMeshPath()), QString());
    window.advanceTicks(kTicksIntoContact);
    ASSERT_TRUE(window.session().observed().contact);
    const RenderScene& scene = window.viewport()->scene();
    EXPECT_EQ(scene.highestRing(), 2);
    EXPECT_EQ(scene.ringVertexCount(0), 1u);
    EXPECT_EQ(scene.rings()[window.session().observed().touched], 0);
    EXPECT_GT(scene.ringVertexCount(1), 3u);
    EXPECT_GT(scene.ringVertexCount(2), scene.ringVertexCount(1));

    window.advanceTicks(6500 - kTicksIntoContact);  // the stroke is over and the tissue has relaxed
    EXPECT_EQ(scene.highestRing(), -1);
}

int main(int argc, char** argv) {
    // Before QApplication: the platform is chosen in its constructor. No GPU, no display needed.
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QStandardPaths::setTestModeEnabled(true);  // the windows' results databases are not the user's
    QApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
