#include "engine/models/RadiusOfInfluenceParams.h"

#include "engine/models/ParamText.h"

#include <algorithm>
#include <cmath>

namespace palpate {

double evaluateProfile(const RadiusOfInfluenceParams& p, double rho) {
    const int degree = std::clamp(p.degree, 0, kMaxProfileDegree);
    double value = 0.0;
    for (int k = degree; k >= 0; --k) value = value * rho + p.coefficients[std::size_t(k)];
    return value;
}

std::array<double, kMaxProfileDegree + 1> powerProfileCoefficients(int degree) {
    std::array<double, kMaxProfileDegree + 1> c{};
    degree = std::clamp(degree, 0, kMaxProfileDegree);
    // (1 - rho)^d = sum_k C(d, k) (-rho)^k
    double binomial = 1.0;
    for (int k = 0; k <= degree; ++k) {
        c[std::size_t(k)] = (k % 2 == 0 ? 1.0 : -1.0) * binomial;
        binomial = binomial * double(degree - k) / double(k + 1);
    }
    return c;
}

std::vector<std::string> validateRadiusOfInfluenceParams(const RadiusOfInfluenceParams& p) {
    using namespace paramtext;
    std::vector<std::string> errors;
    requirePositive(errors, p.radiusMm, "radiusMm", "mm");
    requirePositive(errors, p.stiffnessNPerMm, "stiffnessNPerMm", "N/mm");
    if (!requireRange(errors, p.degree, 2, kMaxProfileDegree, "degree")) return errors;
    bool finite = true;
    for (int k = 0; k <= p.degree; ++k)
        if (!std::isfinite(p.coefficients[std::size_t(k)])) {
            errors.push_back("coefficients[" + std::to_string(k) + "] = " + number(p.coefficients[std::size_t(k)]) +
                             " must be finite");
            finite = false;
        }
    if (!finite) return errors;
    // The three conditions that make it a dent: the touched vertex follows the tool, and the
    // profile meets the rest surface at the radius with zero value and zero slope.
    constexpr double kTolerance = 1e-9;
    double atRadius = 0.0, slopeAtRadius = 0.0, scale = 0.0;
    for (int k = 0; k <= p.degree; ++k) {
        const double c = p.coefficients[std::size_t(k)];
        atRadius += c;
        slopeAtRadius += k * c;
        scale = std::max(scale, std::abs(c) * std::max(1, k));
    }
    if (std::abs(p.coefficients[0] - 1.0) > kTolerance)
        errors.push_back("coefficients[0] = " + number(p.coefficients[0]) +
                         " must be 1: phi(0) = 1 makes the touched vertex follow the tool");
    if (std::abs(atRadius) > kTolerance * std::max(1.0, scale))
        errors.push_back("coefficients: phi(1) = sum of coefficients = " + number(atRadius) +
                         " must be 0 (the dent ends at the radius)");
    if (std::abs(slopeAtRadius) > kTolerance * std::max(1.0, scale))
        errors.push_back("coefficients: phi'(1) = sum of k c_k = " + number(slopeAtRadius) +
                         " must be 0 (the dent meets the rest surface without a kink)");
    return errors;
}

}  // namespace palpate
