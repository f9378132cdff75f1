#pragma once
// Parameters of the volumetric slope-ring model (the paper's future work): the slope-ring update
// on rings taken in a tetrahedral mesh's edge graph. The slope-ring parameters mean what they mean
// on the surface (docs/method.md); ring r is now every tet node r edges away, inside or on the surface.

#include "engine/models/slopering/SlopeRingParams.h"

#include <string>
#include <vector>

namespace palpate {

struct VolumetricRingsParams {
    /// Slopes per ring (of the tet graph), contact stiffness and relaxation, return springs.
    SlopeRingParams slopeRing;
};

/// Every problem found, each naming the field; empty when valid.
std::vector<std::string> validateVolumetricRingsParams(const VolumetricRingsParams& params);

}  // namespace palpate
