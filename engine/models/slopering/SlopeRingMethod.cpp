#include "engine/models/slopering/SlopeRingMethod.h"

namespace palpate {

namespace {
// What presets, exercises and recordings written before the rename call the coherent method.
constexpr std::string_view kCoherentFormerName = "palpate";
}  // namespace

std::string_view methodName(SlopeRingMethod method) {
    switch (method) {
        case SlopeRingMethod::Previous: return "previous";
        case SlopeRingMethod::Hybrid: return "hybrid";
        case SlopeRingMethod::Proposed: return "proposed";
        case SlopeRingMethod::Coherent: return "coherent";
    }
    return "unknown";
}

std::optional<SlopeRingMethod> parseMethod(std::string_view name) {
    for (auto m : {SlopeRingMethod::Previous, SlopeRingMethod::Hybrid, SlopeRingMethod::Proposed,
                   SlopeRingMethod::Coherent})
        if (methodName(m) == name) return m;
    if (name == kCoherentFormerName) return SlopeRingMethod::Coherent;
    return std::nullopt;
}

}  // namespace palpate
