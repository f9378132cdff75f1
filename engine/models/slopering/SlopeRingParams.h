#pragma once
// Parameters of the slope-ring model (the paper's Eq. (1)-(3) generalised to N rings).
// Slopes are stored as magnitudes in mm/N; the paper's sign (m < 0: the vertex moves against the
// outward reaction force, into the tissue) is applied by the model. See docs/method.md.

#include "engine/core/Rings.h"
#include "base/params/FieldTable.h"

#include <array>
#include <string>
#include <vector>

namespace palpate {

/// Knots of the strain-stiffening curve (docs/method.md, "Tissue that stiffens with depth").
inline constexpr int kMaxStiffeningKnots = 8;
/// The largest force a knot may sit at: far past any press on tissue (a desktop device renders
/// 3 N, a strong hand 100 N), and small enough that the tick's float arithmetic on the knots stays
/// exact to a micronewton (a knot at 3.4e38 N made the effective force infinite: the tool never
/// touched the tissue).
inline constexpr double kMaxStiffeningForceN = 1000.0;

/// The slope model's loop is stable while alpha (1 + gain) stays below this (docs/stability.md,
/// "The slope model's loop gain"): the one statement of the rule; the validator, the stability
/// bounds and the Parameters panel read it.
inline constexpr double kLoopProductLimit = 2.0;

struct SlopeRingParams {
    /// Rings beyond the touched vertex (the paper uses 2).
    int ringCount = 2;
    /// |m| per ring in mm/N: [0] the touched vertex (the paper's m1), [1] ring 1 (m2), ...
    /// Only the first ringCount + 1 entries are used; they must decrease strictly.
    std::array<double, kMaxRings + 1> slopeMagnitudeMmPerN{0.6, 0.35, 0.15, 0.08, 0.04, 0.02, 0.01, 0.005, 0.0025};
    /// Upper bound for |m1|. The paper's range is (0, 1) mm/N; calibrated soft tissue may need more,
    /// allowed only where the loop-gain bound (docs/method.md) holds.
    double slopeLimitMmPerN = 1.0;
    /// Stiffness of the tool-tissue contact (penalty), N/mm. The loop gain is |m1| * this.
    double contactStiffnessNPerMm = 1.0;
    /// Per-tick relaxation of the contact force, in (0, 1]; 0 selects the exact one-tick solve
    /// alpha = 1 / (1 + gain). The iteration is stable for alpha * (1 + gain) < 2.
    double forceRelaxation = 0.0;
    /// Return springs tying each vertex to its rest position, N/mm. The touched vertex's spring
    /// reaction is the force rendered to the user.
    double springStiffnessNPerMm = 1.5;
    /// Damping of the return springs as a fraction of critical (1 = no overshoot).
    double dampingRatio = 1.0;
    /// Lumped mass per vertex for the relaxation after release, kg.
    double vertexMassKg = 0.001;

    /// Strain stiffening (docs/method.md, "Tissue that stiffens with depth"): above a contact force
    /// of stiffeningForceN[k] the tissue yields stiffeningCompliance[k] |m1| mm per further newton
    /// (below the first knot |m1|). The rings follow the effective force E(F) this gives, so every
    /// slope scales by E(F) / F; the force rendered stays k_s |m1| F. 0 knots: linear, the paper's model.
    int stiffeningKnots = 0;
    /// Ascending, N. The unused entries hold valid values, so that only the count can be wrong.
    std::array<double, kMaxStiffeningKnots> stiffeningForceN{1, 2, 3, 4, 5, 6, 7, 8};
    std::array<double, kMaxStiffeningKnots> stiffeningCompliance{1, 1, 1, 1, 1, 1, 1, 1};  ///< in (0, 1], not rising

    double loopGain() const { return slopeMagnitudeMmPerN[0] * contactStiffnessNPerMm; }
    /// alpha (1 + gain): the slope model's loop converges only while it stays below
    /// kLoopProductLimit (docs/stability.md, "The slope model's loop gain").
    double loopProduct() const { return effectiveRelaxation() * (1.0 + loopGain()); }
    double effectiveRelaxation() const { return forceRelaxation > 0.0 ? forceRelaxation : 1.0 / (1.0 + loopGain()); }
    /// The stiffness a held press renders, N/mm: R = k_s |m1| F with F = k_c d / (1 + g) at rest
    /// (docs/method.md, "Contact and force, per tick"). Stiffening tissue renders more on its
    /// stiffest piece, k_s |m1| k_c / (1 + g q_K): that one, so that the stability and passivity
    /// margins hold for the deepest press.
    double renderedStiffnessNPerMm() const {
        const int knots = stiffeningKnots < 0 ? 0 : stiffeningKnots > kMaxStiffeningKnots ? kMaxStiffeningKnots : stiffeningKnots;
        const double stiffest = knots > 0 ? stiffeningCompliance[std::size_t(knots - 1)] : 1.0;
        return springStiffnessNPerMm * slopeMagnitudeMmPerN[0] * contactStiffnessNPerMm / (1.0 + loopGain() * stiffest);
    }
};

/// What the slope-ring update reads each tick, derived once from the parameters, in the float the
/// tick computes in (the surface and the volumetric slope-ring models share it).
struct SlopeRingConstants {
    float signedSlope[kMaxRings + 1] = {};  ///< -|m_r|, mm/N
    int ringCount = 2;
    float alpha = 1.0f;             ///< the contact force's relaxation
    float contactStiffness = 1.0f;  ///< N/mm
    float springStiffness = 1.0f;   ///< N/mm
    float omega2 = 0.0f;            ///< return-spring omega^2, 1/s^2
    float twoZetaOmega = 0.0f;      ///< 2 zeta omega, 1/s
    int stiffeningKnots = 0;        ///< 0: linear
    float stiffeningForceN[kMaxStiffeningKnots] = {};
    float stiffeningCompliance[kMaxStiffeningKnots] = {};
    float stiffeningEffectiveN[kMaxStiffeningKnots] = {};  ///< E at each knot
};

/// E(F): the force the rings follow (F when there are no knots). O(knots), no allocation.
inline float stiffenedForceN(const SlopeRingConstants& c, float forceN) {
    if (c.stiffeningKnots == 0 || forceN <= c.stiffeningForceN[0]) return forceN;
    int k = 0;
    while (k + 1 < c.stiffeningKnots && forceN > c.stiffeningForceN[k + 1]) ++k;
    return c.stiffeningEffectiveN[k] + c.stiffeningCompliance[k] * (forceN - c.stiffeningForceN[k]);
}

/// The inverse: the contact force whose effective force is `effectiveN`.
inline float unstiffenedForceN(const SlopeRingConstants& c, float effectiveN) {
    if (c.stiffeningKnots == 0 || effectiveN <= c.stiffeningForceN[0]) return effectiveN;
    int k = 0;
    while (k + 1 < c.stiffeningKnots && effectiveN > c.stiffeningEffectiveN[k + 1]) ++k;
    return c.stiffeningForceN[k] + (effectiveN - c.stiffeningEffectiveN[k]) / c.stiffeningCompliance[k];
}
SlopeRingConstants slopeRingConstants(const SlopeRingParams& params);

/// The fields of SlopeRingParams in file order (base/params/FieldTable.h).
FieldTable<SlopeRingParams> slopeRingFields();

/// Every problem found, each naming the field and the rule; empty when valid. Beyond the table's
/// ranges: slopes below the slope limit and decreasing outward, and the loop-gain bound.
Problems validateSlopeRingParams(const SlopeRingParams& params);

}  // namespace palpate
