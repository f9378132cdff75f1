// Octree: our exact nearest-vertex search against brute force, over many tree shapes, query kinds
// (near the surface, far outside the root, exactly on cell borders) and on a deformed mesh; and the
// paper's faithful searchNode, whose documented blind spots each get a test.

#include "engine/core/MeshGenerator.h"
#include "engine/core/Octree.h"
#include "tests/engine/TestMeshes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <random>
#include <set>
#include <stdexcept>

namespace palpate {
namespace {

using test::dist2;

const OctreeDef kDefs[] = {{1, 1},  {1, 64}, {2, 4},  {3, 16}, {4, 1},  {5, 32},
                           {6, 8},  {8, 2},  {10, 16}, {12, 1}, {12, 64}, {7, 3}};

const TissueMesh& sphere1442() {
    static const TissueMesh mesh = *generateMesh(GeneratedShape::Sphere, 1442).mesh;
    return mesh;
}
const TissueMesh& stomach642() {
    static const TissueMesh mesh = *generateMesh(GeneratedShape::Stomach, 642).mesh;
    return mesh;
}

glm::vec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<float> g(0.0f, 1.0f);
    for (;;) {
        const glm::vec3 v(g(rng), g(rng), g(rng));
        const float len = glm::length(v);
        if (len > 1e-3f) return v / len;
    }
}

/// A query point of a random kind: near the surface, in or around the root box, far away, exactly
/// on a cell border of a random node, or exactly on a vertex.
glm::vec3 randomQuery(std::mt19937& rng, const Octree& tree, std::span<const glm::vec3> positions, int kind) {
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    const auto& nodes = tree.nodes();
    const Octree::Node& root = nodes[0];
    switch (kind % 6) {
        case 0: {  // near the surface
            const glm::vec3 p = positions[rng() % positions.size()];
            return p + randomUnit(rng) * (u01(rng) * 6.0f);
        }
        case 1: {  // anywhere in the root cube, inflated by 30 %
            const float s = root.cellSizeMm;
            return root.cellMinMm - 0.3f * s + glm::vec3(u01(rng), u01(rng), u01(rng)) * (1.6f * s);
        }
        case 2: {  // far outside the root box
            const float far = std::pow(10.0f, 3.0f + 3.0f * u01(rng));
            return root.cellMinMm + 0.5f * root.cellSizeMm + randomUnit(rng) * far;
        }
        case 3:
        case 4: {  // exactly on a border of a node's cell (faces, edges and corners)
            const Octree::Node& node = nodes[rng() % nodes.size()];
            glm::vec3 t(u01(rng), u01(rng), u01(rng));
            const int onBorder = 1 + int(rng() % 3);
            for (int k = 0; k < onBorder; ++k) t[int(rng() % 3)] = float(rng() % 3) * 0.5f;  // 0, 1/2 or 1
            return node.cellMinMm + t * node.cellSizeMm;
        }
        default:  // exactly on a vertex
            return positions[rng() % positions.size()];
    }
}

void expectSameNearest(const Octree& tree, std::span<const glm::vec3> positions, std::span<const VertexId> displaced,
                       const glm::vec3& q, std::mt19937& rng, const char* what) {
    const VertexId linear = nearestLinear(q, positions);
    const VertexId exact = tree.nearestExact(q, positions, displaced, kNoVertex);
    ASSERT_NE(linear, kNoVertex);
    ASSERT_NE(exact, kNoVertex) << what;
    ASSERT_LT(exact, positions.size());
    ASSERT_EQ(dist2(positions[exact], q), dist2(positions[linear], q))
        << what << ": query (" << q.x << ", " << q.y << ", " << q.z << ") depth " << tree.def().maxDepth
        << " leafCapacity " << tree.def().leafCapacity << ": exact " << exact << " linear " << linear;
    // Both document "ties go to the lower index", so the vertex itself must agree too.
    EXPECT_EQ(exact, linear) << what;
    const VertexId warm = VertexId(rng() % positions.size());
    EXPECT_EQ(tree.nearestExact(q, positions, displaced, warm), exact) << what << ": warm start " << warm;
    EXPECT_EQ(tree.nearestExact(q, positions, displaced, linear), exact) << what << ": warm start at the answer";
}

TEST(Octree, RejectsBadDefinitions) {
    EXPECT_TRUE(validateOctreeDef({10, 16}).empty());
    EXPECT_NE(joinedMessages(validateOctreeDef({0, 16})).find("maxDepth"), std::string::npos);
    EXPECT_NE(joinedMessages(validateOctreeDef({21, 16})).find("maxDepth"), std::string::npos);
    EXPECT_NE(joinedMessages(validateOctreeDef({10, 0})).find("leafCapacity"), std::string::npos);
    EXPECT_TRUE(hasProblem(validateOctreeDef({21, 16}), "maxDepth"));
    EXPECT_TRUE(hasProblem(validateOctreeDef({10, 0}), "leafCapacity"));
    EXPECT_THROW(Octree(sphere1442(), OctreeDef{0, 16}), std::invalid_argument);
    EXPECT_THROW(Octree(sphere1442(), OctreeDef{10, 0}), std::invalid_argument);
}

TEST(Octree, NodesPartitionTheVerticesAndContainThem) {
    for (const TissueMesh* mesh : {&sphere1442(), &stomach642()}) {
        const auto& rest = mesh->restPositionsMm();
        for (const OctreeDef& def : kDefs) {
            const Octree tree(*mesh, def);
            const auto& nodes = tree.nodes();
            ASSERT_FALSE(nodes.empty());
            EXPECT_EQ(nodes[0].begin, 0u);
            EXPECT_EQ(nodes[0].end, mesh->vertexCount());
            EXPECT_LE(tree.depth(), def.maxDepth);
            std::vector<int> leafOf(mesh->vertexCount(), 0);
            std::size_t leaves = 0;
            // Cells are float boxes derived from double-precision Morton codes: a vertex on a cell
            // border may fall outside its cell by rounding (seen: -1e-15 against a border at 0).
            const float slack = 1e-6f * nodes[0].cellSizeMm;
            for (const auto& node : nodes) {
                const glm::vec3 hi = node.cellMinMm + glm::vec3(node.cellSizeMm);
                for (std::uint32_t v = node.begin; v < node.end; ++v) {
                    for (int a = 0; a < 3; ++a) {
                        ASSERT_GE(rest[v][a], node.cellMinMm[a] - slack);
                        ASSERT_LE(rest[v][a], hi[a] + slack);
                        ASSERT_GE(rest[v][a], node.tightMinMm[a]);
                        ASSERT_LE(rest[v][a], node.tightMaxMm[a]);
                    }
                    if (node.leaf) ++leafOf[v];
                }
                if (node.leaf) {
                    ++leaves;
                    continue;
                }
                // Children: contiguous, covering the parent's range, cells half the size inside it.
                std::uint32_t covered = 0;
                for (int c = 0; c < 8; ++c) {
                    if (node.child[c] < 0) continue;
                    const auto& child = nodes[std::size_t(node.child[c])];
                    EXPECT_EQ(child.cellSizeMm, node.cellSizeMm * 0.5f);
                    for (int a = 0; a < 3; ++a) {
                        EXPECT_GE(child.cellMinMm[a], node.cellMinMm[a] - slack);
                        EXPECT_LE(child.cellMinMm[a] + child.cellSizeMm, hi[a] + slack);
                    }
                    EXPECT_GT(child.end, child.begin);
                    covered += child.end - child.begin;
                }
                EXPECT_EQ(covered, node.end - node.begin);
            }
            EXPECT_EQ(leaves, tree.leafCount());
            for (int count : leafOf) ASSERT_EQ(count, 1) << "every vertex is in exactly one leaf";
        }
    }
}

TEST(Octree, ExactEqualsLinearOnRestMesh) {
    std::mt19937 rng(20240601);
    std::size_t queries = 0;
    for (const TissueMesh* mesh : {&sphere1442(), &stomach642()}) {
        const auto& rest = mesh->restPositionsMm();
        for (const OctreeDef& def : kDefs) {
            const Octree tree(*mesh, def);
            for (int q = 0; q < 600; ++q, ++queries) {
                const glm::vec3 point = randomQuery(rng, tree, rest, q);
                expectSameNearest(tree, rest, {}, point, rng, "rest");
                if (::testing::Test::HasFatalFailure()) return;
            }
        }
    }
    EXPECT_GE(queries, 10000u);
}

TEST(Octree, ExactEqualsLinearOnDeformedMesh) {
    std::mt19937 rng(777);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    std::size_t queries = 0;
    for (const TissueMesh* mesh : {&sphere1442(), &stomach642()}) {
        const auto& rest = mesh->restPositionsMm();
        for (const OctreeDef& def : kDefs) {
            const Octree tree(*mesh, def);
            for (int trial = 0; trial < 4; ++trial) {
                // Displace a random set of vertices by up to 8 mm (a whole region and random ones).
                std::vector<glm::vec3> positions = rest;
                std::vector<VertexId> displaced;
                const VertexId centre = VertexId(rng() % rest.size());
                for (VertexId v = 0; v < rest.size(); ++v) {
                    const bool nearCentre = glm::length(rest[v] - rest[centre]) < 12.0f;
                    if (nearCentre || rng() % 40 == 0) {
                        positions[v] += randomUnit(rng) * (8.0f * u01(rng));
                        displaced.push_back(v);
                    }
                }
                // Listing a vertex that did not move is allowed too.
                displaced.push_back(VertexId(rng() % rest.size()));
                for (int q = 0; q < 150; ++q, ++queries) {
                    glm::vec3 point;
                    if (q % 3 == 0) point = positions[displaced[rng() % displaced.size()]] + randomUnit(rng) * (3.0f * u01(rng));
                    else point = randomQuery(rng, tree, positions, q);
                    expectSameNearest(tree, positions, displaced, point, rng, "deformed");
                    if (::testing::Test::HasFatalFailure()) return;
                }
            }
        }
    }
    EXPECT_GE(queries, 10000u);
}

TEST(Octree, SingleVertexWorldAndTinyMeshes) {
    // The smallest closed mesh: a tetrahedron. Every tree shape, every vertex and a far point.
    test::RawMesh tet;
    tet.positions = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 0, 10}};
    tet.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    auto loaded = tet.build("tetrahedron");
    ASSERT_TRUE(loaded.mesh) << loaded.error();
    std::mt19937 rng(5);
    for (const OctreeDef& def : kDefs) {
        const Octree tree(*loaded.mesh, def);
        const auto& rest = loaded.mesh->restPositionsMm();
        for (int q = 0; q < 50; ++q) expectSameNearest(tree, rest, {}, randomQuery(rng, tree, rest, q), rng, "tet");
    }
}

TEST(Octree, NearestRestKEqualsSortedBruteForce) {
    // Our touched-vertex search's cache: the K nearest rest vertices, ascending, whatever the
    // seeds (none, the answer itself, a stale answer from elsewhere, random vertices).
    std::mt19937 rng(99);
    constexpr int kK = 16;
    for (const TissueMesh* mesh : {&sphere1442(), &stomach642()}) {
        const auto& rest = mesh->restPositionsMm();
        for (const OctreeDef& def : kDefs) {
            const Octree tree(*mesh, def);
            VertexId stale[kK];
            int staleCount = 0;
            for (int q = 0; q < 120; ++q) {
                const glm::vec3 point = randomQuery(rng, tree, rest, q);
                std::vector<float> all(rest.size());
                for (VertexId v = 0; v < rest.size(); ++v) all[v] = dist2(rest[v], point);
                std::vector<float> sorted = all;
                std::sort(sorted.begin(), sorted.end());
                for (int seeding = 0; seeding < 4; ++seeding) {
                    VertexId ids[kK];
                    float d2[kK];
                    glm::vec3 positions[kK];
                    int seeds = 0;
                    if (seeding == 1) {  // the answer itself
                        seeds = tree.nearestRestK(point, kK, ids, d2);
                    } else if (seeding == 2) {  // last query's answer
                        std::copy(stale, stale + staleCount, ids);
                        seeds = staleCount;
                    } else if (seeding == 3) {  // random distinct vertices
                        seeds = 5;
                        for (int i = 0; i < seeds; ++i) ids[i] = VertexId((rng() % (rest.size() / 5)) * 5 + VertexId(i));
                    }
                    const int found = tree.nearestRestK(point, kK, ids, d2, seeds, positions);
                    ASSERT_EQ(found, kK) << "seeding " << seeding;
                    std::set<VertexId> distinct(ids, ids + found);
                    EXPECT_EQ(distinct.size(), std::size_t(found)) << "seeding " << seeding;
                    for (int i = 0; i < found; ++i) {
                        ASSERT_EQ(d2[i], sorted[std::size_t(i)]) << "rank " << i << " seeding " << seeding;
                        ASSERT_EQ(d2[i], all[ids[i]]) << "rank " << i << " seeding " << seeding;
                        ASSERT_EQ(positions[i], rest[ids[i]]) << "rank " << i;
                    }
                    if (seeding == 0) {
                        std::copy(ids, ids + found, stale);
                        staleCount = found;
                    }
                }
            }
        }
    }
}

TEST(Octree, NearestRestKOnAMeshSmallerThanK) {
    test::RawMesh tet;
    tet.positions = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 0, 10}};
    tet.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    auto loaded = tet.build("tetrahedron");
    ASSERT_TRUE(loaded.mesh) << loaded.error();
    const Octree tree(*loaded.mesh, OctreeDef{});
    VertexId ids[16];
    float d2[16];
    EXPECT_EQ(tree.nearestRestK(glm::vec3(3, 3, 3), 16, ids, d2), 4);
    EXPECT_TRUE(std::is_sorted(d2, d2 + 4));
}

// --- The paper's searchNode, kept as written: its blind spots. ---

TEST(OctreeFaithful, FindsNothingOutsideTheRootBox) {
    const TissueMesh& mesh = sphere1442();
    const auto& rest = mesh.restPositionsMm();
    for (const OctreeDef& def : kDefs) {
        const Octree tree(mesh, def);
        const auto& root = tree.nodes()[0];
        const glm::vec3 points[] = {root.cellMinMm - glm::vec3(1.0f),
                                    root.cellMinMm + glm::vec3(root.cellSizeMm * 0.5f, root.cellSizeMm * 0.5f,
                                                               root.cellSizeMm + 0.5f),
                                    glm::vec3(1e5f, 0.0f, 0.0f)};
        for (const glm::vec3& p : points) {
            EXPECT_EQ(tree.searchNodeFaithful(p, rest), kNoVertex);
            const VertexId exact = tree.nearestExact(p, rest, {}, kNoVertex);
            ASSERT_NE(exact, kNoVertex);
            EXPECT_EQ(dist2(rest[exact], p), dist2(rest[nearestLinear(p, rest)], p));
        }
    }
}

TEST(OctreeFaithful, FindsNothingOrAWrongVertexInAnEmptyOctant) {
    // The centre of a hollow sphere: the cells around it hold no vertex.
    const TissueMesh& mesh = sphere1442();
    const auto& rest = mesh.restPositionsMm();
    const Octree tree(mesh, OctreeDef{10, 8});
    for (const glm::vec3& p : {glm::vec3(0.0f), glm::vec3(1.0f, 2.0f, 3.0f), glm::vec3(-3.0f, 1.0f, -2.0f),
                               glm::vec3(0.0f, 0.0f, -20.0f)}) {
        const VertexId faithful = tree.searchNodeFaithful(p, rest);
        const VertexId exact = tree.nearestExact(p, rest, {}, kNoVertex);
        ASSERT_NE(exact, kNoVertex);
        EXPECT_EQ(dist2(rest[exact], p), dist2(rest[nearestLinear(p, rest)], p));
        EXPECT_TRUE(faithful == kNoVertex || dist2(rest[faithful], p) > dist2(rest[exact], p))
            << "searchNodeFaithful found the true nearest vertex at (" << p.x << ", " << p.y << ", " << p.z << ")";
    }
    // At the very centre the octants are empty: nothing is found.
    EXPECT_EQ(tree.searchNodeFaithful(glm::vec3(1.0f, 2.0f, 3.0f), rest), kNoVertex);
}

TEST(OctreeFaithful, MissesTheNearestVertexInANeighbouringLeaf) {
    const TissueMesh& mesh = sphere1442();
    const auto& rest = mesh.restPositionsMm();
    const Octree tree(mesh, OctreeDef{10, 4});
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    const float edge = float(mesh.meanEdgeLengthMm());
    int misses = 0, found = 0;
    for (int attempt = 0; attempt < 20000 && misses < 5; ++attempt) {
        const glm::vec3 p = rest[rng() % rest.size()] + randomUnit(rng) * (edge * u01(rng));
        const VertexId faithful = tree.searchNodeFaithful(p, rest);
        if (faithful == kNoVertex) continue;
        ++found;
        const VertexId exact = tree.nearestExact(p, rest, {}, kNoVertex);
        const VertexId linear = nearestLinear(p, rest);
        ASSERT_EQ(dist2(rest[exact], p), dist2(rest[linear], p));
        if (dist2(rest[faithful], p) > dist2(rest[linear], p)) {
            ++misses;
            // The faithful result is a vertex of the leaf holding p; the true nearest is elsewhere.
            EXPECT_NE(faithful, exact);
        }
    }
    EXPECT_GT(found, 0);
    EXPECT_GE(misses, 1) << "expected searchNodeFaithful to miss a nearest vertex across a leaf border";
}

TEST(OctreeFaithful, FindsTheNearestWhenItIsInTheSameLeaf) {
    // The baseline is not broken: a query exactly on a vertex strictly inside its leaf's cell is
    // answered with that vertex (or one at the same place).
    const TissueMesh& mesh = sphere1442();
    const auto& rest = mesh.restPositionsMm();
    for (const OctreeDef& def : kDefs) {
        const Octree tree(mesh, def);
        int checked = 0;
        for (const auto& node : tree.nodes()) {
            if (!node.leaf) continue;
            const glm::vec3 hi = node.cellMinMm + glm::vec3(node.cellSizeMm);
            for (std::uint32_t v = node.begin; v < node.end; ++v) {
                const glm::vec3 p = rest[v];
                const bool inside = p.x > node.cellMinMm.x && p.y > node.cellMinMm.y && p.z > node.cellMinMm.z &&
                                    p.x < hi.x && p.y < hi.y && p.z < hi.z;
                if (!inside) continue;
                const VertexId f = tree.searchNodeFaithful(p, rest);
                ASSERT_NE(f, kNoVertex);
                EXPECT_EQ(dist2(rest[f], p), 0.0f);
                ++checked;
            }
        }
        EXPECT_GT(checked, int(rest.size()) / 2);
    }
}

}  // namespace
}  // namespace palpate
