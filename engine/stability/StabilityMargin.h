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
    /// 1 - (used / allowed) of the quantity that limits the model: alpha (1 + g) / 2 for the slope
    /// model, h omega_max / bound for the explicit mass-spring integrators; 1 where nothing limits.
    double margin = 1.0;
    std::string text;  ///< e.g. "alpha (1 + g) = 0.80 of 2: margin 60 %"; names the parameter
};

/// The passive stiffness of the device at 1 kHz the margins assume when none is given: DeviceSpec's
/// default (1 N/mm), i.e. physical damping b = 0.5 N s/m (docs/stability.md section 3).
inline constexpr double kDefaultPassiveStiffnessAt1kHzNPerMm = 1.0;

/// The margin of `def` on `mesh` at period `dtS`. Mass-spring uses Gershgorin's omega_max (the
/// model's own, on the safe side; the exact one is massSpringOmegaMaxRadPerS) and the sub-steps
/// the model would take. The geometric models (radius of influence, FFD), which have no step or
/// loop-gain bound, get the haptic one: 1 - k_s / K_passive, K_passive = Colgate and Brown's 2 b / T
/// for a device passive up to `passiveStiffnessAt1kHzNPerMm` at 1 kHz.
StabilityMargin stabilityMargin(const ModelDef& def, const TissueMesh& mesh, double dtS,
                                double passiveStiffnessAt1kHzNPerMm = kDefaultPassiveStiffnessAt1kHzNPerMm);
/// As above with the mesh optional: nullopt when the kind needs one (stabilityMarginNeedsMesh) and
/// `mesh` is null.
std::optional<StabilityMargin> stabilityMarginIfKnown(const ModelDef& def, const TissueMesh* mesh, double dtS,
                                                      double passiveStiffnessAt1kHzNPerMm = kDefaultPassiveStiffnessAt1kHzNPerMm);
/// True when the margin of `kind` depends on the mesh (the mass-spring kinds): without a mesh the
/// caller cannot compute it.
bool stabilityMarginNeedsMesh(ModelKind kind);
/// The geometric models' margin alone (no mesh needed).
StabilityMargin renderedStiffnessMargin(double stiffnessNPerMm, double dtS,
                                        double passiveStiffnessAt1kHzNPerMm = kDefaultPassiveStiffnessAt1kHzNPerMm);

}  // namespace palpate
