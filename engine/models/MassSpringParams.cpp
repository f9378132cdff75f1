#include "engine/models/MassSpringParams.h"

#include "engine/core/Rings.h"
#include "engine/models/ParamText.h"

namespace palpate {

std::string_view integratorName(MassSpringIntegrator integrator) {
    switch (integrator) {
        case MassSpringIntegrator::SymplecticEuler: return "symplectic";
        case MassSpringIntegrator::Rk4: return "rk4";
        case MassSpringIntegrator::BackwardEuler: return "implicit";
    }
    return "?";
}

std::optional<MassSpringIntegrator> parseIntegrator(std::string_view name) {
    for (auto i : {MassSpringIntegrator::SymplecticEuler, MassSpringIntegrator::Rk4, MassSpringIntegrator::BackwardEuler})
        if (integratorName(i) == name) return i;
    return std::nullopt;
}

std::vector<std::string> validateMassSpringParams(const MassSpringParams& p) {
    using namespace paramtext;
    std::vector<std::string> errors;
    requirePositive(errors, p.vertexMassKg, "vertexMassKg", "kg");
    requirePositive(errors, p.anchorStiffnessNPerMm, "anchorStiffnessNPerMm", "N/mm");
    if (!std::isfinite(p.edgeStiffnessNPerMm) || p.edgeStiffnessNPerMm < 0.0)
        errors.push_back("edgeStiffnessNPerMm = " + number(p.edgeStiffnessNPerMm) + " N/mm must be 0 or more");
    requirePositive(errors, p.contactStiffnessNPerMm, "contactStiffnessNPerMm", "N/mm");
    requireRange(errors, p.dampingRatio, 0.0, 100.0, "dampingRatio");
    requireRange(errors, p.maxSubsteps, 1, 100000, "maxSubsteps");
    requireRange(errors, p.substeps, 0, std::max(1, p.maxSubsteps), "substeps");
    requireRange(errors, p.cgMaxIterations, 1, 100000, "cgMaxIterations");
    if (!std::isfinite(p.cgTolerance) || p.cgTolerance <= 0.0 || p.cgTolerance >= 1.0)
        errors.push_back("cgTolerance = " + number(p.cgTolerance) + " must be in (0, 1)");
    requireRange(errors, p.localRingCount, 1, kMaxRings, "localRingCount");
    requirePositive(errors, p.restEpsilonMm, "restEpsilonMm", "mm");
    return errors;
}

}  // namespace palpate
