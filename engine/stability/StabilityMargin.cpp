#include "engine/stability/StabilityMargin.h"

#include "engine/stability/RenderedStiffness.h"
#include "engine/stability/SampledPassivity.h"
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
    m.text = format("alpha (1 + |m1| k_c) = %.3g of 2: loop-gain margin %.0f %%", used, 100.0 * m.margin);
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
             format(" (%.0f sub-steps): step margin %.0f %%", double(substeps), 100.0 * m.margin);
    if (m.margin <= 0.0) m.text += "; raise substeps (or 0 = automatic), lower the stiffnesses, or use backward Euler";
    return m;
}

/// The passivity line of one rendered stiffness against the device's passive stiffness.
StabilityMargin passivity(const RenderedStiffnessLine& line, double dtS, double passiveAt1kHz) {
    const double device = devicePassiveStiffnessNPerMm(passiveAt1kHz, dtS);
    const double keq = line.passiveEquivalentNPerMm;
    const std::string why = line.why.empty() ? std::string() : ", " + line.why;
    StabilityMargin m;
    m.passivityMargin = device > 0.0 && std::isfinite(keq) ? 1.0 - keq / device : -kNoBound;
    m.margin = m.passivityMargin;
    m.text = line.what == "normal" ? std::string() : line.what + ": ";
    if (!std::isfinite(line.staticNPerMm)) m.text += "rendered stiffness " + line.why;  // not measured
    else {
        m.text += format("rendered stiffness %.3g N/mm", line.staticNPerMm, 0.0);
        if (!std::isfinite(keq)) m.text += " (passive-equivalent unbounded" + why + ")";
        else if (std::abs(keq - line.staticNPerMm) > 1e-3 * std::abs(line.staticNPerMm) || !why.empty())
            m.text += format(" (passive-equivalent %.3g N/mm", keq, 0.0) + why + ")";
    }
    if (m.passivityMargin > 0.0) {
        m.text += format(" of the device's passive %.3g N/mm at %.0f Hz", device, 1.0 / dtS) +
                  format(": passivity margin %.0f %%", 100.0 * m.passivityMargin, 0.0);
    } else {
        m.text += std::isfinite(keq) && device > 0.0 ? format(" is %.3gx", keq / device, 0.0) : std::string(": beyond");
        m.text += format(" the device's passive %.3g N/mm at %.0f Hz: ", device, 1.0 / dtS) + line.lower;
    }
    return m;
}

/// The model's bound and every passivity line in one margin: the smallest wins, the text lists all.
StabilityMargin combine(StabilityMargin bound, const std::optional<RenderedStiffness>& rendered, double dtS,
                        double passiveAt1kHz) {
    StabilityMargin m = bound;
    m.boundMargin = bound.margin;
    m.passivityMargin = 1.0;
    if (rendered)
        for (const RenderedStiffnessLine& line : rendered->lines) {
            const StabilityMargin p = passivity(line, dtS, passiveAt1kHz);
            m.passivityMargin = std::min(m.passivityMargin, p.passivityMargin);
            m.text += (m.text.empty() ? "" : "\n") + p.text;
        }
    m.margin = std::min(m.boundMargin, m.passivityMargin);
    // A model beyond its own bound diverges before passivity matters, and a diverging model has no
    // finite K_eq: its bound is the number that says how far it is.
    if (m.boundMargin <= 0.0 && !std::isfinite(m.passivityMargin)) m.margin = m.boundMargin;
    return m;
}

StabilityMargin noBound(const char* why) {
    StabilityMargin m;
    m.text = why;
    return m;
}

}  // namespace

bool stabilityMarginNeedsMesh(const ModelDef& def) { return renderedStiffnessNeedsMesh(def); }

StabilityMargin renderedStiffnessMargin(double stiffness, double dtS, double passiveAt1kHz) {
    ModelDef def;
    def.kind = ModelKind::RadiusOfInfluence;
    def.radiusOfInfluence.stiffnessNPerMm = stiffness;
    StabilityMargin m = passivity(renderedStiffness(def, nullptr, dtS)->lines.front(), dtS, passiveAt1kHz);
    return m;
}

StabilityMargin stabilityMargin(const ModelDef& def, const TissueMesh& mesh, double dtS, double passiveAt1kHz) {
    return *stabilityMarginIfKnown(def, &mesh, dtS, passiveAt1kHz);
}

std::optional<StabilityMargin> stabilityMarginIfKnown(const ModelDef& def, const TissueMesh* meshOrNull, double dtS,
                                                      double passiveAt1kHz) {
    if (stabilityMarginNeedsMesh(def) && !meshOrNull) return std::nullopt;
    const ModelStability rules = modelDescriptor(def).stability(def);
    StabilityMargin bound;
    switch (rules.bound) {
        case ModelStability::Bound::LoopGain: bound = slopeRing(def.slopeRing); break;
        case ModelStability::Bound::IntegratorStep:
            bound = massSpring(def.massSpring, rules.integrator, *meshOrNull, dtS);
            break;
        case ModelStability::Bound::None:
            bound = noBound("no loop-gain or step bound (the dent follows the tool, not the force)");
            break;
    }
    return combine(bound, renderedStiffness(def, meshOrNull, dtS), dtS, passiveAt1kHz);
}

}  // namespace palpate
