#include "engine/lod/SurfaceEmbedding.h"

#include "engine/lod/NearestTriangle.h"

#include <glm/geometric.hpp>

namespace palpate {

namespace {

/// Unit normal of the triangle (b - a) x (c - a); zero for a degenerate one.
glm::dvec3 unitNormal(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double len = glm::length(n);
    return len > 0.0 ? n / len : glm::dvec3(0.0);
}

}  // namespace

std::vector<EmbeddedPoint> embedPoints(std::span<const glm::vec3> pointsMm, const TissueMesh& onto,
                                       const std::atomic<bool>* cancel) {
    NearestTriangle search(onto);
    const auto& rest = onto.restPositionsMm();
    const auto& tris = onto.triangles();
    std::vector<EmbeddedPoint> out(pointsMm.size());
    for (std::size_t i = 0; i < pointsMm.size(); ++i) {
        if (cancel && (i & 1023) == 0 && cancel->load(std::memory_order_relaxed)) return {};
        const glm::dvec3 p(pointsMm[i]);
        const auto hit = search.nearest(p);
        const auto& t = tris[hit.triangle];
        const glm::dvec3 a(rest[t[0]]), b(rest[t[1]]), c(rest[t[2]]);
        const glm::dvec3 n = unitNormal(a, b, c);
        const double h = glm::dot(p - a, n);
        const glm::dvec3 q = p - h * n;  // projection onto the plane
        // Barycentric coordinates of q by the usual dot-product solve (Ericson 3.4).
        const glm::dvec3 v0 = b - a, v1 = c - a, v2 = q - a;
        const double d00 = glm::dot(v0, v0), d01 = glm::dot(v0, v1), d11 = glm::dot(v1, v1);
        const double d20 = glm::dot(v2, v0), d21 = glm::dot(v2, v1);
        const double denom = d00 * d11 - d01 * d01;
        EmbeddedPoint e;
        e.triangle = hit.triangle;
        if (denom > 0.0) {
            const double wb = (d11 * d20 - d01 * d21) / denom;
            const double wc = (d00 * d21 - d01 * d20) / denom;
            e.barycentric = {float(1.0 - wb - wc), float(wb), float(wc)};
            e.normalOffsetMm = float(h);
        } else {
            // A degenerate triangle has no plane: tie the point to its first corner.
            e.barycentric = {1.0f, 0.0f, 0.0f};
            e.normalOffsetMm = 0.0f;
        }
        out[i] = e;
    }
    return out;
}

void placeEmbeddedPoints(std::span<const EmbeddedPoint> points, const TissueMesh& onto,
                         std::span<const glm::vec3> ontoPositionsMm, std::span<glm::vec3> outMm) {
    const auto& tris = onto.triangles();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const EmbeddedPoint& e = points[i];
        const auto& t = tris[e.triangle];
        const glm::dvec3 a(ontoPositionsMm[t[0]]), b(ontoPositionsMm[t[1]]), c(ontoPositionsMm[t[2]]);
        const glm::dvec3 q = double(e.barycentric[0]) * a + double(e.barycentric[1]) * b + double(e.barycentric[2]) * c;
        outMm[i] = glm::vec3(q + double(e.normalOffsetMm) * unitNormal(a, b, c));
    }
}

void interpolateAtEmbeddedPoints(std::span<const EmbeddedPoint> points, const TissueMesh& onto,
                                 std::span<const glm::vec3> ontoField, std::span<glm::vec3> out) {
    const auto& tris = onto.triangles();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const EmbeddedPoint& e = points[i];
        const auto& t = tris[e.triangle];
        out[i] = e.barycentric[0] * ontoField[t[0]] + e.barycentric[1] * ontoField[t[1]] + e.barycentric[2] * ontoField[t[2]];
    }
}

}  // namespace palpate
