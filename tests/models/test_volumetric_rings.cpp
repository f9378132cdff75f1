// Volumetric slope-rings: the tet fill, rings through the interior, and parity with the surface
// model where the two must agree (ring 0 only).
#include "engine/core/Octree.h"
#include "engine/core/SceneTarget.h"
#include "engine/models/slopering/CoherentSlopeRing.h"
#include "engine/models/slopering/PaperSlopeRing.h"
#include "engine/core/ToolPath.h"
#include "engine/models/VolumetricFill.h"
#include "engine/models/VolumetricRingsModel.h"
#include "tests/models/ModelTestMeshes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

using namespace palpate;

TEST(VolumetricFill, StarShapedFillKeepsTheSurfaceFirstAndFillsTheVolumeExactly) {
    const TissueMesh mesh = test::sphereMesh(642);
    const TetMesh tets = fillStarShapedSurface(mesh, 2);
    ASSERT_EQ(tets.nodeCount(), 3 * mesh.vertexCount() + 1);
    for (VertexId v = 0; v < mesh.vertexCount(); ++v) ASSERT_EQ(glm::vec3(tets.nodesMm[v]), mesh.restPositionsMm()[v]);
    ASSERT_EQ(tets.tetCount(), mesh.triangleCount() * 7);
    // Positively oriented, and together exactly the volume the surface encloses (divergence theorem).
    double tetVolume6 = 0.0;
    for (const auto& t : tets.tets) {
        const double v6 = tetSignedVolume6(tets.nodesMm[t[0]], tets.nodesMm[t[1]], tets.nodesMm[t[2]], tets.nodesMm[t[3]]);
        ASSERT_GT(v6, 0.0);
        tetVolume6 += v6;
    }
    double surfaceVolume6 = 0.0;
    for (const auto& t : mesh.triangles()) {
        const glm::dvec3 a(mesh.restPositionsMm()[t[0]]), b(mesh.restPositionsMm()[t[1]]), c(mesh.restPositionsMm()[t[2]]);
        surfaceVolume6 += glm::dot(a, glm::cross(b, c));
    }
    EXPECT_NEAR(tetVolume6, surfaceVolume6, 1e-9 * surfaceVolume6);
}

TEST(VolumetricFill, TheLeadFillerRenumberedPutsTheSurfaceFirst) {
    // fillSurfaceWithTets: SurfaceFill's prism layers, surface nodes first in the mesh's order,
    // every tet positively oriented, and rings of a surface vertex reaching its inner column.
    for (auto shape : {GeneratedShape::Sphere, GeneratedShape::Stomach}) {
        auto generated = generateMesh(shape, 1442);
        ASSERT_TRUE(generated.mesh);
        const TissueMesh& mesh = *generated.mesh;
        const TetMesh tets = fillSurfaceWithTets(mesh);
        ASSERT_GT(tets.nodeCount(), mesh.vertexCount());
        for (VertexId v = 0; v < mesh.vertexCount(); ++v) ASSERT_EQ(glm::vec3(tets.nodesMm[v]), mesh.restPositionsMm()[v]);
        for (const auto& t : tets.tets)
            ASSERT_GT(tetSignedVolume6(tets.nodesMm[t[0]], tets.nodesMm[t[1]], tets.nodesMm[t[2]], tets.nodesMm[t[3]]), 0.0);
        const Octree octree(mesh, {});
        VolumetricRingsModel model(mesh, octree, tets, {});
        const VertexId t = defaultTargetVertex(mesh);
        const TickResult r = model.step(mesh.restPositionsMm()[t] - 2.0f * mesh.restNormals()[t], 0.001);
        ASSERT_TRUE(r.contact) << shapeName(shape);
        int interior = 0;
        for (std::uint32_t node : model.activeNodes()) interior += node >= mesh.vertexCount() ? 1 : 0;
        EXPECT_GT(interior, 0) << shapeName(shape);
    }
}

TEST(VolumetricFill, RefusesASurfaceThatIsNotStarShaped) {
    auto stomach = generateMesh(GeneratedShape::Stomach, 1442);
    ASSERT_TRUE(stomach.mesh);
    try {
        fillStarShapedSurface(*stomach.mesh, 1);
        FAIL() << "the stomach is not star-shaped about its centroid";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("star-shaped"), std::string::npos) << e.what();
    }
}

TEST(VolumetricRings, RingsReachThroughTheInteriorAndFollowTheSlopes) {
    const TissueMesh mesh = test::sphereMesh(642);
    const Octree octree(mesh, {});
    const TetMesh tets = fillStarShapedSurface(mesh, 2);
    VolumetricRingsParams p;
    VolumetricRingsModel model(mesh, octree, tets, p);
    const VertexId t = defaultTargetVertex(mesh);
    const glm::vec3 n = mesh.restNormals()[t];
    const float depth = 2.0f;
    TickResult r;
    for (int i = 0; i < 5; ++i) r = model.step(mesh.restPositionsMm()[t] - depth * n, 0.001);
    ASSERT_TRUE(r.contact);
    ASSERT_EQ(r.touched, t);
    // Equilibrium of the contact update in one tick (alpha = 1 / (1 + g)): F = k_c d / (1 + g).
    const SlopeRingParams& s = p.slopeRing;
    const double f = s.contactStiffnessNPerMm * depth / (1.0 + s.loopGain());
    EXPECT_NEAR(model.contactForceN(), f, 1e-5);
    EXPECT_NEAR(glm::length(r.forceN), s.springStiffnessNPerMm * s.slopeMagnitudeMmPerN[0] * f, 1e-5);
    // Ring 1 holds the node just below t on the next shell (an interior node).
    const auto ring1 = model.activeNodes().subspan(model.activeRingStart(1), model.activeRingStart(2) - model.activeRingStart(1));
    EXPECT_NE(std::find(ring1.begin(), ring1.end(), std::uint32_t(mesh.vertexCount() + t)), ring1.end());
    // Every node of ring r at rest + m_r F n; the surface shown is the first n nodes.
    const auto nodes = model.nodePositionsMm();
    for (int ring = 0; ring <= model.activeRingCount(); ++ring)
        for (std::uint32_t i = model.activeRingStart(ring); i < model.activeRingStart(ring + 1); ++i) {
            const std::uint32_t node = model.activeNodes()[i];
            const glm::vec3 rest = node < mesh.vertexCount() ? mesh.restPositionsMm()[node] : glm::vec3(tets.nodesMm[node]);
            ASSERT_LT(glm::length(nodes[node] - (rest - float(s.slopeMagnitudeMmPerN[std::size_t(ring)] * f) * n)), 1e-5f);
        }
    EXPECT_EQ(model.positionsMm().size(), mesh.vertexCount());
    // Release: everything returns to rest.
    for (int i = 0; i < 500; ++i) model.step(mesh.restPositionsMm()[t] + 2.0f * n, 0.001);
    for (std::size_t i = 0; i < model.nodeCount(); ++i) {
        const glm::vec3 rest = i < mesh.vertexCount() ? mesh.restPositionsMm()[i] : glm::vec3(tets.nodesMm[i]);
        ASSERT_EQ(nodes[i], rest) << i;
    }
}

TEST(VolumetricRings, WithRingZeroOnlyItIsTheSurfaceModel) {
    // Ring 0 is the touched vertex alone in either graph: the same contact force, rendered force
    // and touched vertex on every tick of a press and stroke.
    const TissueMesh mesh = test::sphereMesh(1442);
    const Octree octree(mesh, {});
    const TetMesh tets = fillStarShapedSurface(mesh, 1);
    VolumetricRingsParams p;
    p.slopeRing.ringCount = 0;
    VolumetricRingsModel volumetric(mesh, octree, tets, p);
    // The surface model with the same vertex contact (the exact paper method; ours blends a contact
    // triangle's rings instead).
    PaperSlopeRing surface(mesh, octree, p.slopeRing, SlopeRingMethod::Previous);
    for (const glm::vec3& tool : makePressAndStrokePath(mesh)) {
        const TickResult a = volumetric.step(tool, 0.001);
        const TickResult b = surface.step(tool, 0.001);
        ASSERT_EQ(a.touched, b.touched);
        ASSERT_EQ(a.contact, b.contact);
        ASSERT_LT(glm::length(a.forceN - b.forceN), 1e-5f);  // float rounding of two formula orders
    }
}

TEST(VolumetricRings, RejectsATetMeshThatDoesNotStartWithTheSurface) {
    const TissueMesh mesh = test::sphereMesh(642);
    const Octree octree(mesh, {});
    TetMesh tets = fillStarShapedSurface(mesh, 1);
    std::swap(tets.nodesMm[0], tets.nodesMm[1]);
    EXPECT_THROW(VolumetricRingsModel(mesh, octree, tets, {}), std::invalid_argument);
}
