#pragma once
// Scoring a detection exercise by signal detection (docs/scoring.md, "Detection"): the trainee's
// findings are matched one-to-one to the hidden lumps, so that two marks on one lump are a hit
// and a false alarm, never two hits.

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

struct DetectionResult {
    std::size_t hits = 0;
    std::size_t misses = 0;
    std::size_t falseAlarms = 0;
    std::optional<double> sensitivity;        ///< hits / lumps; absent when there are no lumps
    std::optional<double> positivePredictive; ///< hits / findings; absent when nothing was marked
    /// For each lump, the finding matched to it (index into the findings), or -1 (a miss).
    std::vector<int> findingOfLump;
    /// For each lump, the distance from its matched finding to its centre, mm (-1 for a miss).
    std::vector<double> localisationMm;
};

/// The matching that pairs the most findings with lumps (each within reach), and among those the
/// one with the smallest total distance: an assignment solved exactly (Hungarian method).
DetectionResult scoreDetection(const std::vector<HiddenLump>& lumps, const std::vector<glm::dvec3>& findingsMm,
                               const DetectionDef& def = {});

}  // namespace palpate
