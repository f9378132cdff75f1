#pragma once
// An exercise placed on a mesh: its surface points snapped to vertices (in the engine's vertex
// order), the trace path as a polyline with coverage samples, the inclusion's vertices and their
// compliance factors, the vertex areas damage is measured with, and the rubric it is graded by.
// Self-contained (copies what it needs from the mesh), immutable, shared by scorers.

#include "engine/core/TissueMesh.h"
#include "engine/exercise/Exercise.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace palpate {

class HapticScene;

struct ResolvedTarget {
    VertexId vertex = kNoVertex;  ///< engine numbering
    glm::vec3 pointMm{0.0f};      ///< the vertex's rest position
    PressTarget def;
};

/// Detect lumps: one lump placed on the mesh (docs/scoring.md, "Lumps under the surface").
struct ResolvedLump {
    LumpDef def;
    VertexId vertex = kNoVertex;  ///< the surface vertex above its centre (engine numbering)
    glm::vec3 surfaceMm{0.0f};    ///< that vertex's rest position: where a finding should be
    glm::vec3 centreMm{0.0f};     ///< the sphere's centre, depth + radius below it along the normal
    std::size_t footprintVertices = 0;  ///< vertices with this lump under them
};

/// What an exercise's kind places on the mesh (ExerciseKind::place fills its part; the rest stays
/// empty).
struct PlacedGeometry {
    std::vector<ResolvedTarget> targets;      ///< press targets
    VertexId lumpVertex = kNoVertex;          ///< find the lump: the inclusion's centre vertex
    glm::vec3 lumpCentreMm{0.0f};
    /// Find the lump, detect lumps: every vertex's compliance factor (1 where the tissue is as set).
    std::vector<float> compliance;
    std::size_t inclusionVertices = 0;        ///< vertices with a factor below 1
    std::vector<ResolvedLump> lumps;          ///< detect lumps
    std::vector<float> engageDepthMm;         ///< detect lumps: per vertex, where a lump begins to resist
    std::vector<std::int16_t> lumpOfVertex;   ///< detect lumps: per vertex, the lump under it (-1: none)
    std::vector<glm::vec3> pathMm;            ///< trace: the snapped polyline
    std::vector<VertexId> pathVertices;
    std::vector<glm::vec3> coverageMm;        ///< trace: points at most 1 mm apart along it
    double pathLengthMm = 0.0;
};

/// Snaps an exercise's surface points to a mesh, for its kind's ExerciseKind::place.
class GeometryPlacer {
public:
    /// The first problem goes to `error`.
    GeometryPlacer(const TissueMesh& mesh, std::string& error) : mMesh(mesh), mError(error) {}
    /// The vertex of `point` (engine numbering); kNoVertex, with the first problem naming `key`,
    /// when its vertex is not on the mesh.
    VertexId place(const SurfacePoint& point, const std::string& key);
    const TissueMesh& mesh() const { return mMesh; }

private:
    const TissueMesh& mMesh;
    std::string& mError;
};

class ExerciseGeometry {
public:
    /// Null with `error` naming the key when a vertex is not on the mesh.
    static std::shared_ptr<const ExerciseGeometry> build(const Exercise& exercise, const TissueMesh& mesh,
                                                         std::string& error);

    const Exercise& exercise() const { return mExercise; }
    const Rubric& rubric() const { return mRubric; }
    std::size_t vertexCount() const { return mRestMm.size(); }
    const std::vector<glm::vec3>& restMm() const { return mRestMm; }
    const std::vector<glm::vec3>& normals() const { return mNormals; }
    /// A third of the area of the triangles around each vertex (they sum to the surface area).
    const std::vector<float>& vertexAreasMm2() const { return mVertexAreaMm2; }
    /// The mesh's adjacency (TissueMesh's compressed form), for walks over the surface.
    const std::vector<std::uint32_t>& neighbourStart() const { return mNeighbourStart; }
    const std::vector<VertexId>& neighbours() const { return mNeighbours; }

    const std::vector<ResolvedTarget>& targets() const { return mPlaced.targets; }

    /// Find the lump: the centre vertex and its rest position, and the factor of every vertex
    /// (1 outside the inclusion); empty for other types.
    VertexId lumpVertex() const { return mPlaced.lumpVertex; }
    glm::vec3 lumpCentreMm() const { return mPlaced.lumpCentreMm; }
    const std::vector<float>& compliance() const { return mPlaced.compliance; }
    std::size_t inclusionVertexCount() const { return mPlaced.inclusionVertices; }
    /// Detect lumps: the lumps, and for every vertex the depth below it at which a lump begins to
    /// resist (engageDepthMm, 0 where there is none: with compliance 1 it does not matter) and the
    /// lump under it (-1: none). The compliance above is 1 / contrast over a lump.
    const std::vector<ResolvedLump>& lumps() const { return mPlaced.lumps; }
    const std::vector<float>& engageDepthMm() const { return mPlaced.engageDepthMm; }
    const std::vector<std::int16_t>& lumpOfVertex() const { return mPlaced.lumpOfVertex; }

    /// Trace: the polyline (snapped points), its length, and the points coverage is counted on
    /// (spaced at most 1 mm along it).
    const std::vector<glm::vec3>& pathMm() const { return mPlaced.pathMm; }
    /// The vertex (engine numbering) of each polyline point.
    const std::vector<VertexId>& pathVertices() const { return mPlaced.pathVertices; }
    double pathLengthMm() const { return mPlaced.pathLengthMm; }
    const std::vector<glm::vec3>& coverageSamplesMm() const { return mPlaced.coverageMm; }
    /// Distance from p to the polyline.
    double distanceToPathMm(const glm::vec3& p) const;

    /// Vertex (engine numbering) of a surface point: the file's vertex, or the nearest at rest.
    static VertexId snap(const SurfacePoint& point, const TissueMesh& mesh);

private:
    ExerciseGeometry() = default;

    Exercise mExercise;
    Rubric mRubric{};
    std::vector<glm::vec3> mRestMm, mNormals;
    std::vector<float> mVertexAreaMm2;
    std::vector<std::uint32_t> mNeighbourStart;
    std::vector<VertexId> mNeighbours;
    PlacedGeometry mPlaced;
};

/// Gives a scene the exercise's physics: for find-the-lump, the inclusion's compliance factors,
/// for detect-lumps the lumps' compliance and engagement depths, on its slope-ring model (the mesh must be the exercise's). "" or the problem. Not real-time:
/// call before the scene goes to the loop (RecordingPlayer's prepareScene does it for replays).
std::string applyExercisePhysics(const ExerciseGeometry& geometry, HapticScene& scene);

}  // namespace palpate
