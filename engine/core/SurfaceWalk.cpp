#include "engine/core/SurfaceWalk.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace palpate {

namespace {
inline float dist2(const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 d = a - b;
    return glm::dot(d, d);
}
}  // namespace

SurfaceWalk::SurfaceWalk(const TissueMesh& mesh) : mMesh(mesh) {
    const auto& triangles = mesh.triangles();
    const std::size_t n = mesh.vertexCount();
    mAcross.assign(3 * triangles.size(), kNoTriangle);
    // Edge (i, j), i < j -> the first triangle seen with it and its corner opposite the edge. A
    // non-manifold edge (three or more triangles) keeps the first pair.
    std::unordered_map<std::uint64_t, std::pair<TriangleId, int>> open;
    open.reserve(triangles.size() * 2);
    for (TriangleId t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const VertexId a = triangles[t][(k + 1) % 3], b = triangles[t][(k + 2) % 3];
            const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
            const auto [it, inserted] = open.try_emplace(key, t, k);
            if (inserted) continue;
            const auto [other, otherK] = it->second;
            if (mAcross[3 * std::size_t(other) + std::size_t(otherK)] == kNoTriangle &&
                mAcross[3 * std::size_t(t) + std::size_t(k)] == kNoTriangle) {
                mAcross[3 * std::size_t(other) + std::size_t(otherK)] = t;
                mAcross[3 * std::size_t(t) + std::size_t(k)] = other;
            }
        }
}

TrianglePoint SurfaceWalk::closest(const glm::vec3& p, TriangleId t) const {
    const auto& tri = mMesh.triangles()[t];
    const auto& rest = mMesh.restPositionsMm();
    return closestTrianglePoint(p, rest[tri[0]], rest[tri[1]], rest[tri[2]]);
}

SurfaceHit SurfaceWalk::walk(const glm::vec3& p, TriangleId from, bool* converged) const {
    SurfaceHit here{from, closest(p, from)};
    float here2 = dist2(here.at.pointMm, p);
    for (int step = 0; step < kMaxSteps; ++step) {
        // On the triangle's inside the distance is at a local minimum; on an edge the triangle
        // across it may be closer; at a corner, any triangle around that corner.
        const float* w = here.at.weight;
        const int zeros = (w[0] == 0.0f) + (w[1] == 0.0f) + (w[2] == 0.0f);
        if (zeros == 0) break;
        SurfaceHit best = here;
        float best2 = here2;
        const auto consider = [&](TriangleId t) {
            if (t == kNoTriangle || t == here.triangle) return;
            const TrianglePoint c = closest(p, t);
            const float d2 = dist2(c.pointMm, p);
            if (d2 < best2) {
                best2 = d2;
                best = {t, c};
            }
        };
        if (zeros == 1) {
            for (int k = 0; k < 3; ++k)
                if (w[k] == 0.0f) consider(across(here.triangle, k));
        } else {
            int corner = w[0] != 0.0f ? 0 : w[1] != 0.0f ? 1 : 2;
            const VertexId v = mMesh.triangles()[here.triangle][std::size_t(corner)];
            for (const TriangleId* t = fanBegin(v); t != fanEnd(v); ++t) consider(*t);
        }
        if (best.triangle == here.triangle) {
            if (converged) *converged = true;
            return here;
        }
        here = best;
        here2 = best2;
    }
    // Converged on the inside, or out of steps (then `here` is still the best point seen).
    if (converged) {
        const float* w = here.at.weight;
        *converged = w[0] != 0.0f && w[1] != 0.0f && w[2] != 0.0f;
    }
    return here;
}

namespace {
// Newton's method on P(w) + h N(w) = x over one triangle's plane of weights (w1, w2 free, w0 =
// 1 - w1 - w2), started from the plane's foot. Weights may leave [0, 1]: the caller walks on.
bool shadedWeights(const glm::vec3& x, const glm::vec3* P, const glm::vec3* N, float* w, const float* start) {
    const glm::vec3 e1 = P[1] - P[0], e2 = P[2] - P[0], d1 = N[1] - N[0], d2 = N[2] - N[0];
    const glm::vec3 r = x - P[0];
    float u, v, h;
    if (start) {
        // Warm: last tick's weights on this triangle (the tool moved a few µm), h along N there.
        u = start[1];
        v = start[2];
        const glm::vec3 n = N[0] + u * d1 + v * d2;
        const float nn = glm::dot(n, n);
        if (!(nn > 0.0f)) return false;
        h = glm::dot(r - u * e1 - v * e2, n) / nn;
    } else {
        const glm::vec3 facet = glm::cross(e1, e2);
        const float area2 = glm::dot(facet, facet);
        if (!(area2 > 0.0f)) return false;
        u = glm::dot(glm::cross(r, e2), facet) / area2;  // the foot on the plane
        v = glm::dot(glm::cross(e1, r), facet) / area2;
        const glm::vec3 unit = facet / std::sqrt(area2);
        const glm::vec3 n0 = N[0] + u * d1 + v * d2;
        const float along = glm::dot(n0, unit);
        if (!(std::fabs(along) > 1e-6f)) return false;
        h = glm::dot(r - u * e1 - v * e2, unit) / along;
    }
    for (int iteration = 0; iteration < 8; ++iteration) {
        const glm::vec3 n = N[0] + u * d1 + v * d2;
        const glm::vec3 f = P[0] + u * e1 + v * e2 + h * n - x;
        // Solved to 10 nm: done (a warm start from last tick usually gets here after one step).
        if (iteration > 0 && glm::dot(f, f) < 1e-10f) break;
        const glm::vec3 c0 = e1 + h * d1, c1 = e2 + h * d2;
        const float det = glm::dot(c0, glm::cross(c1, n));
        if (!(std::fabs(det) > 1e-12f)) return false;
        // Cramer's rule for J [du dv dh] = f.
        const float inverse = 1.0f / det;
        const float du = glm::dot(f, glm::cross(c1, n)) * inverse;
        const float dv = glm::dot(c0, glm::cross(f, n)) * inverse;
        const float dh = glm::dot(c0, glm::cross(c1, f)) * inverse;
        u -= du;
        v -= dv;
        h -= dh;
        if (std::fabs(du) + std::fabs(dv) < 1e-6f) break;  // a few nm on a mm triangle; float noise is ~1e-7
    }
    if (!std::isfinite(u) || !std::isfinite(v)) return false;
    w[0] = 1.0f - u - v;
    w[1] = u;
    w[2] = v;
    return true;
}
}  // namespace

SurfaceHit SurfaceWalk::project(const glm::vec3& p, TriangleId from, bool* converged, const float* startWeights) const {
    const auto& rest = mMesh.restPositionsMm();
    const auto& normals = mMesh.restNormals();
    // Weights this far below 0 leave the triangle; closer ones are rounding, clamped.
    constexpr float kOutside = -1e-6f;
    TriangleId t = from, previous = kNoTriangle;
    for (int step = 0; step < kMaxSteps; ++step) {
        const auto& tri = mMesh.triangles()[t];
        const glm::vec3 P[3] = {rest[tri[0]], rest[tri[1]], rest[tri[2]]};
        const glm::vec3 N[3] = {normals[tri[0]], normals[tri[1]], normals[tri[2]]};
        float w[3];
        if (!shadedWeights(p, P, N, w, t == from ? startWeights : nullptr)) break;
        int k = 0;
        for (int i = 1; i < 3; ++i)
            if (w[i] < w[k]) k = i;
        const TriangleId next = w[k] < kOutside ? across(t, k) : t;
        // Inside (or on a boundary it cannot cross, or bouncing back over the edge it came from:
        // the solution is on that edge): clamp to the triangle and renormalise.
        if (next == t || next == kNoTriangle || next == previous) {
            SurfaceHit hit{t, {}};
            float sum = 0.0f;
            // Weights within a hair of 0 (1e-6 of the triangle) are 0: on an edge or at a vertex
            // exactly, where the neighbours' blends agree bit for bit.
            for (int i = 0; i < 3; ++i) sum += (hit.at.weight[i] = w[i] < 1e-6f ? 0.0f : w[i]);
            for (int i = 0; i < 3; ++i) hit.at.weight[i] /= sum;
            hit.at.pointMm = hit.at.weight[0] * P[0] + hit.at.weight[1] * P[1] + hit.at.weight[2] * P[2];
            if (converged) *converged = true;
            return hit;
        }
        previous = t;
        t = next;
    }
    return walk(p, from, converged);
}

SurfaceHit SurfaceWalk::fromVertex(const glm::vec3& p, VertexId v, bool* converged) const {
    TriangleId bestT = kNoTriangle;
    float best2 = 0.0f;
    for (const TriangleId* t = fanBegin(v); t != fanEnd(v); ++t) {
        const float d2 = dist2(closest(p, *t).pointMm, p);
        if (bestT == kNoTriangle || d2 < best2) {
            best2 = d2;
            bestT = *t;
        }
    }
    if (bestT == kNoTriangle) {  // an isolated vertex: no triangle to stand on
        if (converged) *converged = false;
        return {};
    }
    return walk(p, bestT, converged);
}

}  // namespace palpate
