// Free-form deformation: the Bernstein lattice at rest reproduces the mesh exactly; the model's
// surface is the lattice's map with the moved control points; the least-norm control update.
#include "engine/core/Octree.h"
#include "engine/core/SceneTarget.h"
#include "engine/models/FfdModel.h"
#include "tests/models/ModelTestMeshes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace palpate;

TEST(FfdLattice, BernsteinPolynomialsArePositiveAndSumToOne) {
    double b[16];
    for (int degree = 1; degree <= 15; ++degree)
        for (double s : {0.0, 0.13, 0.5, 0.77, 1.0}) {
            FfdLattice::bernstein(degree, s, b);
            double sum = 0.0;
            for (int i = 0; i <= degree; ++i) {
                EXPECT_GE(b[i], 0.0);
                sum += b[i];
            }
            EXPECT_NEAR(sum, 1.0, 1e-14);
            // B_1^3(s) = 3 s (1 - s)^2, by hand.
            if (degree == 3) {
                EXPECT_NEAR(b[1], 3.0 * s * (1.0 - s) * (1.0 - s), 1e-15);
            }
        }
}

TEST(FfdLattice, AtRestReproducesTheMeshExactly) {
    // sum_ijk B_i(s) B_j(t) B_k(u) P_ijk with P_ijk = origin + (i/d, j/d, k/d) * size is the
    // identity (Bernstein polynomials reproduce linear functions): every vertex maps to itself.
    const TissueMesh mesh = test::sphereMesh(1442);
    for (int points : {2, 3, 5, 8, 16}) {
        const FfdLattice lattice(glm::dvec3(mesh.boundsMinMm()) - 3.0, glm::dvec3(mesh.boundsMaxMm()) + 4.0, points);
        const auto control = lattice.restControlPoints();
        double worst = 0.0;
        for (const glm::vec3& p : mesh.restPositionsMm()) {
            const glm::dvec3 x = lattice.evaluate(lattice.latticeCoordinates(glm::dvec3(p)), control);
            worst = std::max(worst, glm::length(x - glm::dvec3(p)));
        }
        EXPECT_LT(worst, 1e-9) << points << " points per axis";
    }
}

TEST(FfdModel, SurfaceIsTheLatticeMapOfTheMovedControlPoints) {
    const TissueMesh mesh = test::sphereMesh(1442);
    const Octree octree(mesh, {});
    FfdParams p;
    FfdModel model(mesh, octree, p);
    // At rest the model is the mesh.
    for (VertexId v = 0; v < mesh.vertexCount(); ++v) ASSERT_EQ(model.positionsMm()[v], mesh.restPositionsMm()[v]);

    const VertexId t = defaultTargetVertex(mesh);
    const glm::vec3 n = mesh.restNormals()[t];
    const glm::vec3 tool = mesh.restPositionsMm()[t] - 3.0f * n;
    const TickResult r = model.step(tool, 0.001);
    ASSERT_TRUE(r.contact);
    ASSERT_EQ(r.touched, t);
    // The surface point under the tool follows it along its normal; force = k_s times that.
    EXPECT_LT(glm::length(model.positionsMm()[t] - tool), 1e-5f);
    EXPECT_NEAR(glm::length(r.forceN), p.stiffnessNPerMm * 3.0, 1e-6);

    // The moved control points: only the 4 x 4 x 4 block, each parallel to D and proportional to
    // the touched vertex's weight (least norm: in the row space of the 1 x 64 constraint), and the
    // constraint holds: sum w_i dP_i = D.
    const auto dP = model.controlPointDisplacementsMm();
    const auto& lattice = model.lattice();
    const glm::dvec3 stu = model.latticeCoordinatesOf(t);
    double bs[16], bt[16], bu[16];
    FfdLattice::bernstein(lattice.degree(), stu.x, bs);
    FfdLattice::bernstein(lattice.degree(), stu.y, bt);
    FfdLattice::bernstein(lattice.degree(), stu.z, bu);
    glm::dvec3 reached(0.0);
    int moved = 0;
    double ratio = -1.0;
    const glm::dvec3 d = glm::dvec3(tool - mesh.restPositionsMm()[t]);
    for (int i = 0; i <= lattice.degree(); ++i)
        for (int j = 0; j <= lattice.degree(); ++j)
            for (int k = 0; k <= lattice.degree(); ++k) {
                const glm::dvec3 m = dP[lattice.index(i, j, k)];
                const double w = bs[i] * bt[j] * bu[k];
                reached += w * m;
                if (glm::length(m) == 0.0) continue;
                ++moved;
                EXPECT_NEAR(glm::length(glm::cross(m, d)), 0.0, 1e-6 * glm::length(m) * glm::length(d));
                const double r2 = glm::length(m) / w;
                if (ratio < 0.0) ratio = r2;
                EXPECT_NEAR(r2, ratio, 1e-4 * ratio);
            }
    EXPECT_EQ(moved, p.movedPerAxis * p.movedPerAxis * p.movedPerAxis);
    EXPECT_LT(glm::length(reached - d), 1e-5);

    // Every vertex is where the lattice map with the moved control points puts it.
    auto control = lattice.restControlPoints();
    for (std::size_t c = 0; c < control.size(); ++c) control[c] += dP[c];
    double worst = 0.0;
    for (VertexId v = 0; v < mesh.vertexCount(); ++v) {
        const glm::dvec3 x = lattice.evaluate(model.latticeCoordinatesOf(v), control);
        worst = std::max(worst, glm::length(x - glm::dvec3(model.positionsMm()[v])));
    }
    EXPECT_LT(worst, 1e-4);

    // Release: back to the mesh.
    model.step(mesh.restPositionsMm()[t] + 2.0f * n, 0.001);
    for (VertexId v = 0; v < mesh.vertexCount(); ++v) ASSERT_EQ(model.positionsMm()[v], mesh.restPositionsMm()[v]);
}

TEST(FfdParams, ValidatorNamesTheField) {
    FfdParams p;
    EXPECT_TRUE(messagesOf(validateFfdParams(p)).empty());
    p.controlPointsPerAxis = 40;
    p.movedPerAxis = 0;
    const auto errors = messagesOf(validateFfdParams(p));
    ASSERT_EQ(errors.size(), 2u);
    EXPECT_NE(errors[0].find("controlPointsPerAxis"), std::string::npos);
    EXPECT_NE(errors[1].find("movedPerAxis"), std::string::npos);
}
