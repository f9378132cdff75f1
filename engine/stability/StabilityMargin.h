#pragma once
// How far a model definition is from its derived stability boundary at a loop period, in one
// number and one sentence, for the parameter panel and presets (docs/stability.md): margin > 0
// inside, <= 0 at or beyond; the text names the parameter that sets it. Qt-free, not real-time.

#include "engine/core/TissueMesh.h"
#include "engine/models/ModelRegistry.h"

#include <optional>
#include <string>

namespace palpate {

struct StabilityMargin {
    /// The smaller of the two below: > 0 inside both, <= 0 beyond either.
    double margin = 1.0;
    /// One sentence per line ('\n'), each naming what limits it and, beyond it, the parameter to
    /// change: the model's own bound first, then one line per rendered stiffness (passivity).
    std::string text;
    /// The model's own bound, 1 - used / allowed: 1 - alpha (1 + g) / 2 for the slope model,
    /// 1 - h omega_max / bound for the explicit mass-spring integrators; 1 where nothing limits
    /// (backward Euler, the geometric models).
    double boundMargin = 1.0;
    /// Passivity, 1 - K_eq / K_device: the largest passive-equivalent stiffness the model renders
    /// (RenderedStiffness.h) against the device's passive stiffness at the period.
    double passivityMargin = 1.0;
};

/// The passive stiffness of the device at 1 kHz the margins assume when none is given: DeviceSpec's
/// default (1 N/mm), i.e. physical damping b = 0.5 N s/m (docs/stability.md section 3).
inline constexpr double kDefaultPassiveStiffnessAt1kHzNPerMm = 1.0;

/// Warn below this margin (the panel's "close to the limit" state): 20 %.
inline constexpr double kStabilityMarginWarning = 0.2;

/// The margin of `def` on `mesh` at period `dtS`: the smaller of the model's own bound and its
/// passivity. Mass-spring's bound uses Gershgorin's omega_max (the model's own, on the safe side;
/// the exact one is massSpringOmegaMaxRadPerS) and the sub-steps the model would take; the
/// geometric models (radius of influence, FFD) have no step or loop-gain bound. Passivity, for
/// every model: 1 - K_eq / K_passive, K_eq the passive-equivalent stiffness of what it renders
/// (RenderedStiffness.h; measured on `mesh` for the mass-spring kinds), K_passive = 2 b / T for a
/// device passive up to `passiveStiffnessAt1kHzNPerMm` at 1 kHz.
StabilityMargin stabilityMargin(const ModelDef& def, const TissueMesh& mesh, double dtS,
                                double passiveStiffnessAt1kHzNPerMm = kDefaultPassiveStiffnessAt1kHzNPerMm);
/// As above with the mesh optional: nullopt when the kind needs one (stabilityMarginNeedsMesh) and
/// `mesh` is null.
std::optional<StabilityMargin> stabilityMarginIfKnown(const ModelDef& def, const TissueMesh* mesh, double dtS,
                                                      double passiveStiffnessAt1kHzNPerMm = kDefaultPassiveStiffnessAt1kHzNPerMm);
/// True when the margin of the model depends on the mesh (the mass-spring kinds): without a mesh the
/// caller cannot compute it.
bool stabilityMarginNeedsMesh(const ModelDef& def);
/// The passivity margin of a pure spring (the geometric models' k_s; no mesh needed).
StabilityMargin renderedStiffnessMargin(double stiffnessNPerMm, double dtS,
                                        double passiveStiffnessAt1kHzNPerMm = kDefaultPassiveStiffnessAt1kHzNPerMm);

}  // namespace palpate
