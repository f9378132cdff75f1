#include "engine/stability/StabilityMargin.h"

#include "engine/stability/StabilityBounds.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace palpate {

namespace {

std::string format(const char* pattern, double a, double b) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, pattern, a, b);
    return buffer;
}

StabilityMargin slopeRing(const SlopeRingParams& p) {
    const double used = p.effectiveRelaxation() * (1.0 + p.loopGain());
    StabilityMargin m;
    m.margin = slopeRingMargin(p.effectiveRelaxation(), p.loopGain());
    m.text = format("alpha (1 + |m1| k_c) = %.3g of 2: margin %.0f %%", used, 100.0 * m.margin);
    if (m.margin <= 0.0) m.text += "; lower forceRelaxation (0 = automatic), |m1| or contactStiffness";
    return m;
}

StabilityMargin massSpring(const MassSpringParams& p, MassSpringIntegrator integrator, const TissueMesh& mesh,
                           double dtS) {
    StabilityMargin m;
    if (integrator == MassSpringIntegrator::BackwardEuler) {
        m.text = "backward Euler: stable at every step";
        return m;
    }
    const double omega = massSpringOmegaGershgorinRadPerS(mesh, p);
    // As MassSpringModel::substepsFor: automatic sub-steps keep h omega at 0.9 x the bound, capped.
    const double bound = integrator == MassSpringIntegrator::Rk4 ? 2.78 : 2.0;
    const int substeps = p.substeps > 0 ? p.substeps
                                        : int(std::clamp(std::ceil(dtS * omega / (0.9 * bound)), 1.0,
                                                         double(std::max(1, p.maxSubsteps))));
    const double used = dtS / substeps * omega;
    m.margin = 1.0 - used / bound;
    m.text = format("h omega_max = %.3g of %.3g", used, bound) +
             format(" (%.0f sub-steps): margin %.0f %%", double(substeps), 100.0 * m.margin);
    if (m.margin <= 0.0) m.text += "; raise substeps (or 0 = automatic), lower the stiffnesses, or use backward Euler";
    return m;
}

}  // namespace

bool stabilityMarginNeedsMesh(ModelKind kind) {
    return kind == ModelKind::MassSpringSymplectic || kind == ModelKind::MassSpringRk4 ||
           kind == ModelKind::MassSpringImplicit || kind == ModelKind::MassSpringLocal;
}

StabilityMargin renderedStiffnessMargin(double stiffness, double dtS, double passiveAt1kHz) {
    // b = K_1kHz x 1 ms / 2, so K_passive(T) = 2 b / T = K_1kHz (1 ms / T).
    const double passive = passiveMaxStiffnessNPerMm(passiveAt1kHz * 1e-3 / 2.0, dtS);
    StabilityMargin m;
    m.margin = passive > 0.0 ? 1.0 - stiffness / passive : -kNoBound;
    m.text = format("k_s = %.3g N/mm of the device's passive %.3g N/mm", stiffness, passive) +
             format(" at %.0f Hz (Colgate and Brown): margin %.0f %%", 1.0 / dtS, 100.0 * m.margin);
    if (m.margin <= 0.0) m.text += "; lower stiffness (k_s) or raise the haptic rate";
    return m;
}

StabilityMargin stabilityMargin(const ModelDef& def, const TissueMesh& mesh, double dtS, double passiveAt1kHz) {
    return *stabilityMarginIfKnown(def, &mesh, dtS, passiveAt1kHz);
}

std::optional<StabilityMargin> stabilityMarginIfKnown(const ModelDef& def, const TissueMesh* meshOrNull, double dtS,
                                                      double passiveAt1kHz) {
    if (stabilityMarginNeedsMesh(def.kind) && !meshOrNull) return std::nullopt;
    switch (def.kind) {
        case ModelKind::SlopeRing: return slopeRing(def.slopeRing);
        case ModelKind::VolumetricRings: return slopeRing(def.volumetricRings.slopeRing);
        case ModelKind::MassSpringSymplectic:
            return massSpring(def.massSpring, MassSpringIntegrator::SymplecticEuler, *meshOrNull, dtS);
        case ModelKind::MassSpringRk4: return massSpring(def.massSpring, MassSpringIntegrator::Rk4, *meshOrNull, dtS);
        case ModelKind::MassSpringImplicit:
            return massSpring(def.massSpring, MassSpringIntegrator::BackwardEuler, *meshOrNull, dtS);
        case ModelKind::MassSpringLocal: return massSpring(def.massSpring, def.massSpring.localIntegrator, *meshOrNull, dtS);
        case ModelKind::RadiusOfInfluence:
            return renderedStiffnessMargin(def.radiusOfInfluence.stiffnessNPerMm, dtS, passiveAt1kHz);
        case ModelKind::Ffd: return renderedStiffnessMargin(def.ffd.stiffnessNPerMm, dtS, passiveAt1kHz);
    }
    return StabilityMargin{};
}

}  // namespace palpate
