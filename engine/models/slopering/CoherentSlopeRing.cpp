#include "engine/models/slopering/CoherentSlopeRing.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
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
    : SlopeRingModel(mesh, octree, SlopeRingMethod::Coherent), mEagerPositions(eagerPositions), mWalk(mesh) {
    const std::size_t n = mesh.vertexCount();
    mCornerRings = mRingFinder.makeRingSet();
    // Room for the old set and the new one side by side while the set changes (changeActiveSet).
    mActive.resize(2 * n);
    mActiveRestX.resize(2 * n);
    mActiveRestY.resize(2 * n);
    mActiveRestZ.resize(2 * n);
    mActiveRing.resize(6 * n);
    mActiveSlope.resize(6 * n);
    mActiveNearestRing.resize(2 * n);
    mActiveStamp.assign(n, 0);
    mActiveIndex.assign(n, 0);
    mRelaxing.resize(n);
    mRelaxingSlot.assign(n, kNoSlot);
    mDisplacedScratch.reserve(n);
    setParams(params);
}

void CoherentSlopeRing::paramsReplaced(bool /*ringsChanged*/) {
    for (int r = 0; r < 16; ++r)
        mSlopeByRing[r] = r <= mHot.ringCount ? -mHot.signedSlope[r] : 0.0f;
    releaseActiveSet();
    setContact(mContactDef);  // the friction's stiffness is the rendered one
}

void CoherentSlopeRing::setContact(const ContactDef& contact) {
    mContactDef = contact;
    mToolRadiusMm = float(contact.toolRadiusMm);
    mFriction.setCoefficients(float(contact.staticFriction), float(contact.dynamicFriction),
                              float(mParams.renderedStiffnessNPerMm()));
}

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
    mEngageOffsetMm.clear();
    releaseActiveSet();
}

void CoherentSlopeRing::setLumps(std::vector<float> factors, const std::vector<float>& engageDepthMm) {
    if (engageDepthMm.size() != factors.size())
        throw std::invalid_argument("lumps: " + std::to_string(engageDepthMm.size()) + " engagement depths for " +
                                    std::to_string(factors.size()) + " compliance factors");
    for (std::size_t v = 0; v < engageDepthMm.size(); ++v)
        if (!(engageDepthMm[v] >= 0.0f && engageDepthMm[v] < 1e6f))
            throw std::invalid_argument("lumps: engagement depth[" + std::to_string(v) + "]: " +
                                        std::to_string(engageDepthMm[v]) + " mm is not a depth");
    setCompliance(std::move(factors));
    if (mCompliance.empty()) return;
    // b = (1 - c) z: the sink's stiff line, c |m1| F + b, meets the soft one, |m1| F, at depth z.
    mEngageOffsetMm.resize(mCompliance.size());
    for (std::size_t v = 0; v < mCompliance.size(); ++v) mEngageOffsetMm[v] = (1.0f - mCompliance[v]) * engageDepthMm[v];
}

void CoherentSlopeRing::releaseActiveSet() {
    // New slopes or rings: the active set is rebuilt on the next tick; its vertices relax from
    // where they are until then.
    if (mActiveTriangle == kNoTriangle) return;
    writeActivePositions();
    if (mActiveContact)
        for (std::uint32_t i = 0; i < mActiveCount; ++i) {
            mVelocitiesMmPerS[mActive[i]] = glm::vec3(0.0f);
            addRelaxing(mActive[i]);
        }
    mActiveCount = 0;
    ++mActiveGeneration;
    mActiveTriangle = kNoTriangle;
    mActiveContact = false;
}

glm::vec3 CoherentSlopeRing::activeDisplacementMm(std::uint32_t i) const {
    const float* slope = &mActiveSlope[3 * std::size_t(i)];
    const float blended = mFieldWeight[0] * slope[0] + mFieldWeight[1] * slope[1] + mFieldWeight[2] * slope[2];
    return (-blended * mFieldForceN) * mFieldNormal;
}

std::size_t CoherentSlopeRing::copyDisplaced(VertexId* ids, glm::vec3* positionsMm, std::uint8_t* rings,
                                             std::size_t capacity) const {
    DisplacedOutput out{ids, positionsMm, rings, capacity};
    if (mActiveTriangle != kNoTriangle && mActiveContact)
        for (std::uint32_t i = 0; i < mActiveCount; ++i) {
            // The ring of the touched corner (the largest weight), as the paper's methods report
            // it; a vertex only in another corner's rings gets its nearest ring from any corner.
            const std::uint8_t touchedRing = mActiveRing[3 * std::size_t(i) + std::size_t(mFieldTouchedCorner)];
            const std::uint8_t nearest = touchedRing != kBeyondRings ? touchedRing : mActiveNearestRing[i];
            out.put(mActive[i],
                    glm::vec3(mActiveRestX[i], mActiveRestY[i], mActiveRestZ[i]) + activeDisplacementMm(i), nearest);
        }
    for (std::size_t i = 0; i < mRelaxingCount; ++i) out.put(mRelaxing[i], mPositions[mRelaxing[i]], kRelaxingRing);
    return out.count;
}

void CoherentSlopeRing::reset() {
    resetShared();
    for (std::size_t i = 0; i < mRelaxingCount; ++i) mRelaxingSlot[mRelaxing[i]] = kNoSlot;
    mRelaxingCount = 0;
    mActiveTriangle = kNoTriangle;
    mActiveContact = false;
    mActiveDirty = false;
    mActiveCount = 0;
    ++mActiveGeneration;
    mFieldForceN = 0.0f;
    mContactPoint = {};
    mContactNormal = glm::vec3(0.0f);
    mLastClearanceMm = std::numeric_limits<float>::infinity();
    mFriction.release(glm::vec3(0.0f));
    mCache.clear();
}

std::span<const glm::vec3> CoherentSlopeRing::positionsMm() const {
    writeActivePositions();
    return mPositions;
}

void CoherentSlopeRing::copyPositionsMm(std::span<const VertexId> ids, glm::vec3* out) const {
    const bool active = mActiveTriangle != kNoTriangle && mActiveContact && mActiveDirty;
    for (std::size_t k = 0; k < ids.size(); ++k) {
        const VertexId v = ids[k];
        if (active && mActiveStamp[v] == mActiveGeneration) {
            const std::uint32_t i = mActiveIndex[v];
            out[k] = glm::vec3(mActiveRestX[i], mActiveRestY[i], mActiveRestZ[i]) + activeDisplacementMm(i);
        } else {
            out[k] = mPositions[v];
        }
    }
}

std::span<const VertexId> CoherentSlopeRing::displacedVertices() const {
    mDisplacedScratch.clear();
    if (mActiveTriangle != kNoTriangle && mActiveContact)
        mDisplacedScratch.insert(mDisplacedScratch.end(), mActive.begin(),
                                 mActive.begin() + std::ptrdiff_t(mActiveCount));
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

VertexId CoherentSlopeRing::nearestRestVertex(const glm::vec3& tool) const {
    VertexId best = kNoVertex;
    float best2 = std::numeric_limits<float>::infinity();
    const auto nothingDisplaced = [](VertexId) { return false; };
    if (mCache.certifyNearest(mOctree, tool, best, best2, nothingDisplaced)) return best;
    return mOctree.nearestExact(tool, mMesh.restPositionsMm(), {}, best);
}

SurfaceHit CoherentSlopeRing::findContactPoint(const glm::vec3& tool, bool walkFromLast) const {
    // In contact the proxy walks from where it stood (it moves over the surface, never through
    // it); otherwise the surface is found afresh from the nearest rest vertex.
    // The contact point is the shaded projection (SurfaceWalk::project), which moves smoothly
    // with the tool where the closest point of the facets would rest on a vertex.
    if (walkFromLast && mContactPoint.triangle != kNoTriangle) {
        bool converged = false;
        const SurfaceHit p = mWalk.project(tool, mContactPoint.triangle, &converged, mContactPoint.at.weight);
        if (converged) return p;
    }
    const VertexId v = nearestRestVertex(tool);
    if (v == kNoVertex) return {};
    const SurfaceHit closest = mWalk.fromVertex(tool, v);
    if (closest.triangle == kNoTriangle) return closest;
    bool converged = false;
    const SurfaceHit p = mWalk.project(tool, closest.triangle, &converged);
    return converged ? p : closest;
}

bool CoherentSlopeRing::walksFromLast(const glm::vec3& tool) const {
    // In contact the proxy walks. Out of contact too while the tool hovers near the surface and
    // moves a little per tick (the projection is then the same local solution, found in a step);
    // after a jump, or far from the surface, the surface is found afresh.
    if (mContactPoint.triangle == kNoTriangle) return false;
    if (mContact) return true;
    const glm::vec3 moved = tool - mLastToolMm;
    return glm::dot(moved, moved) < kHoverWalkStepMm * kHoverWalkStepMm && mLastClearanceMm < kHoverWalkClearanceMm;
}

float CoherentSlopeRing::blendedCompliance(TriangleId t, const float* w) const {
    if (mCompliance.empty()) return 1.0f;
    const auto& tri = mMesh.triangles()[t];
    // As differences from corner 0, so that equal factors blend to exactly that factor (all ones:
    // bit for bit the model without an inclusion).
    const float c0 = mCompliance[tri[0]];
    return c0 + w[1] * (mCompliance[tri[1]] - c0) + w[2] * (mCompliance[tri[2]] - c0);
}

float CoherentSlopeRing::blendedOffsetMm(TriangleId t, const float* w) const {
    if (mEngageOffsetMm.empty()) return 0.0f;
    const auto& tri = mMesh.triangles()[t];
    const float b0 = mEngageOffsetMm[tri[0]];
    return b0 + w[1] * (mEngageOffsetMm[tri[1]] - b0) + w[2] * (mEngageOffsetMm[tri[2]] - b0);
}

void CoherentSlopeRing::warm(const glm::vec3& lastToolMm) const {
    if (!isFinite(lastToolMm)) return;
    volatile float sink = findContactPoint(lastToolMm, walksFromLast(lastToolMm)).at.pointMm.x;
    if (mActiveCount > 0) sink = sink + mActiveRestX[0] + mActiveRestX[mActiveCount - 1];
    (void)sink;
}

VertexId CoherentSlopeRing::findTouched(const glm::vec3& tool) const {
    if (!isFinite(tool)) return kNoVertex;
    const SurfaceHit p = findContactPoint(tool, walksFromLast(tool));
    if (p.triangle == kNoTriangle) return kNoVertex;
    const float* w = p.at.weight;
    const int k = largestWeightCorner(w);
    return mMesh.triangles()[p.triangle][std::size_t(k)];
}

TickResult CoherentSlopeRing::step(const glm::vec3& tool, double dtS) {
    prepareTick(dtS);
    const bool toolValid = isFinite(tool);
    SurfaceHit contact = mContactPoint;
    if (toolValid) {
        const SurfaceHit found = findContactPoint(tool, walksFromLast(tool));
        if (found.triangle != kNoTriangle) contact = found;
    }
    const bool touching = toolValid && contact.triangle != kNoTriangle;
    float depth = 0.0f, compliance = 1.0f, offsetMm = 0.0f;
    glm::vec3 normal = mContactNormal;
    VertexId touched = mTouched;
    if (touching) {
        // The shaded normal (Morgenbesser and Srinivasan): the corners' rest normals blended with
        // the contact's weights; the depth of the sphere's lowest point below the rest surface.
        const auto& tri = mMesh.triangles()[contact.triangle];
        const auto& normals = mMesh.restNormals();
        const float* w = contact.at.weight;
        const glm::vec3 blended = w[0] * normals[tri[0]] + w[1] * normals[tri[1]] + w[2] * normals[tri[2]];
        const float length = glm::length(blended);
        if (length > 0.0f) normal = blended / length;
        const float clearance = glm::dot(tool - contact.at.pointMm, normal);
        depth = mToolRadiusMm - clearance;
        mLastClearanceMm = clearance - mToolRadiusMm;
        compliance = blendedCompliance(contact.triangle, w);
        offsetMm = blendedOffsetMm(contact.triangle, w);
        const int k = largestWeightCorner(w);
        touched = tri[std::size_t(k)];
    }
    const float penetration = updateContactForce(depth, touching, compliance, offsetMm);
    mTouched = touched;
    mContactPoint = contact;
    mContactNormal = normal;
    if (toolValid) mLastToolMm = tool;
    stepRings(contact, mContact);

    TickResult result;
    result.touched = touched;
    result.contact = mContact;
    result.penetrationMm = penetration;
    // The contact point moves by |m1| c F (c: the blended compliance) along the normal; the force
    // rendered is its spring's reaction, k_s |m1| F, the touched spring being stiffer by 1 / c.
    const float normalForceN = mHot.springStiffness * (-mHot.signedSlope[0]) * mContactForceN;
    const glm::vec3 friction = mFriction.step(contact.at.pointMm, normal, mContact ? normalForceN : 0.0f);
    if (mContact) {
        result.forceN = normalForceN * normal + friction;
        result.normal = normal;
        const float sink = offsetMm > 0.0f ? sinkMm(mContactForceN, compliance, offsetMm)
                                           : -mHot.signedSlope[0] * compliance * stiffenedForceN(mHot, mContactForceN);
        result.proxyMm = mFriction.stickMm() + (mToolRadiusMm - sink) * normal;
    } else if (touching) {
        result.proxyMm = tool;
    }
    return result;
}

void CoherentSlopeRing::writeActivePositions() const {
    if (!mActiveDirty) return;
    for (std::uint32_t i = 0; i < mActiveCount; ++i)
        mPositions[mActive[i]] = glm::vec3(mActiveRestX[i], mActiveRestY[i], mActiveRestZ[i]) + activeDisplacementMm(i);
    mActiveDirty = false;
}

void CoherentSlopeRing::changeActiveSet(TriangleId triangle, bool contact) {
    // The old set is written where it stands, then those of its vertices that leave start relaxing
    // from there.
    writeActivePositions();
    const std::uint32_t oldCount = mActiveCount;
    const bool oldContact = mActiveTriangle != kNoTriangle && mActiveContact;
    if (++mActiveGeneration == 0) {
        std::fill(mActiveStamp.begin(), mActiveStamp.end(), 0u);
        mActiveGeneration = 1;
    }
    // The new set goes after the old one's entries while those are still read (in place would
    // overwrite them), then moves to the front.
    std::uint32_t count = 0;
    std::vector<VertexId>& list = mActive;
    const std::uint32_t base = oldContact ? oldCount : 0;
    if (contact) {
        const auto& tri = mMesh.triangles()[triangle];
        const auto& rest = mMesh.restPositionsMm();
        for (int k = 0; k < 3; ++k) {
            mRingFinder.find(tri[std::size_t(k)], mHot.ringCount, mCornerRings);
            for (int r = 0; r <= mCornerRings.ringCount; ++r)
                for (VertexId v : mCornerRings.ring(r)) {
                    if (mActiveStamp[v] != mActiveGeneration) {
                        mActiveStamp[v] = mActiveGeneration;
                        mActiveIndex[v] = count;
                        list[base + count] = v;
                        std::uint8_t* ring = &mActiveRing[3 * std::size_t(base + count)];
                        ring[0] = ring[1] = ring[2] = kBeyondRings;
                        ++count;
                    }
                    mActiveRing[3 * std::size_t(base + mActiveIndex[v]) + std::size_t(k)] = std::uint8_t(r);
                }
        }
        for (std::uint32_t j = 0; j < count; ++j) {
            const VertexId v = list[base + j];
            const std::uint8_t* ring = &mActiveRing[3 * std::size_t(base + j)];
            for (int k = 0; k < 3; ++k) mActiveSlope[3 * std::size_t(base + j) + std::size_t(k)] = mSlopeByRing[ring[k]];
            mActiveNearestRing[base + j] = std::min({ring[0], ring[1], ring[2]});
            removeRelaxing(v);  // its velocity is not read while it is active; zeroed when it leaves
            mActiveRestX[base + j] = rest[v].x;
            mActiveRestY[base + j] = rest[v].y;
            mActiveRestZ[base + j] = rest[v].z;
        }
    }
    if (oldContact)
        for (std::uint32_t i = 0; i < oldCount; ++i) {
            const VertexId v = list[i];
            if (mActiveStamp[v] != mActiveGeneration) {
                mVelocitiesMmPerS[v] = glm::vec3(0.0f);
                addRelaxing(v);
            }
        }
    if (base > 0)
        for (std::uint32_t j = 0; j < count; ++j) {
            list[j] = list[base + j];
            mActiveRestX[j] = mActiveRestX[base + j];
            mActiveRestY[j] = mActiveRestY[base + j];
            mActiveRestZ[j] = mActiveRestZ[base + j];
            for (int k = 0; k < 3; ++k) {
                mActiveRing[3 * std::size_t(j) + std::size_t(k)] = mActiveRing[3 * std::size_t(base + j) + std::size_t(k)];
                mActiveSlope[3 * std::size_t(j) + std::size_t(k)] = mActiveSlope[3 * std::size_t(base + j) + std::size_t(k)];
            }
            mActiveNearestRing[j] = mActiveNearestRing[base + j];
        }
    mActiveCount = count;
    mActiveTriangle = triangle;
    mActiveContact = contact;
}

void CoherentSlopeRing::stepRings(const SurfaceHit& contact, bool inContact) {
    // Work only where something changed: the active set is rebuilt when the contact triangle or
    // the contact changes; its positions are a function of the field (weights, normal, force),
    // written when read (or every tick with eagerPositions); only the relaxing vertices are
    // integrated.
    if (contact.triangle != mActiveTriangle || inContact != mActiveContact)
        changeActiveSet(contact.triangle, inContact);
    if (inContact) {
        // The blend, normalised so that the contact point (the corners' displacements
        // interpolated with the same weights) moves by exactly |m1| c F: corner j is at ring 0 of
        // itself and ring 1 of the others, so it moves by (w_j s0 + (1 - w_j) s1) and the contact
        // point by sum_j w_j (w_j s0 + (1 - w_j) s1) = s1 + (s0 - s1) sum_j w_j^2.
        const float* w = contact.at.weight;
        const float s0 = mSlopeByRing[0], s1 = mSlopeByRing[1];
        // Written as s0 - (s0 - s1)(1 - sum w^2) so that at a vertex (weights 1, 0, 0) the factor
        // is exactly 1: there ours is the paper's model bit for bit.
        const float interpolated = s0 - (s0 - s1) * (1.0f - (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
        const float compliance = blendedCompliance(contact.triangle, w);
        const float offsetMm = blendedOffsetMm(contact.triangle, w);
        for (int k = 0; k < 3; ++k) mFieldWeight[k] = w[k];
        mFieldTouchedCorner = largestWeightCorner(w);
        mFieldNormal = mContactNormal;
        // The force the field follows moves the contact point by the sink: c F, or over a lump
        // under the surface sink(F) / |m1|.
        const float fieldForceN = offsetMm > 0.0f ? sinkMm(mContactForceN, compliance, offsetMm) / s0
                                                  : compliance * stiffenedForceN(mHot, mContactForceN);
        mFieldForceN = fieldForceN * (s0 / interpolated);
    }
    mActiveDirty = inContact;
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
