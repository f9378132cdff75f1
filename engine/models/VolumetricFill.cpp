#include "engine/models/VolumetricFill.h"

#include "engine/fem/SurfaceFill.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace palpate {

TetMesh fillStarShapedSurface(const TissueMesh& mesh, int innerShells) {
    const std::size_t n = mesh.vertexCount();
    if (n < 4 || mesh.triangleCount() < 4) throw std::invalid_argument("tet fill: the surface has too few vertices");
    if (mesh.report().boundaryEdgeCount > 0) throw std::invalid_argument("tet fill: the surface is open (" + mesh.report().source + ")");
    if (innerShells < 0 || innerShells > 64) throw std::invalid_argument("tet fill: innerShells must be in 0..64");
    const auto& rest = mesh.restPositionsMm();
    glm::dvec3 centre(0.0);
    for (const auto& p : rest) centre += glm::dvec3(p);
    centre /= double(n);
    // Star-shaped about the centre: every triangle faces away from it.
    for (const auto& t : mesh.triangles()) {
        const glm::dvec3 a(rest[t[0]]), b(rest[t[1]]), c(rest[t[2]]);
        const glm::dvec3 normal = glm::cross(b - a, c - a);
        if (!(glm::dot(normal, (a + b + c) / 3.0 - centre) > 1e-9 * glm::dot(normal, normal)))
            throw std::invalid_argument("tet fill: " + mesh.report().source +
                                        " is not star-shaped about its centroid (a triangle faces it)");
    }
    TetMesh tets;
    const int layers = innerShells + 1;  // layer 0 = the surface
    tets.nodesMm.reserve(n * std::size_t(layers) + 1);
    for (int layer = 0; layer < layers; ++layer) {
        const double scale = 1.0 - double(layer) / double(layers);
        for (std::size_t v = 0; v < n; ++v) tets.nodesMm.push_back(centre + scale * (glm::dvec3(rest[v]) - centre));
    }
    const auto centreNode = TetNodeId(tets.nodesMm.size());
    tets.nodesMm.push_back(centre);
    auto node = [&](int layer, VertexId v) { return TetNodeId(std::size_t(layer) * n + v); };
    auto add = [&](TetNodeId a, TetNodeId b, TetNodeId c, TetNodeId d) {
        const double v6 = tetSignedVolume6(tets.nodesMm[a], tets.nodesMm[b], tets.nodesMm[c], tets.nodesMm[d]);
        if (v6 < 0.0) std::swap(c, d);
        if (!(std::abs(v6) > 0.0)) throw std::invalid_argument("tet fill: a degenerate tetrahedron");
        tets.tets.push_back({a, b, c, d});
    };
    tets.tets.reserve(mesh.triangleCount() * (3 * std::size_t(innerShells) + 1));
    for (const auto& t : mesh.triangles()) {
        std::array<VertexId, 3> s = t;
        std::sort(s.begin(), s.end());
        const VertexId i = s[0], j = s[1], k = s[2];
        for (int layer = 0; layer < innerShells; ++layer) {
            // Prism (i, j, k) over (i', j', k'): each side's diagonal joins the lower-index vertex
            // on the outer shell to the higher-index one on the inner, the same from both prisms.
            const int o = layer, in = layer + 1;
            add(node(o, i), node(o, j), node(o, k), node(in, k));
            add(node(o, i), node(o, j), node(in, j), node(in, k));
            add(node(o, i), node(in, i), node(in, j), node(in, k));
        }
        add(node(innerShells, i), node(innerShells, j), node(innerShells, k), centreNode);
    }
    return tets;
}

TetMesh fillSurfaceWithTets(const TissueMesh& mesh) {
    const FilledSurface filled = fillSurface(mesh);  // throws std::invalid_argument naming the problem
    // SurfaceFill numbers each vertex's column of nodes contiguously (node(v, l)); the volumetric
    // model wants the surface (l = 0) first in the mesh's order, then the inner nodes.
    const std::size_t n = filled.surfaceVertexCount;
    const int layers = filled.layers;
    const std::size_t nodes = filled.mesh.nodeCount();
    if (n != mesh.vertexCount() || nodes != n * std::size_t(layers + 1))
        throw std::invalid_argument("tet fill: the filled surface does not match the mesh (" + mesh.report().source + ")");
    std::vector<TetNodeId> renumber(nodes);
    for (std::size_t v = 0; v < n; ++v)
        for (int l = 0; l <= layers; ++l)
            renumber[filled.node(VertexId(v), l)] =
                l == 0 ? TetNodeId(v) : TetNodeId(n + v * std::size_t(layers) + std::size_t(l - 1));
    TetMesh tets;
    tets.nodesMm.resize(nodes);
    for (std::size_t i = 0; i < nodes; ++i) tets.nodesMm[renumber[i]] = filled.mesh.nodesMm[i];
    tets.tets.reserve(filled.mesh.tetCount());
    for (const auto& t : filled.mesh.tets) tets.tets.push_back({renumber[t[0]], renumber[t[1]], renumber[t[2]], renumber[t[3]]});
    return tets;
}

}  // namespace palpate
