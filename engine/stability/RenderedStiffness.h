#pragma once
// What each model renders per unit tool displacement, and what that asks of the device
// (docs/stability.md, "Rendered stiffness and passivity"): the static stiffness, and the
// passive-equivalent stiffness K_eq = 2 b_req / T of its transfer H(z) (SampledPassivity.h), in
// closed form where the tick is a closed form (slope ring, volumetric rings, radius of influence,
// FFD) and measured on the real model where it is not (the mass-spring kinds, TransferProbe.h).
// Qt-free, not real-time.

#include "engine/core/TissueMesh.h"
#include "engine/models/ModelRegistry.h"
#include "engine/stability/SampledPassivity.h"

#include <optional>
#include <string>
#include <vector>

namespace palpate {

/// Slope ring, linearised while in contact: F_n = lambda F_{n-1} + alpha k_c d_n with
/// lambda = 1 - alpha (1 + g), g = |m1| k_c, alpha = effectiveRelaxation(); rendered R = k_s |m1| F,
/// whose static stiffness is SlopeRingParams::renderedStiffnessNPerMm(), K_r = k_s |m1| k_c / (1 + g).
double slopeRingRelaxationPole(const SlopeRingParams& params);
/// H(z) = k_s |m1| alpha k_c / (1 - lambda z^-1) = K_r (1 - lambda) / (1 - lambda z^-1).
RenderedTransfer slopeRingTransfer(const SlopeRingParams& params);
/// Its K_eq in closed form: K_r (1 + |lambda|) / (1 - |lambda|) (the sweep's supremum is at
/// theta -> 0 for lambda > 0, a lag, and at theta = pi for lambda < 0, an alternation); infinity
/// for |lambda| >= 1.
double slopeRingPassiveEquivalentNPerMm(const SlopeRingParams& params);

/// One thing the device renders: the normal contact force, or the coherent method's friction proxy.
struct RenderedStiffnessLine {
    std::string what;                      ///< "normal" or "proxy (friction, stick)"
    double staticNPerMm = 0.0;             ///< H(1), the stiffness of a slow press
    double passiveEquivalentNPerMm = 0.0;  ///< K_eq (infinity when no finite device damping will do)
    double worstThetaRad = 0.0;            ///< where the sweep found K_eq
    std::string why;                       ///< what makes K_eq differ from the static stiffness
    std::string lower;                     ///< the parameters that lower K_eq, for the margin's text
};

struct RenderedStiffness {
    std::vector<RenderedStiffnessLine> lines;  ///< the normal force first
};

/// True when the model's rendered stiffness is measured on the mesh (the mass-spring kinds).
bool renderedStiffnessNeedsMesh(const ModelDef& def);

/// Every line of `def` at period `periodS`. The mass-spring kinds are measured on `mesh` (pressed at
/// its highest-valence vertex: the stiffest point), so need it: nullopt without one.
std::optional<RenderedStiffness> renderedStiffness(const ModelDef& def, const TissueMesh* mesh, double periodS);

}  // namespace palpate
