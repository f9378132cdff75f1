#include "engine/core/SceneTarget.h"

namespace palpate {

VertexId defaultTargetVertex(const TissueMesh& mesh) {
    const auto& rest = mesh.restPositionsMm();
    VertexId best = 0;
    for (VertexId v = 1; v < rest.size(); ++v)
        if (rest[v].x > rest[best].x) best = v;
    return best;
}

void aimAtDefaultTarget(HapticDevice& device, const TissueMesh& mesh, float toolRadiusMm) {
    if (mesh.vertexCount() == 0) return;
    const VertexId v = defaultTargetVertex(mesh);
    const glm::vec3 normal = mesh.restNormals()[v];
    device.setScene(mesh.restPositionsMm()[v] + toolRadiusMm * normal, normal, glm::vec3(0.0f, 1.0f, 0.0f));
}

}  // namespace palpate
