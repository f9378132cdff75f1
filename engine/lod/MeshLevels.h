#pragma once
// A mesh's levels of detail (docs/lod.md): the source surface and coarser copies of it made by the
// OpenMesh Decimater (MeshDecimation.h), each tied to the source by a mapping both ways
// (SurfaceEmbedding.h), so that a deformation computed on any level can be shown on any other.
// Generation may run on a worker thread: it reports progress and stops when asked.

#include "base/params/Problem.h"

#include "engine/core/TissueMesh.h"
#include "engine/lod/MeshDecimation.h"
#include "engine/lod/SurfaceEmbedding.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace palpate {

/// Which levels to make. The defaults give 8664 -> 4332 -> 2166 -> 1083 -> 541 -> 270.
struct LevelDef {
    double vertexRatio = 0.5;        ///< each level keeps this fraction of the previous one's vertices
    std::size_t minVertices = 250;   ///< no level below this
    int maxCoarseLevels = 5;         ///< levels besides the source
    DecimationGuards guards;
};

/// "" when usable, else a message naming the field.
Problems validateLevelDef(const LevelDef& options);
/// The vertex counts the coarse levels aim at for a source of `sourceVertices` (descending).
std::vector<std::size_t> levelTargets(std::size_t sourceVertices, const LevelDef& options);

struct MeshLevel {
    TissueMesh mesh;
    std::size_t targetVertices = 0;          ///< what was asked; the mesh may have more (guards)
    double seconds = 0.0;                    ///< time to make it (decimation share and mapping)
    std::vector<EmbeddedPoint> fineOnLevel;  ///< each source vertex on this level's triangles (empty at level 0)
    std::vector<EmbeddedPoint> levelOnFine;  ///< each of this level's vertices on the source's triangles
};

/// Called with the fraction done (0..1) and what is being done, from the generating thread.
using LodProgressFn = std::function<void(double fraction, const std::string& stage)>;

struct MeshLevels {
    std::vector<MeshLevel> levels;   ///< [0] is the source; then coarser, fewer vertices each
    std::uint64_t sourceHash = 0;    ///< meshHash of the source (engine/core/MeshHash.h)
    bool cancelled = false;          ///< generation stopped early; the levels made so far are kept
    std::vector<std::string> notes;  ///< targets the guards did not let the decimater reach, ...

    /// A state of `level` (positions in its vertex order) shown on the source surface.
    std::vector<glm::vec3> toFine(std::size_t level, std::span<const glm::vec3> levelPositionsMm) const;
    /// A state of the source surface carried to `level`.
    std::vector<glm::vec3> fromFine(std::size_t level, std::span<const glm::vec3> finePositionsMm) const;
    /// Between any two levels, through the source (the one surface every level is tied to).
    std::vector<glm::vec3> transfer(std::size_t fromLevel, std::size_t toLevel, std::span<const glm::vec3> positionsMm) const;
};

/// Makes the levels. Throws std::invalid_argument for bad options (naming the field) and
/// std::runtime_error when the source cannot be decimated (naming the mesh). On cancel, returns
/// the complete levels made so far with `cancelled` set.
MeshLevels generateLevels(const TissueMesh& source, const LevelDef& options, const LodProgressFn& progress = {},
                          const std::atomic<bool>* cancel = nullptr);

/// A level from an already decimated mesh (the cache's): computes its mappings to `source`.
/// Returns false when cancelled.
bool mapLevelToSource(const TissueMesh& source, MeshLevel& level, const std::atomic<bool>* cancel = nullptr);

/// Counts of what makes a level unfit to simulate on: boundary edges on a closed source, and
/// non-manifold edges or vertices (TissueMesh's validation). "" when closed and manifold.
std::string levelTopologyProblem(const TissueMesh& source, const TissueMesh& level);

}  // namespace palpate
