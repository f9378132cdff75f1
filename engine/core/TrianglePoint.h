#pragma once
// The point of a triangle closest to a query point, with its barycentric weights (Ericson,
// Real-Time Collision Detection, 5.1.5), in the float the haptic tick computes in. In an edge or
// corner region the weights of the corners not on that feature are exactly 0, which the surface
// walk (SurfaceWalk) reads to know which neighbours to try. Real-time safe.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace palpate {

struct TrianglePoint {
    glm::vec3 pointMm{0.0f};
    float weight[3] = {1.0f, 0.0f, 0.0f};  ///< of corners a, b, c; sum 1, each >= 0
};

/// The corner with the largest weight (ties: the first).
inline int largestWeightCorner(const float* w) { return w[0] >= w[1] && w[0] >= w[2] ? 0 : w[1] >= w[2] ? 1 : 2; }

inline TrianglePoint closestTrianglePoint(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                                          const glm::vec3& c) {
    const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0f && d2 <= 0.0f) return {a, {1.0f, 0.0f, 0.0f}};
    const glm::vec3 bp = p - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0f && d4 <= d3) return {b, {0.0f, 1.0f, 0.0f}};
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) {
        const float v = d1 / (d1 - d3);
        return {a + v * ab, {1.0f - v, v, 0.0f}};
    }
    const glm::vec3 cp = p - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0f && d5 <= d6) return {c, {0.0f, 0.0f, 1.0f}};
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) {
        const float w = d2 / (d2 - d6);
        return {a + w * ac, {1.0f - w, 0.0f, w}};
    }
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f) {
        const float w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {b + w * (c - b), {0.0f, 1.0f - w, w}};
    }
    const float area = va + vb + vc;
    if (!(area > 0.0f)) return {a, {1.0f, 0.0f, 0.0f}};  // degenerate (the mesh report counts these)
    const float denom = 1.0f / area;
    const float v = vb * denom, w = vc * denom;
    return {a + ab * v + ac * w, {1.0f - v - w, v, w}};
}

}  // namespace palpate
