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

    const std::vector<ResolvedTarget>& targets() const { return mTargets; }

    /// Find the lump: the centre vertex and its rest position, and the factor of every vertex
    /// (1 outside the inclusion); empty for other types.
    VertexId lumpVertex() const { return mLumpVertex; }
    glm::vec3 lumpCentreMm() const { return mLumpCentreMm; }
    const std::vector<float>& compliance() const { return mCompliance; }
    std::size_t inclusionVertexCount() const { return mInclusionVertices; }
    /// Detect lumps: the lumps, and for every vertex the depth below it at which a lump begins to
    /// resist (engageDepthMm, 0 where there is none: with compliance 1 it does not matter) and the
    /// lump under it (-1: none). The compliance above is 1 / contrast over a lump.
    const std::vector<ResolvedLump>& lumps() const { return mLumps; }
    const std::vector<float>& engageDepthMm() const { return mEngageDepthMm; }
    const std::vector<std::int16_t>& lumpOfVertex() const { return mLumpOfVertex; }

    /// Trace: the polyline (snapped points), its length, and the points coverage is counted on
    /// (spaced at most 1 mm along it).
    const std::vector<glm::vec3>& pathMm() const { return mPathMm; }
    /// The vertex (engine numbering) of each polyline point.
    const std::vector<VertexId>& pathVertices() const { return mPathVertices; }
    double pathLengthMm() const { return mPathLengthMm; }
    const std::vector<glm::vec3>& coverageSamplesMm() const { return mCoverageMm; }
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
    std::vector<ResolvedTarget> mTargets;
    VertexId mLumpVertex = kNoVertex;
    glm::vec3 mLumpCentreMm{0.0f};
    std::vector<float> mCompliance;
    std::size_t mInclusionVertices = 0;
    std::vector<ResolvedLump> mLumps;
    std::vector<float> mEngageDepthMm;
    std::vector<std::int16_t> mLumpOfVertex;
    std::vector<glm::vec3> mPathMm, mCoverageMm;
    std::vector<VertexId> mPathVertices;
    double mPathLengthMm = 0.0;
};

/// Gives a scene the exercise's physics: for find-the-lump, the inclusion's compliance factors,
/// for detect-lumps the lumps' compliance and engagement depths, on its slope-ring model (the mesh must be the exercise's). "" or the problem. Not real-time:
/// call before the scene goes to the loop (RecordingPlayer's prepareScene does it for replays).
std::string applyExercisePhysics(const ExerciseGeometry& geometry, HapticScene& scene);

}  // namespace palpate
