#pragma once
// A mesh's size as the window and the import dialog say it: "152 × 98 × 80 mm" (docs/meshes.md, "Units").

#include <glm/vec3.hpp>

#include <QString>

namespace palpate {

/// One extent in mm with the digits that matter at that size: "152", "9.8", "0.15".
QString formatLengthMm(double mm);
/// The bounding-box extent: "152 × 98 × 80 mm".
QString meshSizeText(const glm::dvec3& sizeMm);

}  // namespace palpate
