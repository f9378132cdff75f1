// The linear-elastic tet FEM on its own: one element's stiffness, the patch test (a linear field
// on the boundary of an irregular mesh is reproduced exactly inside, with the constant stress),
// reactions, solver agreement, and rejection of bad input.

#include "engine/fem/LinearElasticFem.h"
#include "tests/accuracy/AccuracyTestMeshes.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace palpate {
namespace {

constexpr ElasticMaterial kMaterial{0.01, 0.3};

/// Lame constants by hand (not from the code under test).
double lambdaOf(const ElasticMaterial& m) {
    return m.youngsModulusNPerMm2 * m.poissonRatio / ((1 + m.poissonRatio) * (1 - 2 * m.poissonRatio));
}
double muOf(const ElasticMaterial& m) { return m.youngsModulusNPerMm2 / (2 * (1 + m.poissonRatio)); }

const std::array<glm::dvec3, 4> kTet{glm::dvec3{0.1, -0.2, 0.05}, glm::dvec3{1.3, 0.1, -0.1},
                                     glm::dvec3{0.2, 0.9, 0.3}, glm::dvec3{0.4, 0.3, 1.1}};

std::array<double, 12> times(const std::array<double, 144>& k, const std::array<double, 12>& u) {
    std::array<double, 12> f{};
    for (int i = 0; i < 12; ++i)
        for (int j = 0; j < 12; ++j) f[std::size_t(i)] += k[std::size_t(12 * i + j)] * u[std::size_t(j)];
    return f;
}

double maxAbs(const std::array<double, 144>& k) {
    double m = 0;
    for (double v : k) m = std::max(m, std::abs(v));
    return m;
}

TEST(TetStiffness, RigidBodyModesGiveZeroForce) {
    const auto k = tetStiffness(kTet, kMaterial);
    const double scale = maxAbs(k);
    const glm::dvec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const auto& axis : axes) {
        std::array<double, 12> translation{}, rotation{};
        for (int n = 0; n < 4; ++n) {
            const glm::dvec3 r = glm::dvec3(axis.y * kTet[n].z - axis.z * kTet[n].y, axis.z * kTet[n].x - axis.x * kTet[n].z,
                                            axis.x * kTet[n].y - axis.y * kTet[n].x);  // axis x p
            for (int i = 0; i < 3; ++i) {
                translation[std::size_t(3 * n + i)] = axis[i];
                rotation[std::size_t(3 * n + i)] = r[i];
            }
        }
        for (double f : times(k, translation)) EXPECT_NEAR(f, 0.0, 1e-13 * scale);
        for (double f : times(k, rotation)) EXPECT_NEAR(f, 0.0, 1e-13 * scale);
    }
}

TEST(TetStiffness, SymmetricAndStoresTheStrainEnergy) {
    const auto k = tetStiffness(kTet, kMaterial);
    for (int i = 0; i < 12; ++i)
        for (int j = 0; j < 12; ++j) EXPECT_NEAR(k[std::size_t(12 * i + j)], k[std::size_t(12 * j + i)], 1e-14 * maxAbs(k));
    // u = A x with symmetric A: u^T K u = V (lambda tr(A)^2 + 2 mu A:A), energy by hand.
    const double a[3][3] = {{0.01, 0.002, -0.003}, {0.002, -0.004, 0.005}, {-0.003, 0.005, 0.007}};
    std::array<double, 12> u{};
    for (int n = 0; n < 4; ++n)
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) u[std::size_t(3 * n + i)] += a[i][j] * kTet[n][j];
    const auto f = times(k, u);
    double uKu = 0;
    for (int i = 0; i < 12; ++i) uKu += u[std::size_t(i)] * f[std::size_t(i)];
    const double volume = tetSignedVolume6(kTet[0], kTet[1], kTet[2], kTet[3]) / 6.0;
    double trace = 0, aa = 0;
    for (int i = 0; i < 3; ++i) {
        trace += a[i][i];
        for (int j = 0; j < 3; ++j) aa += a[i][j] * a[i][j];
    }
    const double expected = volume * (lambdaOf(kMaterial) * trace * trace + 2 * muOf(kMaterial) * aa);
    EXPECT_NEAR(uKu, expected, 1e-12 * expected);
}

TEST(TetStiffness, RejectsAFlatTet) {
    std::array<glm::dvec3, 4> flat = kTet;
    flat[3] = 0.5 * (flat[1] + flat[2]);
    EXPECT_THROW(tetStiffness(flat, kMaterial), std::invalid_argument);
}

/// The patch test: u = A x + c on the boundary of a jittered box; every solver reproduces it
/// inside to 1e-9 relative and every tet carries the stress C : sym(A).
void expectPatchTestPasses(FemSolverDef options, const ElasticMaterial& material = kMaterial) {
    const auto box = test::kuhnBox(4, {-1.0, 0.5, -2.0}, 3.0, 0.2, 7);
    const double a[3][3] = {{0.010, 0.004, -0.002}, {-0.003, 0.006, 0.001}, {0.002, -0.005, -0.008}};
    const glm::dvec3 c{0.05, -0.02, 0.01};
    auto exact = [&](const glm::dvec3& p) {
        glm::dvec3 u = c;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) u[i] += a[i][j] * p[j];
        return u;
    };
    std::vector<std::uint8_t> fixed(box.mesh.dofCount(), 0);
    std::vector<double> prescribed(box.mesh.dofCount(), 0.0);
    std::size_t interior = 0;
    for (std::size_t n = 0; n < box.mesh.nodeCount(); ++n) {
        if (!box.onBoundary[n]) {
            ++interior;
            continue;
        }
        const glm::dvec3 u = exact(box.mesh.nodesMm[n]);
        for (int i = 0; i < 3; ++i) {
            fixed[3 * n + std::size_t(i)] = 1;
            prescribed[3 * n + std::size_t(i)] = u[i];
        }
    }
    ASSERT_EQ(interior, 27u);
    LinearElasticFem fem(box.mesh, material, fixed, options);
    const FemSolution s = fem.solve(prescribed);
    double scale = 0;
    for (const auto& p : box.mesh.nodesMm) scale = std::max(scale, glm::length(exact(p)));
    for (std::size_t n = 0; n < box.mesh.nodeCount(); ++n)
        EXPECT_LE(glm::length(s.displacementMm[n] - exact(box.mesh.nodesMm[n])), 1e-9 * scale) << "node " << n;

    // Constant stress: sigma = lambda tr(eps) I + 2 mu eps with eps = sym(A), by hand.
    const double lambda = lambdaOf(material), mu = muOf(material);
    const double trace = a[0][0] + a[1][1] + a[2][2];
    const std::array<double, 6> expected{lambda * trace + 2 * mu * a[0][0], lambda * trace + 2 * mu * a[1][1],
                                         lambda * trace + 2 * mu * a[2][2], mu * (a[1][2] + a[2][1]),
                                         mu * (a[0][2] + a[2][0]),         mu * (a[0][1] + a[1][0])};
    double stressScale = 0;
    for (double v : expected) stressScale = std::max(stressScale, std::abs(v));
    for (const auto& t : box.mesh.tets) {
        const std::array<glm::dvec3, 4> p{box.mesh.nodesMm[t[0]], box.mesh.nodesMm[t[1]], box.mesh.nodesMm[t[2]],
                                          box.mesh.nodesMm[t[3]]};
        const std::array<glm::dvec3, 4> u{s.displacementMm[t[0]], s.displacementMm[t[1]], s.displacementMm[t[2]],
                                          s.displacementMm[t[3]]};
        const auto stress = tetStressNPerMm2(p, u, material);
        for (int i = 0; i < 6; ++i) EXPECT_NEAR(stress[std::size_t(i)], expected[std::size_t(i)], 1e-9 * stressScale);
    }
    // No body force: the reactions balance, and interior nodes carry none.
    glm::dvec3 total(0.0);
    double largest = 0;
    for (std::size_t n = 0; n < box.mesh.nodeCount(); ++n) {
        total += s.reactionN[n];
        largest = std::max(largest, glm::length(s.reactionN[n]));
        if (!box.onBoundary[n]) {
            EXPECT_EQ(glm::length(s.reactionN[n]), 0.0);
        }
    }
    EXPECT_GT(largest, 0.0);
    EXPECT_LE(glm::length(total), 1e-10 * largest);
}

TEST(LinearElasticFem, PatchTestDirect) {
    // Both elements, and nearly incompressible: a uniform volume change averaged at the nodes is
    // itself, so the nodal-pressure element passes the patch test as the constant-strain one does.
    for (const TetElement element : {TetElement::ConstantStrain, TetElement::NodalPressure})
        for (const double nu : {0.3, 0.499}) {
            SCOPED_TRACE(std::string(tetElementName(element)) + ", nu " + std::to_string(nu));
            FemSolverDef o;
            o.kind = FemSolverKind::DirectLdlt;
            o.element = element;
            expectPatchTestPasses(o, ElasticMaterial{0.01, nu});
        }
}

// The nodal-pressure element's K gives no force for a rigid motion, and a nearly incompressible
// box pressed with its sides free needs far less force than with constant-strain tets, which lock.
TEST(StiffnessMatrix, NodalPressureIsRigidFreeAndDoesNotLock) {
    const auto box = test::kuhnBox(3, {0, 0, 0}, 1.0, 0.15, 3);
    const ElasticMaterial nearlyIncompressible{0.01, 0.499};
    std::vector<std::uint8_t> bottom(box.mesh.dofCount(), 0);
    for (std::size_t n = 0; n < box.mesh.nodeCount(); ++n)
        if (box.mesh.nodesMm[n].z < 1e-9) bottom[3 * n] = bottom[3 * n + 1] = bottom[3 * n + 2] = 1;
    // Rigid motions of the whole box: no reaction anywhere (prescribe all DOFs).
    std::vector<std::uint8_t> all(box.mesh.dofCount(), 1);
    all[0] = 0;  // one free DOF: the system needs one
    const LinearElasticFem free(box.mesh, nearlyIncompressible, all);
    std::vector<double> rigid(box.mesh.dofCount(), 0.0);
    for (std::size_t n = 0; n < box.mesh.nodeCount(); ++n) {
        const glm::dvec3& p = box.mesh.nodesMm[n];
        const glm::dvec3 u = glm::dvec3(0.01, -0.02, 0.03) + glm::cross(glm::dvec3(0.02, 0.01, -0.015), p);
        for (int i = 0; i < 3; ++i) rigid[3 * n + std::size_t(i)] = u[i];
    }
    const FemSolution r = free.solve(rigid);
    for (std::size_t n = 1; n < box.mesh.nodeCount(); ++n) EXPECT_NEAR(glm::length(r.reactionN[n]), 0.0, 1e-15);
    // The top pressed down 1 % with the bottom held: nearly incompressible constant-strain tets
    // lock (the top barely moves without changing volume); the nodal-pressure element needs far
    // less force.
    std::vector<std::uint8_t> pressed = bottom;
    std::vector<double> values(box.mesh.dofCount(), 0.0);
    for (std::size_t n = 0; n < box.mesh.nodeCount(); ++n)
        if (box.mesh.nodesMm[n].z > 1.0 - 1e-9) {
            pressed[3 * n + 2] = 1;
            values[3 * n + 2] = -0.01;
        }
    double force[2] = {0.0, 0.0};
    for (const TetElement element : {TetElement::ConstantStrain, TetElement::NodalPressure}) {
        FemSolverDef o;
        o.element = element;
        const FemSolution s = LinearElasticFem(box.mesh, nearlyIncompressible, pressed, o).solve(values);
        for (std::size_t n = 0; n < box.mesh.nodeCount(); ++n)
            if (box.mesh.nodesMm[n].z > 1.0 - 1e-9) force[element == TetElement::NodalPressure] -= s.reactionN[n].z;
    }
    std::printf("[ figures  ] box pressed 1 %% at nu 0.499: %.4g N constant strain, %.4g N nodal pressure\n", force[0],
                force[1]);
    EXPECT_GT(force[1], 0.0);
    EXPECT_LT(force[1], 0.5 * force[0]);
    EXPECT_EQ(parseTetElement("nodal-pressure"), TetElement::NodalPressure);
    EXPECT_EQ(parseTetElement("constant-strain"), TetElement::ConstantStrain);
    EXPECT_FALSE(parseTetElement("quadratic"));
}

TEST(LinearElasticFem, PatchTestConjugateGradientBothPreconditioners) {
    for (auto pre : {FemPreconditioner::Diagonal, FemPreconditioner::IncompleteCholesky, FemPreconditioner::NodeBlockJacobi}) {
        FemSolverDef o;
        o.kind = FemSolverKind::ConjugateGradient;
        o.preconditioner = pre;
        o.cgRelativeTolerance = 1e-13;
        expectPatchTestPasses(o);
    }
}

TEST(LinearElasticFem, SolverChoiceAndStats) {
    const auto box = test::kuhnBox(3, {0, 0, 0}, 1.0);
    std::vector<std::uint8_t> fixed(box.mesh.dofCount(), 0);
    std::vector<double> prescribed(box.mesh.dofCount(), 0.0);
    for (std::size_t n = 0; n < box.mesh.nodeCount(); ++n) {
        const auto& p = box.mesh.nodesMm[n];
        if (p.z == 0.0) fixed[3 * n] = fixed[3 * n + 1] = fixed[3 * n + 2] = 1;
        if (p.z == 1.0) {
            fixed[3 * n + 2] = 1;
            prescribed[3 * n + 2] = -0.01;  // compress by 1 %
        }
    }
    FemSolverDef direct;  // Auto: this small system goes to LDLT
    FemSolverDef cg;
    cg.kind = FemSolverKind::ConjugateGradient;
    cg.cgRelativeTolerance = 1e-12;
    LinearElasticFem a(box.mesh, kMaterial, fixed, direct), b(box.mesh, kMaterial, fixed, cg);
    EXPECT_EQ(a.solverName(), "ldlt");
    EXPECT_EQ(b.solverName(), "cg+diag");
    EXPECT_EQ(a.fixedDofCount() + a.freeDofCount(), box.mesh.dofCount());
    const auto sa = a.solve(prescribed);
    const auto many = b.solveMany({prescribed, prescribed});
    ASSERT_EQ(many.size(), 2u);
    EXPECT_GT(many[0].stats.iterations, 0);
    EXPECT_TRUE(many[0].stats.converged);
    EXPECT_LT(many[0].stats.relativeResidual, 1e-11);
    for (std::size_t n = 0; n < box.mesh.nodeCount(); ++n) {
        EXPECT_NEAR(glm::length(sa.displacementMm[n] - many[0].displacementMm[n]), 0.0, 1e-9);
        EXPECT_EQ(many[0].displacementMm[n], many[1].displacementMm[n]);
    }
    // Laterally free top, fixed bottom: the top is pushed down, the bottom pushes back up.
    double top = 0, bottom = 0;
    for (std::size_t n = 0; n < box.mesh.nodeCount(); ++n) {
        if (box.mesh.nodesMm[n].z == 1.0) top += sa.reactionN[n].z;
        if (box.mesh.nodesMm[n].z == 0.0) bottom += sa.reactionN[n].z;
    }
    EXPECT_LT(top, 0.0);
    EXPECT_NEAR(top + bottom, 0.0, 1e-12 * std::abs(top));
}

TEST(StiffnessMatrix, RotatedEqualsAssemblingTheRotatedMesh) {
    const auto box = test::kuhnBox(2, {0.2, -0.1, 0.3}, 1.5, 0.2, 3);
    const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
    const glm::dvec3 t1 = glm::normalize(glm::cross(glm::dvec3(1, 0, 0), n));
    const glm::dvec3 t2 = glm::cross(n, t1);
    TetMesh turned = box.mesh;
    for (auto& p : turned.nodesMm) p = {glm::dot(p, t1), glm::dot(p, t2), glm::dot(p, n)};
    // Same partition and prescribed values in the new frame: same solution, node by node.
    std::vector<std::uint8_t> fixed(box.mesh.dofCount(), 0);
    std::vector<double> values(box.mesh.dofCount(), 0.0);
    for (std::size_t i = 0; i < box.mesh.nodeCount(); ++i)
        if (box.onBoundary[i]) {
            fixed[3 * i + 2] = 1;
            values[3 * i + 2] = 0.01 * double(i % 5);
            if (i % 3 == 0) fixed[3 * i] = fixed[3 * i + 1] = 1;
        }
    for (const TetElement element : {TetElement::ConstantStrain, TetElement::NodalPressure}) {
        FemSolverDef o;
        o.element = element;
        const StiffnessMatrix k(box.mesh, kMaterial, element);
        const auto a = LinearElasticFem(k.rotated(glm::transpose(glm::dmat3(t1, t2, n))), fixed).solve(values);
        const auto b = LinearElasticFem(turned, kMaterial, fixed, o).solve(values);
        for (std::size_t i = 0; i < box.mesh.nodeCount(); ++i) {
            EXPECT_NEAR(glm::length(a.displacementMm[i] - b.displacementMm[i]), 0.0, 1e-12);
            EXPECT_NEAR(glm::length(a.reactionN[i] - b.reactionN[i]), 0.0, 1e-14);
        }
    }
}

TEST(LinearElasticFem, RejectsBadInput) {
    const auto box = test::kuhnBox(2, {0, 0, 0}, 1.0);
    std::vector<std::uint8_t> someFixed(box.mesh.dofCount(), 0);  // the bottom face held
    for (std::size_t n = 0; n < box.mesh.nodeCount(); ++n)
        if (box.mesh.nodesMm[n].z == 0.0) someFixed[3 * n] = someFixed[3 * n + 1] = someFixed[3 * n + 2] = 1;
    EXPECT_THROW(LinearElasticFem(box.mesh, kMaterial, std::vector<std::uint8_t>(5, 0)), std::invalid_argument);
    EXPECT_THROW(LinearElasticFem(box.mesh, ElasticMaterial{0.01, 0.5}, someFixed), std::invalid_argument);
    EXPECT_THROW(LinearElasticFem(box.mesh, ElasticMaterial{std::nan(""), 0.3}, someFixed), std::invalid_argument);
    EXPECT_THROW(LinearElasticFem(box.mesh, kMaterial, std::vector<std::uint8_t>(box.mesh.dofCount(), 1)),
                 std::invalid_argument);
    TetMesh inverted = box.mesh;
    std::swap(inverted.tets[3][0], inverted.tets[3][1]);
    try {
        LinearElasticFem fem(inverted, kMaterial, someFixed);
        FAIL() << "an inverted tet was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("tet 3"), std::string::npos) << e.what();
    }
    TetMesh nan = box.mesh;
    nan.nodesMm[4].y = std::numeric_limits<double>::infinity();
    EXPECT_THROW(LinearElasticFem(nan, kMaterial, someFixed), std::invalid_argument);
    LinearElasticFem ok(box.mesh, kMaterial, someFixed);
    EXPECT_THROW(ok.solve(std::vector<double>(3)), std::invalid_argument);
    std::vector<double> bad(box.mesh.dofCount(), 0.0);
    bad[0] = std::nan("");
    EXPECT_THROW(ok.solve(bad), std::invalid_argument);
}

}  // namespace
}  // namespace palpate
