// Coverage (engine/exercise/PalpationCoverage.h) on a flat grid whose answers are counted by hand:
// a 20 x 20 mm square of 1 mm cells, each cut into two triangles, so every interior vertex stands
// for 1 mm^2 and the whole surface is 400 mm^2.

#include "engine/exercise/PalpationCoverage.h"

#include <gtest/gtest.h>

namespace palpate {
namespace {

constexpr int kSide = 20;

TissueMesh flatGrid() {
    std::vector<glm::vec3> p;
    std::vector<std::array<VertexId, 3>> t;
    for (int j = 0; j <= kSide; ++j)
        for (int i = 0; i <= kSide; ++i) p.push_back({float(i), float(j), 0.0f});
    auto id = [](int i, int j) { return VertexId(j * (kSide + 1) + i); };
    for (int j = 0; j < kSide; ++j)
        for (int i = 0; i < kSide; ++i) {
            t.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            t.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    auto built = TissueMesh::fromTriangles(p, t, "grid", false);  // file order kept: id(i, j)
    EXPECT_TRUE(built.mesh) << built.error();
    return std::move(*built.mesh);
}

/// Lattice points (i, j) with i^2 + j^2 <= r^2.
int latticePointsInDisc(int r) {
    int n = 0;
    for (int i = -r; i <= r; ++i)
        for (int j = -r; j <= r; ++j) n += i * i + j * j <= r * r ? 1 : 0;
    return n;
}

TEST(PalpationCoverage, AFirmPressCoversTheDiscAroundItByArea) {
    const TissueMesh mesh = flatGrid();
    PalpationCoverage c(mesh, {1.0, 5.0});
    const VertexId centre = VertexId(10 * (kSide + 1) + 10);
    c.add(centre, {10, 10, 0}, 2.0);
    EXPECT_EQ(latticePointsInDisc(5), 81);
    EXPECT_NEAR(c.coveredFraction(), 81.0 / 400.0, 1e-9);
    EXPECT_FLOAT_EQ(c.peakForceN()[centre], 2.0f);
    EXPECT_FLOAT_EQ(c.peakForceN()[VertexId(10 * (kSide + 1) + 15)], 2.0f);  // 5 mm away: inside
    EXPECT_FLOAT_EQ(c.peakForceN()[VertexId(10 * (kSide + 1) + 16)], 0.0f);  // 6 mm away
}

TEST(PalpationCoverage, ALightTouchExaminesNothingAndARepeatCountsOnce) {
    const TissueMesh mesh = flatGrid();
    PalpationCoverage c(mesh, {1.0, 5.0});
    const VertexId centre = VertexId(10 * (kSide + 1) + 10);
    c.add(centre, {10, 10, 0}, 0.9);
    EXPECT_DOUBLE_EQ(c.coveredFraction(), 0.0);
    c.add(centre, {10, 10, 0}, 1.5);
    c.add(centre, {10, 10, 0}, 3.0);
    EXPECT_NEAR(c.coveredFraction(), 81.0 / 400.0, 1e-9);
    EXPECT_FLOAT_EQ(c.peakForceN()[centre], 3.0f);  // the largest force is kept
}

TEST(PalpationCoverage, SweepingTheWholeSquareCoversAllOfIt) {
    const TissueMesh mesh = flatGrid();
    PalpationCoverage c(mesh, {1.0, 3.0});
    for (int j = 0; j <= kSide; j += 2)
        for (int i = 0; i <= kSide; i += 2) c.add(VertexId(j * (kSide + 1) + i), {float(i), float(j), 0}, 1.0);
    EXPECT_NEAR(c.coveredFraction(), 1.0, 1e-9);
}

TEST(PalpationCoverage, TwoSeparatePressesAddUp) {
    const TissueMesh mesh = flatGrid();
    PalpationCoverage c(mesh, {1.0, 2.0});
    c.add(VertexId(5 * (kSide + 1) + 5), {5, 5, 0}, 2.0);
    c.add(VertexId(15 * (kSide + 1) + 15), {15, 15, 0}, 2.0);
    EXPECT_EQ(latticePointsInDisc(2), 13);
    EXPECT_NEAR(c.coveredFraction(), 26.0 / 400.0, 1e-9);
}

}  // namespace
}  // namespace palpate
