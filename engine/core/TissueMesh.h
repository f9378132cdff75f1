#pragma once
// A closed (or open, reported) triangle surface with flat arrays for the haptic loop.
// Read as a polygon soup (engine/core/PolygonSoup.h) and checked by findMeshFaults; written by
// OpenMesh. The hot loop reads only the flat arrays here.

#include "engine/core/MeshFaults.h"
#include "engine/core/MeshUnit.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

using VertexId = std::uint32_t;
inline constexpr VertexId kNoVertex = 0xffffffffu;

/// What validation found. Errors make a mesh unusable; warnings (open boundary) are reported only.
struct MeshReport {
    std::string source;                  ///< file path or generator name, for messages
    std::size_t vertexCount = 0;
    std::size_t triangleCount = 0;
    std::size_t boundaryEdgeCount = 0;   ///< > 0 means the surface is open (allowed, reported)
    std::size_t nonManifoldVertexCount = 0;
    std::size_t nonManifoldEdgeCount = 0;
    std::size_t degenerateTriangleCount = 0;
    std::size_t nonFiniteVertexCount = 0;
    std::size_t isolatedVertexCount = 0;
    double bboxDiagonalMm = 0.0;
    MeshUnit unit;                       ///< the file's unit; every size here is already in mm
    glm::dvec3 sizeMm{0.0};              ///< bounding-box extent (x, y, z)
    std::size_t holeCount = 0;           ///< closed loops of boundary edges
    std::size_t componentCount = 0;      ///< pieces connected through shared vertices
    std::size_t duplicateVertexCount = 0;  ///< at exactly another vertex's position
    std::size_t misorientedEdgeCount = 0;
    std::vector<std::string> notes;      ///< what the reader tolerated ("12 quads triangulated")
    std::vector<std::string> errors;     ///< each names the source and the problem
    std::vector<std::string> warnings;

    bool valid() const { return errors.empty(); }
    /// Human-readable, multi-line; what `palpate-cli mesh check` prints.
    std::string text() const;
};

/// The tissue surface. Vertices are renumbered along a space-filling curve at construction so that
/// rings and octree leaves are close in memory; `originalIndex` maps back to the file's numbering.
class TissueMesh {
public:
    struct LoadResult;

    /// Loads OBJ/OFF/PLY/STL/OM with coordinates in `unit`, scaled to mm. Never throws; on failure
    /// the report names the file and the problem.
    static LoadResult load(const std::string& path, const MeshUnit& unit = kMillimetres);
    /// Builds from a triangle list (generators, tests). Same validation as `load`.
    static LoadResult fromTriangles(std::vector<glm::vec3> positionsMm,
                                    const std::vector<std::array<VertexId, 3>>& triangles,
                                    const std::string& sourceName,
                                    bool reorderAlongCurve = true);

    std::size_t vertexCount() const { return mRestMm.size(); }
    std::size_t triangleCount() const { return mTriangles.size(); }

    const std::vector<glm::vec3>& restPositionsMm() const { return mRestMm; }
    const std::vector<glm::vec3>& restNormals() const { return mRestNormals; }
    const std::vector<std::array<VertexId, 3>>& triangles() const { return mTriangles; }
    /// Compressed adjacency: neighbours of v are mNeighbours[mNeighbourStart[v] .. mNeighbourStart[v+1]).
    const std::vector<std::uint32_t>& neighbourStart() const { return mNeighbourStart; }
    const std::vector<VertexId>& neighbours() const { return mNeighbours; }
    /// The triangles around each vertex (CSR): those of v are fanTriangles()[fanStart()[v] .. [v + 1]).
    const std::vector<std::uint32_t>& fanStart() const { return mFanStart; }
    const std::vector<std::uint32_t>& fanTriangles() const { return mFanTriangles; }
    /// The smallest height of v's fan triangles at rest, mm: while no corner of the fan moves by
    /// half of it, none of those triangles can turn over (the divergence guard skips the test).
    const std::vector<float>& fanMinHeightMm() const { return mFanMinHeightMm; }
    const std::vector<VertexId>& originalIndex() const { return mOriginalIndex; }
    const MeshReport& report() const { return mReport; }
    std::size_t maxValence() const { return mMaxValence; }
    /// Mean edge length of the rest surface, for scale-aware defaults.
    double meanEdgeLengthMm() const { return mMeanEdgeMm; }
    glm::vec3 boundsMinMm() const { return mBoundsMin; }
    glm::vec3 boundsMaxMm() const { return mBoundsMax; }

    /// Writes OBJ/OFF/PLY/STL chosen by extension, in the current (curve) order. Returns an error or "".
    std::string save(const std::string& path) const;

private:
    std::vector<glm::vec3> mRestMm;
    std::vector<glm::vec3> mRestNormals;
    std::vector<std::array<VertexId, 3>> mTriangles;
    std::vector<std::uint32_t> mNeighbourStart;
    std::vector<VertexId> mNeighbours;
    std::vector<std::uint32_t> mFanStart;
    std::vector<std::uint32_t> mFanTriangles;
    std::vector<float> mFanMinHeightMm;
    std::vector<VertexId> mOriginalIndex;
    MeshReport mReport;
    std::size_t mMaxValence = 0;
    double mMeanEdgeMm = 0.0;
    glm::vec3 mBoundsMin{0.0f};
    glm::vec3 mBoundsMax{0.0f};

    friend struct MeshBuilder;
};

struct TissueMesh::LoadResult {
    std::optional<TissueMesh> mesh;  ///< set only when the report has no errors
    MeshReport report;
    /// First error, or "" when loaded.
    std::string error() const { return report.errors.empty() ? std::string() : report.errors.front(); }
};

}  // namespace palpate
