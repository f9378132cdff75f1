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

StabilityMargin stabilityMargin(const ModelDef& def, const TissueMesh& mesh, double dtS) {
    switch (def.kind) {
        case ModelKind::SlopeRing: return slopeRing(def.slopeRing);
        case ModelKind::VolumetricRings: return slopeRing(def.volumetricRings.slopeRing);
        case ModelKind::MassSpringSymplectic:
            return massSpring(def.massSpring, MassSpringIntegrator::SymplecticEuler, mesh, dtS);
        case ModelKind::MassSpringRk4: return massSpring(def.massSpring, MassSpringIntegrator::Rk4, mesh, dtS);
        case ModelKind::MassSpringImplicit:
            return massSpring(def.massSpring, MassSpringIntegrator::BackwardEuler, mesh, dtS);
        case ModelKind::MassSpringLocal: return massSpring(def.massSpring, def.massSpring.localIntegrator, mesh, dtS);
        case ModelKind::RadiusOfInfluence:
        case ModelKind::Ffd: break;
    }
    StabilityMargin m;
    m.text = "geometric model: nothing integrates, no step bound";
    return m;
}

}  // namespace palpate
