#include "engine/scoring/DamageProbe.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace palpate {

DamageProbe::DamageProbe(const std::vector<glm::vec3>& restMm, const std::vector<float>& vertexAreaMm2,
                         double displacementLimitMm)
    : mRestMm(restMm), mVertexAreaMm2(vertexAreaMm2), mLimitMm(float(displacementLimitMm)) {}

void DamageProbe::add(VertexId v, const glm::vec3& positionMm, DamageSummary& out) const {
    if (v >= mRestMm.size()) return;  // another mesh's vertex (a scene switch): not this exercise's tissue
    const float displacement = glm::length(positionMm - mRestMm[v]);
    out.maxDisplacementMm = std::max(out.maxDisplacementMm, displacement);
    if (displacement > mLimitMm) out.areaAboveLimitMm2 += mVertexAreaMm2[v];
}

DamageSummary DamageProbe::measure(const HapticSnapshot& s,
                                   const std::function<std::span<const glm::vec3>()>& allPositions) const {
    DamageSummary out;
    if (s.displacedTotal <= s.displacedCount || !allPositions) {
        for (std::uint32_t i = 0; i < s.displacedCount; ++i) add(s.displacedIds[i], s.displacedPositionsMm[i], out);
        return out;
    }
    const std::span<const glm::vec3> all = allPositions();
    const std::size_t n = std::min(all.size(), mRestMm.size());
    for (std::size_t v = 0; v < n; ++v) add(VertexId(v), all[v], out);
    return out;
}

}  // namespace palpate
