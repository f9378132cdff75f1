#include "engine/models/VolumetricRingsParams.h"

namespace palpate {

Problems validateVolumetricRingsParams(const VolumetricRingsParams& params) {
    Problems problems = validateSlopeRingParams(params.slopeRing);
    for (Problem& p : problems) p.message = "slopeRing: " + p.message;
    return problems;
}

}  // namespace palpate
