#pragma once
// Parameters of the radius-of-influence model (Basdogan et al. 1998, cited by the paper): every
// vertex within a radius of the contact moves by a polynomial profile of its distance,
// phi(rho) = sum_k c_k rho^k with rho = distance / radius, whatever the mesh's edges.

#include "base/params/FieldTable.h"

#include <array>
#include <string>
#include <vector>

namespace palpate {

inline constexpr int kMaxProfileDegree = 8;

struct RadiusOfInfluenceParams {
    /// Radius of influence, mm. Default: 5 radii of the default 5 mm tool, the region over which
    /// the accuracy metric compares with the flat punch (docs/calibration.md), so the profile covers it.
    double radiusMm = 25.0;
    /// Degree of the profile polynomial, 2..kMaxProfileDegree (Basdogan's is second order).
    int degree = 2;
    /// c_0..c_degree. phi(0) = 1 (the touched vertex follows the tool), phi(1) = 0 and
    /// phi'(1) = 0 (the dent meets the rest surface without a kink). Default (1 - rho)^2.
    std::array<double, kMaxProfileDegree + 1> coefficients{1.0, -2.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    /// k_s: the rendered force is k_s times the touched vertex's displacement, N/mm. Default
    /// 2 a E* for the default tissue (E = 10 kPa, nu = 0.45) and tool (a = 5 mm): the punch's stiffness.
    double stiffnessNPerMm = 0.125;
};

/// The profile phi(rho) for these parameters (Horner).
double evaluateProfile(const RadiusOfInfluenceParams& params, double rho);

/// Coefficients of (1 - rho)^degree, the default family: zero with zero slope at the radius for degree >= 2.
std::array<double, kMaxProfileDegree + 1> powerProfileCoefficients(int degree);

/// The fields of RadiusOfInfluenceParams in file order (base/params/FieldTable.h). Setting the
/// degree to a new value resets the coefficients to (1 - rho)^degree; a file's coefficients,
/// read after it, replace them.
FieldTable<RadiusOfInfluenceParams> radiusOfInfluenceFields();

/// Every problem found, each naming the field; empty when valid.
Problems validateRadiusOfInfluenceParams(const RadiusOfInfluenceParams& params);

}  // namespace palpate
