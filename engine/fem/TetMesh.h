#pragma once
// A linear tetrahedral mesh: the input of the reference FEM (LinearElasticFem), made by the graded
// block (GradedBlock) and the surface filler (SurfaceFill). Plain data, no topology checks here.

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace palpate {

using TetNodeId = std::uint32_t;

/// Nodes (mm) and 4-node tets. Each tet is positively oriented:
/// dot(n1 - n0, cross(n2 - n0, n3 - n0)) > 0.
struct TetMesh {
    std::vector<glm::dvec3> nodesMm;
    std::vector<std::array<TetNodeId, 4>> tets;

    std::size_t nodeCount() const { return nodesMm.size(); }
    std::size_t tetCount() const { return tets.size(); }
    std::size_t dofCount() const { return 3 * nodesMm.size(); }
};

/// Six times the signed volume of a tet (positive for the orientation above).
inline double tetSignedVolume6(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
    const glm::dvec3 u = b - a, v = c - a, w = d - a;
    return u.x * (v.y * w.z - v.z * w.y) - u.y * (v.x * w.z - v.z * w.x) + u.z * (v.x * w.y - v.y * w.x);
}

}  // namespace palpate
