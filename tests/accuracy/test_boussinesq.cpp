// The Boussinesq field that the reference block imposes on its far faces: checked against
// elasticity itself (equilibrium, a traction-free surface, the load it carries) by finite
// differences, and reproduced by the FEM inside a box away from the load, converging as h^2.

#include "engine/fem/ClosedForms.h"
#include "engine/fem/LinearElasticFem.h"
#include "tests/accuracy/AccuracyTestMeshes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace palpate {
namespace {

constexpr ElasticMaterial kMaterial{0.01, 0.3};
constexpr double kLoadN = 0.002;

/// Stress (xx, yy, zz, yz, xz, xy) from central differences of the displacement.
std::array<double, 6> stressAt(const glm::dvec3& p, double step) {
    double g[3][3];  // du_i / dx_j
    for (int j = 0; j < 3; ++j) {
        glm::dvec3 e(0.0);
        e[j] = step;
        const glm::dvec3 d =
            (boussinesqDisplacementMm(kMaterial, kLoadN, p + e) - boussinesqDisplacementMm(kMaterial, kLoadN, p - e)) /
            (2 * step);
        for (int i = 0; i < 3; ++i) g[i][j] = d[i];
    }
    const double nu = kMaterial.poissonRatio, e = kMaterial.youngsModulusNPerMm2;
    const double lambda = e * nu / ((1 + nu) * (1 - 2 * nu)), mu = e / (2 * (1 + nu));
    const double tr = g[0][0] + g[1][1] + g[2][2];
    return {lambda * tr + 2 * mu * g[0][0], lambda * tr + 2 * mu * g[1][1], lambda * tr + 2 * mu * g[2][2],
            mu * (g[1][2] + g[2][1]),      mu * (g[0][2] + g[2][0]),      mu * (g[0][1] + g[1][0])};
}

TEST(BoussinesqField, SatisfiesEquilibriumInside) {
    for (const glm::dvec3 p : {glm::dvec3{1.0, 0.5, -1.0}, glm::dvec3{-2.0, 1.0, -0.5}, glm::dvec3{0.3, -0.2, -3.0}}) {
        const double rho = glm::length(p);
        const double h = 2e-3 * rho;
        // div sigma by central differences of the stress.
        glm::dvec3 div(0.0);
        const int column[3][3] = {{0, 5, 4}, {5, 1, 3}, {4, 3, 2}};  // Voigt index of sigma_ij
        for (int j = 0; j < 3; ++j) {
            glm::dvec3 e(0.0);
            e[j] = h;
            const auto plus = stressAt(p + e, 1e-2 * h), minus = stressAt(p - e, 1e-2 * h);
            for (int i = 0; i < 3; ++i) div[i] += (plus[std::size_t(column[i][j])] - minus[std::size_t(column[i][j])]) / (2 * h);
        }
        const auto s = stressAt(p, 1e-2 * h);
        double scale = 0;
        for (double v : s) scale = std::max(scale, std::abs(v));
        EXPECT_LT(glm::length(div) * rho / scale, 1e-4) << p.x << " " << p.y << " " << p.z;
    }
}

TEST(BoussinesqField, SurfaceIsTractionFreeAwayFromTheLoad) {
    for (double r : {0.5, 2.0, 7.0}) {
        const glm::dvec3 p{r * 0.6, r * 0.8, 0.0};
        // One-sided (second-order) derivative in z: the field exists only for z <= 0.
        const double h = 1e-4 * r;
        auto u = [&](const glm::dvec3& q) { return boussinesqDisplacementMm(kMaterial, kLoadN, q); };
        const glm::dvec3 dz = (3.0 * u(p) - 4.0 * u(p - glm::dvec3(0, 0, h)) + u(p - glm::dvec3(0, 0, 2 * h))) / (2 * h);
        const glm::dvec3 dx = (u(p + glm::dvec3(h, 0, 0)) - u(p - glm::dvec3(h, 0, 0))) / (2 * h);
        const glm::dvec3 dy = (u(p + glm::dvec3(0, h, 0)) - u(p - glm::dvec3(0, h, 0))) / (2 * h);
        const double nu = kMaterial.poissonRatio, e = kMaterial.youngsModulusNPerMm2;
        const double lambda = e * nu / ((1 + nu) * (1 - 2 * nu)), mu = e / (2 * (1 + nu));
        const double tr = dx.x + dy.y + dz.z;
        const double szz = lambda * tr + 2 * mu * dz.z, sxz = mu * (dz.x + dx.z), syz = mu * (dz.y + dy.z);
        const double scale = mu * glm::length(dx);  // a typical stress there
        EXPECT_LT(std::abs(szz) / scale, 1e-5) << r;
        EXPECT_LT(std::abs(sxz) / scale, 1e-5) << r;
        EXPECT_LT(std::abs(syz) / scale, 1e-5) << r;
        // And the surface displacement is Boussinesq's P (1 - nu^2) / (pi E r), pointing in.
        EXPECT_NEAR(-u(p).z, kLoadN * (1 - nu * nu) / (std::numbers::pi * e * r), 1e-12);
    }
}

TEST(BoussinesqField, CarriesTheLoadThroughAnyPlane) {
    // Integral of sigma_zz over the plane z = -d is -P (compression), at any depth.
    for (double d : {0.5, 2.0}) {
        double force = 0.0;
        // r = d sinh(s): dense near the axis, reaches 500 d (the tail beyond carries ~(d/r)^3 of P).
        const int steps = 4000;
        const double sMax = std::asinh(500.0);
        for (int i = 0; i < steps; ++i) {
            const double s = (i + 0.5) * sMax / steps;
            const double r = d * std::sinh(s), drds = d * std::cosh(s);
            const double szz = stressAt({r, 0.0, -d}, 1e-4 * std::hypot(r, d))[2];
            force += szz * 2 * std::numbers::pi * r * drds * (sMax / steps);
        }
        EXPECT_NEAR(force / kLoadN, -1.0, 1e-4) << d;
    }
}

TEST(BoussinesqField, FemReproducesItInABoxAwayFromTheLoadAtSecondOrder) {
    // Box [1, 3] x [1, 3] x [-3, -1]: the field is smooth there; impose it on the boundary.
    // RMS nodal error over the interior nodes, relative to the largest displacement; measured
    // 9.6e-4, 2.4e-4, 6.0e-5 for n = 4, 8, 16 (a factor ~4 per halving of h).
    double previousError = 0.0;
    for (int n : {4, 8, 16}) {
        const auto box = test::kuhnBox(n, {1.0, 1.0, -3.0}, 2.0);
        std::vector<std::uint8_t> fixed(box.mesh.dofCount(), 0);
        std::vector<double> values(box.mesh.dofCount(), 0.0);
        for (std::size_t i = 0; i < box.mesh.nodeCount(); ++i)
            if (box.onBoundary[i]) {
                const glm::dvec3 u = boussinesqDisplacementMm(kMaterial, kLoadN, box.mesh.nodesMm[i]);
                for (int d = 0; d < 3; ++d) {
                    fixed[3 * i + std::size_t(d)] = 1;
                    values[3 * i + std::size_t(d)] = u[d];
                }
            }
        FemSolverDef o;
        o.cgRelativeTolerance = 1e-12;
        const auto s = LinearElasticFem(box.mesh, kMaterial, fixed, o).solve(values);
        double sumSq = 0, scale = 0;
        int interior = 0;
        for (std::size_t i = 0; i < box.mesh.nodeCount(); ++i) {
            const glm::dvec3 exact = boussinesqDisplacementMm(kMaterial, kLoadN, box.mesh.nodesMm[i]);
            scale = std::max(scale, glm::length(exact));
            if (box.onBoundary[i]) continue;
            const double e = glm::length(s.displacementMm[i] - exact);
            sumSq += e * e;
            ++interior;
        }
        const double error = std::sqrt(sumSq / interior) / scale;
        EXPECT_LT(error, 2e-3) << "n = " << n;
        if (previousError > 0.0) {
            EXPECT_GT(previousError / error, 3.5) << "n = " << n;  // second order: ~4 per halving of h
        }
        previousError = error;
    }
}

}  // namespace
}  // namespace palpate
