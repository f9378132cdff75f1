#include "engine/models/slopering/PaperSlopeRing.h"

#include <stdexcept>

namespace palpate {

namespace {
constexpr std::uint8_t kNotInRing = 0xff;
}  // namespace

PaperSlopeRing::PaperSlopeRing(const TissueMesh& mesh, const Octree& octree, const SlopeRingParams& params,
                               SlopeRingMethod method)
    : SlopeRingModel(mesh, octree, method) {
    const std::size_t n = mesh.vertexCount();
    switch (method) {
        case SlopeRingMethod::Previous:
        case SlopeRingMethod::Hybrid: mRingOf.assign(n, kNotInRing); break;
        case SlopeRingMethod::Proposed: mPreviousRingVertices.reserve(n); break;
        case SlopeRingMethod::Coherent:
            throw std::invalid_argument(
                "PaperSlopeRing runs the paper's methods (previous, hybrid, proposed), not coherent");
    }
    setParams(params);
}

void PaperSlopeRing::paramsReplaced(bool ringsChanged) {
    if (ringsChanged || mRingLists.empty()) precomputeRingLists();
}

void PaperSlopeRing::precomputeRingLists() {
    const std::size_t n = mMesh.vertexCount();
    mRingLists.assign(n, {});
    RingSet scratch = mRingFinder.makeRingSet();
    for (VertexId v = 0; v < n; ++v) {
        mRingFinder.find(v, mHot.ringCount, scratch);
        auto& lists = mRingLists[v];
        lists.resize(std::size_t(mHot.ringCount));
        for (int r = 1; r <= mHot.ringCount; ++r) {
            const auto ring = scratch.ring(r);
            lists[std::size_t(r - 1)].assign(ring.begin(), ring.end());
        }
    }
}

void PaperSlopeRing::reset() {
    resetShared();
    mPreviousRingVertices.clear();
}

std::size_t PaperSlopeRing::copyDisplaced(VertexId* ids, glm::vec3* positionsMm, std::uint8_t* rings,
                                          std::size_t capacity) const {
    DisplacedOutput out{ids, positionsMm, rings, capacity};
    auto put = [&out](VertexId v, const glm::vec3& p, std::uint8_t ring) { out.put(v, p, ring); };
    // Ring membership of the current touched vertex's rings.
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
    if (mMethod == SlopeRingMethod::Proposed) {
        for (VertexId v : mPreviousRingVertices)
            if (mPositions[v] != rest[v]) put(v, mPositions[v], ringOf(v));
    } else {
        for (VertexId v = 0; v < mPositions.size(); ++v)
            if (mPositions[v] != rest[v]) put(v, mPositions[v], ringOf(v));
    }
    return out.count;
}

VertexId PaperSlopeRing::findTouched(const glm::vec3& tool) const {
    if (mMethod == SlopeRingMethod::Previous) return nearestLinear(tool, mPositions);
    return mOctree.searchNodeFaithful(tool, mPositions);
}

TickResult PaperSlopeRing::step(const glm::vec3& tool, double dtS) {
    prepareTick(dtS);
    const bool toolValid = isFinite(tool);
    VertexId touched = mTouched;
    if (toolValid) {
        const VertexId found = findTouched(tool);
        if (found != kNoVertex) touched = found;  // the paper's search leaves touchedNode unchanged
    }
    const float penetration = updateContact(tool, toolValid, touched, 1.0f);  // as published: no inclusion
    if (mMethod == SlopeRingMethod::Proposed) stepProposed(touched, mContact);
    else stepWholeModel(touched, mContact);
    return tickResult(touched, penetration,
                      mContact ? mPositions[touched] - mMesh.restPositionsMm()[touched] : glm::vec3(0.0f));
}

void PaperSlopeRing::stepWholeModel(VertexId touched, bool contact) {
    // The paper's "previous" and "hybrid": every vertex of the model is processed every tick.
    const auto& rest = mMesh.restPositionsMm();
    if (contact) {
        mRingOf[touched] = 0;
        const auto& lists = mRingLists[touched];
        for (int r = 1; r <= mHot.ringCount; ++r)
            for (VertexId v : lists[std::size_t(r - 1)]) mRingOf[v] = std::uint8_t(r);
    }
    const glm::vec3 normal = touched != kNoVertex ? mMesh.restNormals()[touched] : glm::vec3(0.0f);
    const std::size_t n = mPositions.size();
    for (std::size_t v = 0; v < n; ++v) {
        const std::uint8_t r = mRingOf[v];
        if (r != kNotInRing) {
            mPositions[v] = rest[v] + ringDisplacementMm(r, mContactForceN, normal);
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

void PaperSlopeRing::stepProposed(VertexId touched, bool contact) {
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
    mPositions[touched] = rest[touched] + ringDisplacementMm(0, mContactForceN, normal);
    mPreviousRingVertices.push_back(touched);
    const auto& lists = mRingLists[touched];
    for (int r = 1; r <= mHot.ringCount; ++r) {
        const glm::vec3 displacement = ringDisplacementMm(r, mContactForceN, normal);
        for (VertexId v : lists[std::size_t(r - 1)]) {
            mPositions[v] = rest[v] + displacement;
            mPreviousRingVertices.push_back(v);
        }
    }
}

}  // namespace palpate
