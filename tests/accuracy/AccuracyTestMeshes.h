#pragma once
// Tet meshes for the FEM tests, built here by hand (not by GradedBlock or SurfaceFill) so that the
// tests do not share the code under test: a box of Kuhn-split cubes, optionally jittered.

#include "engine/fem/TetMesh.h"

#include <glm/vec3.hpp>

#include <array>
#include <random>
#include <utility>

namespace palpate::test {

/// n x n x n cubes over [lo, lo + size]^3, each cut into 6 tets along its main diagonal. Interior
/// nodes are moved by up to `jitter` cube sizes in each coordinate (jitter < 0.25 keeps every tet
/// positive), which makes the mesh irregular. `onBoundary[i]` marks nodes on the box faces.
struct BoxMesh {
    TetMesh mesh;
    std::vector<bool> onBoundary;
};

inline BoxMesh kuhnBox(int n, glm::dvec3 lo, double size, double jitter = 0.0, unsigned seed = 1) {
    BoxMesh b;
    const double h = size / n;
    auto id = [n](int i, int j, int k) { return TetNodeId((k * (n + 1) + j) * (n + 1) + i); };
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> shake(-jitter * h, jitter * h);
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const bool boundary = i == 0 || j == 0 || k == 0 || i == n || j == n || k == n;
                glm::dvec3 p = lo + h * glm::dvec3(i, j, k);
                if (!boundary) p += glm::dvec3(shake(rng), shake(rng), shake(rng));
                b.mesh.nodesMm.push_back(p);
                b.onBoundary.push_back(boundary);
            }
    const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                for (const auto& order : orders) {
                    int at[3] = {i, j, k};
                    std::array<TetNodeId, 4> t{id(i, j, k), 0, 0, 0};
                    for (int s = 0; s < 3; ++s) {
                        ++at[order[s]];
                        t[std::size_t(s) + 1] = id(at[0], at[1], at[2]);
                    }
                    const auto& p = b.mesh.nodesMm;
                    if (tetSignedVolume6(p[t[0]], p[t[1]], p[t[2]], p[t[3]]) < 0) std::swap(t[2], t[3]);
                    b.mesh.tets.push_back(t);
                }
    return b;
}

}  // namespace palpate::test
