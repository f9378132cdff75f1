#include "engine/SlopeRingDeformer.h"

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

inline float dist2(const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 d = a - b;
    return d.x * d.x + d.y * d.y + d.z * d.z;
}
}  // namespace

SlopeRingDeformer::SlopeRingDeformer(const TissueMesh& mesh, const Octree& octree, const SlopeRingParams& params,
                                     SlopeRingMethod method)
    : mMesh(mesh),
      mOctree(octree),
      mMethod(method),
      mPositions(mesh.restPositionsMm()),
      mVelocitiesMmPerS(mesh.vertexCount(), glm::vec3(0.0f)),
      mRingFinder(mesh),
      mActive(mRingFinder.makeRingSet()),
      mActiveStamp(mesh.vertexCount(), 0),
      mDisplaced(mesh.vertexCount()),
      mDisplacedSlot(mesh.vertexCount(), kNoSlot) {
    if (method == SlopeRingMethod::Previous || method == SlopeRingMethod::Hybrid)
        mRingOf.assign(mesh.vertexCount(), kNotInRing);
    if (method == SlopeRingMethod::Proposed) mPreviousRingVertices.reserve(mesh.vertexCount());
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
    mActiveCentre = kNoVertex;  // re-derive the active set with the new rings and slopes
    mWrittenForceN = -1.0f;
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
    for (std::size_t i = 0; i < mDisplacedCount; ++i) mDisplacedSlot[mDisplaced[i]] = kNoSlot;
    mDisplacedCount = 0;
    mTouched = kNoVertex;
    mForceN = 0.0f;
    mContact = false;
    mActiveCentre = kNoVertex;
    mActiveContact = false;
    mWrittenForceN = -1.0f;
    mPreviousRingVertices.clear();
}

// Backward Euler on m x'' = -k x - c x' for one vertex: unconditionally stable and dissipative.
void SlopeRingDeformer::relaxVertex(VertexId v) {
    const glm::vec3 rest = mMesh.restPositionsMm()[v];
    const glm::vec3 u = mPositions[v] - rest;
    glm::vec3& vel = mVelocitiesMmPerS[v];
    vel = (vel - (mRelaxDt * mOmega2) * u) * mRelaxDenominatorInv;
    mPositions[v] = rest + (u + mRelaxDt * vel);
}

void SlopeRingDeformer::addDisplaced(VertexId v) {
    if (mDisplacedSlot[v] != kNoSlot) return;
    mDisplacedSlot[v] = std::uint32_t(mDisplacedCount);
    mDisplaced[mDisplacedCount++] = v;
}

VertexId SlopeRingDeformer::searchPalpate(const glm::vec3& tool) const {
    // Greedy walk from last tick's touched vertex (the tool moves little between ticks), then the
    // exact octree search bounded by the walk's distance, which proves or corrects it.
    VertexId best = mTouched;
    if (best != kNoVertex) {
        const auto& start = mMesh.neighbourStart();
        const auto& neighbours = mMesh.neighbours();
        float bestD2 = dist2(mPositions[best], tool);
        for (bool improved = true; improved;) {
            improved = false;
            for (std::uint32_t k = start[best], end = start[best + 1]; k < end; ++k) {
                const VertexId w = neighbours[k];
                const float d2 = dist2(mPositions[w], tool);
                if (d2 < bestD2) {
                    bestD2 = d2;
                    best = w;
                    improved = true;
                }
            }
        }
    }
    return mOctree.nearestExact(tool, mPositions, {mDisplaced.data(), mDisplacedCount}, best);
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

    // Contact and the contact force: F <- (1 - alpha) F + alpha k_c e, e = penetration below the
    // touched vertex's current position along its rest normal (docs/method.md).
    float penetration = 0.0f;
    glm::vec3 normal(0.0f);
    if (toolValid && touched != kNoVertex) {
        normal = mMesh.restNormals()[touched];
        penetration = glm::dot(mPositions[touched] - tool, normal);
    }
    const bool contact = penetration > 0.0f;
    mForceN = contact ? (1.0f - mAlpha) * mForceN + mAlpha * (mContactStiffness * penetration) : 0.0f;
    mTouched = touched;
    mContact = contact;

    switch (mMethod) {
        case SlopeRingMethod::Previous:
        case SlopeRingMethod::Hybrid: stepWholeModel(touched, contact); break;
        case SlopeRingMethod::Proposed: stepProposed(touched, contact); break;
        case SlopeRingMethod::Palpate: stepPalpate(tool, touched, contact); break;
    }

    TickResult result;
    result.touched = touched;
    result.contact = contact;
    result.penetrationMm = penetration;
    if (contact) result.forceN = -mSpringStiffness * (mPositions[touched] - mMesh.restPositionsMm()[touched]);
    return result;
}

void SlopeRingDeformer::stepPalpate(const glm::vec3&, VertexId touched, bool contact) {
    const auto& rest = mMesh.restPositionsMm();
    bool rewrite = false;
    if (touched != mActiveCentre || contact != mActiveContact) {
        // The active set changes: the old one relaxes from where it is; the new one is marked.
        if (++mActiveGeneration == 0) {
            std::fill(mActiveStamp.begin(), mActiveStamp.end(), 0u);
            mActiveGeneration = 1;
        }
        mActiveCentre = touched;
        mActiveContact = contact;
        if (contact) {
            mRingFinder.find(touched, mRingCount, mActive);
            for (std::size_t i = 0, n = mActive.size(); i < n; ++i) {
                const VertexId v = mActive.vertices[i];
                mActiveStamp[v] = mActiveGeneration;
                mVelocitiesMmPerS[v] = glm::vec3(0.0f);
                addDisplaced(v);
            }
        }
        rewrite = true;
    }
    if (contact && (rewrite || mForceN != mWrittenForceN)) {
        const glm::vec3 normal = mMesh.restNormals()[touched];
        for (int r = 0; r <= mRingCount; ++r) {
            const glm::vec3 displacement = (mSignedSlope[r] * mForceN) * normal;
            for (std::uint32_t i = mActive.ringStart[r], end = mActive.ringStart[r + 1]; i < end; ++i) {
                const VertexId v = mActive.vertices[i];
                mPositions[v] = rest[v] + displacement;
            }
        }
        mWrittenForceN = mForceN;
    }
    if (!contact) mWrittenForceN = -1.0f;

    // Relax every displaced vertex outside the active set; those back at rest leave the list.
    const float restEps2 = kRestEpsilonMm * kRestEpsilonMm;
    for (std::size_t i = 0; i < mDisplacedCount;) {
        const VertexId v = mDisplaced[i];
        if (contact && mActiveStamp[v] == mActiveGeneration) {
            ++i;
            continue;
        }
        relaxVertex(v);
        const glm::vec3 step = mRelaxDt * mVelocitiesMmPerS[v];
        if (dist2(mPositions[v], rest[v]) < restEps2 && glm::dot(step, step) < restEps2) {
            mPositions[v] = rest[v];
            mVelocitiesMmPerS[v] = glm::vec3(0.0f);
            mDisplacedSlot[v] = kNoSlot;
            const VertexId last = mDisplaced[--mDisplacedCount];
            if (last != v) {
                mDisplaced[i] = last;
                mDisplacedSlot[last] = std::uint32_t(i);
            }
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
