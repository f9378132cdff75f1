#pragma once
// A lump marker of the instructor's see-through view under the vertex of `viewport`'s scene nearest
// the camera: its surface circle there and its body 8 mm inside, towards the camera's target.

#include "widgets/ExerciseMarkers.h"
#include "widgets/Viewport.h"

#include <glm/geometric.hpp>

namespace palpate::test {

inline ExerciseMarker lumpMarkerFacingTheCamera(const Viewport& viewport) {
    const auto positions = viewport.scene().positionsMm();
    const glm::vec3 eye = viewport.camera().eyeMm();
    std::size_t front = 0;
    for (std::size_t v = 1; v < positions.size(); ++v)
        if (glm::length(positions[v] - eye) < glm::length(positions[front] - eye)) front = v;
    const glm::vec3 surfaceMm = positions[front];
    const glm::vec3 inward = glm::normalize(viewport.camera().targetMm() - surfaceMm);
    ExerciseMarker lump;
    lump.kind = ExerciseMarker::Kind::Inclusion;
    lump.positionMm = surfaceMm;
    lump.normal = -inward;
    lump.radiusMm = 4.0;
    lump.bodyRadiusMm = 4.0;
    lump.bodyCentreMm = surfaceMm + 8.0f * inward;
    return lump;
}

}  // namespace palpate::test
