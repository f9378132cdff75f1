// Closed forms checked against values computed here by hand from the textbook formulas
// (Johnson, Contact Mechanics, 1985): continuity where the regimes meet, far-field decay, and
// the Boussinesq surface field.
#include "engine/fem/ClosedForms.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace palpate;

namespace {
const ElasticMaterial kGel{0.01, 0.3};  // 10 kPa
}

TEST(ClosedForms, PlaneStrainModulus) {
    EXPECT_DOUBLE_EQ(planeStrainModulusNPerMm2(kGel), 0.01 / (1.0 - 0.09));
}

TEST(ClosedForms, PunchForceIsLinearInIndentation) {
    // F = 2 a E* delta: a = 5 mm, delta = 2 mm, E* = 0.01/0.91.
    EXPECT_NEAR(punchForceN(kGel, 5.0, 2.0), 2.0 * 5.0 * (0.01 / 0.91) * 2.0, 1e-15);
    EXPECT_NEAR(punchForceN(kGel, 5.0, 4.0), 2.0 * punchForceN(kGel, 5.0, 2.0), 1e-15);
}

TEST(ClosedForms, PunchProfileIsFlatUnderTheToolAndContinuousAtItsEdge) {
    EXPECT_DOUBLE_EQ(punchSurfaceDisplacementMm(5.0, 2.0, 0.0), 2.0);
    EXPECT_DOUBLE_EQ(punchSurfaceDisplacementMm(5.0, 2.0, 4.9), 2.0);
    EXPECT_NEAR(punchSurfaceDisplacementMm(5.0, 2.0, 5.0 + 1e-9), 2.0, 1e-3);
    // Outside: (2 delta / pi) asin(a / r); at r = 2a, asin(1/2) = pi/6, so delta / 3.
    EXPECT_NEAR(punchSurfaceDisplacementMm(5.0, 2.0, 10.0), 2.0 / 3.0, 1e-12);
    // Far away it decays like 2 delta a / (pi r).
    EXPECT_NEAR(punchSurfaceDisplacementMm(5.0, 2.0, 5000.0), 2.0 * 2.0 * 5.0 / (std::numbers::pi * 5000.0), 1e-9);
}

TEST(ClosedForms, HertzContactRadiusForceAndProfile) {
    const double R = 10.0, delta = 0.4;
    const double a = std::sqrt(R * delta);  // 2 mm
    EXPECT_NEAR(hertzContactRadiusMm(R, delta), 2.0, 1e-12);
    EXPECT_NEAR(hertzForceN(kGel, R, delta), 4.0 / 3.0 * (0.01 / 0.91) * std::sqrt(R) * std::pow(delta, 1.5), 1e-15);
    EXPECT_DOUBLE_EQ(hertzSurfaceDisplacementMm(R, delta, 0.0), delta);
    // Both branches give delta / 2 at the contact edge (a^2 = R delta).
    EXPECT_NEAR(hertzSurfaceDisplacementMm(R, delta, a), delta / 2.0, 1e-12);
    EXPECT_NEAR(hertzSurfaceDisplacementMm(R, delta, a * (1.0 + 1e-9)), delta / 2.0, 1e-6);
    // Far field: like a point load, u ~ a^3 * 2 / (3 R r) ... decreasing monotonically.
    EXPECT_GT(hertzSurfaceDisplacementMm(R, delta, 3.0), hertzSurfaceDisplacementMm(R, delta, 6.0));
    EXPECT_EQ(hertzForceN(kGel, R, -1.0), 0.0);
}

TEST(ClosedForms, BoussinesqSurfaceField) {
    const double P = 0.5, r = 7.0;
    const glm::dvec3 u = boussinesqDisplacementMm(kGel, P, {r, 0.0, 0.0});
    // Surface: u_z = -P (1 - nu^2) / (pi E r) (into the half-space); u_r = -(1 - 2 nu)(1 + nu) P / (2 pi E r).
    EXPECT_NEAR(u.z, -P * (1.0 - 0.09) / (std::numbers::pi * 0.01 * r), 1e-12);
    EXPECT_NEAR(u.x, -(1.0 - 0.6) * 1.3 * P / (2.0 * std::numbers::pi * 0.01 * r), 1e-12);
    EXPECT_NEAR(u.y, 0.0, 1e-15);
    // Axisymmetric: the same at the same radius in another direction.
    const glm::dvec3 v = boussinesqDisplacementMm(kGel, P, {0.0, r, 0.0});
    EXPECT_NEAR(v.z, u.z, 1e-15);
    EXPECT_NEAR(v.y, u.x, 1e-15);
    // On the axis below the load: purely vertical, u_z = -P/(4 pi G) (1/z + 2(1 - nu)/z) = -P (3 - 2 nu)/(4 pi G z).
    const double G = 0.01 / 2.6;
    const glm::dvec3 w = boussinesqDisplacementMm(kGel, P, {0.0, 0.0, -4.0});
    EXPECT_NEAR(w.z, -P * (3.0 - 0.6) / (4.0 * std::numbers::pi * G * 4.0), 1e-12);
    EXPECT_EQ(w.x, 0.0);
}

TEST(ClosedForms, MaterialValidationNamesTheField) {
    EXPECT_TRUE(validateElasticMaterial(kGel).empty());
    EXPECT_TRUE(hasProblem(validateElasticMaterial({-1.0, 0.3}), "youngsModulusNPerMm2"));
    EXPECT_NE(joinedMessages(validateElasticMaterial({-1.0, 0.3})).find("Young"), std::string::npos);
    EXPECT_TRUE(hasProblem(validateElasticMaterial({0.01, 0.5}), "poissonRatio"));
    EXPECT_NE(joinedMessages(validateElasticMaterial({0.01, 0.5})).find("Poisson"), std::string::npos);
    EXPECT_TRUE(hasProblem(validateElasticMaterial({NAN, 0.3}), "youngsModulusNPerMm2"));
}
