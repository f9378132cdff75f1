#include "engine/models/RadiusOfInfluenceParams.h"

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

namespace {

int coefficientsUsed(const RadiusOfInfluenceParams& p) { return std::clamp(p.degree, 0, kMaxProfileDegree) + 1; }

const FieldDef<RadiusOfInfluenceParams> kFields[] = {
    field<&RadiusOfInfluenceParams::radiusMm>(
        {.key = "radiusMm",
         .jsonKey = "radius_mm",
         .unit = "mm",
         .lo = 0,
         .hi = kNoLimit,
         .lower = Bound::Open,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Radius R:"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "Every vertex within this distance of the touched vertex (in 3D, whatever the edges) moves, mm."),
         .decimals = 4,
         .step = 1.0}),
    customField<RadiusOfInfluenceParams>(
        {.key = "degree",
         .jsonKey = "degree",
         .lo = 2,
         .hi = kMaxProfileDegree,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Profile degree:"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "The profile is (1 − r/R)^degree (2..8); a preset file's own coefficients are kept until the degree "
             "changes.")},
        FieldType::Whole, [](const RadiusOfInfluenceParams& p, int) { return double(p.degree); },
        [](RadiusOfInfluenceParams& p, int, double v) {
            if (int(v) == p.degree) return;
            p.degree = int(v);
            p.coefficients = powerProfileCoefficients(int(v));
        }),
    listField<&RadiusOfInfluenceParams::coefficients, coefficientsUsed>({.key = "coefficients",
                                                                         .jsonKey = "coefficients",
                                                                         .lo = -kNoLimit,
                                                                         .hi = kNoLimit,
                                                                         .decimals = 6,
                                                                         .step = 0.1,
                                                                         .sizeKey = "degree"}),
    field<&RadiusOfInfluenceParams::stiffnessNPerMm>(
        {.key = "stiffnessNPerMm",
         .jsonKey = "stiffness_n_per_mm",
         .unit = "N/mm",
         .lo = 0,
         .hi = kNoLimit,
         .lower = Bound::Open,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Stiffness k_s:"),
         .tip = PALPATE_TRANSLATE_NOOP("palpate::Parameters",
                                       "The rendered force is k_s times the touched vertex's displacement, N/mm."),
         .decimals = 6,
         .step = 0.01}),
};

}  // namespace

FieldTable<RadiusOfInfluenceParams> radiusOfInfluenceFields() { return kFields; }

Problems validateRadiusOfInfluenceParams(const RadiusOfInfluenceParams& p) {
    Problems problems;
    checkFields(radiusOfInfluenceFields(), p, problems);
    if (hasProblem(problems, "degree") || hasProblem(problems, "coefficients")) return problems;
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
        problems.push_back({"coefficients", 0, -1,
                            "coefficients[0] = " + formatNumber(p.coefficients[0]) +
                                " must be 1: phi(0) = 1 makes the touched vertex follow the tool"});
    if (std::abs(atRadius) > kTolerance * std::max(1.0, scale))
        problems.push_back({"coefficients", -1, -1,
                            "coefficients: phi(1) = sum of coefficients = " + formatNumber(atRadius) +
                                " must be 0 (the dent ends at the radius)"});
    if (std::abs(slopeAtRadius) > kTolerance * std::max(1.0, scale))
        problems.push_back({"coefficients", -1, -1,
                            "coefficients: phi'(1) = sum of k c_k = " + formatNumber(slopeAtRadius) +
                                " must be 0 (the dent meets the rest surface without a kink)"});
    return problems;
}

}  // namespace palpate
