#pragma once
// Novint Falcon kinematics: encoder counts -> tool position, and a Cartesian force -> motor
// commands. The Falcon is a 3-leg translational parallel robot analysed by R. E. Stamper ("A
// three degree of freedom parallel manipulator with only translational degrees of freedom",
// PhD thesis, University of Maryland, 1997); the geometry constants and the encoder-to-angle map
// are the ones libnifalcon measured (FalconGeometry.h, FalconKinematic.h; BSD). docs/devices.md
// gives the derivation. Units here are millimetres and radians; no allocation (runs at 1 kHz on
// the device's I/O thread).

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>

namespace palpate {

/// Geometry of one Falcon (Stamper's symbols; lengths in mm).
struct FalconGeometry {
    double a = 60.0;     ///< leg base to knee
    double b = 102.5;    ///< shin parallelogram side
    double c = 14.0;     ///< shin joint to end-effector centre, u component
    double d = 11.25;    ///< shin to end-effector joint
    double e = 11.25;    ///< knee to shin joint
    double f = -25.0;    ///< shin joint to end-effector centre, v component
    double r = 37.233758;   ///< frame origin to leg base, u component
    double s = -27.330909;  ///< frame origin to leg base, v component
    /// Leg angles about the z axis: 90, -30, -150 degrees, each tilted by the 15-degree desk offset.
    std::array<double, 3> legAngleRad{1.5707963267948966 + 0.2617993877991494, -0.5235987755982988 + 0.2617993877991494,
                                      -2.6179938779914944 + 0.2617993877991494};
    // Encoder: 320 slots x 4 (quadrature) per turn of a 14.25 mm shaft driving a 110 mm arm
    // pulley; count 0 is about 35 degrees.
    double encoderSlots = 320.0;
    double shaftDiameterMm = 14.25;
    double armDiameterMm = 110.0;
    double thetaOffsetDeg = 35.0;
};

/// Motor angle (radians) of an encoder count.
double falconEncoderToThetaRad(std::int16_t counts, const FalconGeometry& g = {});

/// Inverse kinematics: the three motor angles (theta1 of each leg, radians) at a position (mm, the
/// Falcon's frame). False when the position is outside what the legs can reach.
bool falconInverseKinematics(const glm::dvec3& positionMm, glm::dvec3& thetaRad, const FalconGeometry& g = {});

/// d(theta)/d(position) at a position (rad/mm), by central differences of the inverse kinematics.
bool falconAngleJacobian(const glm::dvec3& positionMm, glm::dmat3& dThetaDx, const FalconGeometry& g = {});

/// Forward kinematics by Newton's method from `guessMm` (the last position: it converges in a few
/// steps). False (out left at the best estimate) when it does not converge to `toleranceRad`.
bool falconForwardKinematics(const glm::dvec3& thetaRad, const glm::dvec3& guessMm, glm::dvec3& positionMm,
                             const FalconGeometry& g = {}, double toleranceRad = 1e-7);

/// Motor torques (N*m) that make the tool push with `forceN` at `positionMm`: tau = J^T F with
/// J = d(position)/d(theta) (virtual work: tau . dtheta = F . dx).
bool falconTorquesNm(const glm::dvec3& positionMm, const glm::dvec3& forceN, glm::dvec3& torqueNm,
                     const FalconGeometry& g = {});

struct FalconForceMapDef {
    /// Motor command per N*m, and its sign (libnifalcon: command = -10000 * torque).
    double motorCountsPerNm = -10000.0;
    /// Largest motor command; a larger set is scaled down as a whole, keeping the force's direction.
    double maxMotorCounts = 32000.0;
};

/// Motor commands for a force at a position; zero when the kinematics fail there (better nothing
/// than a wrong direction).
std::array<std::int16_t, 3> falconMotorCommands(const glm::dvec3& positionMm, const glm::dvec3& forceN,
                                                const FalconForceMapDef& map = {}, const FalconGeometry& g = {});

}  // namespace palpate
