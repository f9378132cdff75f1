#include "engine/models/slopering/CandidateCache.h"

#include <limits>

namespace palpate {

void CandidateCache::refresh(const Octree& octree, const glm::vec3& tool, const glm::vec3& toolStepMm,
                             bool offsetCentre) {
    // Any centre gives a valid bound; this one makes it last (docs/method.md). Beyond the tool,
    // on the line from the nearest cached vertex through it, then ahead along the tool's last step.
    glm::vec3 centre = tool;
    if (offsetCentre && mCount > 0) {
        float nearest2 = std::numeric_limits<float>::infinity();
        glm::vec3 from = tool;
        for (int i = 0; i < mCount; ++i) {
            const glm::vec3 d = mRestMm[i] - tool;
            const float d2 = d.x * d.x + d.y * d.y + d.z * d.z;
            if (d2 < nearest2) {
                nearest2 = d2;
                from = mRestMm[i];
            }
        }
        const glm::vec3 away = tool - from;
        const float distance = std::sqrt(nearest2);
        const glm::vec3 axis = distance > 0.0f ? away / distance : glm::vec3(0.0f);
        const float along = glm::dot(toolStepMm, axis);
        glm::vec3 lead = kLeadTicks * (toolStepMm - along * axis) + (kAxialLeadTicks * along) * axis;
        const float leadMax = 0.5f * distance, leadLength = glm::length(lead);
        if (!std::isfinite(leadLength)) lead = glm::vec3(0.0f);
        else if (leadLength > leadMax) lead *= leadMax / leadLength;
        centre = tool + kCentreOffset * away + lead;
    }
    float d2[kCacheSize];
    mCount = octree.nearestRestK(centre, kCacheSize, mIds, d2, mCount, mRestMm);
    for (int i = 0; i < mCount; ++i) mDistanceMm[i] = std::sqrt(d2[i]);
    mRadiusMm = mCount < kCacheSize ? std::numeric_limits<float>::infinity() : mDistanceMm[kCacheSize - 1];
    mCentreMm = centre;
    ++mRefreshes;
}

}  // namespace palpate
