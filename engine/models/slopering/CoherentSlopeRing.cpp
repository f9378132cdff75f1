#include "engine/models/slopering/CoherentSlopeRing.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace palpate {

namespace {
constexpr std::uint32_t kNoSlot = 0xffffffffu;
// A relaxing vertex closer than this to rest, and slower than this per tick, snaps back and rests.
constexpr float kRestEpsilonMm = 1e-4f;

inline float dist2(const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 d = a - b;
    return d.x * d.x + d.y * d.y + d.z * d.z;
}
}  // namespace

CoherentSlopeRing::CoherentSlopeRing(const TissueMesh& mesh, const Octree& octree, const SlopeRingParams& params,
                                     bool eagerPositions)
    : SlopeRingModel(mesh, octree, SlopeRingMethod::Coherent), mEagerPositions(eagerPositions) {
    const std::size_t n = mesh.vertexCount();
    mActive = mRingFinder.makeRingSet();
    mNextActive = mRingFinder.makeRingSet();
    mActiveRestX.resize(n);
    mActiveRestY.resize(n);
    mActiveRestZ.resize(n);
    mActiveScan.distance2Mm2.resize(n);
    mActiveStamp.assign(n, 0);
    mRelaxing.resize(n);
    mRelaxingSlot.assign(n, kNoSlot);
    // The full-search fallback lists active and relaxing vertices (disjoint: at most n) in the
    // tick: reserved here so that it never allocates.
    mDisplacedScratch.reserve(n);
    setParams(params);
}

void CoherentSlopeRing::paramsReplaced(bool /*ringsChanged*/) { releaseActiveSet(); }

void CoherentSlopeRing::setCompliance(std::vector<float> factors) {
    if (!factors.empty()) {
        if (factors.size() != mMesh.vertexCount())
            throw std::invalid_argument("compliance: " + std::to_string(factors.size()) + " factors for " +
                                        std::to_string(mMesh.vertexCount()) + " vertices");
        for (std::size_t v = 0; v < factors.size(); ++v)
            if (!(factors[v] > 0.0f && factors[v] <= 1.0f))  // also refuses NaN
                throw std::invalid_argument("compliance[" + std::to_string(v) + "]: " + std::to_string(factors[v]) +
                                            " is outside (0, 1] (only stiffer inclusions keep the loop-gain bound)");
    }
    mCompliance = std::move(factors);
    releaseActiveSet();
}

void CoherentSlopeRing::releaseActiveSet() {
    // New slopes or rings: the active set is rebuilt on the next tick; its vertices relax from
    // where they are until then (those that are active again stop relaxing).
    if (mActiveCentre == kNoVertex) return;
    writeActivePositions();
    if (mActiveContact)
        for (std::size_t i = 0, n = mActive.size(); i < n; ++i) {
            mVelocitiesMmPerS[mActive.vertices[i]] = glm::vec3(0.0f);
            addRelaxing(mActive.vertices[i]);
        }
    mActive.ringCount = 0;
    mActive.ringStart[1] = 0;
    ++mActiveGeneration;
    mActiveScan.valid = false;
    mActiveCentre = kNoVertex;
    mActiveContact = false;
}

std::size_t CoherentSlopeRing::copyDisplaced(VertexId* ids, glm::vec3* positionsMm, std::uint8_t* rings,
                                             std::size_t capacity) const {
    DisplacedOutput out{ids, positionsMm, rings, capacity};
    auto put = [&out](VertexId v, const glm::vec3& p, std::uint8_t ring) { out.put(v, p, ring); };
    if (mActiveCentre != kNoVertex && mActiveContact)
        for (int r = 0; r <= mActive.ringCount; ++r) {
            const glm::vec3 displacement = ringDisplacementMm(r, mActiveForceN, mActiveNormal);
            for (std::uint32_t i = mActive.ringStart[r], end = mActive.ringStart[r + 1]; i < end; ++i)
                put(mActive.vertices[i], glm::vec3(mActiveRestX[i], mActiveRestY[i], mActiveRestZ[i]) + displacement,
                    std::uint8_t(r));
        }
    for (std::size_t i = 0; i < mRelaxingCount; ++i) put(mRelaxing[i], mPositions[mRelaxing[i]], kRelaxingRing);
    return out.count;
}

void CoherentSlopeRing::reset() {
    resetShared();
    for (std::size_t i = 0; i < mRelaxingCount; ++i) mRelaxingSlot[mRelaxing[i]] = kNoSlot;
    mRelaxingCount = 0;
    mActiveCentre = kNoVertex;
    mActiveContact = false;
    mActiveDirty = false;
    mActiveForceN = 0.0f;
    mActiveScan.valid = false;
    mActive.ringCount = 0;
    mActive.ringStart[1] = 0;  // empty: no vertex is active
    ++mActiveGeneration;
    mCache.clear();
}

std::span<const glm::vec3> CoherentSlopeRing::positionsMm() const {
    writeActivePositions();
    return mPositions;
}

std::span<const VertexId> CoherentSlopeRing::displacedVertices() const {
    mDisplacedScratch.clear();
    if (mActiveCentre != kNoVertex && mActiveContact)
        mDisplacedScratch.insert(mDisplacedScratch.end(), mActive.vertices.begin(),
                                 mActive.vertices.begin() + std::ptrdiff_t(mActive.size()));
    mDisplacedScratch.insert(mDisplacedScratch.end(), mRelaxing.begin(),
                             mRelaxing.begin() + std::ptrdiff_t(mRelaxingCount));
    return mDisplacedScratch;
}

void CoherentSlopeRing::addRelaxing(VertexId v) {
    if (mRelaxingSlot[v] != kNoSlot) return;
    mRelaxingSlot[v] = std::uint32_t(mRelaxingCount);
    mRelaxing[mRelaxingCount++] = v;
}

void CoherentSlopeRing::removeRelaxing(VertexId v) {
    const std::uint32_t slot = mRelaxingSlot[v];
    if (slot == kNoSlot) return;
    const VertexId last = mRelaxing[--mRelaxingCount];
    mRelaxing[slot] = last;
    mRelaxingSlot[last] = slot;
    mRelaxingSlot[v] = kNoSlot;
}

void CoherentSlopeRing::searchActive(const glm::vec3& tool, VertexId& best, float& best2) const {
    const float slope1 = -mHot.signedSlope[0];
    ActiveScan& scan = mActiveScan;
    if (scan.valid) {
        // Every active vertex moved relative to the tool by at most |dtool| + |m1| |dF|.
        const float moved = glm::length(tool - scan.toolMm) + slope1 * std::fabs(mActiveForceN - scan.forceN);
        const float margin = scan.secondMm - moved;
        const std::uint32_t i = scan.best;
        const glm::vec3 q = tool - ringDisplacementMm(scan.bestRing, mActiveForceN, mActiveNormal);
        const float dx = mActiveRestX[i] - q.x, dy = mActiveRestY[i] - q.y, dz = mActiveRestZ[i] - q.z;
        const float d2 = dx * dx + dy * dy + dz * dz;
        if (margin > 0.0f && d2 < margin * margin) {
            best = mActive.vertices[i];
            best2 = d2;
            return;
        }
    }
    // Full scan: the active rings from their rest copy shifted by each ring's displacement
    // (contiguous arrays, so the distance loop vectorises).
    float* d2 = scan.distance2Mm2.data();
    const float* rx = mActiveRestX.data();
    const float* ry = mActiveRestY.data();
    const float* rz = mActiveRestZ.data();
    for (int r = 0; r <= mActive.ringCount; ++r) {
        const glm::vec3 q = tool - ringDisplacementMm(r, mActiveForceN, mActiveNormal);
        const std::uint32_t begin = mActive.ringStart[r], end = mActive.ringStart[r + 1];
        for (std::uint32_t i = begin; i < end; ++i) {
            const float dx = rx[i] - q.x, dy = ry[i] - q.y, dz = rz[i] - q.z;
            d2[i] = dx * dx + dy * dy + dz * dz;
        }
    }
    std::uint32_t bestIndex = 0;
    float first = std::numeric_limits<float>::infinity(), second = first;
    for (std::uint32_t i = 0, n = std::uint32_t(mActive.size()); i < n; ++i) {
        const float v = d2[i];
        if (v < first || (v == first && mActive.vertices[i] < mActive.vertices[bestIndex])) {
            second = first;
            first = v;
            bestIndex = i;
        } else if (v < second) {
            second = v;
        }
    }
    best = mActive.vertices[bestIndex];
    best2 = first;
    int ring = 0;
    while (bestIndex >= mActive.ringStart[ring + 1]) ++ring;
    scan.valid = true;
    scan.toolMm = tool;
    scan.forceN = mActiveForceN;
    scan.best = bestIndex;
    scan.bestRing = ring;
    scan.secondMm = std::sqrt(second);
}

VertexId CoherentSlopeRing::search(const glm::vec3& tool) const {
    // Exact nearest vertex over current positions, in three parts: (1) every displaced vertex:
    // the active rings from their rest copy shifted by each ring's displacement (contiguous, so the
    // compiler vectorises it), the relaxing ones directly; (2) the cached rest vertices that could
    // still beat the best so far; (3) a proof that no other vertex at rest can: those are at least
    // the cache's radius from its centre (docs/method.md).
    VertexId best = kNoVertex;
    float best2 = std::numeric_limits<float>::infinity();
    const bool activeInContact = mActiveCentre != kNoVertex && mActiveContact;
    if (activeInContact) searchActive(tool, best, best2);
    for (std::size_t i = 0; i < mRelaxingCount; ++i) {
        const VertexId v = mRelaxing[i];
        const float d2 = dist2(mPositions[v], tool);
        if (d2 < best2 || (d2 == best2 && v < best)) {
            best2 = d2;
            best = v;
        }
    }
    const auto displaced = [&](VertexId v) {
        return (activeInContact && mActiveStamp[v] == mActiveGeneration) || mRelaxingSlot[v] != kNoSlot;
    };
    if (mCache.certifyNearest(mOctree, tool, best, best2, displaced)) return best;
    writeActivePositions();
    return mOctree.nearestExact(tool, mPositions, displacedVertices(), best);
}

void CoherentSlopeRing::warm(const glm::vec3& lastToolTipMm) const {
    if (!std::isfinite(lastToolTipMm.x)) return;
    volatile VertexId sink = search(lastToolTipMm);
    (void)sink;
    if (mTouched != kNoVertex) {
        volatile float touch = mMesh.restPositionsMm()[mTouched].x + mMesh.restNormals()[mTouched].x;
        (void)touch;
    }
}

VertexId CoherentSlopeRing::findTouched(const glm::vec3& tool) const { return search(tool); }

TickResult CoherentSlopeRing::step(const glm::vec3& tool, double dtS) {
    prepareTick(dtS);
    const bool toolValid = isFinite(tool);
    VertexId touched = mTouched;
    if (toolValid) {
        const VertexId found = search(tool);
        if (found != kNoVertex) touched = found;
    }
    const float compliance = mCompliance.empty() || touched == kNoVertex ? 1.0f : mCompliance[touched];
    const float penetration = updateContact(tool, toolValid, touched, compliance);
    stepRings(touched, mContact);
    // The touched vertex's spring reaction: its active position may be unwritten, but its
    // displacement is known exactly: (m1 F) n.
    return tickResult(touched, penetration, ringDisplacementMm(0, mContactForceN, mActiveNormal));
}

void CoherentSlopeRing::writeActivePositions() const {
    if (!mActiveDirty) return;
    for (int r = 0; r <= mActive.ringCount; ++r) {
        const glm::vec3 displacement = ringDisplacementMm(r, mActiveForceN, mActiveNormal);
        for (std::uint32_t i = mActive.ringStart[r], end = mActive.ringStart[r + 1]; i < end; ++i)
            mPositions[mActive.vertices[i]] = glm::vec3(mActiveRestX[i], mActiveRestY[i], mActiveRestZ[i]) +
                                              displacement;
    }
    mActiveDirty = false;
}

void CoherentSlopeRing::changeActiveSet(VertexId touched, bool contact) {
    // The old active set is written where it stands (at the force it was last displaced by), then
    // those of its vertices that leave start relaxing from there.
    writeActivePositions();
    if (++mActiveGeneration == 0) {
        std::fill(mActiveStamp.begin(), mActiveStamp.end(), 0u);
        mActiveGeneration = 1;
    }
    if (contact) {
        mRingFinder.find(touched, mHot.ringCount, mNextActive);
        const auto& rest = mMesh.restPositionsMm();
        for (std::size_t i = 0, n = mNextActive.size(); i < n; ++i) {
            const VertexId v = mNextActive.vertices[i];
            mActiveStamp[v] = mActiveGeneration;
            // Its velocity is not read while it is active, and is zeroed when it leaves (below).
            removeRelaxing(v);
            mActiveRestX[i] = rest[v].x;
            mActiveRestY[i] = rest[v].y;
            mActiveRestZ[i] = rest[v].z;
        }
    } else {
        mNextActive.ringCount = 0;
        mNextActive.ringStart[1] = 0;
    }
    if (mActiveCentre != kNoVertex && mActiveContact)
        for (std::size_t i = 0, n = mActive.size(); i < n; ++i) {
            const VertexId v = mActive.vertices[i];
            if (mActiveStamp[v] != mActiveGeneration) {
                mVelocitiesMmPerS[v] = glm::vec3(0.0f);
                addRelaxing(v);
            }
        }
    std::swap(mActive, mNextActive);
    mActiveScan.valid = false;
    mActiveCentre = touched;
    mActiveContact = contact;
    mActiveNormal = touched != kNoVertex ? mMesh.restNormals()[touched] : glm::vec3(0.0f);
}

void CoherentSlopeRing::stepRings(VertexId touched, bool contact) {
    // Work only where something changed: the active set is rebuilt when the touched vertex or the
    // contact changes; its positions are a function of the force, written when read (or every
    // tick with eagerPositions); only the relaxing vertices are integrated.
    if (touched != mActiveCentre || contact != mActiveContact) changeActiveSet(touched, contact);
    // The rings follow c F (c: the touched vertex's compliance factor); the rendered force stays
    // k_s |m1| F, the touched spring being stiffer by 1 / c.
    mActiveForceN = mCompliance.empty() || touched == kNoVertex ? mContactForceN
                                                                : mCompliance[touched] * mContactForceN;
    mActiveDirty = contact;
    if (mEagerPositions) writeActivePositions();

    const auto& rest = mMesh.restPositionsMm();
    const float restEps2 = kRestEpsilonMm * kRestEpsilonMm;
    for (std::size_t i = 0; i < mRelaxingCount;) {
        const VertexId v = mRelaxing[i];
        relaxVertex(v);
        const glm::vec3 step = mRelaxDt * mVelocitiesMmPerS[v];
        if (dist2(mPositions[v], rest[v]) < restEps2 && glm::dot(step, step) < restEps2) {
            mPositions[v] = rest[v];
            mVelocitiesMmPerS[v] = glm::vec3(0.0f);
            removeRelaxing(v);  // moves the last one into slot i
            continue;
        }
        ++i;
    }
}

}  // namespace palpate
