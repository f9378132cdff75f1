#include "engine/core/SceneTarget.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <cmath>

namespace palpate {

VertexId defaultTargetVertex(const TissueMesh& mesh) {
    const auto& rest = mesh.restPositionsMm();
    VertexId best = 0;
    for (VertexId v = 1; v < rest.size(); ++v)
        if (rest[v].x > rest[best].x) best = v;
    // A flat side (a phantom block, an imported box) has many vertices at the largest x; the first
    // found may be on its rim, where the normal leans and a press slides off. Of those within a
    // hair of the largest x (float noise on a flat face; no curved mesh has ties at this
    // tolerance), the one nearest their centre is taken.
    const float tolerance = 1e-5f * glm::length(mesh.boundsMaxMm() - mesh.boundsMinMm());
    glm::dvec2 centre(0.0);
    std::size_t ties = 0;
    for (VertexId v = 0; v < rest.size(); ++v)
        if (rest[v].x >= rest[best].x - tolerance) {
            centre += glm::dvec2(rest[v].y, rest[v].z);
            ++ties;
        }
    if (ties < 2) return best;
    centre /= double(ties);
    const float maxX = rest[best].x;
    double bestDistance = INFINITY;
    for (VertexId v = 0; v < rest.size(); ++v) {
        if (rest[v].x < maxX - tolerance) continue;
        const double d = glm::length(glm::dvec2(rest[v].y, rest[v].z) - centre);
        if (d < bestDistance) {
            bestDistance = d;
            best = v;
        }
    }
    return best;
}

void aimAtDefaultTarget(HapticDevice& device, const TissueMesh& mesh, float toolRadiusMm) {
    if (mesh.vertexCount() == 0) return;
    const VertexId v = defaultTargetVertex(mesh);
    const glm::vec3 normal = mesh.restNormals()[v];
    device.setScene(mesh.restPositionsMm()[v] + toolRadiusMm * normal, normal, glm::vec3(0.0f, 1.0f, 0.0f));
}

}  // namespace palpate
