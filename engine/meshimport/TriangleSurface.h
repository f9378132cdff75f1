#pragma once
// A triangle surface in mm as repair and remeshing hand it on (engine/meshimport): plain arrays, so
// that CGAL's types stay inside the files that use them.

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace palpate {

struct TriangleSurface {
    std::vector<glm::dvec3> positionsMm;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

}  // namespace palpate
