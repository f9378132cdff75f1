#pragma once
// The reference FEM on any tissue surface: a closed, outward-oriented TissueMesh is filled with
// tets (prism layers extruded inward along the vertex normals, each prism split into 3 tets), the
// innermost layer is held fixed (tissue over a rigid core), and a flat punch pressed at a surface
// vertex gives the per-vertex displacement and the force that slope calibration fits to.
// Own method (no TetGen/CGAL: licences). Units: mm, N, N/mm^2.

#include "engine/core/TissueMesh.h"
#include "engine/fem/LinearElasticFem.h"
#include "engine/fem/TetMesh.h"

#include <glm/vec3.hpp>

#include <memory>
#include <optional>
#include <vector>

namespace palpate {

struct SurfaceFillDef {
    int layers = 4;                      ///< prism layers, 1..32
    /// Total thickness T (mm) of the tissue over the core; nullopt = a quarter of the smallest
    /// extent of the bounding box. Must be positive and finite when given.
    std::optional<double> thicknessMm;
    double layerGrowth = 1.5;            ///< each layer this much thicker than the one outside it (fine at the surface)
    int maxHalvings = 6;                 ///< T is halved at most this often while a tet inverts
    /// 0: every vertex's column is T deep. Above 0 (at most 0.45): vertex v's column is
    /// min(T, fraction * d_v), d_v the distance from v along -n_v to the surface's other side, so a
    /// thin part of the organ gets a thin layer and the rest keeps T (docs/accuracy.md, "Local
    /// thickness"); neighbouring columns then differ by at most maxThicknessSlope per mm apart.
    double localThicknessFraction = 0.0;
    double maxThicknessSlope = 0.5;
};

/// The filled surface. Node node(v, l) is surface vertex v (TissueMesh order) moved inward along
/// its normal by the depth of layer l (l = 0: the surface itself, l = layers: the fixed core).
struct FilledSurface {
    TetMesh mesh;
    std::size_t surfaceVertexCount = 0;
    int layers = 0;
    /// A vertex's column of nodes is contiguous (better locality for the solver than layer-major).
    TetNodeId node(VertexId v, int layer) const { return TetNodeId(std::size_t(v) * std::size_t(layers + 1) + std::size_t(layer)); }
    double requestedThicknessMm = 0.0;
    double thicknessMm = 0.0;            ///< as used, after halvings (the deepest column with local thickness)
    std::vector<double> vertexThicknessMm;  ///< each surface vertex's column depth, as used
    int halvings = 0;
    double minTetVolumeMm3 = 0.0;
    double seconds = 0.0;
};

/// Fills the surface. Throws std::invalid_argument with a message naming the problem: open or
/// inward-facing surface, bad options, or no positive-volume fill after maxHalvings.
FilledSurface fillSurface(const TissueMesh& mesh, const SurfaceFillDef& options = {});

struct SurfaceIndentation {
    std::vector<glm::dvec3> displacementMm;  ///< per surface vertex, TissueMesh order
    double reactionForceN = 0.0;             ///< along the touched vertex's rest normal, positive pushing in
    std::size_t prescribedVertexCount = 0;   ///< surface vertices under the punch
    std::size_t nodes = 0, tets = 0, dofs = 0, freeDofs = 0;
    double thicknessMm = 0.0;
    FemSolveStats solve;
    double seconds = 0.0;                    ///< assembly + factorization + solve of this indentation
};

/// One filled surface, indented at any vertex (the fill is done once).
class SurfaceIndenter {
public:
    /// Throws std::invalid_argument (see fillSurface; also a bad material).
    SurfaceIndenter(const TissueMesh& mesh, const ElasticMaterial& material, const SurfaceFillDef& fill = {},
                    const FemSolverDef& solver = {});

    /// Flat frictionless punch of radius a: the surface vertices within distance a of `touched`
    /// (at least `touched`) move by `indentationMm` along minus the touched vertex's rest normal;
    /// their motion across that normal is free. Throws std::invalid_argument on bad input.
    SurfaceIndentation indent(VertexId touched, double punchRadiusMm, double indentationMm) const;

    const FilledSurface& filled() const { return mFilled; }
    /// Time to assemble K once (global frame); each indentation rotates it instead of reassembling.
    double assemblySeconds() const { return mStiffness.assemblySeconds(); }

private:
    std::vector<glm::dvec3> mRestMm;
    std::vector<glm::dvec3> mNormals;
    FemSolverDef mSolver;
    FilledSurface mFilled;
    StiffnessMatrix mStiffness;
};

/// Convenience: fill and indent once.
SurfaceIndentation indentSurface(const TissueMesh& mesh, VertexId touched, double punchRadiusMm, double indentationMm,
                                 const ElasticMaterial& material, const SurfaceFillDef& fill = {});

}  // namespace palpate
