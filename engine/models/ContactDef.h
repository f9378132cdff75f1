#pragma once
// The tool a model's contact touches with and the friction it feels (docs/method.md, "Contact"
// and "Friction"). Defined by the tissue preset (TissueProperties: the tool radius the slopes are
// calibrated for, the friction coefficients); presetModelDef copies them here. A definition built
// without a preset gets a point tool without friction.

namespace palpate {

struct ContactDef {
    double toolRadiusMm = 0.0;     ///< 0: a point tool
    double staticFriction = 0.0;   ///< Coulomb: stick while |F_t| <= this * F_n
    double dynamicFriction = 0.0;  ///< while sliding, |F_t| = this * F_n (at most staticFriction)
};

}  // namespace palpate
