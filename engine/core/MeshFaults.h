#pragma once
// The faults of a triangle list, each counted and named exactly (docs/meshes.md, "Faults"): what
// `mesh check`, the loader and the import preview report, and what repair (engine/meshimport) fixes.

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace palpate {

struct MeshFaults {
    std::size_t invalidIndexTriangles = 0;   ///< refer to vertices that do not exist
    std::size_t nonFiniteVertices = 0;       ///< NaN or infinite coordinates
    std::size_t degenerateTriangles = 0;     ///< a repeated corner or zero area
    std::size_t duplicateVertices = 0;       ///< at exactly the position of an earlier vertex
    std::size_t nonManifoldEdges = 0;        ///< shared by three or more triangles
    std::size_t misorientedEdges = 0;        ///< two triangles run along it the same way
    std::size_t bowTieVertices = 0;          ///< separate fans of triangles meet only there
    std::size_t boundaryEdges = 0;           ///< used by one triangle
    std::size_t holes = 0;                   ///< loops of boundary edges (two meeting at a vertex count as one)
    std::size_t components = 0;              ///< pieces connected through shared vertices
    std::size_t unusedVertices = 0;          ///< used by no triangle

    /// Faults that make a mesh unusable for the haptic loop (the loader refuses them).
    bool hasErrors() const {
        return invalidIndexTriangles || nonFiniteVertices || degenerateTriangles || nonManifoldEdges ||
               misorientedEdges || bowTieVertices;
    }
    /// One line per fault present, errors first ("6 edges where neighbouring triangles are
    /// inconsistently oriented"), then the reported-only ones (holes, duplicates, components).
    std::vector<std::string> errorTexts() const;
    std::vector<std::string> warningTexts() const;
};

/// Counts every fault of `triangles` over `positions` (any unit). Linear in the size, apart from
/// sorting the edges and the positions.
MeshFaults findMeshFaults(const std::vector<glm::dvec3>& positions,
                          const std::vector<std::array<std::uint32_t, 3>>& triangles);

}  // namespace palpate
