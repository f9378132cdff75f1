#include "engine/models/slopering/SlopeRingParams.h"

#include <cmath>

namespace palpate {

namespace {

std::string slopeName(int r) { return "|m" + std::to_string(r + 1) + "|"; }
int slopesUsed(const SlopeRingParams& p) { return std::clamp(p.ringCount, 0, kMaxRings) + 1; }

int knotsUsed(const SlopeRingParams& p) { return std::clamp(p.stiffeningKnots, 0, kMaxStiffeningKnots); }
std::string knotForceName(int k) { return "stiffening force " + std::to_string(k + 1); }
std::string knotComplianceName(int k) { return "stiffening compliance " + std::to_string(k + 1); }

constexpr FieldDef<SlopeRingParams> kFields[] = {
    field<&SlopeRingParams::ringCount>(
        {.key = "ringCount",
         .jsonKey = "ring_count",
         .lo = 0,
         .hi = kMaxRings,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Ring count:"),
         .name = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "ring count"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "Rings of neighbours displaced with the touched vertex (ring r: the vertices r edges away). The paper "
             "uses 2; each ring adds a slope below."),
         .required = true,
         .entryLo = 0,
         .entryHi = kMaxRings}),
    listField<&SlopeRingParams::slopeMagnitudeMmPerN, slopesUsed>(
        {.key = "slopeMagnitudeMmPerN",
         .jsonKey = "slopes_mm_per_n",
         .unit = "mm/N",
         .lo = 0,
         .hi = kNoLimit,
         .lower = Bound::Open,
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "Slope magnitude |m| in mm/N: how far the vertex moves per newton of contact force; the model applies "
             "the paper's sign (m < 0), which moves the vertex into the tissue."),
         .decimals = 9,
         .step = 0.01,
         .required = true,
         .sizeKey = "ring_count",
         .itemName = slopeName}),
    field<&SlopeRingParams::slopeLimitMmPerN>(
        {.key = "slopeLimitMmPerN",
         .jsonKey = "slope_limit_mm_per_n",
         .unit = "mm/N",
         .lo = 0,
         .hi = 100,
         .lower = Bound::Open,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Slope limit:"),
         .name = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "slope limit"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "Every slope magnitude must stay below this limit. The paper's range ends at 1 mm/N; calibrated soft "
             "tissue may need more (at most 100 mm/N), allowed while the loop gain stays stable. Slopes above "
             "1 mm/N are marked as outside the paper's range."),
         .decimals = 4,
         .step = 0.1}),
    field<&SlopeRingParams::contactStiffnessNPerMm>(
        {.key = "contactStiffnessNPerMm",
         .jsonKey = "contact_stiffness_n_per_mm",
         .unit = "N/mm",
         .lo = 0,
         .hi = kNoLimit,
         .lower = Bound::Open,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Contact stiffness k_c:"),
         .name = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "contact stiffness"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "Stiffness of the tool-tissue contact (a penalty spring). The loop gain is |m1| × k_c."),
         .decimals = 4,
         .step = 0.1}),
    field<&SlopeRingParams::forceRelaxation>(
        {.key = "forceRelaxation",
         .jsonKey = "force_relaxation",
         .lo = 0,
         .hi = 1,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Force relaxation α:"),
         .name = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "force relaxation"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "Per-tick relaxation α of the contact force, in (0, 1]. Automatic (0) uses α = 1 / (1 + gain), which "
             "solves the contact in one tick for any gain. The update is stable while α·(1 + gain) < 2."),
         .decimals = 4,
         .step = 0.05}),
    field<&SlopeRingParams::springStiffnessNPerMm>(
        {.key = "springStiffnessNPerMm",
         .jsonKey = "spring_stiffness_n_per_mm",
         .unit = "N/mm",
         .lo = 0,
         .hi = kNoLimit,
         .lower = Bound::Open,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Spring stiffness k:"),
         .name = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "spring stiffness"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "Stiffness of the springs that tie each vertex to its rest position. The touched vertex's spring "
             "reaction is the force rendered to the user."),
         .decimals = 9,
         .step = 0.1}),
    field<&SlopeRingParams::dampingRatio>(
        {.key = "dampingRatio",
         .jsonKey = "damping_ratio",
         .lo = 0,
         .hi = 100,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Damping ratio:"),
         .name = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "damping ratio"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "Damping of the return springs as a fraction of critical: 1 returns without overshoot, below 1 the "
             "tissue rings before it settles (0..100)."),
         .decimals = 3,
         .step = 0.1}),
    field<&SlopeRingParams::vertexMassKg>(
        {.key = "vertexMassKg",
         .jsonKey = "vertex_mass_kg",
         .unit = "kg",
         .lo = 0,
         .hi = kNoLimit,
         .lower = Bound::Open,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Vertex mass:"),
         .name = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "vertex mass"),
         .tip = PALPATE_TRANSLATE_NOOP("palpate::Parameters",
                                       "Lumped mass per vertex, for the relaxation after the tool lets go."),
         .decimals = 7,
         .step = 0.0005}),
    field<&SlopeRingParams::stiffeningKnots>(
        {.key = "stiffeningKnots",
         .jsonKey = "stiffening_knots",
         .lo = 0,
         .hi = kMaxStiffeningKnots,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Stiffening knots:"),
         .name = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "stiffening knots"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "Points of the strain-stiffening curve, calibrated from the hyperelastic reference. 0: linear tissue, "
             "the paper's model."),
         .entryLo = 0,
         .entryHi = kMaxStiffeningKnots}),
    listField<&SlopeRingParams::stiffeningForceN, knotsUsed>(
        {.key = "stiffeningForceN",
         .jsonKey = "stiffening_force_n",
         .unit = "N",
         .lo = 0,
         .hi = kMaxStiffeningForceN,
         .lower = Bound::Open,
         .tip = PALPATE_TRANSLATE_NOOP("palpate::Parameters",
                                       "Contact force above which the next stiffening compliance applies, N."),
         .decimals = 6,
         .step = 0.1,
         .sizeKey = "stiffening_knots",
         .itemName = knotForceName}),
    listField<&SlopeRingParams::stiffeningCompliance, knotsUsed>(
        {.key = "stiffeningCompliance",
         .jsonKey = "stiffening_compliance",
         .lo = 0,
         .hi = 1,
         .lower = Bound::Open,
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "Above its knot the tissue yields this fraction of |m1| per further newton: below 1, it stiffens."),
         .decimals = 6,
         .step = 0.01,
         .sizeKey = "stiffening_knots",
         .itemName = knotComplianceName}),
};

}  // namespace

FieldTable<SlopeRingParams> slopeRingFields() { return kFields; }

SlopeRingConstants slopeRingConstants(const SlopeRingParams& p) {
    SlopeRingConstants c;
    c.ringCount = p.ringCount;
    for (int r = 0; r <= kMaxRings; ++r) c.signedSlope[r] = -float(p.slopeMagnitudeMmPerN[std::size_t(r)]);
    c.alpha = float(p.effectiveRelaxation());
    c.contactStiffness = float(p.contactStiffnessNPerMm);
    c.springStiffness = float(p.springStiffnessNPerMm);
    // k [N/mm] * 1000 = N/m; omega^2 = k / m.
    const double omega2 = p.springStiffnessNPerMm * 1000.0 / p.vertexMassKg;
    c.omega2 = float(omega2);
    c.twoZetaOmega = float(2.0 * p.dampingRatio * std::sqrt(omega2));
    c.stiffeningKnots = knotsUsed(p);
    float effective = 0.0f, previousForce = 0.0f, previousCompliance = 1.0f;
    for (int k = 0; k < c.stiffeningKnots; ++k) {
        const float f = float(p.stiffeningForceN[std::size_t(k)]);
        effective += previousCompliance * (f - previousForce);
        c.stiffeningForceN[k] = f;
        c.stiffeningCompliance[k] = float(p.stiffeningCompliance[std::size_t(k)]);
        c.stiffeningEffectiveN[k] = effective;
        previousForce = f;
        previousCompliance = c.stiffeningCompliance[k];
    }
    return c;
}

Problems validateSlopeRingParams(const SlopeRingParams& p) {
    Problems problems;
    checkFields(slopeRingFields(), p, problems);
    const bool limitOk = !hasProblem(problems, "slopeLimitMmPerN");
    const int used = slopesUsed(p);
    for (int r = 0; r < used; ++r) {
        const double m = p.slopeMagnitudeMmPerN[std::size_t(r)];
        if (!std::isfinite(m) || m <= 0.0) continue;  // named by the table's range
        if (limitOk && m >= p.slopeLimitMmPerN)
            problems.push_back({"slopeMagnitudeMmPerN", r, -1,
                                slopeName(r) + " = " + formatNumber(m) + " mm/N must be below the slope limit " +
                                    formatNumber(p.slopeLimitMmPerN) + " mm/N" +
                                    (p.slopeLimitMmPerN == 1.0 ? " (the paper's range is (0, 1))" : "")});
        if (r > 0) {
            const double inner = p.slopeMagnitudeMmPerN[std::size_t(r - 1)];
            if (std::isfinite(inner) && !(m < inner))
                problems.push_back({"slopeMagnitudeMmPerN", r, r - 1,
                                    "slopes must decrease outward: " + slopeName(r - 1) + " = " + formatNumber(inner) +
                                        " mm/N is not greater than " + slopeName(r) + " = " + formatNumber(m) +
                                        " mm/N"});
        }
    }
    for (int k = 1; k < knotsUsed(p); ++k) {
        const double f = p.stiffeningForceN[std::size_t(k)], before = p.stiffeningForceN[std::size_t(k - 1)];
        if (std::isfinite(f) && std::isfinite(before) && !(f > before))
            problems.push_back({"stiffeningForceN", k, k - 1,
                                "stiffening forces must rise: " + knotForceName(k) + " = " + formatNumber(f) +
                                    " N is not above " + knotForceName(k - 1) + " = " + formatNumber(before) + " N"});
        const double q = p.stiffeningCompliance[std::size_t(k)], qBefore = p.stiffeningCompliance[std::size_t(k - 1)];
        if (std::isfinite(q) && std::isfinite(qBefore) && q > qBefore)
            problems.push_back({"stiffeningCompliance", k, k - 1,
                                "tissue only stiffens: " + knotComplianceName(k) + " = " + formatNumber(q) +
                                    " is above " + knotComplianceName(k - 1) + " = " + formatNumber(qBefore)});
    }
    if (problems.empty()) {
        const double alpha = p.effectiveRelaxation();
        const double gain = p.loopGain();
        if (!(p.loopProduct() < kLoopProductLimit))
            problems.push_back({"forceRelaxation", -1, -1,
                                "unstable: loop gain |m1| * contactStiffness = " + formatNumber(gain) +
                                    " with forceRelaxation " + formatNumber(alpha) + " gives alpha * (1 + gain) = " +
                                    formatNumber(p.loopProduct()) + ", which must stay below " +
                                    formatNumber(kLoopProductLimit)});
    }
    return problems;
}

}  // namespace palpate
