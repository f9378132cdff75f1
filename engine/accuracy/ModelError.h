#pragma once
// How far a deformation model is from elasticity (docs/calibration.md): press the model's touched
// vertex straight in, let it settle, and compare its surface with the flat-punch solution at the same
// indentation. Displacement error: RMS over the vertices within 5 tool radii of the contact of
// (u_model - u_punch), divided by the peak (the indentation). Force error: |F_model - F_punch| / F_punch.

#include "engine/models/DeformationModel.h"
#include "engine/core/TissueMesh.h"
#include "engine/accuracy/Calibration.h"

namespace palpate {

struct PressDef {
    double toolDepthMm = 3.0;    ///< tool tip below the touched vertex's rest position
    int settleTicks = 300;       ///< ticks at 1 kHz before the surface is measured
    double regionInRadii = 5.0;  ///< compare vertices within this many tool radii (docs/calibration.md: 5)
};

struct ModelError {
    double displacementError = 0.0;  ///< RMS error / peak over the region
    double forceError = 0.0;         ///< relative, at the model's own indentation
    double indentationMm = 0.0;      ///< how far the touched vertex went in
    double forceN = 0.0;             ///< force the model renders
    double referenceForceN = 0.0;    ///< punch force at the same indentation
    int verticesCompared = 0;
};

/// Presses `model` (reset first) at `touched` and measures its error against the flat punch of
/// `contact`. Throws std::runtime_error when the model makes no contact (naming the vertex).
ModelError measureModelError(DeformationModel& model, const TissueMesh& mesh, VertexId touched,
                             const ToolContact& contact, const PressDef& press = {});

/// The displacement error alone for given per-vertex normal displacements (positive into the
/// tissue), e.g. a reference FEM's or an analytic field's. The peak is the touched vertex's value.
double displacementErrorAgainstPunch(const TissueMesh& mesh, VertexId touched, const std::vector<double>& normalDisplacementMm,
                                     double toolRadiusMm, double regionInRadii = 5.0, int* verticesCompared = nullptr);

/// The displacement error of `normalDisplacementMm` against any reference field (e.g. the FEM's),
/// over the same region as displacementErrorAgainstPunch; the peak is the reference's at `touched`.
double displacementErrorAgainstField(const TissueMesh& mesh, VertexId touched, const std::vector<double>& normalDisplacementMm,
                                     const std::vector<double>& referenceNormalDisplacementMm, double toolRadiusMm,
                                     double regionInRadii = 5.0, int* verticesCompared = nullptr);

/// The normal displacement (positive into the tissue, along the touched vertex's rest normal) of a
/// model's current surface.
std::vector<double> normalDisplacementsMm(const DeformationModel& model, const TissueMesh& mesh, VertexId touched);

}  // namespace palpate
