#pragma once
// The tool a model's contact touches with and the friction it feels (docs/method.md, "Contact"
// and "Friction"). Defined by the tissue preset (TissueProperties: the tool radius the slopes are
// calibrated for, the friction coefficients); presetModelDef copies them here. A definition built
// without a preset gets a point tool without friction.

#include "base/params/Problem.h"

#include <cmath>
#include <string>

namespace palpate {

struct ContactDef {
    double toolRadiusMm = 0.0;     ///< 0: a point tool
    double staticFriction = 0.0;   ///< Coulomb: stick while |F_t| <= this * F_n
    double dynamicFriction = 0.0;  ///< while sliding, |F_t| = this * F_n (at most staticFriction)
};

/// What the contact needs to be defined at all: finite, not negative, sliding at most static
/// (the tissue table, TissueProperties, holds the ranges a person may choose from).
inline Problems validateContactDef(const ContactDef& c) {
    Problems problems;
    const auto check = [&](const char* field, double value) {
        if (!std::isfinite(value) || value < 0.0)
            problems.push_back({.field = field, .message = std::string(field) + " = " + std::to_string(value) +
                                                           " must be a finite number >= 0"});
    };
    check("toolRadiusMm", c.toolRadiusMm);
    check("staticFriction", c.staticFriction);
    check("dynamicFriction", c.dynamicFriction);
    if (problems.empty() && c.dynamicFriction > c.staticFriction)
        problems.push_back({.field = "dynamicFriction",
                            .message = "dynamicFriction = " + std::to_string(c.dynamicFriction) +
                                       " is above staticFriction = " + std::to_string(c.staticFriction)});
    return problems;
}

}  // namespace palpate
