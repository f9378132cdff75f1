#pragma once
// Scoring a detection exercise by signal detection (docs/scoring.md, "Detection"): the trainee's
// findings are matched one-to-one to the hidden lumps, so that two marks on one lump are a hit
// and a false alarm, never two hits.

#include "engine/exercise/PalpationResult.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace palpate {

struct HiddenLump {
    glm::dvec3 centreMm{0.0};
    double radiusMm = 0.0;
};

struct DetectionDef {
    /// A finding counts for a lump when it is within the lump's radius plus this of its centre.
    double toleranceMm = 5.0;
};

/// The matching that pairs the most findings with lumps (each within reach), and among those the
/// one with the smallest total distance: an assignment solved exactly (Hungarian method).
DetectionResult scoreDetection(const std::vector<HiddenLump>& lumps, const std::vector<glm::dvec3>& findingsMm,
                               const DetectionDef& def = {});

}  // namespace palpate
