#include "device/usb/FalconKinematics.h"

#include <glm/matrix.hpp>

#include <cmath>

namespace palpate {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

double falconEncoderToThetaRad(std::int16_t counts, const FalconGeometry& g) {
    // Arc travelled by the shaft surface per count, converted to the arm pulley's angle.
    const double shaftArcMmPerCount = kPi * g.shaftDiameterMm / (g.encoderSlots * 4.0);
    const double armDeg = shaftArcMmPerCount * double(counts) / (kPi * g.armDiameterMm) * 360.0;
    return (armDeg + g.thetaOffsetDeg) * kPi / 180.0;
}

bool falconInverseKinematics(const glm::dvec3& p, glm::dvec3& thetaRad, const FalconGeometry& g) {
    for (int leg = 0; leg < 3; ++leg) {
        // Position in the leg's (u, v, w) frame: rotate by the leg angle about z, shift to its base.
        const double cphi = std::cos(g.legAngleRad[leg]), sphi = std::sin(g.legAngleRad[leg]);
        const double u = cphi * p.x + sphi * p.y - g.r;
        const double v = -sphi * p.x + cphi * p.y - g.s;
        const double w = p.z;
        // theta3: the parallelogram's out-of-plane angle, from v alone (the + root fits the Falcon).
        const double cos3 = (v + g.f) / g.b;
        if (!(cos3 > -1.0 && cos3 < 1.0)) return false;
        const double sin3 = std::sqrt(1.0 - cos3 * cos3);
        // theta1 solves A cos(theta1) + B sin(theta1) = C, written as a quadratic in
        // t = tan(theta1/2): (K - 2aU) - 4aw t + (K + 2aU) t^2 = 0 with U = u + c and
        // K = U^2 + w^2 + a^2 - (b sin(theta3) + d + e)^2 (the knee-to-end-effector distance closes).
        const double U = u + g.c;
        const double reach = g.b * sin3 + g.d + g.e;
        const double K = U * U + w * w + g.a * g.a - reach * reach;
        const double l0 = K - 2.0 * g.a * U;
        const double l1 = -4.0 * g.a * w;
        const double l2 = K + 2.0 * g.a * U;
        const double disc = l1 * l1 - 4.0 * l0 * l2;
        if (!(disc >= 0.0) || l2 == 0.0) return false;
        const double t = (-l1 - std::sqrt(disc)) / (2.0 * l2);  // the knee-out branch, as on the device
        thetaRad[leg] = 2.0 * std::atan(t);
        if (!std::isfinite(thetaRad[leg])) return false;
    }
    return true;
}

bool falconAngleJacobian(const glm::dvec3& p, glm::dmat3& dThetaDx, const FalconGeometry& g) {
    const double h = 1e-3;  // mm: small against the workspace, large against rounding
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 plus = p, minus = p, tp, tm;
        plus[axis] += h;
        minus[axis] -= h;
        if (!falconInverseKinematics(plus, tp, g) || !falconInverseKinematics(minus, tm, g)) return false;
        // glm is column-major: column `axis` holds d(theta)/d(x_axis).
        dThetaDx[axis] = (tp - tm) / (2.0 * h);
    }
    return true;
}

bool falconForwardKinematics(const glm::dvec3& thetaRad, const glm::dvec3& guessMm, glm::dvec3& positionMm,
                             const FalconGeometry& g, double toleranceRad) {
    glm::dvec3 x = guessMm;
    for (int iteration = 0; iteration < 30; ++iteration) {
        glm::dvec3 theta;
        glm::dmat3 jac;
        if (!falconInverseKinematics(x, theta, g) || !falconAngleJacobian(x, jac, g)) {
            positionMm = x;
            return false;
        }
        const glm::dvec3 error = thetaRad - theta;
        if (std::fabs(error.x) < toleranceRad && std::fabs(error.y) < toleranceRad && std::fabs(error.z) < toleranceRad) {
            positionMm = x;
            return true;
        }
        if (std::fabs(glm::determinant(jac)) < 1e-12) break;  // singular: no sensible step
        glm::dvec3 step = glm::inverse(jac) * error;
        // Damp big steps: a guess far from the answer may leave the reachable set.
        const double length = std::sqrt(glm::dot(step, step));
        if (length > 10.0) step *= 10.0 / length;
        x += step;
    }
    positionMm = x;
    return false;
}

bool falconTorquesNm(const glm::dvec3& positionMm, const glm::dvec3& forceN, glm::dvec3& torqueNm,
                     const FalconGeometry& g) {
    glm::dmat3 dThetaDx;
    if (!falconAngleJacobian(positionMm, dThetaDx, g) || std::fabs(glm::determinant(dThetaDx)) < 1e-12) return false;
    const glm::dmat3 dXdTheta = glm::inverse(dThetaDx);  // mm/rad
    // tau_i = sum_j dx_j/dtheta_i F_j, in N*mm; /1000 -> N*m.
    torqueNm = glm::transpose(dXdTheta) * forceN / 1000.0;
    return std::isfinite(torqueNm.x) && std::isfinite(torqueNm.y) && std::isfinite(torqueNm.z);
}

std::array<std::int16_t, 3> falconMotorCommands(const glm::dvec3& positionMm, const glm::dvec3& forceN,
                                                const FalconForceMapDef& map, const FalconGeometry& g) {
    std::array<std::int16_t, 3> out{};
    glm::dvec3 torque;
    if (!falconTorquesNm(positionMm, forceN, torque, g)) return out;
    glm::dvec3 counts = torque * map.motorCountsPerNm;
    const double largest = std::fmax(std::fabs(counts.x), std::fmax(std::fabs(counts.y), std::fabs(counts.z)));
    // One scale for all three motors: clipping one alone would bend the force.
    if (largest > map.maxMotorCounts) counts *= map.maxMotorCounts / largest;
    for (int i = 0; i < 3; ++i) out[i] = std::int16_t(std::lround(counts[i]));
    return out;
}

}  // namespace palpate
