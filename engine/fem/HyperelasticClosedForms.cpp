#include "engine/fem/HyperelasticClosedForms.h"

#include "engine/fem/LinearElasticFem.h"

#include <cmath>
#include <stdexcept>

namespace palpate {

namespace {

/// P_11 and P_33 of F = diag(t, t, s).
struct Principal {
    double lateral, axial;
};

Principal principalStress(double lambda, double mu, double b, double s, double t) {
    const double lnJ = std::log(s * t * t);
    const double psi = s * s + 2.0 * t * t - 3.0 - 2.0 * lnJ;
    const double w1 = b > 0.0 ? mu * std::exp(b * psi) : mu;
    return {w1 * (t - 1.0 / t) + lambda * lnJ / t, w1 * (s - 1.0 / s) + lambda * lnJ / s};
}

}  // namespace

UniaxialStress uniaxialStress(const HyperelasticMaterial& m, double stretch) {
    if (!(stretch > 0.0) || !std::isfinite(stretch)) throw std::invalid_argument("stretch must be a positive number");
    const auto [lambda, mu] = lameConstantsNPerMm2(m.smallStrain);
    const double b = m.law == HyperelasticLaw::Exponential ? m.stiffeningExponent : 0.0;
    // Bisection in log t: the lateral stress rises with t, negative as t -> 0, positive as t -> inf.
    double lo = std::log(1e-6), hi = std::log(1e6);
    for (int i = 0; i < 400 && hi - lo > 1e-16; ++i) {
        const double mid = 0.5 * (lo + hi);
        (principalStress(lambda, mu, b, stretch, std::exp(mid)).lateral < 0.0 ? lo : hi) = mid;
    }
    UniaxialStress out;
    out.lateralStretch = std::exp(0.5 * (lo + hi));
    out.nominalStressNPerMm2 = principalStress(lambda, mu, b, stretch, out.lateralStretch).axial;
    out.cauchyStressNPerMm2 = out.nominalStressNPerMm2 * stretch / (stretch * out.lateralStretch * out.lateralStretch);
    return out;
}

}  // namespace palpate
