#pragma once
// What the hand feels of a force sequence (docs/bench/README.md, "Feel"): the largest tick-to-tick
// step and the ripple relative to the mean force, the friction ratio, and the dropouts of a
// threaded run. Pure functions of the sequence, so that they are tested on sequences with known
// answers.

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>

namespace palpate {

/// One tick as the metrics see it: the rendered force and the unit outward direction of its
/// normal part (TickResult::normal; zero when the model gives none).
struct FeelTick {
    glm::vec3 forceN{0.0f};
    glm::vec3 normal{0.0f};
};

struct FeelMetrics {
    std::size_t ticks = 0;
    double meanForceN = 0.0;        ///< mean |F|
    double maxStepPct = 0.0;        ///< max |F_t - F_{t-1}| / mean |F|, in %
    double maxNormalStepPct = 0.0;  ///< max |Fn_t - Fn_{t-1}| / mean |F|, in % (Fn = F . normal)
    double ripplePct = 0.0;         ///< (max |F| - min |F|) / mean |F|, in %
    double meanNormalN = 0.0;       ///< mean Fn
    double meanTangentialN = 0.0;   ///< mean |F - Fn normal|
    double frictionRatio = 0.0;     ///< meanTangentialN / meanNormalN (0 without normal force)
};

/// The metrics of a window of consecutive ticks (steps between neighbours inside it). A tick with a
/// force but no normal renders no friction: all of its force is normal. Without force in the
/// window (mean |F| = 0) the percentages are NaN: nothing was felt to compare with.
FeelMetrics feelMetrics(std::span<const FeelTick> ticks);

/// One tick of a threaded run: the force the device was sent and whether the model was in contact.
struct FeltTick {
    double forceN = 0.0;  ///< |F| after the safety filter
    bool contact = false;
};

/// Contact ticks among [begin, end) whose force fell below `fraction` of the mean force of its
/// neighbours within +-halfWidth ticks (itself left out; neighbours outside the sequence too):
/// the hand feels a hole in the force. Ticks without contact are not counted.
std::size_t countDropouts(std::span<const FeltTick> ticks, std::size_t begin, std::size_t end, int halfWidth = 3,
                          double fraction = 0.5);

}  // namespace palpate
