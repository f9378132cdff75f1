#include "engine/fem/ClosedForms.h"

#include <cmath>
#include <numbers>

namespace palpate {

Problems validateElasticMaterial(const ElasticMaterial& m) {
    if (!std::isfinite(m.youngsModulusNPerMm2) || m.youngsModulusNPerMm2 <= 0.0)
        return oneProblem("youngsModulusNPerMm2", "Young's modulus must be a positive number");
    if (!std::isfinite(m.poissonRatio) || m.poissonRatio <= -1.0 || m.poissonRatio >= 0.5)
        return oneProblem("poissonRatio", "Poisson's ratio must be in (-1, 0.5)");
    return {};
}

double planeStrainModulusNPerMm2(const ElasticMaterial& m) {
    return m.youngsModulusNPerMm2 / (1.0 - m.poissonRatio * m.poissonRatio);
}

double punchForceN(const ElasticMaterial& m, double punchRadiusMm, double indentationMm) {
    return 2.0 * punchRadiusMm * planeStrainModulusNPerMm2(m) * indentationMm;
}

double punchSurfaceDisplacementMm(double punchRadiusMm, double indentationMm, double radialDistanceMm) {
    const double r = std::abs(radialDistanceMm);
    if (r <= punchRadiusMm) return indentationMm;
    return 2.0 * indentationMm / std::numbers::pi * std::asin(punchRadiusMm / r);
}

double hertzContactRadiusMm(double sphereRadiusMm, double indentationMm) {
    return std::sqrt(sphereRadiusMm * std::max(indentationMm, 0.0));
}

double hertzForceN(const ElasticMaterial& m, double sphereRadiusMm, double indentationMm) {
    const double delta = std::max(indentationMm, 0.0);
    return 4.0 / 3.0 * planeStrainModulusNPerMm2(m) * std::sqrt(sphereRadiusMm) * delta * std::sqrt(delta);
}

double hertzSurfaceDisplacementMm(double sphereRadiusMm, double indentationMm, double radialDistanceMm) {
    const double r = std::abs(radialDistanceMm);
    const double a = hertzContactRadiusMm(sphereRadiusMm, indentationMm);
    if (r <= a) return indentationMm - r * r / (2.0 * sphereRadiusMm);
    return ((2.0 * a * a - r * r) * std::asin(a / r) + a * std::sqrt(r * r - a * a)) /
           (std::numbers::pi * sphereRadiusMm);
}

namespace {
double sneddonIndentationMm(double r, double a) { return 0.5 * a * std::log((r + a) / (r - a)); }
}  // namespace

// delta(a) rises monotonically from 0 (a = 0) to infinity (a -> R): bisection to the last bit.
double sneddonSphereContactRadiusMm(double sphereRadiusMm, double indentationMm) {
    if (!(indentationMm > 0.0)) return 0.0;
    double lo = 0.0, hi = sphereRadiusMm;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * sphereRadiusMm; ++i) {
        const double mid = 0.5 * (lo + hi);
        (sneddonIndentationMm(sphereRadiusMm, mid) < indentationMm ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

double sneddonSphereForceN(const ElasticMaterial& m, double sphereRadiusMm, double indentationMm) {
    const double r = sphereRadiusMm, a = sneddonSphereContactRadiusMm(r, indentationMm);
    if (a == 0.0) return 0.0;
    return 0.5 * planeStrainModulusNPerMm2(m) * ((a * a + r * r) * std::log((r + a) / (r - a)) - 2.0 * a * r);
}

glm::dvec3 boussinesqDisplacementMm(const ElasticMaterial& m, double loadN, const glm::dvec3& pointMm) {
    // Johnson, Contact Mechanics (1985) §3.2 with depth z' = -z >= 0 and the load along -z:
    // u_r = P/(4 pi G) [r z'/rho^3 - (1 - 2 nu) r/(rho (rho + z'))],
    // u_z' = P/(4 pi G) [z'^2/rho^3 + 2 (1 - nu)/rho]   (u_z' positive into the half-space).
    const double nu = m.poissonRatio;
    const double shearModulus = m.youngsModulusNPerMm2 / (2.0 * (1.0 + nu));
    const double depth = -pointMm.z;
    const double r = std::hypot(pointMm.x, pointMm.y);
    const double rho = std::sqrt(r * r + depth * depth);
    const double c = loadN / (4.0 * std::numbers::pi * shearModulus);
    const double uRadial = c * (r * depth / (rho * rho * rho) - (1.0 - 2.0 * nu) * r / (rho * (rho + depth)));
    const double uDepth = c * (depth * depth / (rho * rho * rho) + 2.0 * (1.0 - nu) / rho);
    const double cosPhi = r > 0.0 ? pointMm.x / r : 0.0;
    const double sinPhi = r > 0.0 ? pointMm.y / r : 0.0;
    return {uRadial * cosPhi, uRadial * sinPhi, -uDepth};
}

}  // namespace palpate
