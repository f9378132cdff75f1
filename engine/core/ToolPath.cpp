#include "engine/core/ToolPath.h"

#include "engine/core/SceneTarget.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>

namespace palpate {

std::vector<glm::vec3> makePressAndStrokePath(const TissueMesh& mesh, const ToolPathDef& def) {
    const auto& rest = mesh.restPositionsMm();
    const auto& normals = mesh.restNormals();
    const VertexId start = defaultTargetVertex(mesh);

    // Stroke: a greedy walk over the mesh towards a target along the tangent, as a polyline of
    // surface points and normals.
    glm::vec3 tangent = glm::vec3(0, 1, 0) - glm::dot(glm::vec3(0, 1, 0), normals[start]) * normals[start];
    if (glm::length(tangent) < 1e-3f) tangent = glm::vec3(0, 0, 1);
    tangent = glm::normalize(tangent);
    const glm::vec3 target = rest[start] + float(def.strokeLengthMm) * tangent;
    std::vector<VertexId> walk{start};
    for (;;) {
        const VertexId at = walk.back();
        VertexId best = at;
        float bestD = glm::length(rest[at] - target);
        for (std::uint32_t k = mesh.neighbourStart()[at]; k < mesh.neighbourStart()[at + 1]; ++k) {
            const VertexId w = mesh.neighbours()[k];
            const float d = glm::length(rest[w] - target);
            if (d < bestD) {
                bestD = d;
                best = w;
            }
        }
        if (best == at) break;
        walk.push_back(best);
    }
    std::vector<float> arc(walk.size(), 0.0f);
    for (std::size_t i = 1; i < walk.size(); ++i) arc[i] = arc[i - 1] + glm::length(rest[walk[i]] - rest[walk[i - 1]]);
    auto surfaceAt = [&](float s, glm::vec3& point, glm::vec3& normal) {
        if (walk.size() == 1 || arc.back() <= 0.0f) {
            point = rest[walk[0]];
            normal = normals[walk[0]];
            return;
        }
        s = std::clamp(s, 0.0f, arc.back());
        std::size_t i = std::size_t(std::upper_bound(arc.begin(), arc.end(), s) - arc.begin());
        i = std::clamp<std::size_t>(i, 1, walk.size() - 1);
        const float t = (s - arc[i - 1]) / std::max(1e-6f, arc[i] - arc[i - 1]);
        point = glm::mix(rest[walk[i - 1]], rest[walk[i]], t);
        normal = glm::normalize(glm::mix(normals[walk[i - 1]], normals[walk[i]], t));
    };

    std::vector<glm::vec3> path;
    path.reserve(std::size_t(def.approachTicks + def.pressTicks + def.holdTicks + def.strokeTicks + def.releaseTicks));
    const float depth = float(def.depthMm);
    const float above = 2.0f;
    glm::vec3 p, n;
    surfaceAt(0.0f, p, n);
    for (int i = 0; i < def.approachTicks; ++i) path.push_back(p + n * (above * (1.0f - float(i) / def.approachTicks)));
    for (int i = 0; i < def.pressTicks; ++i) path.push_back(p - n * (depth * float(i + 1) / def.pressTicks));
    for (int i = 0; i < def.holdTicks; ++i) path.push_back(p - n * depth);
    for (int i = 0; i < def.strokeTicks; ++i) {
        surfaceAt(arc.back() * float(i + 1) / def.strokeTicks, p, n);
        path.push_back(p - n * depth);
    }
    for (int i = 0; i < def.releaseTicks; ++i)
        path.push_back(p + n * (-depth + (depth + above) * float(i + 1) / def.releaseTicks));
    return path;
}

}  // namespace palpate
