#pragma once
// Homogeneous deformations of the hyperelastic laws (engine/fem/HyperelasticMaterial.h) in closed form:
// the ground truth the hyperelastic FEM is checked against (docs/accuracy.md).

#include "engine/fem/HyperelasticMaterial.h"

namespace palpate {

/// Uniaxial stress: stretch `stretch` along one axis, the two lateral faces traction-free.
struct UniaxialStress {
    double lateralStretch = 1.0;          ///< from P_lateral = 0, the law's one scalar equation
    double nominalStressNPerMm2 = 0.0;    ///< P along the stretch: force per rest area
    double cauchyStressNPerMm2 = 0.0;     ///< force per deformed area
};

/// With F = diag(t, t, s): P_lateral = w1 (t - 1/t) + lambda ln J / t = 0 (J = s t^2) is solved
/// for t by bisection to machine precision (it rises monotonically in t), then
/// P = w1 (s - 1/s) + lambda ln J / s. For nu -> 0.5 the neo-Hookean law tends to mu (s - s^-2).
UniaxialStress uniaxialStress(const HyperelasticMaterial& m, double stretch);

}  // namespace palpate
