#include "engine/core/MeshFaults.h"

#include "engine/core/CountedText.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace palpate {

namespace {

/// Union-find over indices with path halving.
struct DisjointSets {
    explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    std::uint32_t find(std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    bool unite(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a == b) return false;
        parent[a] = b;
        return true;
    }
    std::vector<std::uint32_t> parent;
};

}  // namespace

std::vector<std::string> MeshFaults::errorTexts() const {
    std::vector<std::string> out;
    if (invalidIndexTriangles)
        out.push_back(countedText(invalidIndexTriangles, "triangle refers", "triangles refer") +
                      " to vertices that do not exist");
    if (nonFiniteVertices) out.push_back(countedText(nonFiniteVertices, "vertex", "vertices") + " with NaN or infinite coordinates");
    if (degenerateTriangles)
        out.push_back(countedText(degenerateTriangles, "degenerate triangle", "degenerate triangles") +
                      " (zero area or a repeated corner)");
    if (misorientedEdges)
        out.push_back(countedText(misorientedEdges, "edge", "edges") +
                      " where neighbouring triangles are inconsistently oriented (one of them is wound the wrong way)");
    if (nonManifoldEdges)
        out.push_back("non-manifold: " + countedText(nonManifoldEdges, "edge", "edges") + " shared by three or more triangles");
    if (bowTieVertices)
        out.push_back("non-manifold: " + countedText(bowTieVertices, "bow-tie vertex", "bow-tie vertices") +
                      " where separate fans of triangles touch at a single point");
    return out;
}

std::vector<std::string> MeshFaults::warningTexts() const {
    std::vector<std::string> out;
    if (holes)
        out.push_back("open surface: " + countedText(holes, "hole", "holes") + " (" +
                      countedText(boundaryEdges, "boundary edge", "boundary edges") + ")");
    else if (boundaryEdges)
        out.push_back("open surface: " + countedText(boundaryEdges, "boundary edge", "boundary edges"));
    if (duplicateVertices)
        out.push_back(countedText(duplicateVertices, "duplicate vertex", "duplicate vertices") +
                      " (at exactly another vertex's position: the surface is split along them)");
    if (components > 1) out.push_back(std::to_string(components) + " separate components (pieces not connected to each other)");
    if (unusedVertices) out.push_back(countedText(unusedVertices, "vertex", "vertices") + " used by no triangle");
    return out;
}

MeshFaults findMeshFaults(const std::vector<glm::dvec3>& positions,
                          const std::vector<std::array<std::uint32_t, 3>>& triangles) {
    MeshFaults f;
    const std::size_t nv = positions.size();

    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::dvec3& p : positions) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            ++f.nonFiniteVertices;
            continue;
        }
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double diagonal = f.nonFiniteVertices == nv ? 0.0 : glm::length(hi - lo);
    // Zero area relative to the model's scale (a float coordinate's resolution, squared twice).
    const double minArea2 = std::pow(diagonal * 1e-7, 4);

    std::vector<std::array<std::uint32_t, 3>> usable;
    usable.reserve(triangles.size());
    for (const auto& t : triangles) {
        if (t[0] >= nv || t[1] >= nv || t[2] >= nv) {
            ++f.invalidIndexTriangles;
            continue;
        }
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
            ++f.degenerateTriangles;
            continue;
        }
        const glm::dvec3 n = glm::cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]);
        if (!(glm::dot(n, n) > minArea2)) ++f.degenerateTriangles;
        usable.push_back(t);
    }

    // Duplicates: sorted by position, equal neighbours.
    std::vector<std::uint32_t> byPosition(nv);
    std::iota(byPosition.begin(), byPosition.end(), 0u);
    auto less = [&](std::uint32_t a, std::uint32_t b) {
        const glm::dvec3 &p = positions[a], &q = positions[b];
        if (p.x != q.x) return p.x < q.x;
        if (p.y != q.y) return p.y < q.y;
        return p.z < q.z;
    };
    std::sort(byPosition.begin(), byPosition.end(), less);
    for (std::size_t i = 1; i < byPosition.size(); ++i)
        if (positions[byPosition[i]] == positions[byPosition[i - 1]]) ++f.duplicateVertices;

    // Edges: boundary (1 use), manifold (2, opposite directions), misoriented (2, same), non-manifold (3+).
    struct DirectedEdge {
        std::uint64_t key;
        bool forward;
    };
    std::vector<DirectedEdge> edges;
    edges.reserve(usable.size() * 3);
    for (const auto& t : usable)
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t a = t[i], b = t[(i + 1) % 3];
            edges.push_back({std::uint64_t(std::min(a, b)) << 32 | std::max(a, b), a < b});
        }
    std::sort(edges.begin(), edges.end(), [](const DirectedEdge& x, const DirectedEdge& y) { return x.key < y.key; });
    DisjointSets boundaryLoops(nv);
    std::vector<bool> onBoundary(nv, false);
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        int forward = 0;
        while (j < edges.size() && edges[j].key == edges[i].key) forward += edges[j++].forward ? 1 : 0;
        const std::size_t count = j - i;
        if (count == 1) {
            ++f.boundaryEdges;
            const auto a = std::uint32_t(edges[i].key >> 32), b = std::uint32_t(edges[i].key & 0xffffffffu);
            boundaryLoops.unite(a, b);
            onBoundary[a] = onBoundary[b] = true;
        } else if (count > 2) {
            ++f.nonManifoldEdges;
        } else if (forward != 1) {
            ++f.misorientedEdges;
        }
        i = j;
    }
    for (std::uint32_t v = 0; v < nv; ++v)
        if (onBoundary[v] && boundaryLoops.find(v) == v) ++f.holes;

    // Components (through shared vertices) and unused vertices.
    DisjointSets pieces(nv);
    std::vector<bool> used(nv, false);
    for (const auto& t : usable) {
        pieces.unite(t[0], t[1]);
        pieces.unite(t[1], t[2]);
        for (std::uint32_t v : t) used[v] = true;
    }
    for (std::uint32_t v = 0; v < nv; ++v) {
        if (!used[v]) ++f.unusedVertices;
        else if (pieces.find(v) == v) ++f.components;
    }

    // Bow-ties: a manifold vertex's triangles form one fan (connected through their other corners).
    std::vector<std::uint32_t> incidentStart(nv + 1, 0);
    for (const auto& t : usable)
        for (std::uint32_t v : t) ++incidentStart[v + 1];
    for (std::size_t v = 0; v < nv; ++v) incidentStart[v + 1] += incidentStart[v];
    std::vector<std::uint32_t> incident(incidentStart.back());
    {
        std::vector<std::uint32_t> fill(incidentStart.begin(), incidentStart.end() - 1);
        for (std::uint32_t t = 0; t < usable.size(); ++t)
            for (std::uint32_t v : usable[t]) incident[fill[v]++] = t;
    }
    std::vector<std::uint32_t> others;
    for (std::uint32_t v = 0; v < nv; ++v) {
        const std::uint32_t begin = incidentStart[v], end = incidentStart[v + 1];
        if (begin == end) continue;
        others.clear();
        for (std::uint32_t i = begin; i < end; ++i)
            for (std::uint32_t w : usable[incident[i]])
                if (w != v) others.push_back(w);
        std::sort(others.begin(), others.end());
        others.erase(std::unique(others.begin(), others.end()), others.end());
        auto slot = [&](std::uint32_t w) {
            return std::uint32_t(std::lower_bound(others.begin(), others.end(), w) - others.begin());
        };
        DisjointSets fan(others.size());
        std::size_t fans = others.size();
        for (std::uint32_t i = begin; i < end; ++i) {
            std::uint32_t a = UINT32_MAX, b = UINT32_MAX;
            for (std::uint32_t w : usable[incident[i]])
                if (w != v) (a == UINT32_MAX ? a : b) = w;
            if (a != UINT32_MAX && b != UINT32_MAX && fan.unite(slot(a), slot(b))) --fans;
        }
        if (fans > 1) ++f.bowTieVertices;
    }
    return f;
}

}  // namespace palpate
