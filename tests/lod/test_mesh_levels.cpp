// Decimation into levels: every level stays closed, manifold, genus 0 and outward-facing, reaches
// its vertex target (or says it did not), and follows the source surface; progress rises to 1;
// cancel stops with complete levels only; bad options and unusable input are named errors.
#include "engine/lod/MeshLevels.h"
#include "engine/lod/NearestTriangle.h"
#include "tests/engine/TestMeshes.h"
#include "tests/lod/LodTestMeshes.h"

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <set>

namespace palpate {
namespace {

using test::generated;
using test::levelsOf;

class Levels : public ::testing::TestWithParam<GeneratedShape> {};

TEST_P(Levels, EveryLevelIsClosedManifoldGenusZeroAndOutward) {
    const MeshLevels& levels = levelsOf(GetParam(), 3970);
    ASSERT_GE(levels.levels.size(), 4u);  // 3970 -> 1985 -> 992 -> 496 -> 248
    EXPECT_FALSE(levels.cancelled);
    for (std::size_t k = 1; k < levels.levels.size(); ++k) {
        const TissueMesh& mesh = levels.levels[k].mesh;
        SCOPED_TRACE("level " + std::to_string(k));
        // Checked from the raw triangles by code that is not the engine's (tests/engine/TestMeshes).
        const auto facts = test::topologyFacts(mesh.vertexCount(), mesh.triangles());
        EXPECT_EQ(facts.boundaryEdges, 0u);
        EXPECT_EQ(facts.nonManifoldEdges, 0u);
        EXPECT_EQ(facts.nonManifoldVertices, 0u);
        EXPECT_EQ(facts.misorientedEdges, 0u);
        // Euler: V - E + F = 2 for a closed genus-0 surface, so F = 2V - 4.
        EXPECT_EQ(mesh.triangleCount(), 2 * mesh.vertexCount() - 4);
        EXPECT_EQ(long(mesh.vertexCount()) - long(facts.edgeCount) + long(mesh.triangleCount()), 2);
        EXPECT_GT(test::signedVolume6(mesh.restPositionsMm(), mesh.triangles()), 0.0);
        EXPECT_EQ(levelTopologyProblem(levels.levels[0].mesh, mesh), "");
        // Fewer vertices each level; the target reached, or a note that says why not.
        EXPECT_LT(mesh.vertexCount(), levels.levels[k - 1].mesh.vertexCount());
        if (mesh.vertexCount() != levels.levels[k].targetVertices) {
            bool noted = false;
            for (const auto& n : levels.notes) noted |= n.find("level " + std::to_string(k)) != std::string::npos;
            EXPECT_TRUE(noted) << mesh.vertexCount() << " vs target " << levels.levels[k].targetVertices;
        }
    }
}

TEST_P(Levels, TargetsAreReachedOnSmoothShapes) {
    const MeshLevels& levels = levelsOf(GetParam(), 3970);
    for (std::size_t k = 1; k < levels.levels.size(); ++k)
        EXPECT_EQ(levels.levels[k].mesh.vertexCount(), levels.levels[k].targetVertices) << "level " << k;
}

TEST_P(Levels, NoTriangleFlipsAgainstTheSourceAndVerticesStayOnIt) {
    const MeshLevels& levels = levelsOf(GetParam(), 3970);
    const TissueMesh& fine = levels.levels[0].mesh;
    NearestTriangle search(fine);
    std::set<std::tuple<float, float, float>> finePoints;
    for (const glm::vec3& p : fine.restPositionsMm()) finePoints.insert({p.x, p.y, p.z});
    for (std::size_t k = 1; k < levels.levels.size(); ++k) {
        const TissueMesh& mesh = levels.levels[k].mesh;
        const auto& rest = mesh.restPositionsMm();
        // A half-edge collapse keeps the surviving vertex where it was.
        for (const glm::vec3& p : rest) EXPECT_TRUE(finePoints.count({p.x, p.y, p.z})) << "level " << k;
        std::size_t flipped = 0;
        for (const auto& t : mesh.triangles()) {
            const glm::dvec3 a(rest[t[0]]), b(rest[t[1]]), c(rest[t[2]]);
            const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
            const glm::dvec3 centroid = (a + b + c) / 3.0;
            const auto& f = fine.triangles()[search.nearest(centroid).triangle];
            const glm::dvec3 fa(fine.restPositionsMm()[f[0]]), fb(fine.restPositionsMm()[f[1]]), fc(fine.restPositionsMm()[f[2]]);
            const glm::dvec3 fn = glm::normalize(glm::cross(fb - fa, fc - fa));
            // The guard bounds each collapse's normal change; over a level the triangle must still
            // face the same side as the surface it stands for.
            if (glm::dot(n, fn) <= 0.0) ++flipped;
        }
        EXPECT_EQ(flipped, 0u) << "level " << k;
    }
}

INSTANTIATE_TEST_SUITE_P(Shapes, Levels, ::testing::Values(GeneratedShape::Sphere, GeneratedShape::Stomach),
                         [](const auto& info) { return std::string(shapeName(info.param)); });

TEST(MeshLevels, TargetsFollowTheOptions) {
    LevelDef o;
    o.vertexRatio = 0.5;
    o.minVertices = 250;
    o.maxCoarseLevels = 5;
    EXPECT_EQ(levelTargets(8664, o), (std::vector<std::size_t>{4332, 2166, 1083, 542, 271}));
    o.maxCoarseLevels = 2;
    EXPECT_EQ(levelTargets(8664, o), (std::vector<std::size_t>{4332, 2166}));
    o.maxCoarseLevels = 5;
    EXPECT_TRUE(levelTargets(400, o).empty());
}

TEST(MeshLevels, ASmallMeshHasOnlyItsSourceLevelAndSaysWhy) {
    LevelDef o;
    o.minVertices = 250;
    const MeshLevels levels = generateLevels(generated(GeneratedShape::Sphere, 300), o);
    ASSERT_EQ(levels.levels.size(), 1u);
    ASSERT_EQ(levels.notes.size(), 1u);
    EXPECT_NE(levels.notes[0].find("no coarser level"), std::string::npos) << levels.notes[0];
}

// A vertex with thousands of triangles around it (a fan from a CAD export) would make the
// decimater run for hours at 0 %: refused at once, naming the vertex and what to do.
TEST(MeshLevels, AHugeFanIsRefusedAtOnceNamingItsVertex) {
    constexpr int kFan = 600;
    std::vector<glm::vec3> positions{{0.0f, 0.0f, 30.0f}};
    for (int i = 0; i < kFan; ++i) {
        const float a = 6.2831853f * float(i) / float(kFan);
        positions.push_back({40.0f * std::cos(a), 40.0f * std::sin(a), 0.0f});
    }
    positions.push_back({0.0f, 0.0f, -30.0f});
    std::vector<std::array<VertexId, 3>> triangles;
    for (int i = 0; i < kFan; ++i) {
        const VertexId a = VertexId(1 + i), b = VertexId(1 + (i + 1) % kFan);
        triangles.push_back({0, a, b});
        triangles.push_back({VertexId(kFan + 1), b, a});
    }
    auto loaded = TissueMesh::fromTriangles(positions, triangles, "hub.off");
    ASSERT_TRUE(loaded.mesh) << loaded.error();
    try {
        generateLevels(*loaded.mesh, LevelDef{});
        ADD_FAILURE() << "a 600-triangle fan was decimated";
    } catch (const std::exception& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("600 triangles around it"), std::string::npos) << what;
        EXPECT_NE(what.find("remesh"), std::string::npos) << what;
    }
}

TEST(MeshLevels, BadOptionsAreNamed) {
    const TissueMesh& mesh = generated(GeneratedShape::Sphere, 1442);
    auto expectThrowNaming = [&](LevelDef o, const std::string& words) {
        try {
            generateLevels(mesh, o);
            ADD_FAILURE() << "accepted options; wanted an error with '" << words << "'";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
    };
    LevelDef o;
    o.vertexRatio = 1.5;
    expectThrowNaming(o, "vertex ratio");
    o = {};
    o.minVertices = 3;
    expectThrowNaming(o, "min vertices");
    o = {};
    o.guards.maxNormalDeviationDeg = -10;
    expectThrowNaming(o, "normal deviation");
    o = {};
    o.guards.maxAspectRatio = 0.5;
    expectThrowNaming(o, "aspect ratio");
}

TEST(MeshLevels, ProgressRisesToOneAndCancelKeepsOnlyCompleteLevels) {
    const TissueMesh& mesh = generated(GeneratedShape::Sphere, 3970);
    LevelDef o;
    o.minVertices = 200;
    std::vector<double> fractions;
    const MeshLevels all = generateLevels(mesh, o, [&](double f, const std::string&) { fractions.push_back(f); });
    ASSERT_GE(fractions.size(), 3u);
    for (std::size_t i = 1; i < fractions.size(); ++i) EXPECT_GE(fractions[i], fractions[i - 1]);
    EXPECT_EQ(fractions.back(), 1.0);

    // Cancelled before it starts: the source only.
    std::atomic<bool> cancel{true};
    const MeshLevels none = generateLevels(mesh, o, {}, &cancel);
    EXPECT_TRUE(none.cancelled);
    EXPECT_EQ(none.levels.size(), 1u);

    // Cancelled from the progress callback (as a GUI's Cancel button would, from another thread)
    // in the middle of decimation: the levels kept are complete, each as the full run made it.
    cancel = false;
    const MeshLevels some = generateLevels(mesh, o, [&](double f, const std::string&) { if (f > 0.2) cancel = true; }, &cancel);
    EXPECT_TRUE(some.cancelled);
    EXPECT_LT(some.levels.size(), all.levels.size());
    for (std::size_t k = 1; k < some.levels.size(); ++k) {
        EXPECT_EQ(some.levels[k].mesh.vertexCount(), all.levels[k].mesh.vertexCount());
        EXPECT_EQ(some.levels[k].fineOnLevel.size(), mesh.vertexCount());
    }
}

TEST(MeshLevels, AnOpenSurfaceStaysUsableAndOpen) {
    auto built = test::gridPatch(40, 40, 1.0f).build("grid");
    ASSERT_TRUE(built.mesh) << built.error();
    LevelDef o;
    o.minVertices = 100;
    const MeshLevels levels = generateLevels(*built.mesh, o);
    ASSERT_GE(levels.levels.size(), 2u);
    for (std::size_t k = 1; k < levels.levels.size(); ++k) {
        const auto facts = test::topologyFacts(levels.levels[k].mesh.vertexCount(), levels.levels[k].mesh.triangles());
        EXPECT_GT(facts.boundaryEdges, 0u);
        EXPECT_EQ(facts.nonManifoldEdges, 0u);
        EXPECT_EQ(facts.nonManifoldVertices, 0u);
    }
}

}  // namespace
}  // namespace palpate

namespace palpate {
namespace {

TEST(MeshLevels, StrictGuardsStopShortAndSaySo) {
    // A 0.01 degree normal guard forbids nearly every collapse on a sphere: the levels that cannot
    // be made are reported, never faked with a copy of the level before.
    LevelDef o;
    o.minVertices = 200;
    o.guards.maxNormalDeviationDeg = 0.01;
    const MeshLevels levels = generateLevels(test::generated(GeneratedShape::Sphere, 1442), o);
    ASSERT_FALSE(levels.notes.empty());
    bool stopped = false;
    for (const auto& n : levels.notes) stopped |= n.find("guards") != std::string::npos;
    EXPECT_TRUE(stopped) << levels.notes.front();
    for (std::size_t k = 1; k < levels.levels.size(); ++k) {
        EXPECT_LT(levels.levels[k].mesh.vertexCount(), levels.levels[k - 1].mesh.vertexCount());
        EXPECT_EQ(levelTopologyProblem(levels.levels[0].mesh, levels.levels[k].mesh), "");
    }
    EXPECT_LT(levels.levels.size(), levelTargets(1442, o).size() + 1);
}

}  // namespace
}  // namespace palpate
