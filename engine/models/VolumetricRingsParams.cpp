#include "engine/models/VolumetricRingsParams.h"

namespace palpate {

std::vector<std::string> validateVolumetricRingsParams(const VolumetricRingsParams& params) {
    std::vector<std::string> errors;
    for (const std::string& e : validateSlopeRingParams(params.slopeRing)) errors.push_back("slopeRing: " + e);
    return errors;
}

}  // namespace palpate
