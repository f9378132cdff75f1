// Radius of influence (Basdogan et al. 1998): the profile, the dent it makes, and its independence
// of the mesh's edges.
#include "engine/core/Octree.h"
#include "engine/core/SceneTarget.h"
#include "engine/models/RadiusOfInfluenceModel.h"
#include "tests/models/ModelTestMeshes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace palpate;

TEST(RadiusOfInfluenceProfile, DefaultIsZeroWithZeroSlopeAtTheRadius) {
    const RadiusOfInfluenceParams p;
    EXPECT_TRUE(messagesOf(validateRadiusOfInfluenceParams(p)).empty());
    EXPECT_EQ(p.degree, 2);
    EXPECT_DOUBLE_EQ(evaluateProfile(p, 0.0), 1.0);
    EXPECT_DOUBLE_EQ(evaluateProfile(p, 0.5), 0.25);  // (1 - 0.5)^2
    EXPECT_DOUBLE_EQ(evaluateProfile(p, 1.0), 0.0);
    const double h = 1e-6;
    EXPECT_NEAR((evaluateProfile(p, 1.0) - evaluateProfile(p, 1.0 - h)) / h, 0.0, 1e-5);  // slope at the radius
    for (int degree = 2; degree <= kMaxProfileDegree; ++degree) {
        RadiusOfInfluenceParams q;
        q.degree = degree;
        q.coefficients = powerProfileCoefficients(degree);
        EXPECT_TRUE(messagesOf(validateRadiusOfInfluenceParams(q)).empty()) << degree;
        EXPECT_NEAR(evaluateProfile(q, 0.3), std::pow(0.7, degree), 1e-12) << degree;
        EXPECT_NEAR(evaluateProfile(q, 1.0), 0.0, 1e-12);
    }
}

TEST(RadiusOfInfluenceProfile, ValidatorNamesTheBrokenCondition) {
    RadiusOfInfluenceParams p;
    p.coefficients = {1.0, -1.0, 0.0};  // 1 - rho: zero at the radius, but with a kink
    auto errors = messagesOf(validateRadiusOfInfluenceParams(p));
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_NE(errors[0].find("phi'(1)"), std::string::npos) << errors[0];
    p.coefficients = {0.5, -1.0, 0.5};
    errors = messagesOf(validateRadiusOfInfluenceParams(p));
    ASSERT_FALSE(errors.empty());
    EXPECT_NE(errors[0].find("coefficients[0]"), std::string::npos) << errors[0];
    p = {};
    p.degree = 1;
    p.radiusMm = -2.0;
    errors = messagesOf(validateRadiusOfInfluenceParams(p));
    ASSERT_EQ(errors.size(), 2u);
    EXPECT_NE(errors[0].find("radiusMm"), std::string::npos);
    EXPECT_NE(errors[1].find("degree"), std::string::npos);
}

TEST(RadiusOfInfluenceModel, DentFollowsTheProfileOfRestDistance) {
    const TissueMesh mesh = test::sphereMesh(1442);
    const Octree octree(mesh, {});
    RadiusOfInfluenceParams p;
    RadiusOfInfluenceModel model(mesh, octree, p);
    const VertexId t = defaultTargetVertex(mesh);
    const glm::vec3 rest = mesh.restPositionsMm()[t], n = mesh.restNormals()[t];
    const float depth = 2.5f;
    const TickResult r = model.step(rest - depth * n, 0.001);
    ASSERT_TRUE(r.contact);
    ASSERT_EQ(r.touched, t);
    // The touched vertex follows the tool; force = k_s times its displacement.
    EXPECT_LT(glm::length(model.positionsMm()[t] - (rest - depth * n)), 1e-5f);
    EXPECT_NEAR(glm::length(r.forceN), p.stiffnessNPerMm * depth, 1e-6);
    EXPECT_GT(glm::dot(r.forceN, n), 0.0f);
    std::size_t inside = 0;
    for (VertexId v = 0; v < mesh.vertexCount(); ++v) {
        const double rho = glm::length(glm::dvec3(mesh.restPositionsMm()[v]) - glm::dvec3(rest)) / p.radiusMm;
        const double expected = rho <= 1.0 ? depth * (1.0 - rho) * (1.0 - rho) : 0.0;  // by hand
        const glm::vec3 moved = model.positionsMm()[v] - mesh.restPositionsMm()[v];
        ASSERT_NEAR(-glm::dot(moved, n), expected, 1e-5) << v;
        ASSERT_NEAR(glm::length(moved - glm::dot(moved, n) * n), 0.0, 1e-5) << v;  // along n only
        if (rho < 1.0) ++inside;
    }
    EXPECT_EQ(model.influencedVertices().size(), inside);
    // Released: the dent is gone.
    EXPECT_FALSE(model.step(rest + 2.0f * n, 0.001).contact);
    for (VertexId v = 0; v < mesh.vertexCount(); ++v) ASSERT_EQ(model.positionsMm()[v], mesh.restPositionsMm()[v]);
}

TEST(RadiusOfInfluenceModel, IgnoresTopology) {
    // Two separate tetrahedra 8 mm apart: pressing one moves the other's vertices within the
    // radius, though no edge joins them (the slope-ring and mass-spring models would not).
    std::vector<glm::vec3> positions;
    std::vector<std::array<VertexId, 3>> triangles;
    test::appendTetrahedron(positions, triangles, glm::vec3(0.0f), 5.0f);
    test::appendTetrahedron(positions, triangles, glm::vec3(18.0f, 0.0f, 0.0f), 5.0f);
    auto loaded = TissueMesh::fromTriangles(positions, triangles, "two tetrahedra");
    ASSERT_TRUE(loaded.mesh) << loaded.error();
    const TissueMesh& mesh = *loaded.mesh;
    const Octree octree(mesh, {});
    RadiusOfInfluenceParams p;
    p.radiusMm = 20.0;
    RadiusOfInfluenceModel model(mesh, octree, p);
    // The vertex of the first tetrahedron nearest the second, pressed along its normal.
    VertexId t = 0;
    for (VertexId v = 0; v < mesh.vertexCount(); ++v)
        if (glm::length(mesh.restPositionsMm()[v]) < 10.0f &&
            (glm::length(mesh.restPositionsMm()[t]) >= 10.0f || mesh.restPositionsMm()[v].x > mesh.restPositionsMm()[t].x))
            t = v;
    const TickResult r = model.step(mesh.restPositionsMm()[t] - 1.0f * mesh.restNormals()[t], 0.001);
    ASSERT_TRUE(r.contact);
    ASSERT_EQ(r.touched, t);
    int movedOnTheOther = 0;
    for (VertexId v = 0; v < mesh.vertexCount(); ++v)
        if (mesh.restPositionsMm()[v].x > 9.0f && model.positionsMm()[v] != mesh.restPositionsMm()[v]) ++movedOnTheOther;
    EXPECT_GT(movedOnTheOther, 0);
}
