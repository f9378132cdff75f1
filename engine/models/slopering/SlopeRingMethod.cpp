#include "engine/models/slopering/SlopeRingMethod.h"

namespace palpate {

std::string_view methodName(SlopeRingMethod method) {
    switch (method) {
        case SlopeRingMethod::Previous: return "previous";
        case SlopeRingMethod::Hybrid: return "hybrid";
        case SlopeRingMethod::Proposed: return "proposed";
        case SlopeRingMethod::Palpate: return "palpate";
    }
    return "unknown";
}

std::optional<SlopeRingMethod> parseMethod(std::string_view name) {
    for (auto m : {SlopeRingMethod::Previous, SlopeRingMethod::Hybrid, SlopeRingMethod::Proposed,
                   SlopeRingMethod::Palpate})
        if (methodName(m) == name) return m;
    return std::nullopt;
}

}  // namespace palpate
