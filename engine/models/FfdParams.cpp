#include "engine/models/FfdParams.h"

#include "engine/models/ParamText.h"

namespace palpate {

std::vector<std::string> validateFfdParams(const FfdParams& p) {
    using namespace paramtext;
    std::vector<std::string> errors;
    const bool resolutionOk = requireRange(errors, p.controlPointsPerAxis, 2, kMaxFfdPointsPerAxis, "controlPointsPerAxis");
    requireRange(errors, p.movedPerAxis, 1, resolutionOk ? p.controlPointsPerAxis : kMaxFfdPointsPerAxis, "movedPerAxis");
    requireRange(errors, p.marginFraction, 0.0, 1.0, "marginFraction");
    if (std::isfinite(p.marginFraction) && p.marginFraction == 0.0)
        errors.push_back("marginFraction = 0 leaves vertices on the lattice's faces; it must be above 0");
    requirePositive(errors, p.stiffnessNPerMm, "stiffnessNPerMm", "N/mm");
    return errors;
}

}  // namespace palpate
