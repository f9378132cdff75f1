#pragma once
// The reference on the organ's own shape (docs/accuracy.md, "The organ's own shape"): the surface
// filled with tets over a rigid core, each vertex's layer as deep as the organ is thick there
// (SurfaceFill's local thickness), pressed by the flat punch of the tool at chosen sites with the
// linear FEM and with the hyperelastic FEM. Models calibrated elsewhere (the half-space punch) are
// measured against it, so no model is scored against the reference it was fitted to.

#include "engine/accuracy/Calibration.h"
#include "engine/accuracy/ModelError.h"
#include "engine/fem/SurfaceFill.h"

#include <memory>
#include <string>
#include <vector>

namespace palpate {

/// A point of the surface the sweep presses, and why it was chosen.
struct OrganSite {
    std::string name;            ///< "thin", "thick", "curved"
    VertexId vertex = 0;
    double thicknessMm = 0.0;    ///< the tissue layer under it
    double curvaturePerMm = 0.0; ///< mean convex curvature over two tool radii (1 / radius)
    std::string reason;
};

/// The thinnest layer, the thickest (the flattest of near ties), and the most convex point among
/// those with at least the median layer, at least 4 tool radii from the other two (curvature
/// without thinness). Throws std::invalid_argument when the surface has no such points.
std::vector<OrganSite> chooseOrganSites(const TissueMesh& mesh, const FilledSurface& filled, double toolRadiusMm);

struct OrganReferenceDef {
    ToolContact contact;                 ///< E, nu, the tool, and b for the hyperelastic law
    SurfaceFillDef fill = [] {
        SurfaceFillDef f;
        f.localThicknessFraction = 0.25;  // half the radius of a round section: its inner cells keep half their size
        return f;
    }();
    double maxDepthMm = 3.0;             ///< the deepest press (the sweep's tool depth)
    double maxDepthOverThickness = 0.3;  ///< ... and at most this fraction of the layer under the site
    int hyperelasticSteps = 6;           ///< depths the hyperelastic field is kept at (equal steps)
};

/// One depth of a reference: the force along the site's normal and every surface vertex's normal
/// displacement (positive into the tissue).
struct OrganField {
    double depthMm = 0.0;
    double forceN = 0.0;
    std::vector<double> normalDisplacementMm;
};

struct OrganReference {
    OrganSite site;
    double maxDepthMm = 0.0;             ///< the deepest press at this site
    OrganField linear;                   ///< at maxDepthMm (scales with depth)
    std::vector<OrganField> hyperelastic;  ///< ascending depth, up to maxDepthMm when completed
    bool hyperelasticCompleted = false;
    std::string failure;
    std::size_t nodes = 0, tets = 0;
    double seconds = 0.0;
};

/// The filled surface, made once, pressed at any site.
class OrganReferenceSolver {
public:
    /// Throws std::invalid_argument (bad contact, surface that cannot be filled).
    OrganReferenceSolver(const TissueMesh& mesh, const OrganReferenceDef& def);
    ~OrganReferenceSolver();
    const FilledSurface& filled() const;
    OrganReference solve(const OrganSite& site) const;

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

/// A model's error against a reference at the model's own indentation: the displacement error
/// (RMS within 5 tool radii over the reference's peak) and the force error. Linear: the field
/// scaled to that indentation. Hyperelastic: interpolated between the two depths around it; NaN
/// (measured = false) when the model went deeper than the reference reached.
struct OrganError {
    double displacementError = 0.0;
    double forceError = 0.0;
    double referenceForceN = 0.0;
    bool measured = false;
};
OrganError errorAgainstLinear(const OrganReference& ref, const TissueMesh& mesh, const std::vector<double>& modelNormalMm,
                              double modelIndentationMm, double modelForceN, double toolRadiusMm);
OrganError errorAgainstHyperelastic(const OrganReference& ref, const TissueMesh& mesh,
                                    const std::vector<double>& modelNormalMm, double modelIndentationMm,
                                    double modelForceN, double toolRadiusMm);

}  // namespace palpate
