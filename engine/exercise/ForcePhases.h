#pragma once
// Search and palpation, told apart from force and motion (docs/scoring.md, "Force by phase"):
// examiners sweep the surface lightly to search and then hold still and press to palpate, and
// successful ones press about 15 % harder in palpation than in search (Laufer, Klatzky and Pugh
// 2024). Each contact sample is one or the other by the tool's speed along the surface, measured
// over a window of time so that a mouse (its target moves at its event rate, 60-125 a second) and
// a device (every tick) moving alike give the same phases.

#include "engine/exercise/PalpationResult.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace palpate {

struct ForcePhaseDef {
    /// Slower than this along the surface is palpation; faster is search.
    double palpationMaxSpeedMmPerS = 10.0;
    /// Below this force there is no examination at all (resting contact).
    double minForceN = 0.1;
    /// The speed is the contact point's travel along the surface over this long: many of a
    /// mouse's events, and short against a hold (examiners hold still for a second or more).
    double speedWindowS = 0.25;
};

/// The contact point's speed along the surface over the last ForcePhaseDef::speedWindowS of one
/// contact: from the point that long ago (or the contact's first) to the current one, its motion
/// along the normal removed. Real-time: the room for a window of ticks is kept at construction.
class SurfaceSpeed {
public:
    SurfaceSpeed(double windowS, double periodS);
    /// A contact ended: the next point starts a new one.
    void reset();
    /// The contact point after a tick of `dtS`; the speed (mm/s) since the window's first point,
    /// nullopt on a contact's first tick.
    std::optional<double> add(double dtS, const glm::dvec3& pointMm, const glm::dvec3& normal);

private:
    struct Timed {
        double timeS;
        glm::dvec3 pointMm;
    };
    double mWindowS;
    std::vector<Timed> mRing;  ///< the last points of the contact, oldest at mOldest
    std::size_t mOldest = 0, mCount = 0;
    double mTimeS = 0.0;  ///< since the contact began
};

/// One sample of a session: the force's magnitude and the tool's speed along the surface.
struct ForceMotionSample {
    double forceN = 0.0;
    double tangentialSpeedMmPerS = 0.0;
};

/// Percentiles by linear interpolation between order statistics (the "type 7" definition).
ForceByPhase forceByPhase(const std::vector<ForceMotionSample>& samples, const ForcePhaseDef& def = {});

}  // namespace palpate
