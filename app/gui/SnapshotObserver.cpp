#include "app/gui/SnapshotObserver.h"

#include <algorithm>

namespace palpate {

void SnapshotObserver::setRestPositions(const std::vector<glm::vec3>& restMm) {
    mRestMm = restMm;
    mView = SceneSnapshot{};
    mView.positionsMm = restMm;
    mView.rings.assign(restMm.size(), kNoRing);
    mView.version = ++mVersion;
    mSet.clear();
    mNextSet.clear();
    // Capacity for the most a snapshot can list: apply() then never allocates. A vertex changes
    // either because it is listed now or because it was listed last time.
    const std::size_t capacity = std::min(restMm.size(), HapticSnapshot::kMaxDisplaced);
    mSet.reserve(capacity);
    mNextSet.reserve(capacity);
    mView.changed.reserve(std::min(restMm.size(), 2 * HapticSnapshot::kMaxDisplaced));
    mStamp.assign(restMm.size(), 0);
    mGeneration = 0;
}

std::size_t SnapshotObserver::apply(const HapticSnapshot& snapshot) {
    const std::size_t vertexCount = mRestMm.size();
    if (++mGeneration == 0) {  // wrapped (after 4e9 updates): old stamps could alias
        std::fill(mStamp.begin(), mStamp.end(), 0u);
        mGeneration = 1;
    }
    std::size_t written = 0;
    mNextSet.clear();
    mView.changed.clear();
    const std::size_t count = std::min<std::size_t>(snapshot.displacedCount, HapticSnapshot::kMaxDisplaced);
    for (std::size_t i = 0; i < count; ++i) {
        const VertexId v = snapshot.displacedIds[i];
        if (v >= vertexCount || mStamp[v] == mGeneration) continue;
        mStamp[v] = mGeneration;
        const glm::vec3& p = snapshot.displacedPositionsMm[i];
        const std::uint8_t ring = snapshot.displacedRings[i];  // kRelaxingRing == kNoRing
        if (mView.positionsMm[v] != p || mView.rings[v] != ring) {
            mView.positionsMm[v] = p;
            mView.rings[v] = ring;
            mView.changed.push_back(v);
        }
        mNextSet.push_back(v);
        ++written;
    }
    // Those set last time and not listed now have come back to rest.
    for (const VertexId v : mSet) {
        if (mStamp[v] == mGeneration) continue;
        if (mView.positionsMm[v] != mRestMm[v] || mView.rings[v] != kNoRing) {
            mView.positionsMm[v] = mRestMm[v];
            mView.rings[v] = kNoRing;
            mView.changed.push_back(v);
        }
        ++written;
    }
    std::swap(mSet, mNextSet);
    if (!mView.changed.empty()) mView.version = ++mVersion;

    mView.touched = snapshot.touched < vertexCount ? snapshot.touched : kNoVertex;
    mView.contact = snapshot.contact;
    mView.hasTool = snapshot.deviceState == DeviceState::Ready && snapshot.toolSampleSequence > 0;
    mView.toolTipMm = snapshot.toolTipMm;
    mView.toolRadiusMm = snapshot.toolRadiusMm;
    mView.proxyMm = snapshot.proxyMm;
    mView.forceN = snapshot.forceN;  // what the device was sent: what the user feels
    return written;
}

}  // namespace palpate
