#include "widgets/RenderScene.h"

#include "widgets/SceneStyle.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace palpate {

void coalesceVertexRanges(std::vector<VertexId>& ids, std::uint32_t maxGap, std::vector<VertexRange>& ranges) {
    ranges.clear();
    std::sort(ids.begin(), ids.end());
    for (const VertexId v : ids) {
        if (!ranges.empty()) {
            VertexRange& last = ranges.back();
            const std::uint64_t end = std::uint64_t(last.first) + last.count;  // one past the last id
            if (v < end) continue;  // a duplicate
            if (v - end <= maxGap) {
                last.count = v - last.first + 1;
                continue;
            }
        }
        ranges.push_back({v, 1});
    }
}

void RenderScene::setMesh(const TissueMesh& mesh) {
    mIndices.clear();
    mIndices.reserve(3 * mesh.triangleCount());
    for (const auto& t : mesh.triangles()) mIndices.insert(mIndices.end(), t.begin(), t.end());
    mRestMm = mesh.restPositionsMm();
    mPositionsMm = mRestMm;
    const std::size_t n = mRestMm.size();
    mPressedWeights.assign(n, 0.0f);
    mRings.assign(n, kNoRing);
    mRingCounts.fill(0);
    mRingCounts[kNoRing] = std::uint32_t(n);

    // Triangles around each vertex by a counting sort: each vertex lists its triangles in
    // increasing order, which keeps updateVertexNormals' sums in computeVertexNormals' order.
    mVertexTriangleStart.assign(n + 1, 0);
    for (const std::uint32_t v : mIndices) ++mVertexTriangleStart[v + 1];
    for (std::size_t v = 0; v < n; ++v) mVertexTriangleStart[v + 1] += mVertexTriangleStart[v];
    mVertexTriangles.resize(mIndices.size());
    std::vector<std::uint32_t> fill(mVertexTriangleStart.begin(), mVertexTriangleStart.end() - 1);
    for (std::size_t i = 0; i < mIndices.size(); ++i) {
        const std::uint32_t v = mIndices[i];
        const std::uint32_t t = std::uint32_t(i / 3);
        // A degenerate triangle naming a vertex twice is listed once.
        if (fill[v] > mVertexTriangleStart[v] && mVertexTriangles[fill[v] - 1] == t) continue;
        mVertexTriangles[fill[v]++] = t;
    }
    // Close the gaps left by degenerate triangles (none in a validated mesh).
    std::uint32_t out = 0;
    for (std::size_t v = 0; v < n; ++v) {
        const std::uint32_t begin = mVertexTriangleStart[v], end = fill[v];
        mVertexTriangleStart[v] = out;
        for (std::uint32_t i = begin; i < end; ++i) mVertexTriangles[out++] = mVertexTriangles[i];
    }
    mVertexTriangleStart[n] = out;
    mVertexTriangles.resize(out);

    mBoundsMinMm = mesh.boundsMinMm();
    mBoundsMaxMm = mesh.boundsMaxMm();
    mOutwardWinding = computeOutwardWinding();
    mVersion = 0;
    mDirty.clear();
    mDirtyStamp.assign(n, 0);
    mDirtyGeneration = 1;
    mNormalStamp.assign(n, 0);
    mNormalGeneration = 0;
    markAllDirty();
    mTouched = kNoVertex;
    mContact = false;
    mHasTool = false;
    mToolTipMm = glm::vec3(0.0f);
    mForceN = glm::vec3(0.0f);
}

void RenderScene::clear() { *this = RenderScene(); }

int RenderScene::computeOutwardWinding() const {
    if (mIndices.empty()) return 0;
    for (std::size_t t = 0; 3 * t + 2 < mIndices.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = mIndices[3 * t + std::size_t(k)], b = mIndices[3 * t + std::size_t((k + 1) % 3)];
            // Exactly one other triangle has this edge, and it runs b -> a.
            int reversed = 0, others = 0;
            for (const std::uint32_t u : vertexTriangles(a)) {
                if (u == t) continue;
                const std::uint32_t* c = &mIndices[3 * u];
                for (int j = 0; j < 3; ++j) {
                    if (c[j] != b) continue;
                    ++others;
                    if (c[(j + 1) % 3] == a) ++reversed;
                }
            }
            if (others != 1 || reversed != 1) return 0;
        }
    }
    double volume = 0.0;  // six times the enclosed volume, by the divergence theorem
    for (std::size_t t = 0; 3 * t + 2 < mIndices.size(); ++t) {
        const glm::dvec3 a(mRestMm[mIndices[3 * t]]), b(mRestMm[mIndices[3 * t + 1]]), c(mRestMm[mIndices[3 * t + 2]]);
        volume += glm::dot(a, glm::cross(b, c));
    }
    return volume > 0.0 ? 1 : volume < 0.0 ? -1 : 0;
}

bool RenderScene::outside(const glm::vec3& eyeMm) const {
    // The tissue may bulge past its rest bounds; a margin of a tenth of the diagonal covers it.
    const glm::vec3 margin(0.1f * diagonalMm());
    const glm::vec3 lo = mBoundsMinMm - margin, hi = mBoundsMaxMm + margin;
    return eyeMm.x < lo.x || eyeMm.y < lo.y || eyeMm.z < lo.z || eyeMm.x > hi.x || eyeMm.y > hi.y || eyeMm.z > hi.z;
}

void RenderScene::markDirty(VertexId v) {
    if (mAllDirty || mDirtyStamp[v] == mDirtyGeneration) return;
    mDirtyStamp[v] = mDirtyGeneration;
    mDirty.push_back(v);
    // Past a quarter of the mesh a whole upload is as cheap as the bookkeeping.
    if (mDirty.size() > mRestMm.size() / 4) markAllDirty();
}

void RenderScene::markAllDirty() {
    mAllDirty = true;
    mDirty.clear();
}

void RenderScene::clearDirty() {
    mAllDirty = false;
    mDirty.clear();
    if (++mDirtyGeneration == 0) {  // wrapped: old stamps could alias
        std::fill(mDirtyStamp.begin(), mDirtyStamp.end(), 0u);
        mDirtyGeneration = 1;
    }
}

void RenderScene::setRing(VertexId v, std::uint8_t ring) {
    --mRingCounts[mRings[v]];
    ++mRingCounts[ring];
    mRings[v] = ring;
}

void RenderScene::setSnapshot(const SceneSnapshot& snapshot) {
    const std::size_t n = mRestMm.size();
    if (n > 0 && snapshot.positionsMm.size() == n) {
        const bool haveRings = snapshot.rings.size() == n;
        auto take = [&](VertexId v) {
            const glm::vec3& p = snapshot.positionsMm[v];
            if (p != mPositionsMm[v]) {
                mPositionsMm[v] = p;
                const float displacementMm = glm::length(p - mRestMm[v]);
                mPressedWeights[v] = std::min(displacementMm / style::kFullTintDisplacementMm, 1.0f);
                markDirty(v);
            }
            const std::uint8_t ring = haveRings ? snapshot.rings[v] : kNoRing;
            if (ring != mRings[v]) {
                setRing(v, ring);
                markDirty(v);
            }
        };
        if (mVersion != 0 && snapshot.version == mVersion) {
            // The state we have already.
        } else if (mVersion != 0 && snapshot.version == mVersion + 1) {
            for (const VertexId v : snapshot.changed)
                if (v < n) take(v);
        } else {
            // Read whole, but still only what differs is marked: the upload stays small.
            for (VertexId v = 0; v < n; ++v) take(v);
        }
        mVersion = snapshot.version;
    }
    mTouched = snapshot.touched < n ? snapshot.touched : kNoVertex;
    mContact = snapshot.contact && mTouched != kNoVertex;
    mHasTool = snapshot.hasTool;
    mToolTipMm = snapshot.toolTipMm;
    mToolRadiusMm = snapshot.toolRadiusMm;
    mProxyMm = snapshot.toolRadiusMm > 0.0f ? snapshot.proxyMm : snapshot.toolTipMm;
    mForceN = snapshot.forceN;
}

std::uint8_t RenderScene::triangleRing(std::size_t triangle) const {
    const std::uint32_t* t = &mIndices[3 * triangle];
    return std::min({mRings[t[0]], mRings[t[1]], mRings[t[2]]});
}

int RenderScene::highestRing() const {
    for (int r = int(style::kRingColourCount) - 1; r >= 0; --r)
        if (mRingCounts[std::size_t(r)] > 0) return r;
    return -1;
}

std::span<const std::uint32_t> RenderScene::vertexTriangles(VertexId v) const {
    return std::span<const std::uint32_t>(mVertexTriangles).subspan(mVertexTriangleStart[v],
                                                                   mVertexTriangleStart[v + 1] - mVertexTriangleStart[v]);
}

glm::vec3 RenderScene::vertexNormal(VertexId v) const {
    glm::vec3 sum(0.0f);
    for (const std::uint32_t t : vertexTriangles(v)) {
        const std::uint32_t a = mIndices[3 * t], b = mIndices[3 * t + 1], c = mIndices[3 * t + 2];
        // The cross product's length is twice the area: larger triangles weigh more, for free.
        sum += glm::cross(mPositionsMm[b] - mPositionsMm[a], mPositionsMm[c] - mPositionsMm[a]);
    }
    const float length = glm::length(sum);
    return length > 0.0f ? sum / length : glm::vec3(0.0f, 0.0f, 1.0f);
}

void RenderScene::computeVertexNormals(std::vector<glm::vec3>& normals) const {
    normals.resize(mPositionsMm.size());
    for (VertexId v = 0; v < normals.size(); ++v) normals[v] = vertexNormal(v);
}

void RenderScene::updateVertexNormals(std::vector<glm::vec3>& normals, std::vector<VertexId>& recomputed) {
    recomputed.clear();
    if (normals.size() != mPositionsMm.size()) {  // not computed yet: everything
        computeVertexNormals(normals);
        recomputed.resize(normals.size());
        for (VertexId v = 0; v < recomputed.size(); ++v) recomputed[v] = v;
        return;
    }
    if (++mNormalGeneration == 0) {
        std::fill(mNormalStamp.begin(), mNormalStamp.end(), 0u);
        mNormalGeneration = 1;
    }
    // A moved vertex changes the triangles around it, and so the normal of each of their corners.
    auto add = [&](VertexId w) {
        if (mNormalStamp[w] == mNormalGeneration) return;
        mNormalStamp[w] = mNormalGeneration;
        recomputed.push_back(w);
    };
    for (const VertexId v : mDirty) {
        add(v);  // listed even if it has no triangle: the caller uploads what is listed
        for (const std::uint32_t t : vertexTriangles(v))
            for (int k = 0; k < 3; ++k) add(mIndices[3 * t + k]);
    }
    for (const VertexId w : recomputed) normals[w] = vertexNormal(w);
}

std::optional<VertexId> RenderScene::pick(const glm::vec3& originMm, const glm::vec3& direction) const {
    const glm::vec3 d = glm::normalize(direction);
    float nearestT = std::numeric_limits<float>::infinity();
    std::size_t hitTriangle = 0;
    bool hit = false;
    // Möller-Trumbore, two-sided: open meshes show their inside.
    for (std::size_t t = 0; 3 * t + 2 < mIndices.size(); ++t) {
        const glm::vec3& a = mPositionsMm[mIndices[3 * t]];
        const glm::vec3 e1 = mPositionsMm[mIndices[3 * t + 1]] - a;
        const glm::vec3 e2 = mPositionsMm[mIndices[3 * t + 2]] - a;
        const glm::vec3 p = glm::cross(d, e2);
        const float det = glm::dot(e1, p);
        if (std::abs(det) < 1e-12f) continue;  // parallel to the triangle, or degenerate
        const float inv = 1.0f / det;
        const glm::vec3 s = originMm - a;
        const float u = glm::dot(s, p) * inv;
        if (u < 0.0f || u > 1.0f) continue;
        const glm::vec3 q = glm::cross(s, e1);
        const float v = glm::dot(d, q) * inv;
        if (v < 0.0f || u + v > 1.0f) continue;
        const float tHit = glm::dot(e2, q) * inv;
        if (tHit > 0.0f && tHit < nearestT) {
            nearestT = tHit;
            hitTriangle = t;
            hit = true;
        }
    }
    if (!hit) return std::nullopt;
    const glm::vec3 hitMm = originMm + nearestT * d;
    VertexId best = mIndices[3 * hitTriangle];
    float bestDistance = std::numeric_limits<float>::infinity();
    for (int k = 0; k < 3; ++k) {
        const VertexId v = mIndices[3 * hitTriangle + k];
        const float distance = glm::length(mPositionsMm[v] - hitMm);
        if (distance < bestDistance) {
            bestDistance = distance;
            best = v;
        }
    }
    return best;
}

float RenderScene::diagonalMm() const { return glm::length(mBoundsMaxMm - mBoundsMinMm); }

}  // namespace palpate
