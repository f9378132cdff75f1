#pragma once
// The derived stability limits of docs/stability.md, as functions: the slope model's loop gain,
// the return springs' integrators, haptic passivity (Colgate and Brown) and triangle inversion.
// The maps (StabilityMap) draw these over what they measure; the guards compare a set against them.

#include "engine/core/TissueMesh.h"
#include "engine/models/MassSpringParams.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace palpate {

inline constexpr double kNoBound = std::numeric_limits<double>::infinity();

/// Slope model, F <- max(0, (1 - alpha) F + alpha k_c (d - |m1| F)): converges iff alpha (1 + g) < 2.
/// Largest loop gain g = |m1| k_c for a relaxation alpha in (0, 1].
double slopeRingMaxGain(double alpha);
/// Largest relaxation alpha for a loop gain g (above 1 the bound is no limit: alpha <= 1 anyway).
double slopeRingMaxRelaxation(double gain);
/// Stability margin of a slope-ring set, 1 - alpha (1 + g) / 2: > 0 inside, <= 0 beyond.
double slopeRingMargin(double alpha, double gain);

/// One mode u'' = -omega^2 u - gamma u' stepped by h. Symplectic Euler with the damping taken
/// implicitly (as MassSpringModel does): h omega < sqrt(4 + 2 h gamma); gamma = 0 gives 2 / omega.
double symplecticEulerMaxStepS(double omegaRadPerS, double gammaPerS = 0.0);
/// Classic RK4, undamped: h omega < 2 sqrt(2) (the stability region's reach along the imaginary axis).
double rk4MaxStepS(double omegaRadPerS);
/// Forward Euler (not in MassSpringModel; derived for the record): h < min over the mode's two
/// eigenvalues of -2 Re(lambda) / |lambda|^2, which is gamma / omega^2 = c / k when underdamped;
/// 0 without damping (unstable at every step).
double forwardEulerMaxStepS(double omegaRadPerS, double gammaPerS);
/// Backward Euler: every step is stable.
inline double backwardEulerMaxStepS(double /*omegaRadPerS*/) { return kNoBound; }

/// Highest angular frequency of the mass-spring model's linear system (anchors, edges and the
/// contact on `touched`, as MassSpringModel::force), rad/s, by power iteration: exact, not
/// Gershgorin's bound. Not real-time (allocates O(n)).
double massSpringOmegaMaxRadPerS(const TissueMesh& mesh, const MassSpringParams& params, VertexId touched);
/// Gershgorin's upper bound of the same (what MassSpringModel sizes its sub-steps with), rad/s.
double massSpringOmegaGershgorinRadPerS(const TissueMesh& mesh, const MassSpringParams& params);

/// Colgate and Brown (1994): a wall of stiffness K (N/mm) and damping B (N s/mm) rendered at
/// period T (s) by a device with physical damping b (N s/mm) is passive iff b > K T / 2 + |B|.
/// Largest passive K for the given b, B and T (0 when |B| >= b).
double passiveMaxStiffnessNPerMm(double deviceDampingNsPerMm, double periodS, double virtualDampingNsPerMm = 0.0);

/// The exact stability limit of the loop Colgate and Brown analyse, without a hand: a 1-DOF device
/// of mass m (kg) and physical damping b (N s/m) rendering a sampled spring K through a zero-order
/// hold at period T (force from the position sampled at the start of the period, held over it).
/// Exact discretisation of m x'' + b x' = F, tau = m / b, delta = exp(-T / tau); Jury's test on
/// the 2 x 2 step matrix leaves two limits, K < b (1 - delta) / (tau (1 - delta) - delta T) (the
/// determinant, = (2 b / T)(1 + b T / 6 m + ...), Colgate's 2 b / T as b T / m -> 0) and
/// K < 2 b (1 + delta) / (T (1 + delta) - 2 tau (1 - delta)) (~ 24 m^2 / (b T^3), far above
/// while b T / m is small). The smaller one, in N/mm (inputs SI).
double sampledWallMaxStiffnessNPerMm(double deviceMassKg, double deviceDampingNsPerM, double periodS);

/// The same loop with the slope ring's rendered force instead of a spring: H(z) = K_r (1 - lambda) /
/// (1 - lambda z^-1) (RenderedStiffness.h), the force from the position sampled at the start of the
/// period. State (x, v, F_{n-1}); Jury's test on the 3 x 3 step matrix's characteristic cubic,
/// bisected in K_r. The largest stable static stiffness K_r, N/mm (inputs SI). lambda = 0 gives
/// sampledWallMaxStiffnessNPerMm; for lambda > 0 it is close to the passivity bound
/// (2 b / T)(1 - lambda) / (1 + lambda), for lambda < 0 far above it (docs/stability.md).
double slopeRingDeviceLoopMaxStiffnessNPerMm(double lambda, double deviceMassKg, double deviceDampingNsPerM,
                                             double periodS);
/// Jury's test for the loop above at one K_r (N/m): true when every pole is inside the unit circle.
bool slopeRingDeviceLoopStable(double renderedStiffnessNPerM, double lambda, double deviceMassKg,
                               double deviceDampingNsPerM, double periodS);

/// As massSpringOmegaMaxRadPerS, for the local variant: only the vertices with simulated[v] != 0
/// move, every other vertex is pinned at rest (its edge springs still pull: the row keeps the
/// vertex's full degree). Not real-time.
double massSpringOmegaMaxRadPerS(const TissueMesh& mesh, const MassSpringParams& params, VertexId touched,
                                 const std::vector<std::uint8_t>& simulated);

/// Triangle inversion under a tangential force: the touched vertex moves |m1| F_t sideways and
/// its ring-1 neighbours |m2| F_t, so the relative shift is |m1 - m2| |F_t|; a fan triangle flips
/// when that exceeds the vertex's height over the opposite edge. Largest |F_t| (N) before it does.
double inversionMaxTangentialForceN(double slope1MmPerN, double slope2MmPerN, double heightOverOppositeEdgeMm);
/// The same for the update as implemented: every ring moves along the touched vertex's rest normal
/// n, so v moves (|m1| - |m2|) F against its neighbours along -n, and a fan triangle (v, a, b) flips
/// (its normal turns against the rest one) at F = |N|^2 / ((|m1| - |m2|) N . ((b - a) x n)) with
/// N its rest normal: h / (|m1 - m2| sin tilt), tilt the angle of n against the face towards the
/// opposite edge. Smallest over the fan, N; kNoBound when no triangle can flip.
double inversionMaxForceAlongNormalN(const TissueMesh& mesh, VertexId v, double slope1MmPerN, double slope2MmPerN);
/// The smallest height of `v` over the opposite edge of any triangle of its fan, at rest, mm.
double minHeightOverOppositeEdgeMm(const TissueMesh& mesh, VertexId v);

}  // namespace palpate
