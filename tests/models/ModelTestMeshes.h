#pragma once
// Small meshes for the models' tests, built from hand-written coordinates.

#include "engine/core/MeshGenerator.h"
#include "engine/core/TissueMesh.h"
#include "tests/support/Meshes.h"

#include <glm/geometric.hpp>

#include <array>
#include <stdexcept>
#include <vector>

namespace palpate::test {

/// Appends a closed tetrahedron (faces wound outward) centred at `centre` with circumradius ~ r*sqrt(3).
inline void appendTetrahedron(std::vector<glm::vec3>& positions, std::vector<std::array<VertexId, 3>>& triangles,
                              const glm::vec3& centre, float r) {
    const auto base = VertexId(positions.size());
    const glm::vec3 corners[4] = {{r, r, r}, {r, -r, -r}, {-r, r, -r}, {-r, -r, r}};
    for (const auto& c : corners) positions.push_back(centre + c);
    const int faces[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    for (const auto& f : faces) {
        std::array<VertexId, 3> t{base + VertexId(f[0]), base + VertexId(f[1]), base + VertexId(f[2])};
        const glm::vec3 a = positions[t[0]], b = positions[t[1]], c = positions[t[2]];
        if (glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0f - centre) < 0.0f) std::swap(t[1], t[2]);
        triangles.push_back(t);
    }
}

/// A regular tetrahedron: 4 vertices, each joined to the other 3 (the complete graph K4).
inline TissueMesh tetrahedronMesh(float r = 10.0f) {
    std::vector<glm::vec3> positions;
    std::vector<std::array<VertexId, 3>> triangles;
    appendTetrahedron(positions, triangles, glm::vec3(0.0f), r);
    auto loaded = TissueMesh::fromTriangles(positions, triangles, "tetrahedron");
    if (!loaded.mesh) throw std::runtime_error(loaded.error());
    return std::move(*loaded.mesh);
}


}  // namespace palpate::test
