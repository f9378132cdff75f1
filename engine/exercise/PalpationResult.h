#pragma once
// What a palpation session measures beyond the metrics (docs/scoring.md, "Detection", "Coverage",
// "Force by phase"): the findings matched to the hidden lumps, how much of the surface was
// examined firmly enough (and the heat map of it), the force in search and in palpation, and the
// feedback drawn from them. Plain data: the scorer fills it (engine/scoring), the report, the
// viewport and the PDF read it.

#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

/// Which contacts examine the surface, and how far around their point (an exercise's "coverage").
struct CoverageDef {
    double minForceN = 1.0;   ///< a lighter contact examines nothing
    double radiusMm = 5.0;    ///< around the contact point
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
    /// The mean localisation over the hits (absent without a hit).
    std::optional<double> meanLocalisationMm() const {
        double sum = 0.0;
        for (double d : localisationMm)
            if (d >= 0.0) sum += d;
        if (hits == 0) return std::nullopt;
        return sum / double(hits);
    }
};

struct ForcePercentiles {
    std::size_t samples = 0;
    double p10N = 0.0, p50N = 0.0, p90N = 0.0, maxN = 0.0;
};

struct ForceByPhase {
    std::optional<ForcePercentiles> search;     ///< absent when no sample was search
    std::optional<ForcePercentiles> palpation;  ///< absent when no sample was palpation
    /// Median palpation force over median search force (absent unless both phases occurred).
    std::optional<double> palpationOverSearch;
};

/// Feedback on how the examination went, each with a stable key (for translations and tests) and
/// its sentence.
struct PalpationFeedback {
    std::string key;   ///< "pressed_too_lightly", "false_alarms", "low_coverage", "light_palpation"
    std::string text;  ///< English
    /// The figures in the text, in its order: a front end says the sentence in its language from
    /// the key and these (report/PalpationSummaryText.h).
    std::vector<double> numbers;
};

struct PalpationSummary {
    CoverageDef coverage;                ///< what counted as examined
    double coverageFraction = 0.0;       ///< covered area / surface area, [0, 1]
    /// The heat map: the largest force that covered each vertex (engine numbering), N; 0 where none.
    std::vector<float> peakForceN;
    ForceByPhase forceByPhase;
    /// Detect lumps only: the findings (contact points at the marks, mm) and their matching.
    std::vector<glm::dvec3> findingsMm;
    std::optional<DetectionResult> detection;
    /// The rendered force at which the deepest lump begins to resist (absent without lumps), N.
    std::optional<double> deepestLumpReachForceN;
    std::vector<PalpationFeedback> feedback;
};

/// A guidance aid shown during the session and how strongly (docs/scoring.md, "Fading guidance").
struct GuidanceAid {
    std::string name;   ///< "force_gauge", ...
    double level = 1.0; ///< 1 fully shown, 0 hidden; a faded gauge's opacity
};

}  // namespace palpate
