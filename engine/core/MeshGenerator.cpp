#include "engine/core/MeshGenerator.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <vector>

namespace palpate {

namespace {

constexpr double kPi = glm::pi<double>();

/// A surface of revolution-like tube: centre line C(u), frame (N, B), radius r(u, phi), u in [0, 1].
struct TubeShape {
    std::function<glm::dvec3(double)> centre;
    std::function<double(double, double)> radius;  // 0 at u = 0 and u = 1
};

TubeShape sphereShape() {
    return {[](double u) { return glm::dvec3(0.0, 0.0, 50.0 * std::cos(kPi * u)); },
            [](double u, double) { return 50.0 * std::sin(kPi * u); }};
}

TubeShape stomachShape() {
    // A bent, unevenly swollen tube: a J-shaped centre line in the x-z plane; a wide fundus near
    // the start, a narrowing body and a tapered antrum; slightly flattened cross-sections.
    auto centre = [](double u) {
        const double angle = -0.35 * kPi + 1.35 * kPi * u;
        const double bend = 70.0 - 20.0 * u;
        return glm::dvec3(bend * std::cos(angle), 0.0, bend * std::sin(angle) + 15.0 * u);
    };
    auto radius = [](double u, double phi) {
        const double envelope = std::pow(std::sin(kPi * u), 0.55);
        const double fundus = 1.0 + 0.45 * std::exp(-std::pow((u - 0.25) / 0.14, 2.0));
        const double body = 30.0 - 10.0 * u;
        const double flatten = 1.0 - 0.12 * std::cos(2.0 * phi) + 0.05 * std::sin(3.0 * phi + 4.0 * u);
        return body * fundus * envelope * flatten;
    };
    return {centre, radius};
}

glm::dvec3 tubePoint(const TubeShape& shape, double u, double phi) {
    const double h = 1e-4;
    const glm::dvec3 c = shape.centre(u);
    const glm::dvec3 tangent = glm::normalize(shape.centre(std::min(1.0, u + h)) - shape.centre(std::max(0.0, u - h)));
    const glm::dvec3 binormal(0.0, 1.0, 0.0);
    const glm::dvec3 normal = glm::normalize(glm::cross(binormal, tangent));
    const double r = shape.radius(u, phi);
    return c + r * (std::cos(phi) * normal + std::sin(phi) * binormal);
}

}  // namespace

std::optional<GeneratedShape> parseShape(std::string_view name) {
    if (name == "sphere") return GeneratedShape::Sphere;
    if (name == "stomach") return GeneratedShape::Stomach;
    return std::nullopt;
}

std::string_view shapeName(GeneratedShape shape) {
    return shape == GeneratedShape::Sphere ? "sphere" : "stomach";
}

TissueMesh::LoadResult generateMesh(GeneratedShape shape, std::size_t vertexCount) {
    const std::string source = "generated " + std::string(shapeName(shape)) + " (" + std::to_string(vertexCount) +
                               " vertices)";
    if (vertexCount < kMinGeneratedVertices) {
        TissueMesh::LoadResult r;
        r.report.source = source;
        r.report.errors.push_back(source + ": needs at least " + std::to_string(kMinGeneratedVertices) + " vertices");
        return r;
    }
    if (vertexCount > kMaxMeshVertices) {
        TissueMesh::LoadResult r;
        r.report.source = source;
        r.report.errors.push_back(source + ": more than the " + std::to_string(kMaxMeshVertices) +
                                  " vertices a mesh may have (base/io/FileLimits.h)");
        return r;
    }
    const TubeShape tube = shape == GeneratedShape::Sphere ? sphereShape() : stomachShape();
    const std::size_t inner = vertexCount - 2;

    // Meridian length and circumference profile, sampled, to choose ring count and ring sizes
    // so that triangles are close to equilateral.
    constexpr int kSamples = 512;
    std::vector<double> arc(kSamples + 1, 0.0), circumference(kSamples + 1, 0.0);
    for (int i = 0; i <= kSamples; ++i) {
        const double u = double(i) / kSamples;
        if (i > 0) arc[i] = arc[i - 1] + glm::length(tubePoint(tube, u, 0.0) - tubePoint(tube, double(i - 1) / kSamples, 0.0));
        double c = 0.0;
        for (int k = 0; k < 32; ++k)
            c += glm::length(tubePoint(tube, u, 2 * kPi * (k + 1) / 32) - tubePoint(tube, u, 2 * kPi * k / 32));
        circumference[i] = c;
    }
    const double meanCircumference = std::accumulate(circumference.begin(), circumference.end(), 0.0) / (kSamples + 1);
    // Rings R with spacing along the meridian ~ spacing around: arc / (R + 1) = R * meanC / inner.
    std::size_t rings = std::size_t(std::max(1.0, std::round(std::sqrt(double(inner) * arc.back() / meanCircumference))));
    rings = std::clamp<std::size_t>(rings, 1, inner / 3);

    // Ring positions equally spaced in arc length; sizes proportional to circumference, >= 3,
    // summing exactly to `inner` (largest remainder).
    std::vector<double> ringU(rings), weight(rings);
    for (std::size_t j = 0; j < rings; ++j) {
        const double target = arc.back() * double(j + 1) / double(rings + 1);
        const auto it = std::lower_bound(arc.begin(), arc.end(), target);
        const std::size_t i = std::size_t(std::clamp<std::ptrdiff_t>(it - arc.begin(), 1, kSamples));
        const double t = (target - arc[i - 1]) / std::max(1e-12, arc[i] - arc[i - 1]);
        ringU[j] = (double(i - 1) + t) / kSamples;
        weight[j] = std::max(1e-6, circumference[i - 1] + t * (circumference[i] - circumference[i - 1]));
    }
    const double weightSum = std::accumulate(weight.begin(), weight.end(), 0.0);
    std::vector<std::size_t> size(rings, 3);
    std::size_t remaining = inner - 3 * rings;
    std::vector<double> share(rings);
    for (std::size_t j = 0; j < rings; ++j) share[j] = double(remaining) * weight[j] / weightSum;
    std::size_t given = 0;
    for (std::size_t j = 0; j < rings; ++j) {
        size[j] += std::size_t(share[j]);
        given += std::size_t(share[j]);
    }
    std::vector<std::size_t> byRemainder(rings);
    std::iota(byRemainder.begin(), byRemainder.end(), 0);
    std::stable_sort(byRemainder.begin(), byRemainder.end(), [&](std::size_t a, std::size_t b) {
        return share[a] - std::floor(share[a]) > share[b] - std::floor(share[b]);
    });
    for (std::size_t k = 0; given < remaining; ++k, ++given) ++size[byRemainder[k % rings]];

    std::vector<glm::vec3> positions;
    positions.reserve(vertexCount);
    std::vector<std::array<VertexId, 3>> triangles;
    triangles.reserve(2 * vertexCount - 4);
    positions.push_back(glm::vec3(tubePoint(tube, 0.0, 0.0)));
    std::vector<std::size_t> ringFirst(rings);
    std::vector<double> ringOffset(rings);
    for (std::size_t j = 0; j < rings; ++j) {
        ringFirst[j] = positions.size();
        ringOffset[j] = (j % 2) * 0.5;  // stagger alternate rings for better triangles
        for (std::size_t k = 0; k < size[j]; ++k) {
            const double phi = 2 * kPi * (double(k) + ringOffset[j]) / double(size[j]);
            positions.push_back(glm::vec3(tubePoint(tube, ringU[j], phi)));
        }
    }
    const auto lastPole = VertexId(positions.size());
    positions.push_back(glm::vec3(tubePoint(tube, 1.0, 0.0)));

    auto ringVertex = [&](std::size_t j, std::size_t k) { return VertexId(ringFirst[j] + k % size[j]); };
    for (std::size_t k = 0; k < size[0]; ++k) triangles.push_back({0, ringVertex(0, k), ringVertex(0, k + 1)});
    for (std::size_t j = 0; j + 1 < rings; ++j) {
        const std::size_t a = size[j], b = size[j + 1];
        auto angleA = [&](std::size_t i) { return (double(i) + ringOffset[j]) / double(a); };
        auto angleB = [&](std::size_t i) { return (double(i) + ringOffset[j + 1]) / double(b); };
        std::size_t i = 0, k = 0;
        while (i < a || k < b) {
            const bool advanceA = k == b || (i < a && angleA(i + 1) < angleB(k + 1));
            if (advanceA) {
                triangles.push_back({ringVertex(j, i), ringVertex(j + 1, k), ringVertex(j, i + 1)});
                ++i;
            } else {
                triangles.push_back({ringVertex(j, i), ringVertex(j + 1, k), ringVertex(j + 1, k + 1)});
                ++k;
            }
        }
    }
    for (std::size_t k = 0; k < size[rings - 1]; ++k)
        triangles.push_back({lastPole, ringVertex(rings - 1, k + 1), ringVertex(rings - 1, k)});
    for (auto& t : triangles) std::swap(t[1], t[2]);  // the zipper winds inward; face outward
    return TissueMesh::fromTriangles(std::move(positions), triangles, source);
}

}  // namespace palpate
