// Mass-spring model: the integrators' energy laws on single modes computed by hand, both sides of
// the explicit stability bound, the static equilibrium, and whole/local parity.
#include "engine/core/Octree.h"
#include "engine/core/Rings.h"
#include "engine/core/SceneTarget.h"
#include "engine/core/ToolPath.h"
#include "engine/models/MassSpringModel.h"
#include "tests/models/ModelTestMeshes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace palpate;

namespace {

const glm::vec3 kNoTool(NAN, NAN, NAN);  // no tool: no touched vertex, no contact

MassSpringParams undamped() {
    MassSpringParams p;
    p.dampingRatio = 0.0;
    p.substeps = 1;
    p.cgTolerance = 1e-7;
    return p;
}

// Sum over vertices of u . w (mm^2/s), for symplectic Euler's invariant.
double sumUW(const MassSpringModel& m) {
    double s = 0.0;
    for (std::size_t v = 0; v < m.displacementsMm().size(); ++v)
        s += double(glm::dot(m.displacementsMm()[v], m.velocitiesMmPerS()[v]));
    return s;
}

// Puts the K4 tetrahedron in one eigenmode: "uniform" (every vertex the same displacement: the
// edges do not stretch, omega^2 = 1000 k_a / m) or "edge" (zero mean: eigenvalue 4 of K4's
// Laplacian, omega^2 = 1000 (k_a + 4 k_e) / m).
double setMode(MassSpringModel& model, bool uniform) {
    const MassSpringParams& p = model.params();
    for (VertexId v = 0; v < 4; ++v)
        model.setVertexState(v, glm::vec3(uniform ? 1.0f : (v == 0 ? 3.0f : -1.0f), 0.0f, 0.0f), glm::vec3(0.0f));
    const double k = uniform ? p.anchorStiffnessNPerMm : p.anchorStiffnessNPerMm + 4.0 * p.edgeStiffnessNPerMm;
    return std::sqrt(1000.0 * k / p.vertexMassKg);
}

}  // namespace

TEST(MassSpringParams, ValidatorNamesTheField) {
    MassSpringParams p;
    EXPECT_TRUE(messagesOf(validateMassSpringParams(p)).empty());
    p.anchorStiffnessNPerMm = -1.0;
    p.cgTolerance = 2.0;
    p.localRingCount = 20;
    const auto errors = messagesOf(validateMassSpringParams(p));
    ASSERT_EQ(errors.size(), 3u);
    EXPECT_NE(errors[0].find("anchorStiffnessNPerMm"), std::string::npos) << errors[0];
    EXPECT_NE(errors[1].find("cgTolerance"), std::string::npos) << errors[1];
    EXPECT_NE(errors[2].find("localRingCount"), std::string::npos) << errors[2];
    const TissueMesh mesh = test::tetrahedronMesh();
    const Octree octree(mesh, {});
    EXPECT_THROW(MassSpringModel(mesh, octree, p, MassSpringIntegrator::Rk4, MassSpringScope::Whole), std::invalid_argument);
}

TEST(MassSpringEnergy, SymplecticEulerConservesItsInvariantAndBoundsTheEnergy) {
    // On one mode of frequency w, symplectic Euler (velocity first) conserves exactly
    // I = v^2 + w^2 x^2 - h w^2 x v, so the energy E = (v^2 + w^2 x^2) / 2 (times the mass) stays
    // within E0 (1 - h w / 2) / (1 + h w / 2) .. E0 (1 + h w / 2) / (1 - h w / 2): no drift.
    const TissueMesh mesh = test::tetrahedronMesh();
    const Octree octree(mesh, {});
    for (bool uniform : {true, false}) {
        MassSpringModel model(mesh, octree, undamped(), MassSpringIntegrator::SymplecticEuler, MassSpringScope::Whole);
        const double w = setMode(model, uniform);
        const double h = 0.0005;
        const double x = h * w / 2.0;
        ASSERT_LT(x, 1.0);
        const double m = model.params().vertexMassKg * 1e-3;  // energy per (mm/s)^2, mJ
        const double e0 = model.energyMilliJ();
        const double i0 = e0 - 0.5 * m * h * w * w * sumUW(model);
        double lo = e0, hi = e0;
        for (int i = 0; i < 4000; ++i) {
            model.step(kNoTool, h);
            const double e = model.energyMilliJ();
            lo = std::min(lo, e);
            hi = std::max(hi, e);
            ASSERT_NEAR(e - 0.5 * m * h * w * w * sumUW(model), i0, 1e-4 * i0) << "tick " << i;
        }
        EXPECT_GE(lo, e0 * (1.0 - x) / (1.0 + x) * (1.0 - 1e-4)) << (uniform ? "uniform" : "edge");
        EXPECT_LE(hi, e0 * (1.0 + x) / (1.0 - x) * (1.0 + 1e-4)) << (uniform ? "uniform" : "edge");
        EXPECT_GT(hi - lo, 1e-3 * e0);  // it does oscillate (h w = 0.16 and 0.72), within the bounds
    }
}

TEST(MassSpringEnergy, BackwardEulerLosesEnergyByExactlyOnePlusHSquaredOmegaSquaredPerStep) {
    // On one mode, backward Euler maps v^2 + w^2 x^2 to itself / (1 + h^2 w^2): derived by hand in
    // docs/models.md. The conjugate-gradient solve must reproduce it.
    const TissueMesh mesh = test::tetrahedronMesh();
    const Octree octree(mesh, {});
    for (bool uniform : {true, false}) {
        MassSpringModel model(mesh, octree, undamped(), MassSpringIntegrator::BackwardEuler, MassSpringScope::Whole);
        const double w = setMode(model, uniform);
        const double h = 0.001;
        const double e0 = model.energyMilliJ();
        double previous = e0;
        for (int i = 1; i <= 60; ++i) {
            model.step(kNoTool, h);
            const double e = model.energyMilliJ();
            EXPECT_LT(e, previous) << "tick " << i;
            previous = e;
            EXPECT_NEAR(e, e0 * std::pow(1.0 + h * h * w * w, -i), 1e-4 * e0) << "tick " << i;
            ASSERT_TRUE(model.lastCgConverged());
        }
        EXPECT_LT(previous, 0.5 * e0);
    }
}

TEST(MassSpringEnergy, Rk4LosesEnergyByItsAmplificationFactor) {
    // RK4 on one mode: the state is multiplied by R(i h w) = 1 + z + z^2/2 + z^3/6 + z^4/24 each
    // step (a normal matrix here), so the energy by |R|^2 = 1 - (hw)^6/72 + (hw)^8/576 < 1.
    const TissueMesh mesh = test::tetrahedronMesh();
    const Octree octree(mesh, {});
    MassSpringModel model(mesh, octree, undamped(), MassSpringIntegrator::Rk4, MassSpringScope::Whole);
    const double w = setMode(model, false);
    const double h = 0.001;
    const double y = h * w;
    const double r2 = 1.0 - std::pow(y, 6) / 72.0 + std::pow(y, 8) / 576.0;
    const double e0 = model.energyMilliJ();
    for (int i = 1; i <= 300; ++i) {
        model.step(kNoTool, h);
        if (i % 50 == 0) {
            EXPECT_NEAR(model.energyMilliJ(), e0 * std::pow(r2, i), 1e-4 * e0) << "tick " << i;
        }
    }
    EXPECT_LT(model.energyMilliJ(), e0);
}

TEST(MassSpringStability, SymplecticEulerBothSidesOfTwoOverOmega) {
    // K4 with its fastest mode: stable for h w < 2, unstable above. The Gershgorin bound the
    // automatic sub-steps use is above the true w.
    const TissueMesh mesh = test::tetrahedronMesh();
    const Octree octree(mesh, {});
    for (double factor : {0.95, 1.05}) {
        MassSpringModel model(mesh, octree, undamped(), MassSpringIntegrator::SymplecticEuler, MassSpringScope::Whole);
        const double w = setMode(model, false);
        EXPECT_GE(model.omegaMaxBoundRadPerS(), w);
        const double e0 = model.energyMilliJ();
        for (int i = 0; i < 100; ++i) model.step(kNoTool, factor * 2.0 / w);
        if (factor < 1.0) {
            EXPECT_LT(model.energyMilliJ(), 100.0 * e0);  // bounded by (1 + 0.475) / (1 - 0.475) = 2.8
        } else {
            EXPECT_GT(model.energyMilliJ(), 1e6 * e0);
        }
    }
    MassSpringParams automatic = undamped();
    automatic.substeps = 0;
    MassSpringModel model(mesh, octree, automatic, MassSpringIntegrator::SymplecticEuler, MassSpringScope::Whole);
    const double w = setMode(model, false);
    const double e0 = model.energyMilliJ();
    for (int i = 0; i < 300; ++i) model.step(kNoTool, 1.05 * 2.0 / w);  // sub-stepped: stable
    EXPECT_GT(model.substepsFor(1.05 * 2.0 / w), 1);
    EXPECT_LT(model.energyMilliJ(), 2.0 * e0);
}

TEST(MassSpringContact, EveryIntegratorSettlesOnTheSameStaticEquilibrium) {
    // Pressed and held, the dent is the solution of K u = f_contact whatever the integrator; the
    // rendered force is k_c times the tool's depth below the displaced touched vertex.
    const TissueMesh mesh = test::sphereMesh(642);
    const Octree octree(mesh, {});
    const VertexId target = defaultTargetVertex(mesh);
    const glm::vec3 n = mesh.restNormals()[target];
    const glm::vec3 tool = mesh.restPositionsMm()[target] - 3.0f * n;
    std::vector<std::vector<glm::vec3>> fields;
    for (auto integrator : {MassSpringIntegrator::BackwardEuler, MassSpringIntegrator::SymplecticEuler, MassSpringIntegrator::Rk4}) {
        MassSpringParams p;
        p.cgTolerance = 1e-7;
        MassSpringModel model(mesh, octree, p, integrator, MassSpringScope::Whole);
        TickResult r;
        for (int i = 0; i < 800; ++i) r = model.step(tool, 0.001);
        ASSERT_TRUE(r.contact) << integratorName(integrator);
        ASSERT_EQ(r.touched, target);
        const glm::vec3 u = model.displacementsMm()[target];
        const float penetration = 3.0f + glm::dot(u, n);
        EXPECT_NEAR(glm::length(r.forceN), p.contactStiffnessNPerMm * penetration, 1e-5);
        EXPECT_GT(glm::dot(r.forceN, n), 0.0f);  // out of the tissue
        // Static residual per vertex: anchor + edges + contact = 0.
        double worst = 0.0;
        for (VertexId v = 0; v < mesh.vertexCount(); ++v) {
            glm::dvec3 f = -p.anchorStiffnessNPerMm * glm::dvec3(model.displacementsMm()[v]);
            for (auto k = mesh.neighbourStart()[v]; k < mesh.neighbourStart()[v + 1]; ++k)
                f += p.edgeStiffnessNPerMm * glm::dvec3(model.displacementsMm()[mesh.neighbours()[k]] - model.displacementsMm()[v]);
            if (v == target) f -= p.contactStiffnessNPerMm * double(penetration) * glm::dvec3(n);
            worst = std::max(worst, glm::length(f));
        }
        EXPECT_LT(worst, 1e-3 * glm::length(r.forceN)) << integratorName(integrator);
        fields.emplace_back(model.displacementsMm().begin(), model.displacementsMm().end());
    }
    for (std::size_t k = 1; k < fields.size(); ++k)
        for (VertexId v = 0; v < mesh.vertexCount(); ++v) ASSERT_NEAR(glm::length(fields[k][v] - fields[0][v]), 0.0f, 2e-3f) << v;
}

TEST(MassSpringLocal, AgreesWithTheWholeModelWhenTheDentFitsInTheRings) {
    // With stiff anchors the whole model's dent decays ~10x per ring, so pinning everything
    // beyond 6 rings changes nothing measurable: same touched vertices, forces and surface.
    const TissueMesh mesh = test::sphereMesh(1442);
    const Octree octree(mesh, {});
    MassSpringParams p;
    p.anchorStiffnessNPerMm = 1.0;
    p.edgeStiffnessNPerMm = 0.2;
    p.cgTolerance = 1e-7;
    const auto path = makePressAndStrokePath(mesh);
    for (auto integrator : {MassSpringIntegrator::BackwardEuler, MassSpringIntegrator::SymplecticEuler}) {
        p.localIntegrator = integrator;
        MassSpringModel whole(mesh, octree, p, integrator, MassSpringScope::Whole);
        MassSpringModel local(mesh, octree, p, integrator, MassSpringScope::Local);
        RingFinder finder(mesh);
        RingSet rings = finder.makeRingSet();
        float worstForce = 0.0f, peak = 0.0f;
        std::size_t mostSimulated = 0, ringSize = 0;
        for (std::size_t i = 0; i < 2000; ++i) {
            const TickResult a = whole.step(path[i], 0.001);
            const TickResult b = local.step(path[i], 0.001);
            ASSERT_EQ(a.touched, b.touched) << "tick " << i;
            ASSERT_EQ(a.contact, b.contact) << "tick " << i;
            worstForce = std::max(worstForce, glm::length(a.forceN - b.forceN));
            peak = std::max(peak, glm::length(a.forceN));
            mostSimulated = std::max(mostSimulated, local.simulatedCount());
            finder.find(b.touched, p.localRingCount, rings);
            ringSize = std::max(ringSize, rings.size());
        }
        EXPECT_LT(worstForce, 1e-3f * peak) << integratorName(integrator);
        float worstPosition = 0.0f;
        for (VertexId v = 0; v < mesh.vertexCount(); ++v)
            worstPosition = std::max(worstPosition, glm::length(whole.positionsMm()[v] - local.positionsMm()[v]));
        EXPECT_LT(worstPosition, 1e-3f) << integratorName(integrator);
        // Bounded work: the rings plus a short trail of vertices still moving.
        EXPECT_LT(mostSimulated, 3 * ringSize) << integratorName(integrator);
        EXPECT_LT(mostSimulated, mesh.vertexCount() / 4);
    }
}

TEST(MassSpringRelaxation, ReturnsToRestAfterRelease) {
    const TissueMesh mesh = test::sphereMesh(642);
    const Octree octree(mesh, {});
    const auto path = makePressAndStrokePath(mesh);
    for (auto scope : {MassSpringScope::Whole, MassSpringScope::Local}) {
        MassSpringModel model(mesh, octree, MassSpringParams{}, MassSpringIntegrator::BackwardEuler, scope);
        for (const auto& tool : path) model.step(tool, 0.001);
        for (int i = 0; i < 500; ++i) model.step(path.back(), 0.001);  // 2 mm above the surface
        EXPECT_LT(model.maxDisplacementMm(), 1e-3f);
        model.reset();
        for (VertexId v = 0; v < mesh.vertexCount(); ++v) ASSERT_EQ(model.positionsMm()[v], mesh.restPositionsMm()[v]);
    }
}
