// Rings: ring r of a vertex = the vertices at edge distance exactly r. Checked on meshes whose
// answer is known by hand (icosahedron, a triangulated grid with a boundary) and against an
// independent breadth-first search over the raw triangles of a generated mesh.

#include "engine/core/MeshGenerator.h"
#include "engine/core/Rings.h"
#include "tests/engine/TestMeshes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <deque>
#include <optional>
#include <random>
#include <set>

namespace palpate {
namespace {

using test::gridDistance;
using test::gridPatch;
using test::icosahedron;

std::set<VertexId> asSet(std::span<const VertexId> s) { return {s.begin(), s.end()}; }

TEST(Rings, IcosahedronEveryVertexHasRings5_5_1) {
    auto loaded = icosahedron(10.0f).build("icosahedron");
    ASSERT_TRUE(loaded.mesh) << loaded.error();
    const TissueMesh& mesh = *loaded.mesh;
    ASSERT_EQ(mesh.vertexCount(), 12u);
    const auto& p = mesh.restPositionsMm();
    const float edge = glm::length(p[mesh.triangles()[0][0]] - p[mesh.triangles()[0][1]]);

    RingFinder finder(mesh);
    RingSet rings = finder.makeRingSet();
    for (VertexId v = 0; v < 12; ++v) {
        finder.find(v, 3, rings);
        ASSERT_EQ(rings.ringCount, 3);
        ASSERT_EQ(rings.ring(0).size(), 1u);
        EXPECT_EQ(rings.ring(0)[0], v);
        EXPECT_EQ(rings.ring(1).size(), 5u) << "vertex " << v;
        EXPECT_EQ(rings.ring(2).size(), 5u) << "vertex " << v;
        EXPECT_EQ(rings.ring(3).size(), 1u) << "vertex " << v;
        EXPECT_EQ(rings.size(), 12u);
        // Exact sets from geometry: ring 1 = the vertices one edge length away, ring 3 = the antipode.
        std::set<VertexId> ring1, ring2, ring3;
        for (VertexId w = 0; w < 12; ++w) {
            if (w == v) continue;
            const float d = glm::length(p[w] - p[v]);
            if (std::abs(d - edge) < 1e-3f * edge) ring1.insert(w);
            else if (glm::length(p[w] + p[v]) < 1e-3f * edge) ring3.insert(w);
            else ring2.insert(w);
        }
        EXPECT_EQ(asSet(rings.ring(1)), ring1) << "vertex " << v;
        EXPECT_EQ(asSet(rings.ring(2)), ring2) << "vertex " << v;
        EXPECT_EQ(asSet(rings.ring(3)), ring3) << "vertex " << v;
    }
}

TEST(Rings, RingsBeyondTheMeshAreEmptyAndRingCountIsClamped) {
    auto loaded = icosahedron(10.0f).build("icosahedron");
    ASSERT_TRUE(loaded.mesh) << loaded.error();
    RingFinder finder(*loaded.mesh);
    RingSet rings = finder.makeRingSet();
    finder.find(4, 6, rings);
    ASSERT_EQ(rings.ringCount, 6);
    EXPECT_EQ(rings.ring(4).size(), 0u);
    EXPECT_EQ(rings.ring(5).size(), 0u);
    EXPECT_EQ(rings.ring(6).size(), 0u);
    EXPECT_EQ(rings.size(), 12u);
    finder.find(4, 0, rings);
    EXPECT_EQ(rings.ringCount, 0);
    EXPECT_EQ(rings.size(), 1u);
    finder.find(4, kMaxRings + 5, rings);
    EXPECT_EQ(rings.ringCount, kMaxRings);
    EXPECT_EQ(rings.size(), 12u);
}

class GridRings : public ::testing::Test {
protected:
    static constexpr int kNx = 7, kNy = 6;
    void SetUp() override {
        auto loaded = gridPatch(kNx, kNy, 2.0f).build("grid");
        ASSERT_TRUE(loaded.mesh) << loaded.error();
        mesh.emplace(std::move(*loaded.mesh));
        // Grid coordinates of every (renumbered) vertex, from its file index.
        for (VertexId v = 0; v < mesh->vertexCount(); ++v) {
            const VertexId file = mesh->originalIndex()[v];
            gridI.push_back(int(file) % kNx);
            gridJ.push_back(int(file) / kNx);
        }
    }
    VertexId vertexAt(int i, int j) const {
        for (VertexId v = 0; v < mesh->vertexCount(); ++v)
            if (gridI[v] == i && gridJ[v] == j) return v;
        return kNoVertex;
    }
    std::set<VertexId> expectedRing(VertexId centre, int r) const {
        std::set<VertexId> out;
        for (VertexId w = 0; w < mesh->vertexCount(); ++w)
            if (gridDistance(gridI[centre], gridJ[centre], gridI[w], gridJ[w]) == r) out.insert(w);
        return out;
    }
    std::optional<TissueMesh> mesh;
    std::vector<int> gridI, gridJ;
};

TEST_F(GridRings, GridIsRenumberedAndOpen) {
    ASSERT_EQ(mesh->vertexCount(), std::size_t(kNx * kNy));
    EXPECT_EQ(mesh->report().boundaryEdgeCount, std::size_t(2 * (kNx - 1) + 2 * (kNy - 1)));
    // Positions agree with the file index (so originalIndex maps back correctly).
    for (VertexId v = 0; v < mesh->vertexCount(); ++v) {
        EXPECT_EQ(mesh->restPositionsMm()[v].x, 2.0f * float(gridI[v]));
        EXPECT_EQ(mesh->restPositionsMm()[v].y, 2.0f * float(gridJ[v]));
    }
}

TEST_F(GridRings, HandCountedRingSizes) {
    RingFinder finder(*mesh);
    RingSet rings = finder.makeRingSet();
    struct Case {
        int i, j;
        std::size_t ring1, ring2;
    };
    // Diagonal (i,j)-(i+1,j+1): interior valence 6; corners (0,0) and (6,5) touch a diagonal (3),
    // corners (6,0) and (0,5) do not (2). Ring 2 counted on paper (listed after the bar).
    const Case cases[] = {
        {3, 2, 6, 12},  // interior, far enough from the rim for a full ring 2
        {0, 0, 3, 5},   // (1,0),(0,1),(1,1) | (2,0),(2,1),(2,2),(1,2),(0,2)
        {6, 0, 2, 3},   // (5,0),(6,1) | (4,0),(5,1),(6,2)
        {0, 5, 2, 3},   // (1,5),(0,4) | (2,5),(1,4),(0,3)
        {6, 5, 3, 5},   // (5,5),(6,4),(5,4) | (4,5),(4,4),(4,3),(5,3),(6,3)
        {3, 0, 4, 7},   // (2,0),(4,0),(3,1),(4,1) | (1,0),(2,1),(3,2),(4,2),(5,2),(5,1),(5,0)
    };
    for (const Case& c : cases) {
        const VertexId v = vertexAt(c.i, c.j);
        ASSERT_NE(v, kNoVertex);
        finder.find(v, 2, rings);
        EXPECT_EQ(rings.ring(1).size(), c.ring1) << "grid (" << c.i << "," << c.j << ")";
        EXPECT_EQ(rings.ring(2).size(), c.ring2) << "grid (" << c.i << "," << c.j << ")";
    }
}

TEST_F(GridRings, ExactSetsForEveryVertexAndRing) {
    RingFinder finder(*mesh);
    RingSet rings = finder.makeRingSet();
    for (VertexId v = 0; v < mesh->vertexCount(); ++v) {
        finder.find(v, kMaxRings, rings);
        ASSERT_EQ(rings.ringCount, kMaxRings);
        std::size_t total = 0;
        for (int r = 0; r <= kMaxRings; ++r) {
            const auto ring = rings.ring(r);
            total += ring.size();
            EXPECT_EQ(asSet(ring).size(), ring.size()) << "duplicates in ring " << r;
            EXPECT_EQ(asSet(ring), expectedRing(v, r))
                << "grid (" << gridI[v] << "," << gridJ[v] << ") ring " << r;
        }
        EXPECT_EQ(total, rings.size());
    }
}

TEST(Rings, MatchIndependentBreadthFirstSearchOnGeneratedMeshes) {
    for (GeneratedShape shape : {GeneratedShape::Sphere, GeneratedShape::Stomach}) {
        auto loaded = generateMesh(shape, 642);
        ASSERT_TRUE(loaded.mesh) << loaded.error();
        const TissueMesh& mesh = *loaded.mesh;
        const std::size_t n = mesh.vertexCount();
        // Adjacency from the raw triangles, not from the mesh's CSR arrays.
        std::vector<std::set<VertexId>> adjacent(n);
        for (const auto& t : mesh.triangles())
            for (int k = 0; k < 3; ++k) {
                adjacent[t[k]].insert(t[(k + 1) % 3]);
                adjacent[t[k]].insert(t[(k + 2) % 3]);
            }
        RingFinder finder(mesh);
        RingSet rings = finder.makeRingSet();
        std::mt19937 rng(1234);
        for (int q = 0; q < 150; ++q) {
            const VertexId centre = VertexId(rng() % n);
            const int ringCount = int(rng() % (kMaxRings + 1));
            std::vector<int> distance(n, -1);
            std::deque<VertexId> queue{centre};
            distance[centre] = 0;
            while (!queue.empty()) {
                const VertexId u = queue.front();
                queue.pop_front();
                for (VertexId w : adjacent[u])
                    if (distance[w] < 0) {
                        distance[w] = distance[u] + 1;
                        queue.push_back(w);
                    }
            }
            finder.find(centre, ringCount, rings);
            ASSERT_EQ(rings.ringCount, ringCount);
            for (int r = 0; r <= ringCount; ++r) {
                std::set<VertexId> expected;
                for (VertexId w = 0; w < n; ++w)
                    if (distance[w] == r) expected.insert(w);
                ASSERT_EQ(asSet(rings.ring(r)), expected) << "centre " << centre << " ring " << r;
                ASSERT_EQ(rings.ring(r).size(), expected.size());
            }
        }
    }
}

}  // namespace
}  // namespace palpate
