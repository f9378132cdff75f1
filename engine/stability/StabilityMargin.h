#pragma once
// How far a model definition is from its derived stability boundary at a loop period, in one
// number and one sentence, for the parameter panel and presets (docs/stability.md): margin > 0
// inside, <= 0 at or beyond; the text names the parameter that sets it. Qt-free, not real-time.

#include "engine/TissueMesh.h"
#include "engine/models/ModelRegistry.h"

#include <string>

namespace palpate {

struct StabilityMargin {
    /// 1 - (used / allowed) of the quantity that limits the model: alpha (1 + g) / 2 for the slope
    /// model, h omega_max / bound for the explicit mass-spring integrators; 1 where nothing limits.
    double margin = 1.0;
    std::string text;  ///< e.g. "alpha (1 + g) = 0.80 of 2: margin 60 %"; names the parameter
};

/// The margin of `def` on `mesh` at period `dtS`. Mass-spring uses Gershgorin's omega_max (the
/// model's own, on the safe side; the exact one is massSpringOmegaMaxRadPerS) and the sub-steps
/// the model would take.
StabilityMargin stabilityMargin(const ModelDef& def, const TissueMesh& mesh, double dtS);

}  // namespace palpate
