#pragma once
// Small meshes with known answers for the engine tests (temporary folders and the command runner
// are tests/support's).
// Everything here is computed from coordinates by hand-written formulas, never by the engine code
// under test, so that the tests can disagree with it.

#include "engine/core/TissueMesh.h"
#include "tests/support/Shell.h"
#include "tests/support/TempDir.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace palpate::test {

using Triangles = std::vector<std::array<VertexId, 3>>;

/// A raw triangle soup (positions in file order, counter-clockwise seen from outside).
struct RawMesh {
    std::vector<glm::vec3> positions;
    Triangles triangles;

    TissueMesh::LoadResult build(const std::string& name, bool reorder = true) const {
        return TissueMesh::fromTriangles(positions, triangles, name, reorder);
    }
    /// The same surface with every triangle's winding reversed (faces inward).
    RawMesh flipped() const;
};

/// Regular icosahedron of the given circumradius, centred at the origin, faces outward.
RawMesh icosahedron(float radiusMm = 10.0f);

/// Octahedron with vertices at (+-r,0,0), (0,+-r,0), (0,0,+-r), faces outward.
RawMesh octahedron(float radiusMm = 10.0f);

/// A closed "tower" whose apex (file index 0) at (0,0,10) has rest normal exactly (0,0,1):
/// apex, a square of 4 at z = 6 (file 1..4: (4,0), (0,4), (-4,0), (0,-4)), a square of 4 at z = 0
/// (file 5..8: (8,0), (0,8), (-8,0), (0,-8)), and a bottom apex (file 9) at (0,0,-10).
/// Rings from the apex: ring 1 = {1..4}, ring 2 = {5..8}, ring 3 = {9}.
RawMesh tower();

/// A flat nx-by-ny grid of points (i * spacing, j * spacing, 0), file index j * nx + i; each quad
/// is split along the diagonal (i,j)-(i+1,j+1). Open surface (boundary = the grid's rim).
RawMesh gridPatch(int nx, int ny, float spacingMm = 1.0f);

/// Edge distance between two grid points of gridPatch (hexagonal metric of that triangulation):
/// steps (+-1,0), (0,+-1), +-(1,1); same-sign offsets cost max(|dx|,|dy|), others |dx|+|dy|.
int gridDistance(int i0, int j0, int i1, int j1);

/// Two tetrahedra that share exactly one vertex (file index 0): a non-manifold "bowtie" vertex.
RawMesh bowtieTetrahedra();

/// Three triangles on the edge (0,1): a non-manifold edge.
RawMesh threeTrianglesOnEdge();

/// Topology facts computed independently of the engine (from the raw triangles).
struct TopologyFacts {
    std::size_t edgeCount = 0;
    std::size_t boundaryEdges = 0;      ///< used by one triangle
    std::size_t nonManifoldEdges = 0;   ///< used by three or more
    std::size_t misorientedEdges = 0;   ///< used twice in the same direction
    std::size_t nonManifoldVertices = 0;  ///< incident triangles do not form one fan
};
TopologyFacts topologyFacts(std::size_t vertexCount, const Triangles& triangles);

/// Six times the signed volume enclosed by a closed triangle surface (positive: faces outward).
double signedVolume6(const std::vector<glm::vec3>& positions, const Triangles& triangles);

/// Squared distance, computed like the engine does (float, component-wise).
float dist2(const glm::vec3& a, const glm::vec3& b);

bool isFinite(const glm::vec3& v);


/// Writers that do not depend on the engine (or OpenMesh), for full control over the bytes.
std::string toOff(const RawMesh& mesh);
std::string toObj(const RawMesh& mesh);
std::string toAsciiPly(const RawMesh& mesh);
std::string toBinaryPly(const RawMesh& mesh);
std::string toBinaryStl(const RawMesh& mesh);
std::string toAsciiStl(const RawMesh& mesh);

/// The raw soup of an engine mesh (current order), for writing it back out.
RawMesh rawOf(const TissueMesh& mesh);

/// Where the command-line tool is (from the build), or "" if the tests were built without it.
std::string cliPath();


}  // namespace palpate::test
