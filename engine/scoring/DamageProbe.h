#pragma once
// Measures tissue damage after a tick from the loop's snapshot: the largest vertex displacement
// and the surface area displaced beyond a limit. The snapshot lists every displaced vertex (the
// active rings and those relaxing) with its position, so this costs the displaced set, not the mesh;
// when the snapshot had to cut the list, the whole surface is read instead.

#include "engine/loop/HapticSnapshot.h"
#include "engine/scoring/ScoreSample.h"

#include <glm/vec3.hpp>

#include <functional>
#include <span>
#include <vector>

namespace palpate {

class DamageProbe {
public:
    /// `restMm` and `vertexAreaMm2`: the mesh's (ExerciseGeometry); must outlive the probe.
    DamageProbe(const std::vector<glm::vec3>& restMm, const std::vector<float>& vertexAreaMm2,
                double displacementLimitMm);

    /// `allPositions` is called only when the snapshot's displaced list was cut (more than
    /// HapticSnapshot::kMaxDisplaced vertices); it returns the whole surface.
    DamageSummary measure(const HapticSnapshot& snapshot,
                          const std::function<std::span<const glm::vec3>()>& allPositions) const;

private:
    void add(VertexId v, const glm::vec3& positionMm, DamageSummary& out) const;

    const std::vector<glm::vec3>& mRestMm;
    const std::vector<float>& mVertexAreaMm2;
    float mLimitMm;
};

}  // namespace palpate
