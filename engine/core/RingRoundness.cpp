#include "engine/core/RingRoundness.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace palpate {

namespace {

/// Standard deviation over mean; 0 for fewer than two values or a zero mean.
struct Moments {
    double sum = 0.0, sumSquares = 0.0;
    std::size_t n = 0;
    void add(double x) {
        sum += x;
        sumSquares += x * x;
        ++n;
    }
    double cv() const {
        if (n < 2 || sum <= 0.0) return 0.0;
        const double mean = sum / double(n);
        const double variance = std::max(0.0, sumSquares / double(n) - mean * mean);
        return std::sqrt(variance) / mean;
    }
};

}  // namespace

double RingRoundness::worstRingCv() const {
    double worst = 0.0;
    for (int k = 1; k <= ringCount; ++k) worst = std::max(worst, ringDistanceCv[k]);
    return worst;
}

RingRoundness measureRingRoundness(const TissueMesh& mesh, int ringCount, std::size_t maxCentres) {
    RingRoundness r;
    r.ringCount = std::clamp(ringCount, 1, kMaxRings);
    const auto& rest = mesh.restPositionsMm();
    const auto& start = mesh.neighbourStart();
    const auto& neighbours = mesh.neighbours();
    const std::size_t n = mesh.vertexCount();
    if (n == 0) return r;

    Moments edges;
    r.minEdgeMm = INFINITY;
    for (std::size_t v = 0; v < n; ++v)
        for (std::uint32_t i = start[v]; i < start[v + 1]; ++i) {
            if (neighbours[i] <= v) continue;
            const double length = glm::length(rest[neighbours[i]] - rest[v]);
            edges.add(length);
            r.minEdgeMm = std::min(r.minEdgeMm, length);
            r.maxEdgeMm = std::max(r.maxEdgeMm, length);
        }
    r.edgeLengthCv = edges.cv();
    r.meanEdgeMm = edges.n ? edges.sum / double(edges.n) : 0.0;
    if (!std::isfinite(r.minEdgeMm)) r.minEdgeMm = 0.0;

    // A vertex whose rings reach the boundary has cut-off rings: its CV would measure the cut, not
    // the mesh. Boundary vertices are those on an edge used by one triangle.
    std::vector<bool> boundary(n, false);
    {
        std::vector<std::uint32_t> uses(neighbours.size(), 0);
        for (const auto& t : mesh.triangles())
            for (int k = 0; k < 3; ++k) {
                const VertexId a = t[k], b = t[(k + 1) % 3];
                const auto begin = neighbours.begin() + start[a], end = neighbours.begin() + start[a + 1];
                const auto at = std::lower_bound(begin, end, b);
                if (at != end && *at == b) ++uses[std::size_t(at - neighbours.begin())];
                const auto beginB = neighbours.begin() + start[b], endB = neighbours.begin() + start[b + 1];
                const auto atB = std::lower_bound(beginB, endB, a);
                if (atB != endB && *atB == a) ++uses[std::size_t(atB - neighbours.begin())];
            }
        for (std::size_t v = 0; v < n; ++v)
            for (std::uint32_t i = start[v]; i < start[v + 1]; ++i)
                if (uses[i] == 1) boundary[v] = boundary[neighbours[i]] = true;
    }

    RingFinder finder(mesh);
    RingSet rings = finder.makeRingSet();
    const std::size_t step = std::max<std::size_t>(1, n / std::max<std::size_t>(1, maxCentres));
    double cvSum[kMaxRings + 1] = {};
    std::size_t cvCount[kMaxRings + 1] = {};
    for (std::size_t c = 0; c < n; c += step) {
        finder.find(VertexId(c), r.ringCount, rings);
        bool touchesBoundary = false;
        for (std::size_t i = 0; i < rings.size() && !touchesBoundary; ++i) touchesBoundary = boundary[rings.vertices[i]];
        if (touchesBoundary) continue;
        ++r.sampledCentres;
        for (int k = 1; k <= std::min(r.ringCount, rings.ringCount); ++k) {
            Moments distances;
            for (VertexId v : rings.ring(k)) distances.add(glm::length(rest[v] - rest[c]));
            if (distances.n < 2) continue;
            cvSum[k] += distances.cv();
            ++cvCount[k];
        }
    }
    for (int k = 1; k <= r.ringCount; ++k) r.ringDistanceCv[k] = cvCount[k] ? cvSum[k] / double(cvCount[k]) : 0.0;
    return r;
}

}  // namespace palpate
