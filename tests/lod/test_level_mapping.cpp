// The mapping between levels: rest positions round-trip through it; a rigid motion of a coarse
// level is shown as the same rigid motion on the fine one; a field carried coarse -> fine -> coarse
// comes back; a smooth deformation carried across matches the deformation itself; and the nearest
// triangle search agrees with brute force.
#include "engine/lod/MeshLevels.h"
#include "engine/lod/NearestTriangle.h"
#include "tests/lod/LodTestMeshes.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace palpate {
namespace {

using test::levelsOf;

double maxDistance(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
    EXPECT_EQ(a.size(), b.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) worst = std::max(worst, double(glm::length(a[i] - b[i])));
    return worst;
}

class Mapping : public ::testing::TestWithParam<GeneratedShape> {
protected:
    const MeshLevels& levels() const { return levelsOf(GetParam(), 3970); }
    /// A tolerance in mm for float round-off at the mesh's scale (about 100-250 mm across).
    double tolMm() const { return 1e-5 * levels().levels[0].mesh.report().bboxDiagonalMm; }
};

TEST_P(Mapping, RestPositionsRoundTripBothWays) {
    const MeshLevels& L = levels();
    const auto& fineRest = L.levels[0].mesh.restPositionsMm();
    for (std::size_t k = 1; k < L.levels.size(); ++k) {
        const auto& levelRest = L.levels[k].mesh.restPositionsMm();
        // fine -> (triangle, barycentric, offset) on level k -> rebuilt from the level's rest
        EXPECT_LT(maxDistance(L.toFine(k, levelRest), fineRest), tolMm()) << "level " << k;
        // level k -> on the fine triangles -> rebuilt from the fine rest
        EXPECT_LT(maxDistance(L.fromFine(k, fineRest), levelRest), tolMm()) << "level " << k;
        // and across two coarse levels, through the source
        if (k + 1 < L.levels.size()) {
            EXPECT_LT(maxDistance(L.transfer(k, k + 1, levelRest), L.levels[k + 1].mesh.restPositionsMm()), tolMm());
        }
    }
    EXPECT_EQ(maxDistance(L.toFine(0, fineRest), fineRest), 0.0);
}

TEST_P(Mapping, ARigidMotionOfACoarseLevelMovesTheFineSurfaceRigidly) {
    const MeshLevels& L = levels();
    const glm::mat4 motion = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(3.0f, -7.0f, 11.0f)), 0.7f,
                                         glm::normalize(glm::vec3(1.0f, 2.0f, 0.5f)));
    auto moved = [&](const std::vector<glm::vec3>& points) {
        std::vector<glm::vec3> out;
        for (const glm::vec3& p : points) out.push_back(glm::vec3(motion * glm::vec4(p, 1.0f)));
        return out;
    };
    const auto& fineRest = L.levels[0].mesh.restPositionsMm();
    for (std::size_t k = 1; k < L.levels.size(); ++k)
        EXPECT_LT(maxDistance(L.toFine(k, moved(L.levels[k].mesh.restPositionsMm())), moved(fineRest)), 10 * tolMm())
            << "level " << k;
}

TEST_P(Mapping, AnyCoarseFieldComesBackFromTheFineLevel) {
    // Decimation keeps each coarse vertex on a fine vertex, so coarse -> fine -> coarse is the
    // identity even for a rough (random) displacement, not only for smooth ones.
    const MeshLevels& L = levels();
    std::mt19937 rng(10);
    std::uniform_real_distribution<float> u(-0.5f, 0.5f);
    for (std::size_t k = 1; k < L.levels.size(); ++k) {
        std::vector<glm::vec3> displaced = L.levels[k].mesh.restPositionsMm();
        for (glm::vec3& p : displaced) p += glm::vec3(u(rng), u(rng), u(rng));
        const auto back = L.fromFine(k, L.toFine(k, displaced));
        EXPECT_LT(maxDistance(back, displaced), 10 * tolMm()) << "level " << k;
    }
}

TEST_P(Mapping, ASmoothDeformationCarriedToTheFineSurfaceMatchesItThere) {
    // A smooth field in space (2 mm along -x, Gaussian of 40 mm around a surface point): applied to
    // a coarse level and carried to the fine one, it must match the field applied to the fine
    // vertices directly within a tenth of its peak (what is left is interpolation across the
    // coarse triangles and their tilt).
    const MeshLevels& L = levels();
    const TissueMesh& fine = L.levels[0].mesh;
    const glm::vec3 centre = fine.restPositionsMm()[0];
    auto field = [&](const glm::vec3& p) {
        const float r = glm::length(p - centre);
        return glm::vec3(-2.0f, 0.0f, 0.0f) * std::exp(-(r * r) / (2.0f * 40.0f * 40.0f));
    };
    auto deformed = [&](const TissueMesh& mesh) {
        std::vector<glm::vec3> out = mesh.restPositionsMm();
        for (glm::vec3& p : out) p += field(p);
        return out;
    };
    const auto truth = deformed(fine);
    for (std::size_t k = 1; k < L.levels.size(); ++k) {
        const auto shown = L.toFine(k, deformed(L.levels[k].mesh));
        EXPECT_LT(maxDistance(shown, truth), 0.1 * 2.0) << "level " << k << " (" << L.levels[k].mesh.vertexCount() << " vertices)";
        // Not merely the rest surface: the deformation is there.
        EXPECT_GT(maxDistance(shown, fine.restPositionsMm()), 1.9);
    }
}

INSTANTIATE_TEST_SUITE_P(Shapes, Mapping, ::testing::Values(GeneratedShape::Sphere, GeneratedShape::Stomach),
                         [](const auto& info) { return std::string(shapeName(info.param)); });

TEST(NearestTriangle, AgreesWithBruteForce) {
    const TissueMesh& mesh = test::generated(GeneratedShape::Stomach, 1442);
    NearestTriangle search(mesh);
    std::mt19937 rng(4);
    const glm::vec3 lo = mesh.boundsMinMm() - glm::vec3(30.0f), hi = mesh.boundsMaxMm() + glm::vec3(30.0f);
    std::uniform_real_distribution<float> ux(lo.x, hi.x), uy(lo.y, hi.y), uz(lo.z, hi.z);
    const auto& rest = mesh.restPositionsMm();
    for (int i = 0; i < 400; ++i) {
        // Points near the surface (the mapping's case) and anywhere in and around the box.
        glm::dvec3 p = i % 2 ? glm::dvec3(ux(rng), uy(rng), uz(rng))
                             : glm::dvec3(rest[rng() % rest.size()]) + glm::dvec3(ux(rng), uy(rng), uz(rng)) * 0.02;
        double best = INFINITY;
        for (const auto& t : mesh.triangles())
            best = std::min(best, glm::length(p - closestPointOnTriangle(p, glm::dvec3(rest[t[0]]), glm::dvec3(rest[t[1]]),
                                                                         glm::dvec3(rest[t[2]]))));
        EXPECT_NEAR(search.nearest(p).distanceMm, best, 1e-9) << i;
    }
    // Far outside the grid it still finds the true nearest.
    const glm::dvec3 far(1e4, -2e4, 5e3);
    double best = INFINITY;
    for (const auto& t : mesh.triangles())
        best = std::min(best, glm::length(far - closestPointOnTriangle(far, glm::dvec3(rest[t[0]]), glm::dvec3(rest[t[1]]),
                                                                       glm::dvec3(rest[t[2]]))));
    EXPECT_NEAR(search.nearest(far).distanceMm, best, 1e-6);
}

TEST(NearestTriangle, ClosestPointOnATriangleByRegion) {
    const glm::dvec3 a(0, 0, 0), b(10, 0, 0), c(0, 10, 0);
    auto near = [](const glm::dvec3& x, const glm::dvec3& y) { return glm::length(x - y) < 1e-12; };
    EXPECT_TRUE(near(closestPointOnTriangle({2, 3, 5}, a, b, c), {2, 3, 0}));    // above the face
    EXPECT_TRUE(near(closestPointOnTriangle({-4, -4, 1}, a, b, c), a));          // beyond a corner
    EXPECT_TRUE(near(closestPointOnTriangle({5, -3, 0}, a, b, c), {5, 0, 0}));   // beyond edge ab
    EXPECT_TRUE(near(closestPointOnTriangle({8, 8, 0}, a, b, c), {5, 5, 0}));    // beyond edge bc
    EXPECT_TRUE(near(closestPointOnTriangle({20, -1, 0}, a, b, c), b));
}

}  // namespace
}  // namespace palpate
