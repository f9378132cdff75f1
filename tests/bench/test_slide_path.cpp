// The feel bench's slide (engine/bench/SlidePath.h): the tool is where the bench says it is. On the
// slide, the distance of the tool to the rest surface (the exact nearest triangle) is
// toolRadius - depth (a point tool's tip 1 mm inside, a sphere's centre 4 mm outside a 5 mm
// sphere), the surface point moves at the requested speed, and the phases are in order.
#include "engine/bench/SlidePath.h"
#include "engine/core/MeshGenerator.h"
#include "engine/lod/NearestTriangle.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace palpate {
namespace {

struct Case {
    GeneratedShape shape;
    std::size_t vertices;
    double toolRadiusMm;
};

class SlidePathDepth : public ::testing::TestWithParam<Case> {};

TEST_P(SlidePathDepth, TheToolIsAtTheRequestedDepthAllAlongTheSlide) {
    const Case c = GetParam();
    auto generated = generateMesh(c.shape, c.vertices);
    ASSERT_TRUE(generated.mesh) << generated.error();
    const TissueMesh& mesh = *generated.mesh;
    const SlideDef def;  // 1 mm deep, 25 mm/s for 1.6 s
    const SlidePath path = makeSlidePath(mesh, c.toolRadiusMm, def);

    ASSERT_EQ(path.toolMm.size(), path.surfaceMm.size());
    ASSERT_EQ(path.toolMm.size(), path.normal.size());
    EXPECT_LT(path.slideBegin, path.statsBegin);
    EXPECT_LT(path.statsBegin, path.slideEnd);
    EXPECT_LT(path.slideEnd, path.toolMm.size());  // the lift comes after
    EXPECT_EQ(path.slideEnd - path.slideBegin, std::size_t(std::llround(def.slideS * def.rateHz)));
    EXPECT_EQ(path.statsBegin - path.slideBegin, std::size_t(std::llround(def.breakawayS * def.rateHz)));
    EXPECT_NEAR(path.lengthMm, def.speedMmPerS * def.slideS, def.speedMmPerS / def.rateHz * 1.01);

    NearestTriangle nearest(mesh);
    const double offset = c.toolRadiusMm - def.depthMm;  // signed: < 0 inside the tissue
    double worst = 0.0;
    for (std::size_t i = path.slideBegin; i < path.slideEnd; ++i) {
        const double distance = nearest.nearest(glm::dvec3(path.toolMm[i])).distanceMm;
        worst = std::max(worst, std::abs(distance - std::abs(offset)));
        // On the side the offset says: inside (against the normal) for a point tool, outside for the sphere.
        const double side = glm::dot(glm::dvec3(path.toolMm[i] - path.surfaceMm[i]), glm::dvec3(path.normal[i]));
        ASSERT_NEAR(side, offset, 1e-4) << "tick " << i;
        ASSERT_NEAR(glm::length(path.normal[i]), 1.0f, 1e-5f);
    }
    // Within 2 % of the offset: the interpolated normal leans a little off the face normals.
    EXPECT_LT(worst, 0.02 * std::abs(offset) + 1e-3) << "largest depth error " << worst << " mm";

    // Constant speed along the surface.
    const double step = def.speedMmPerS / def.rateHz;
    for (std::size_t i = path.slideBegin + 1; i < path.slideEnd; ++i) {
        const double moved = glm::length(glm::dvec3(path.surfaceMm[i] - path.surfaceMm[i - 1]));
        ASSERT_NEAR(moved, step, 0.05 * step) << "tick " << i;
    }

    // The approach starts approachHeightMm above the surface and ends at the depth; the lift ends
    // above the last point.
    const double first = glm::dot(glm::dvec3(path.toolMm.front() - path.surfaceMm.front()),
                                  glm::dvec3(path.normal.front()));
    EXPECT_NEAR(first, c.toolRadiusMm + def.approachHeightMm, 1e-3);
    const double last = glm::dot(glm::dvec3(path.toolMm.back() - path.surfaceMm.back()),
                                 glm::dvec3(path.normal.back()));
    EXPECT_NEAR(last, c.toolRadiusMm + def.approachHeightMm, 1e-3);
    EXPECT_NEAR(glm::length(path.toolMm[path.slideBegin - 1] - path.toolMm[path.slideBegin]), 0.0f, 1e-3f);
}

INSTANTIATE_TEST_SUITE_P(
    Table1Meshes, SlidePathDepth,
    ::testing::Values(Case{GeneratedShape::Sphere, 1442, 0.0}, Case{GeneratedShape::Sphere, 1442, 5.0},
                      Case{GeneratedShape::Sphere, 8664, 0.0}, Case{GeneratedShape::Stomach, 1442, 0.0},
                      Case{GeneratedShape::Stomach, 1442, 5.0}, Case{GeneratedShape::Stomach, 8664, 5.0}));

TEST(SlidePath, InvalidDefinitionsNameTheField) {
    SlideDef def;
    def.depthMm = -1.0;
    def.speedMmPerS = 0.0;
    const Problems problems = validateSlideDef(def);
    EXPECT_TRUE(hasProblem(problems, "depthMm"));
    EXPECT_TRUE(hasProblem(problems, "speedMmPerS"));
    EXPECT_FALSE(hasProblem(problems, "slideS"));
    SlideDef tooShort;
    tooShort.breakawayS = tooShort.slideS;
    EXPECT_TRUE(hasProblem(validateSlideDef(tooShort), "breakawayS"));
    EXPECT_TRUE(validateSlideDef(SlideDef{}).empty());

    auto generated = generateMesh(GeneratedShape::Sphere, 200);
    ASSERT_TRUE(generated.mesh);
    EXPECT_THROW(makeSlidePath(*generated.mesh, 0.0, def), std::invalid_argument);
    EXPECT_THROW(makeSlidePath(*generated.mesh, -1.0, SlideDef{}), std::invalid_argument);
}

}  // namespace
}  // namespace palpate
