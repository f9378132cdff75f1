#pragma once
// Closed-form contact solutions of linear elasticity on a half-space (docs/calibration.md): the ground truth
// that the reference FEM is validated against and that slopes are calibrated from.
// Units: mm, N, moduli in N/mm^2 (= MPa; 1 kPa = 0.001 N/mm^2). The half-space is z <= 0.

#include "base/params/Problem.h"

#include <glm/vec3.hpp>

namespace palpate {

/// Isotropic linear-elastic material.
struct ElasticMaterial {
    double youngsModulusNPerMm2 = 0.01;  ///< E (0.01 N/mm^2 = 10 kPa)
    double poissonRatio = 0.45;          ///< nu, in (-1, 0.5)
};

/// "" when usable, else a message naming the field.
Problems validateElasticMaterial(const ElasticMaterial& m);

/// Plane-strain (contact) modulus E* = E / (1 - nu^2).
double planeStrainModulusNPerMm2(const ElasticMaterial& m);

/// Flat rigid frictionless punch of radius a pressed by delta: F = 2 a E* delta.
double punchForceN(const ElasticMaterial& m, double punchRadiusMm, double indentationMm);
/// Surface displacement (positive into the tissue): delta for r <= a, (2 delta / pi) asin(a / r) outside.
double punchSurfaceDisplacementMm(double punchRadiusMm, double indentationMm, double radialDistanceMm);

/// Hertz rigid sphere of radius R pressed by delta: contact radius a = sqrt(R delta).
double hertzContactRadiusMm(double sphereRadiusMm, double indentationMm);
/// F = (4/3) E* sqrt(R) delta^(3/2).
double hertzForceN(const ElasticMaterial& m, double sphereRadiusMm, double indentationMm);
/// Surface displacement (positive into the tissue): delta - r^2 / (2R) inside the contact,
/// [(2a^2 - r^2) asin(a/r) + a sqrt(r^2 - a^2)] / (pi R) outside.
double hertzSurfaceDisplacementMm(double sphereRadiusMm, double indentationMm, double radialDistanceMm);

/// Sneddon's exact rigid sphere (Sneddon, Int. J. Eng. Sci. 3:47-57, 1965): the sphere itself, not
/// Hertz's paraboloid, so it holds at depths where Hertz does not. With contact radius a:
/// delta = (a/2) ln((R + a)/(R - a)), F = (E*/2) [(a^2 + R^2) ln((R + a)/(R - a)) - 2 a R].
/// Both tend to Hertz as a/R -> 0. Linear elasticity: the half-space's own nonlinearity is not in it.
double sneddonSphereContactRadiusMm(double sphereRadiusMm, double indentationMm);
double sneddonSphereForceN(const ElasticMaterial& m, double sphereRadiusMm, double indentationMm);

/// Boussinesq: a point load P (N) at the origin pushing into the half-space z <= 0 (load along -z).
/// Displacement (mm) at a point with z <= 0 other than the origin; u_z < 0 under the load.
/// The reference FEM imposes it on the far faces of its block.
glm::dvec3 boussinesqDisplacementMm(const ElasticMaterial& m, double loadN, const glm::dvec3& pointMm);

}  // namespace palpate
