#pragma once
// Parameters of the free-form deformation model (Sederberg and Parry 1986): the mesh embedded in
// a trivariate Bernstein lattice of control points; the tool moves the control points nearest the
// contact (docs/models.md).

#include "base/params/FieldTable.h"

#include <string>
#include <vector>

namespace palpate {

inline constexpr int kMaxFfdPointsPerAxis = 16;

struct FfdParams {
    /// Lattice resolution: control points per axis (Bernstein degree + 1), 2..kMaxFfdPointsPerAxis.
    /// 8 (degree 7): a basis function spans about box * sqrt(s (1 - s) / 7), 12-22 mm on the 117 mm
    /// lattice of the 100 mm sphere, the scale of the loaded region (5 radii of the 5 mm tool).
    int controlPointsPerAxis = 8;
    /// Control points moved per axis: the block whose indices are nearest the contact's lattice
    /// coordinates, 1..controlPointsPerAxis. 4 of 8 carry 85 % or more of a point's weight per axis.
    int movedPerAxis = 4;
    /// The lattice box is the mesh's bounding box grown on every side by this fraction of its
    /// diagonal, so that every vertex is strictly inside, 0..1.
    double marginFraction = 0.05;
    /// k_s: the rendered force is k_s times the touched vertex's displacement, N/mm. Default
    /// 2 a E* for the default tissue (E = 10 kPa, nu = 0.45) and tool (a = 5 mm): the punch's stiffness.
    double stiffnessNPerMm = 0.125;
};

/// The fields of FfdParams in file order (base/params/FieldTable.h).
FieldTable<FfdParams> ffdFields();

/// Every problem found, each naming the field; empty when valid.
Problems validateFfdParams(const FfdParams& params);

}  // namespace palpate
