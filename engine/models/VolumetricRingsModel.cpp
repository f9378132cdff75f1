#include "engine/models/VolumetricRingsModel.h"

#include "engine/models/ModelRegistry.h"
#include "engine/models/OctreeQueries.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace palpate {

namespace {
constexpr std::uint32_t kNoSlot = 0xffffffffu;
// As the surface model: a relaxing node this close to rest and this slow snaps back, mm.
constexpr float kRestEpsilonMm = 1e-4f;
}  // namespace

VolumetricRingsModel::VolumetricRingsModel(const TissueMesh& mesh, const Octree& octree, const TetMesh& tets,
                                           const VolumetricRingsParams& params)
    : mMesh(mesh), mOctree(octree), mParams(params) {
    const auto errors = validateVolumetricRingsParams(params);
    if (!errors.empty()) {
        std::string text = "invalid volumetric-rings parameters:";
        for (const auto& e : errors) text += "\n  " + e.message;
        throw std::invalid_argument(text);
    }
    const std::size_t n = mesh.vertexCount();
    const std::size_t nodes = tets.nodeCount();
    if (nodes < n)
        throw std::invalid_argument("volumetric-rings: the tet mesh has " + std::to_string(nodes) +
                                    " nodes, fewer than the surface's " + std::to_string(n) + " vertices");
    for (std::size_t v = 0; v < n; ++v)
        if (glm::length(tets.nodesMm[v] - glm::dvec3(mesh.restPositionsMm()[v])) > 1e-3)
            throw std::invalid_argument("volumetric-rings: tet node " + std::to_string(v) +
                                        " is not surface vertex " + std::to_string(v) +
                                        " (the tet mesh must start with the surface in the mesh's order)");
    mSurfaceCount = n;

    // Edge graph: the tets' six edges and the surface's edges (so that a surface ring is never
    // missing from the tet graph's), deduplicated, compressed.
    std::vector<std::uint64_t> edges;
    edges.reserve(tets.tetCount() * 6 + mesh.neighbours().size() / 2);
    auto addEdge = [&](std::uint32_t a, std::uint32_t b) {
        if (a == b) return;
        if (a > b) std::swap(a, b);
        edges.push_back((std::uint64_t(a) << 32) | b);
    };
    for (const auto& t : tets.tets) {
        for (TetNodeId id : t)
            if (id >= nodes) throw std::invalid_argument("volumetric-rings: a tet names node " + std::to_string(id) + " of " + std::to_string(nodes));
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) addEdge(t[std::size_t(i)], t[std::size_t(j)]);
    }
    for (std::size_t v = 0; v < n; ++v)
        for (std::uint32_t k = mesh.neighbourStart()[v]; k < mesh.neighbourStart()[v + 1]; ++k)
            if (mesh.neighbours()[k] > v) addEdge(std::uint32_t(v), mesh.neighbours()[k]);
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    mNeighbourStart.assign(nodes + 1, 0);
    for (std::uint64_t e : edges) {
        ++mNeighbourStart[(e >> 32) + 1];
        ++mNeighbourStart[(e & 0xffffffffu) + 1];
    }
    for (std::size_t i = 0; i < nodes; ++i) mNeighbourStart[i + 1] += mNeighbourStart[i];
    mNeighbours.resize(mNeighbourStart[nodes]);
    std::vector<std::uint32_t> fill(mNeighbourStart.begin(), mNeighbourStart.end() - 1);
    for (std::uint64_t e : edges) {
        const auto a = std::uint32_t(e >> 32), b = std::uint32_t(e & 0xffffffffu);
        mNeighbours[fill[a]++] = b;
        mNeighbours[fill[b]++] = a;
    }

    mNodeRest.resize(nodes);
    for (std::size_t i = 0; i < nodes; ++i) mNodeRest[i] = i < n ? mesh.restPositionsMm()[i] : glm::vec3(tets.nodesMm[i]);
    mNodePositions = mNodeRest;
    mNodeVelocities.assign(nodes, glm::vec3(0.0f));
    mActive.resize(nodes);
    mPrevious.resize(nodes);
    mStamp.assign(nodes, 0);
    mRelaxing.resize(nodes);
    mRelaxingSlot.assign(nodes, kNoSlot);
    applyParams();
}

void VolumetricRingsModel::applyParams() {
    mHot = slopeRingConstants(mParams.slopeRing);
}

bool VolumetricRingsModel::applyModelParams(const ModelDef& def) {
    if (def.kind != ModelKind::VolumetricRings) return false;
    mParams = VolumetricRingsParams{def.slopeRing};
    applyParams();
    // New slopes or rings: the active set is rebuilt on the next tick; its nodes relax from where they are.
    if (mActiveCentre != kNoVertex) changeActiveSet(mActiveCentre, false);
    mActiveCentre = kNoVertex;
    return true;
}

void VolumetricRingsModel::reset() {
    std::copy(mNodeRest.begin(), mNodeRest.end(), mNodePositions.begin());
    std::fill(mNodeVelocities.begin(), mNodeVelocities.end(), glm::vec3(0.0f));
    for (std::size_t i = 0; i < mRelaxingCount; ++i) mRelaxingSlot[mRelaxing[i]] = kNoSlot;
    mRelaxingCount = 0;
    mActiveCount = 0;
    mActiveRingCount = 0;
    if (++mGeneration == 0) {
        std::fill(mStamp.begin(), mStamp.end(), 0u);
        mGeneration = 1;
    }
    mActiveCentre = kNoVertex;
    mActiveContact = false;
    mTouched = kNoVertex;
    mForceN = 0.0f;
    mContact = false;
    mMaxSurfaceDisplacementMm = 0.0f;
}

void VolumetricRingsModel::findRings(std::uint32_t centre, int ringCount) {
    // Breadth-first over the tet graph; the generation stamp marks both "visited" and "active".
    if (++mGeneration == 0) {
        std::fill(mStamp.begin(), mStamp.end(), 0u);
        mGeneration = 1;
    }
    std::size_t count = 0;
    mActive[count++] = centre;
    mStamp[centre] = mGeneration;
    mActiveRingStart[0] = 0;
    mActiveRingStart[1] = 1;
    for (int r = 1; r <= ringCount; ++r) {
        for (std::uint32_t i = mActiveRingStart[r - 1]; i < mActiveRingStart[r]; ++i) {
            const std::uint32_t u = mActive[i];
            for (std::uint32_t k = mNeighbourStart[u]; k < mNeighbourStart[u + 1]; ++k) {
                const std::uint32_t w = mNeighbours[k];
                if (mStamp[w] == mGeneration) continue;
                mStamp[w] = mGeneration;
                mActive[count++] = w;
            }
        }
        mActiveRingStart[r + 1] = std::uint32_t(count);
    }
    mActiveRingCount = ringCount;
    mActiveCount = count;
}

void VolumetricRingsModel::addRelaxing(std::uint32_t node) {
    if (mRelaxingSlot[node] != kNoSlot) return;
    mRelaxingSlot[node] = std::uint32_t(mRelaxingCount);
    mRelaxing[mRelaxingCount++] = node;
}

void VolumetricRingsModel::removeRelaxing(std::uint32_t node) {
    const std::uint32_t slot = mRelaxingSlot[node];
    if (slot == kNoSlot) return;
    const std::uint32_t last = mRelaxing[--mRelaxingCount];
    mRelaxing[slot] = last;
    mRelaxingSlot[last] = slot;
    mRelaxingSlot[node] = kNoSlot;
}

void VolumetricRingsModel::changeActiveSet(VertexId touched, bool contact) {
    // The old active nodes stay where they were displaced; those not in the new set start relaxing.
    mPreviousCount = mActiveContact ? mActiveCount : 0;
    std::copy(mActive.begin(), mActive.begin() + std::ptrdiff_t(mPreviousCount), mPrevious.begin());
    if (contact) {
        findRings(touched, mHot.ringCount);
        for (std::size_t i = 0; i < mActiveCount; ++i) {
            mNodeVelocities[mActive[i]] = glm::vec3(0.0f);
            removeRelaxing(mActive[i]);
        }
    } else {
        if (++mGeneration == 0) {
            std::fill(mStamp.begin(), mStamp.end(), 0u);
            mGeneration = 1;
        }
        mActiveCount = 0;
        mActiveRingCount = 0;
    }
    for (std::size_t i = 0; i < mPreviousCount; ++i) {
        const std::uint32_t node = mPrevious[i];
        if (mStamp[node] != mGeneration) {
            mNodeVelocities[node] = glm::vec3(0.0f);
            addRelaxing(node);
        }
    }
    mActiveCentre = touched;
    mActiveContact = contact;
    mActiveNormal = touched != kNoVertex ? mMesh.restNormals()[touched] : glm::vec3(0.0f);
}

TickResult VolumetricRingsModel::step(const glm::vec3& tool, double dtS) {
    const bool toolValid = std::isfinite(tool.x) && std::isfinite(tool.y) && std::isfinite(tool.z);
    const auto& rest = mMesh.restPositionsMm();
    VertexId touched = mTouched;
    if (toolValid) {
        const VertexId found = nearestWithBoundedDisplacement(mOctree, tool, positionsMm(), mMaxSurfaceDisplacementMm, mTouched);
        if (found != kNoVertex) touched = found;
    }
    // The contact force, as the surface model (docs/method.md): e = d - |m1| F below the displaced
    // touched vertex; F <- max(0, (1 - alpha) F + alpha k_c e).
    float penetration = 0.0f;
    if (toolValid && touched != kNoVertex) {
        const float depth = glm::dot(rest[touched] - tool, mMesh.restNormals()[touched]);
        penetration = depth + mHot.signedSlope[0] * mForceN;
        mForceN = std::max(0.0f, (1.0f - mHot.alpha) * mForceN + mHot.alpha * (mHot.contactStiffness * penetration));
    } else {
        mForceN = 0.0f;
    }
    const bool contact = mForceN > 0.0f;
    if (touched != mActiveCentre || contact != mActiveContact) changeActiveSet(touched, contact);

    // Every node of ring r (surface or interior) at rest + m_r F n.
    if (contact)
        for (int r = 0; r <= mActiveRingCount; ++r) {
            const glm::vec3 displacement = (mHot.signedSlope[r] * mForceN) * mActiveNormal;
            for (std::uint32_t i = mActiveRingStart[r]; i < mActiveRingStart[r + 1]; ++i)
                mNodePositions[mActive[i]] = mNodeRest[mActive[i]] + displacement;
        }

    // Nodes that left the rings return by damped springs (backward Euler, as the surface model).
    const float dt = dtS > 0.0 && std::isfinite(dtS) ? float(dtS) : 0.0f;  // else nothing relaxes this tick
    const float denominatorInv = 1.0f / (1.0f + dt * mHot.twoZetaOmega + dt * dt * mHot.omega2);
    float maxRelaxing2 = 0.0f;
    for (std::size_t i = 0; i < mRelaxingCount;) {
        const std::uint32_t node = mRelaxing[i];
        const glm::vec3 u = mNodePositions[node] - mNodeRest[node];
        glm::vec3& vel = mNodeVelocities[node];
        vel = (vel - (dt * mHot.omega2) * u) * denominatorInv;
        const glm::vec3 uNext = u + dt * vel;
        const glm::vec3 stepMm = dt * vel;
        if (glm::dot(uNext, uNext) < kRestEpsilonMm * kRestEpsilonMm && glm::dot(stepMm, stepMm) < kRestEpsilonMm * kRestEpsilonMm) {
            mNodePositions[node] = mNodeRest[node];
            vel = glm::vec3(0.0f);
            removeRelaxing(node);  // moves the last one into slot i
            continue;
        }
        mNodePositions[node] = mNodeRest[node] + uNext;
        if (node < mSurfaceCount) maxRelaxing2 = std::max(maxRelaxing2, glm::dot(uNext, uNext));
        ++i;
    }
    // No surface node is farther from rest than the largest ring displacement (|m1| F: slopes
    // decrease outward) or a relaxing node's: the bound the next search relies on.
    mMaxSurfaceDisplacementMm = std::max(contact ? -mHot.signedSlope[0] * mForceN : 0.0f, std::sqrt(maxRelaxing2));

    mTouched = touched;
    mContact = contact;
    TickResult result;
    result.touched = touched;
    result.contact = contact;
    result.penetrationMm = penetration;
    if (contact) result.forceN = -mHot.springStiffness * (mHot.signedSlope[0] * mForceN) * mActiveNormal;
    return result;
}

std::size_t VolumetricRingsModel::copyDisplaced(VertexId* ids, glm::vec3* positionsMm, std::uint8_t* rings,
                                                std::size_t capacity) const {
    std::size_t count = 0;
    auto put = [&](std::uint32_t node, std::uint8_t ring) {
        if (node >= mSurfaceCount || mNodePositions[node] == mNodeRest[node]) return;
        if (count < capacity) {
            ids[count] = node;
            positionsMm[count] = mNodePositions[node];
            rings[count] = ring;
        }
        ++count;
    };
    if (mActiveContact)
        for (int r = 0; r <= mActiveRingCount; ++r)
            for (std::uint32_t i = mActiveRingStart[r]; i < mActiveRingStart[r + 1]; ++i) put(mActive[i], std::uint8_t(r));
    for (std::size_t i = 0; i < mRelaxingCount; ++i) put(mRelaxing[i], kRelaxingRing);
    return count;
}

}  // namespace palpate
