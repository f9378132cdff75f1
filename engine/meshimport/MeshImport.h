#pragma once
// Importing a mesh made by another tool (docs/meshes.md): read it tolerantly, scale it to mm, name
// its faults, repair them with CGAL's Polygon Mesh Processing when asked, remesh it to uniform
// triangles when asked, and measure ring roundness before and after. `palpate-cli mesh import`
// and File > Import Mesh... are this one function.

#include "engine/core/MeshFaults.h"
#include "engine/core/MeshUnit.h"
#include "engine/core/RingRoundness.h"
#include "engine/core/TissueMesh.h"
#include "engine/meshimport/MeshRepair.h"

#include <glm/vec3.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

struct MeshImportDef {
    MeshUnit unit;                 ///< the file's unit; coordinates are scaled to mm
    bool repair = false;           ///< repair the faults (CGAL); without it a faulty mesh is refused
    KeepComponents keep = KeepComponents::Largest;  ///< with repair: pieces to keep
    bool fillHoles = true;         ///< with repair: close holes (fair patches)
    double remeshEdgeMm = 0.0;     ///< > 0: isotropic remeshing to this edge length (mm)
    int remeshIterations = 3;
    int roundnessRings = 3;        ///< rings measured for roundness
};
inline constexpr double kMinRemeshEdgeMm = 0.05;
inline constexpr int kMaxRemeshIterations = 20;

/// Progress for long imports: `fraction` in [0, 1] and the stage ("reading", "repairing",
/// "remeshing", "measuring"); return false to cancel (the import ends with errors "cancelled").
using ImportProgress = std::function<bool(double fraction, const std::string& stage)>;

struct MeshImportResult {
    std::string source;                      ///< the path read
    MeshUnit unit;                           ///< as used
    std::optional<UnitSuggestion> suggestion;  ///< when the size is implausible in `unit`
    double diagonalInFileUnits = 0.0;
    glm::dvec3 sizeMm{0.0};                  ///< bounding-box extent of the source, scaled
    std::size_t sourceVertices = 0;
    std::size_t sourcePolygons = 0;
    std::vector<std::string> notes;          ///< what was tolerated ("12 quads triangulated")
    MeshFaults faults;                       ///< of the source (after triangulation)
    std::vector<std::string> changes;        ///< every change repair and remeshing made
    std::optional<RingRoundness> roundnessBefore;  ///< source (or repaired, before remeshing)
    std::optional<RingRoundness> roundnessAfter;   ///< the result
    std::optional<TissueMesh> mesh;          ///< the result, in mm; absent on errors
    std::vector<std::string> errors;         ///< each names the source and the problem
    std::vector<std::string> warnings;

    bool ok() const { return mesh.has_value(); }
    /// Multi-line, what `palpate-cli mesh import` prints.
    std::string text() const;
};

MeshImportResult importMesh(const std::string& path, const MeshImportDef& options,
                            const ImportProgress& progress = {});

/// A remeshing edge length to offer for a mesh of this extent (mm): about 1/60 of the diagonal,
/// the Table 1 meshes' density, rounded to 0.1 mm.
double suggestedRemeshEdgeMm(const glm::dvec3& sizeMm);

}  // namespace palpate
