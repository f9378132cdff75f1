#include "engine/models/slopering/SlopeRingDeformer.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace palpate {

namespace {
constexpr std::uint32_t kNoSlot = 0xffffffffu;
constexpr std::uint8_t kNotInRing = 0xff;
// A relaxing vertex closer than this to rest, and slower than this per tick, snaps back and rests.
constexpr float kRestEpsilonMm = 1e-4f;
// Relative margin on the search's triangle-inequality bounds: float distances are within a few
// ulps (~1e-7) of the true ones, so a bound shrunk by 1e-5 of its terms holds for the computed ones.
constexpr float kRoundingMargin = 1e-5f;

inline float dist2(const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 d = a - b;
    return d.x * d.x + d.y * d.y + d.z * d.z;
}
}  // namespace

SlopeRingDeformer::SlopeRingDeformer(const TissueMesh& mesh, const Octree& octree, const SlopeRingParams& params,
                                     SlopeRingMethod method, bool eagerPositions)
    : mMesh(mesh),
      mOctree(octree),
      mMethod(method),
      mEagerPositions(eagerPositions),
      mPositions(mesh.restPositionsMm()),
      mVelocitiesMmPerS(mesh.vertexCount(), glm::vec3(0.0f)),
      mRingFinder(mesh) {
    const std::size_t n = mesh.vertexCount();
    if (method == SlopeRingMethod::Palpate) {
        mActive = mRingFinder.makeRingSet();
        mNextActive = mRingFinder.makeRingSet();
        mActiveRestX.resize(n);
        mActiveRestY.resize(n);
        mActiveRestZ.resize(n);
        mScratchDistance2.resize(n);
        mActiveStamp.assign(n, 0);
        mRelaxing.resize(n);
        mRelaxingSlot.assign(n, kNoSlot);
        // The full-search fallback lists active and relaxing vertices (disjoint: at most n) in the
        // tick: reserved here so that it never allocates.
        mDisplacedScratch.reserve(n);
    }
    if (method == SlopeRingMethod::Previous || method == SlopeRingMethod::Hybrid) mRingOf.assign(n, kNotInRing);
    if (method == SlopeRingMethod::Proposed) mPreviousRingVertices.reserve(n);
    setParams(params);
}

std::string SlopeRingDeformer::name() const { return "slope-ring/" + std::string(methodName(mMethod)); }

void SlopeRingDeformer::setParams(const SlopeRingParams& params) {
    const auto errors = validateSlopeRingParams(params);
    if (!errors.empty()) {
        std::string text = "invalid slope-ring parameters:";
        for (const auto& e : errors) text += "\n  " + e;
        throw std::invalid_argument(text);
    }
    const bool ringsChanged = params.ringCount != mParams.ringCount || mRingLists.empty();
    mParams = params;
    applyParams();
    if (ringsChanged && mMethod != SlopeRingMethod::Palpate) precomputeRingLists();
    if (mMethod == SlopeRingMethod::Palpate) releaseActiveSet();
}

void SlopeRingDeformer::setCompliance(std::vector<float> factors) {
    if (!factors.empty()) {
        if (mMethod != SlopeRingMethod::Palpate)
            throw std::invalid_argument("compliance factors need the palpate method (the paper's methods stay as published)");
        if (factors.size() != mMesh.vertexCount())
            throw std::invalid_argument("compliance: " + std::to_string(factors.size()) + " factors for " +
                                        std::to_string(mMesh.vertexCount()) + " vertices");
        for (std::size_t v = 0; v < factors.size(); ++v)
            if (!(factors[v] > 0.0f && factors[v] <= 1.0f))  // also refuses NaN
                throw std::invalid_argument("compliance[" + std::to_string(v) + "]: " + std::to_string(factors[v]) +
                                            " is outside (0, 1] (only stiffer inclusions keep the loop-gain bound)");
    }
    mCompliance = std::move(factors);
    if (mMethod == SlopeRingMethod::Palpate) releaseActiveSet();
}

bool SlopeRingDeformer::applySlopeRingParams(const SlopeRingParams& params) {
    if (mMethod != SlopeRingMethod::Palpate && params.ringCount != mParams.ringCount) return false;
    mParams = params;
    applyParams();
    if (mMethod == SlopeRingMethod::Palpate) releaseActiveSet();
    return true;
}

void SlopeRingDeformer::releaseActiveSet() {
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
    mActiveScanValid = false;
    mActiveCentre = kNoVertex;
    mActiveContact = false;
}

std::size_t SlopeRingDeformer::copyDisplaced(VertexId* ids, glm::vec3* positionsMm, std::uint8_t* rings,
                                             std::size_t capacity) const {
    std::size_t count = 0;
    auto put = [&](VertexId v, const glm::vec3& p, std::uint8_t ring) {
        if (count < capacity) {
            ids[count] = v;
            positionsMm[count] = p;
            rings[count] = ring;
        }
        ++count;
    };
    // For the paper's methods, ring membership of the current touched vertex's rings.
    auto ringOf = [&](VertexId v) -> std::uint8_t {
        if (!mContact || mTouched == kNoVertex) return kRelaxingRing;
        if (v == mTouched) return 0;
        const auto& lists = mRingLists[mTouched];
        for (std::size_t r = 0; r < lists.size(); ++r)
            for (VertexId w : lists[r])
                if (w == v) return std::uint8_t(r + 1);
        return kRelaxingRing;
    };
    const auto& rest = mMesh.restPositionsMm();
    switch (mMethod) {
        case SlopeRingMethod::Palpate:
            if (mActiveCentre != kNoVertex && mActiveContact)
                for (int r = 0; r <= mActive.ringCount; ++r) {
                    const glm::vec3 displacement = (mSignedSlope[r] * mActiveForceN) * mActiveNormal;
                    for (std::uint32_t i = mActive.ringStart[r], end = mActive.ringStart[r + 1]; i < end; ++i)
                        put(mActive.vertices[i], glm::vec3(mActiveRestX[i], mActiveRestY[i], mActiveRestZ[i]) + displacement,
                            std::uint8_t(r));
                }
            for (std::size_t i = 0; i < mRelaxingCount; ++i) put(mRelaxing[i], mPositions[mRelaxing[i]], kRelaxingRing);
            break;
        case SlopeRingMethod::Proposed:
            for (VertexId v : mPreviousRingVertices)
                if (mPositions[v] != rest[v]) put(v, mPositions[v], ringOf(v));
            break;
        case SlopeRingMethod::Previous:
        case SlopeRingMethod::Hybrid:
            for (VertexId v = 0; v < mPositions.size(); ++v)
                if (mPositions[v] != rest[v]) put(v, mPositions[v], ringOf(v));
            break;
    }
    return count;
}

void SlopeRingDeformer::applyParams() {
    mRingCount = mParams.ringCount;
    for (int r = 0; r <= kMaxRings; ++r) mSignedSlope[r] = -float(mParams.slopeMagnitudeMmPerN[std::size_t(r)]);
    mAlpha = float(mParams.effectiveRelaxation());
    mContactStiffness = float(mParams.contactStiffnessNPerMm);
    mSpringStiffness = float(mParams.springStiffnessNPerMm);
    // k [N/mm] * 1000 = N/m; omega^2 = k / m.
    const double omega2 = mParams.springStiffnessNPerMm * 1000.0 / mParams.vertexMassKg;
    mOmega2 = float(omega2);
    mTwoZetaOmega = float(2.0 * mParams.dampingRatio * std::sqrt(omega2));
    mRelaxDtS = -1.0;
}

void SlopeRingDeformer::precomputeRingLists() {
    const std::size_t n = mMesh.vertexCount();
    mRingLists.assign(n, {});
    RingSet scratch = mRingFinder.makeRingSet();
    for (VertexId v = 0; v < n; ++v) {
        mRingFinder.find(v, mRingCount, scratch);
        auto& lists = mRingLists[v];
        lists.resize(std::size_t(mRingCount));
        for (int r = 1; r <= mRingCount; ++r) {
            const auto ring = scratch.ring(r);
            lists[std::size_t(r - 1)].assign(ring.begin(), ring.end());
        }
    }
}

void SlopeRingDeformer::reset() {
    mPositions = mMesh.restPositionsMm();
    std::fill(mVelocitiesMmPerS.begin(), mVelocitiesMmPerS.end(), glm::vec3(0.0f));
    for (std::size_t i = 0; i < mRelaxingCount; ++i) mRelaxingSlot[mRelaxing[i]] = kNoSlot;
    mRelaxingCount = 0;
    mTouched = kNoVertex;
    mForceN = 0.0f;
    mContact = false;
    mActiveCentre = kNoVertex;
    mActiveContact = false;
    mActiveDirty = false;
    mActiveForceN = 0.0f;
    mActiveScanValid = false;
    if (mMethod == SlopeRingMethod::Palpate) {
        mActive.ringCount = 0;
        mActive.ringStart[1] = 0;  // empty: no vertex is active
        ++mActiveGeneration;
    }
    mPreviousRingVertices.clear();
    mCacheCount = 0;
    mPreviousToolMm = glm::vec3(0.0f);
}

std::span<const glm::vec3> SlopeRingDeformer::positionsMm() const {
    writeActivePositions();
    return mPositions;
}

std::span<const VertexId> SlopeRingDeformer::displacedVertices() const {
    mDisplacedScratch.clear();
    if (mMethod != SlopeRingMethod::Palpate) return {};
    if (mActiveCentre != kNoVertex && mActiveContact)
        mDisplacedScratch.insert(mDisplacedScratch.end(), mActive.vertices.begin(),
                                 mActive.vertices.begin() + std::ptrdiff_t(mActive.size()));
    mDisplacedScratch.insert(mDisplacedScratch.end(), mRelaxing.begin(),
                             mRelaxing.begin() + std::ptrdiff_t(mRelaxingCount));
    return mDisplacedScratch;
}

// Backward Euler on m x'' = -k x - c x' for one vertex: unconditionally stable and dissipative.
void SlopeRingDeformer::relaxVertex(VertexId v) {
    const glm::vec3 rest = mMesh.restPositionsMm()[v];
    const glm::vec3 u = mPositions[v] - rest;
    glm::vec3& vel = mVelocitiesMmPerS[v];
    vel = (vel - (mRelaxDt * mOmega2) * u) * mRelaxDenominatorInv;
    mPositions[v] = rest + (u + mRelaxDt * vel);
}

void SlopeRingDeformer::addRelaxing(VertexId v) {
    if (mRelaxingSlot[v] != kNoSlot) return;
    mRelaxingSlot[v] = std::uint32_t(mRelaxingCount);
    mRelaxing[mRelaxingCount++] = v;
}

void SlopeRingDeformer::removeRelaxing(VertexId v) {
    const std::uint32_t slot = mRelaxingSlot[v];
    if (slot == kNoSlot) return;
    const VertexId last = mRelaxing[--mRelaxingCount];
    mRelaxing[slot] = last;
    mRelaxingSlot[last] = slot;
    mRelaxingSlot[v] = kNoSlot;
}

void SlopeRingDeformer::refreshCandidateCache(const glm::vec3& tool, const glm::vec3& toolStepMm,
                                              bool offsetCentre) const {
    // Any centre gives a valid bound; this one makes it last (docs/method.md). Beyond the tool,
    // on the line from the nearest cached vertex through it, then ahead along the tool's last step.
    glm::vec3 centre = tool;
    if (offsetCentre && mCacheCount > 0) {
        float nearest2 = std::numeric_limits<float>::infinity();
        glm::vec3 from = tool;
        for (int i = 0; i < mCacheCount; ++i) {
            const float d2 = dist2(mCacheRestMm[i], tool);
            if (d2 < nearest2) {
                nearest2 = d2;
                from = mCacheRestMm[i];
            }
        }
        const glm::vec3 away = tool - from;
        const float distance = std::sqrt(nearest2);
        const glm::vec3 axis = distance > 0.0f ? away / distance : glm::vec3(0.0f);
        const float along = glm::dot(toolStepMm, axis);
        glm::vec3 lead = kLeadTicks * (toolStepMm - along * axis) + (kAxialLeadTicks * along) * axis;
        const float leadMax = 0.5f * distance, leadLength = glm::length(lead);
        if (!std::isfinite(leadLength))
            lead = glm::vec3(0.0f);
        else if (leadLength > leadMax)
            lead *= leadMax / leadLength;
        centre = tool + kCentreOffset * away + lead;
    }
    float d2[kCacheSize];
    mCacheCount = mOctree.nearestRestK(centre, kCacheSize, mCacheIds, d2, mCacheCount, mCacheRestMm);
    for (int i = 0; i < mCacheCount; ++i) mCacheDistanceMm[i] = std::sqrt(d2[i]);
    mCacheRadiusMm = mCacheCount < kCacheSize ? std::numeric_limits<float>::infinity()
                                              : mCacheDistanceMm[kCacheSize - 1];
    mCacheCentreMm = centre;
    ++mCacheRefreshes;
}

void SlopeRingDeformer::searchActive(const glm::vec3& tool, VertexId& best, float& best2) const {
    const float slope1 = -mSignedSlope[0];
    if (mActiveScanValid) {
        // Every active vertex moved relative to the tool by at most |dtool| + |m1| |dF|.
        const float moved = glm::length(tool - mActiveScanToolMm) + slope1 * std::fabs(mActiveForceN - mActiveScanForceN);
        const float margin = mActiveScanSecondMm - moved;
        const std::uint32_t i = mActiveScanBest;
        const glm::vec3 q = tool - (mSignedSlope[mActiveScanBestRing] * mActiveForceN) * mActiveNormal;
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
    float* d2 = mScratchDistance2.data();
    const float* rx = mActiveRestX.data();
    const float* ry = mActiveRestY.data();
    const float* rz = mActiveRestZ.data();
    for (int r = 0; r <= mActive.ringCount; ++r) {
        const glm::vec3 q = tool - (mSignedSlope[r] * mActiveForceN) * mActiveNormal;
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
    mActiveScanValid = true;
    mActiveScanToolMm = tool;
    mActiveScanForceN = mActiveForceN;
    mActiveScanBest = bestIndex;
    mActiveScanBestRing = ring;
    mActiveScanSecondMm = std::sqrt(second);
}

VertexId SlopeRingDeformer::searchPalpate(const glm::vec3& tool) const {
    // Exact nearest vertex over current positions, in three parts: (1) every displaced vertex:
    // the active rings from their rest copy shifted by each ring's displacement (contiguous, so the
    // compiler vectorises it), the relaxing ones directly; (2) the cached rest vertices that could
    // still beat the best so far; (3) a proof that no other vertex at rest can: those are at least
    // mCacheRadiusMm from the cache centre (docs/method.md).
    const glm::vec3 previousTool = mPreviousToolMm;
    mPreviousToolMm = tool;
    VertexId best = kNoVertex;
    float best2 = std::numeric_limits<float>::infinity();
    auto consider = [&](VertexId v, float d2) {
        if (d2 < best2 || (d2 == best2 && v < best)) {
            best2 = d2;
            best = v;
        }
    };
    const bool activeInContact = mActiveCentre != kNoVertex && mActiveContact;
    if (activeInContact) searchActive(tool, best, best2);
    for (std::size_t i = 0; i < mRelaxingCount; ++i) consider(mRelaxing[i], dist2(mPositions[mRelaxing[i]], tool));
    for (int attempt = 0; attempt < 3; ++attempt) {
        // 0: the cache as it is; 1: retaken around a centre beyond the tool (lasts longer);
        // 2: around the tool itself (the tightest bound here). A first cache is centred on the tool.
        if (attempt > 0 || mCacheCount == 0) refreshCandidateCache(tool, tool - previousTool, attempt == 1);
        // Lower bounds by the triangle inequality, shrunk by a relative margin that covers the
        // rounding of the float distances they are computed from.
        const float shift = glm::length(tool - mCacheCentreMm) * (1.0f + kRoundingMargin);
        for (int i = 0; i < mCacheCount; ++i) {
            const float lower = mCacheDistanceMm[i] * (1.0f - kRoundingMargin) - shift;  // |tool - rest| >= this
            if (lower > 0.0f && lower * lower > best2) break;  // sorted: no later entry can win
            const VertexId v = mCacheIds[i];
            if ((activeInContact && mActiveStamp[v] == mActiveGeneration) || mRelaxingSlot[v] != kNoSlot)
                continue;  // counted above at its current position
            consider(v, dist2(mCacheRestMm[i], tool));  // at rest: its position is its rest position
        }
        // Every rest vertex not cached is at least this far from the tool.
        const float clearance = mCacheRadiusMm * (1.0f - kRoundingMargin) - shift;
        if (clearance > 0.0f && best2 < clearance * clearance) return best;
    }
    ++mFullSearches;
    writeActivePositions();
    return mOctree.nearestExact(tool, mPositions, displacedVertices(), best);
}

void SlopeRingDeformer::warm(const glm::vec3& lastToolTipMm) const {
    // Only the cheap searches; the paper's whole-model methods touch everything anyway.
    if (mMethod != SlopeRingMethod::Palpate || !std::isfinite(lastToolTipMm.x)) return;
    volatile VertexId sink = searchPalpate(lastToolTipMm);
    (void)sink;
    if (mTouched != kNoVertex) {
        volatile float touch = mMesh.restPositionsMm()[mTouched].x + mMesh.restNormals()[mTouched].x;
        (void)touch;
    }
}

VertexId SlopeRingDeformer::findTouched(const glm::vec3& tool) const {
    switch (mMethod) {
        case SlopeRingMethod::Previous: return nearestLinear(tool, mPositions);
        case SlopeRingMethod::Hybrid:
        case SlopeRingMethod::Proposed: return mOctree.searchNodeFaithful(tool, mPositions);
        case SlopeRingMethod::Palpate: return searchPalpate(tool);
    }
    return kNoVertex;
}

TickResult SlopeRingDeformer::step(const glm::vec3& tool, double dtS) {
    if (dtS != mRelaxDtS) {
        mRelaxDtS = dtS;
        mRelaxDt = float(dtS);
        mRelaxDenominatorInv = 1.0f / (1.0f + mRelaxDt * mTwoZetaOmega + mRelaxDt * mRelaxDt * mOmega2);
    }
    const bool toolValid = std::isfinite(tool.x) && std::isfinite(tool.y) && std::isfinite(tool.z);

    VertexId touched = mTouched;
    if (toolValid) {
        const VertexId found = findTouched(tool);
        if (found != kNoVertex) touched = found;  // the paper's search leaves touchedNode unchanged
    }

    // Contact and the contact force (docs/method.md): d = depth of the tip below the touched
    // vertex's rest position along its rest normal; the model displaces that vertex by |m1| F, so
    // the tip is e = d - |m1| F below it. F <- max(0, (1 - alpha) F + alpha k_c e); contact while F > 0.
    // A stiffer inclusion scales the touched vertex's slopes by c in (0, 1] (setCompliance): the
    // tip is d - c |m1| F below it, and the exact solve uses the gain c |m1| k_c (c = 1: unchanged).
    const float compliance = mCompliance.empty() || touched == kNoVertex ? 1.0f : mCompliance[touched];
    float penetration = 0.0f;
    if (toolValid && touched != kNoVertex) {
        const float depth = glm::dot(mMesh.restPositionsMm()[touched] - tool, mMesh.restNormals()[touched]);
        penetration = depth + mSignedSlope[0] * (compliance * mForceN);
    }
    const float alpha = compliance == 1.0f || mParams.forceRelaxation > 0.0
                            ? mAlpha
                            : float(1.0 / (1.0 + mParams.loopGain() * double(compliance)));
    // Projected onto F >= 0 (the tissue only pushes): a non-expansive step, so the iteration
    // converges wherever its linear part does, alpha (1 + gain) < 2, overshoot or not.
    if (toolValid && touched != kNoVertex)
        mForceN = std::max(0.0f, (1.0f - alpha) * mForceN + alpha * (mContactStiffness * penetration));
    else
        mForceN = 0.0f;
    const bool contact = mForceN > 0.0f;
    mTouched = touched;
    mContact = contact;

    switch (mMethod) {
        case SlopeRingMethod::Previous:
        case SlopeRingMethod::Hybrid: stepWholeModel(touched, contact); break;
        case SlopeRingMethod::Proposed: stepProposed(touched, contact); break;
        case SlopeRingMethod::Palpate: stepPalpate(touched, contact); break;
    }

    TickResult result;
    result.touched = touched;
    result.contact = contact;
    result.penetrationMm = penetration;
    if (contact) {
        // The touched vertex's spring reaction. Palpate's active positions may be unwritten; its
        // displacement is known exactly: (m1 F) n.
        const glm::vec3 displacement = mMethod == SlopeRingMethod::Palpate
                                           ? (mSignedSlope[0] * mForceN) * mActiveNormal
                                           : mPositions[touched] - mMesh.restPositionsMm()[touched];
        result.forceN = -mSpringStiffness * displacement;
    }
    return result;
}

void SlopeRingDeformer::writeActivePositions() const {
    if (!mActiveDirty) return;
    for (int r = 0; r <= mActive.ringCount; ++r) {
        const glm::vec3 displacement = (mSignedSlope[r] * mActiveForceN) * mActiveNormal;
        for (std::uint32_t i = mActive.ringStart[r], end = mActive.ringStart[r + 1]; i < end; ++i)
            mPositions[mActive.vertices[i]] =
                glm::vec3(mActiveRestX[i], mActiveRestY[i], mActiveRestZ[i]) + displacement;
    }
    mActiveDirty = false;
}

void SlopeRingDeformer::changeActiveSet(VertexId touched, bool contact) {
    // The old active set is written where it stands (at the force it was last displaced by), then
    // those of its vertices that leave start relaxing from there.
    writeActivePositions();
    if (++mActiveGeneration == 0) {
        std::fill(mActiveStamp.begin(), mActiveStamp.end(), 0u);
        mActiveGeneration = 1;
    }
    if (contact) {
        mRingFinder.find(touched, mRingCount, mNextActive);
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
    mActiveScanValid = false;
    mActiveCentre = touched;
    mActiveContact = contact;
    mActiveNormal = touched != kNoVertex ? mMesh.restNormals()[touched] : glm::vec3(0.0f);
}

void SlopeRingDeformer::stepPalpate(VertexId touched, bool contact) {
    // Work only where something changed: the active set is rebuilt when the touched vertex or the
    // contact changes; its positions are a function of the force, written when read (or every
    // tick with eagerPositions); only the relaxing vertices are integrated.
    if (touched != mActiveCentre || contact != mActiveContact) changeActiveSet(touched, contact);
    // The rings follow c F (c: the touched vertex's compliance factor); the rendered force stays
    // k_s |m1| F, the touched spring being stiffer by 1 / c.
    mActiveForceN = mCompliance.empty() || touched == kNoVertex ? mForceN : mCompliance[touched] * mForceN;
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

void SlopeRingDeformer::stepWholeModel(VertexId touched, bool contact) {
    // The paper's "previous" and "hybrid": every vertex of the model is processed every tick.
    const auto& rest = mMesh.restPositionsMm();
    if (contact) {
        mRingOf[touched] = 0;
        const auto& lists = mRingLists[touched];
        for (int r = 1; r <= mRingCount; ++r)
            for (VertexId v : lists[std::size_t(r - 1)]) mRingOf[v] = std::uint8_t(r);
    }
    const glm::vec3 normal = touched != kNoVertex ? mMesh.restNormals()[touched] : glm::vec3(0.0f);
    const std::size_t n = mPositions.size();
    for (std::size_t v = 0; v < n; ++v) {
        const std::uint8_t r = mRingOf[v];
        if (r != kNotInRing) {
            mPositions[v] = rest[v] + (mSignedSlope[r] * mForceN) * normal;
            mVelocitiesMmPerS[v] = glm::vec3(0.0f);
        } else {
            relaxVertex(VertexId(v));
        }
    }
    if (contact) {
        mRingOf[touched] = kNotInRing;
        for (const auto& list : mRingLists[touched])
            for (VertexId v : list) mRingOf[v] = kNotInRing;
    }
}

void SlopeRingDeformer::stepProposed(VertexId touched, bool contact) {
    // The paper's proposed method: restore last tick's rings, displace this tick's rings.
    const auto& rest = mMesh.restPositionsMm();
    if (!contact) {
        for (VertexId v : mPreviousRingVertices) relaxVertex(v);
        return;
    }
    for (VertexId v : mPreviousRingVertices) {
        mPositions[v] = rest[v];
        mVelocitiesMmPerS[v] = glm::vec3(0.0f);
    }
    mPreviousRingVertices.clear();
    const glm::vec3 normal = mMesh.restNormals()[touched];
    mPositions[touched] = rest[touched] + (mSignedSlope[0] * mForceN) * normal;
    mPreviousRingVertices.push_back(touched);
    const auto& lists = mRingLists[touched];
    for (int r = 1; r <= mRingCount; ++r) {
        const glm::vec3 displacement = (mSignedSlope[r] * mForceN) * normal;
        for (VertexId v : lists[std::size_t(r - 1)]) {
            mPositions[v] = rest[v] + displacement;
            mPreviousRingVertices.push_back(v);
        }
    }
}

}  // namespace palpate
