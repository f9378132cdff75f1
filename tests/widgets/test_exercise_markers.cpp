// The heat map over the tissue is drawn into an image once per camera, size and heat map, and that
// image reused while the view stands still (docs/scoring.md, "Coverage"): these tests hold that
// reuse to never show a heat map, camera or size other than the current one.

#include "widgets/ExerciseMarkers.h"
#include "widgets/OrbitCamera.h"

#include "tests/support/Meshes.h"

#include <QImage>
#include <QPainter>

#include <gtest/gtest.h>

namespace palpate {
namespace {

ExerciseMarkers heatOver(const TissueMesh& mesh, float forceN, std::size_t every) {
    ExerciseMarkers markers;
    markers.heatMinN = 0.4;
    markers.heatMaxN = 4.0;
    for (std::size_t v = 0; v < mesh.vertexCount(); v += every)
        markers.heat.push_back({mesh.restPositionsMm()[v], mesh.restNormals()[v], forceN});
    return markers;
}

QImage painted(const ExerciseMarkers& markers, const OrbitCamera& camera, QSize size = QSize(320, 240)) {
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::black);
    QPainter painter(&image);
    paintExerciseMarkers(painter, markers, camera, size);
    return image;
}

/// The same picture, drawn with nothing cached before it (another heat map painted in between).
QImage paintedFresh(const ExerciseMarkers& markers, const OrbitCamera& camera, QSize size = QSize(320, 240)) {
    ExerciseMarkers other = markers;
    for (HeatPoint& h : other.heat) h.forceN = 0.0f;
    painted(other, camera, QSize(17, 13));
    return painted(markers, camera, size);
}

TEST(HeatMap, TheReusedLayerFollowsTheHeatMapTheCameraAndTheSize) {
    const TissueMesh& mesh = test::generatedMesh(GeneratedShape::Sphere, 1442);
    OrbitCamera camera;
    camera.reset(mesh.restPositionsMm());
    const ExerciseMarkers light = heatOver(mesh, 0.5f, 1), firm = heatOver(mesh, 3.9f, 1);

    const QImage first = painted(light, camera);
    EXPECT_EQ(painted(light, camera), first) << "the same view twice: the same picture";
    EXPECT_EQ(paintedFresh(light, camera), first) << "reused, it is what a fresh drawing gives";
    // Another heat map of as many points (forces changed): drawn anew, in its own colours.
    const QImage firmImage = painted(firm, camera);
    EXPECT_NE(firmImage, first);
    EXPECT_EQ(firmImage, paintedFresh(firm, camera));
    // Fewer points, the camera turned, another size: each drawn anew.
    EXPECT_EQ(painted(heatOver(mesh, 0.5f, 2), camera), paintedFresh(heatOver(mesh, 0.5f, 2), camera));
    OrbitCamera turned = camera;
    turned.orbit(120.0f, 0.0f);
    const QImage turnedImage = painted(light, turned);
    EXPECT_NE(turnedImage, first);
    EXPECT_EQ(turnedImage, paintedFresh(light, turned));
    EXPECT_EQ(painted(light, camera, QSize(400, 300)), paintedFresh(light, camera, QSize(400, 300)));
    // And back to the first view: the first picture.
    EXPECT_EQ(painted(light, camera), first);
}

TEST(HeatMap, OnlyTheSideFacingTheCameraIsColoured) {
    const TissueMesh& mesh = test::generatedMesh(GeneratedShape::Sphere, 1442);
    OrbitCamera camera;
    camera.reset(mesh.restPositionsMm());
    // Only the points facing away: nothing of the heat map's colour inside the sphere's outline.
    ExerciseMarkers away;
    away.heatMinN = 0.4;
    away.heatMaxN = 4.0;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
        if (glm::dot(mesh.restNormals()[v], camera.eyeMm() - mesh.restPositionsMm()[v]) < 0.0f)
            away.heat.push_back({mesh.restPositionsMm()[v], mesh.restNormals()[v], 2.0f});
    ASSERT_FALSE(away.heat.empty());
    const QImage image = painted(away, camera);
    const QColor colour = heatColour(2.0, 0.4, 4.0);
    int coloured = 0;
    for (int y = 0; y < image.height() - 40; ++y)  // above the scale
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            coloured += (c.red() > 40 || c.green() > 40) && std::abs(c.hue() - colour.hue()) < 10 ? 1 : 0;
        }
    EXPECT_EQ(coloured, 0);
    EXPECT_GT(
        [&] {
            int n = 0;
            const QImage facing = painted(heatOver(mesh, 2.0f, 1), camera);
            for (int y = 0; y < facing.height() - 40; ++y)
                for (int x = 0; x < facing.width(); ++x) n += facing.pixelColor(x, y) != QColor(Qt::black) ? 1 : 0;
            return n;
        }(),
        1000);
}

}  // namespace
}  // namespace palpate

namespace palpate {
namespace {

// A lump's label is drawn beside its surface point, never across its ball: also when the
// viewport's edge pushes it to the ball's side (then it goes above or below the ball).
TEST(LumpLabel, NeverCrossesItsBallEvenAtTheViewportsEdge) {
    const TissueMesh& mesh = test::generatedMesh(GeneratedShape::Sphere, 1442);
    OrbitCamera camera;
    camera.reset(mesh.restPositionsMm());
    const QSize size(320, 240);
    const glm::vec2 sizeF(320.0f, 240.0f);
    // The front-facing vertex furthest right on screen: its lump lies to its left, and there is no
    // room for the label on its right.
    VertexId right = 0;
    float rightX = -1e9f;
    for (VertexId v = 0; v < mesh.vertexCount(); ++v) {
        const glm::vec3& p = mesh.restPositionsMm()[v];
        if (glm::dot(mesh.restNormals()[v], camera.eyeMm() - p) <= 0.0f) continue;
        if (const auto px = camera.projectToPixel(p, sizeF); px && px->x > rightX) {
            rightX = px->x;
            right = v;
        }
    }
    ExerciseMarker lump;
    lump.kind = ExerciseMarker::Kind::Inclusion;
    lump.positionMm = mesh.restPositionsMm()[right];
    lump.normal = mesh.restNormals()[right];
    lump.radiusMm = 7.0;
    lump.bodyRadiusMm = 7.0;
    lump.bodyCentreMm = lump.positionMm - 15.0f * lump.normal;  // 8 mm deep
    lump.label = QStringLiteral("lump 1, 8.0 mm deep");
    ExerciseMarkers withLabel, without;
    withLabel.markers.push_back(lump);
    lump.label.clear();
    without.markers.push_back(lump);
    const QImage a = painted(withLabel, camera, size), b = painted(without, camera, size);
    const auto ball = camera.projectToPixel(lump.bodyCentreMm, sizeF);
    ASSERT_TRUE(ball);
    const float ballPx = float(lump.bodyRadiusMm) / camera.mmPerPixelAtTarget(sizeF);
    int labelPixels = 0, onBall = 0;
    for (int y = 0; y < size.height(); ++y)
        for (int x = 0; x < size.width(); ++x) {
            if (a.pixel(x, y) == b.pixel(x, y)) continue;
            ++labelPixels;
            onBall += glm::distance(glm::vec2(float(x) + 0.5f, float(y) + 0.5f), *ball) < 0.9f * ballPx ? 1 : 0;
        }
    EXPECT_GT(labelPixels, 50) << "the label is drawn";
    EXPECT_EQ(onBall, 0) << "of " << labelPixels << " label pixels";
}

}  // namespace
}  // namespace palpate
