#include "engine/core/SpaceFillingCurve.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace palpate {

namespace {
std::uint64_t spreadBits(std::uint64_t x) {
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffffULL;
    x = (x | x << 16) & 0x1f0000ff0000ffULL;
    x = (x | x << 8) & 0x100f00f00f00f00fULL;
    x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
    x = (x | x << 2) & 0x1249249249249249ULL;
    return x;
}
}  // namespace

MortonCube mortonCubeFor(const std::vector<glm::vec3>& pointsMm) {
    MortonCube cube;
    if (pointsMm.empty()) return cube;
    glm::vec3 lo = pointsMm.front(), hi = pointsMm.front();
    for (const glm::vec3& p : pointsMm) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::vec3 extent = hi - lo;
    float size = std::max({extent.x, extent.y, extent.z});
    if (!(size > 0.0f)) size = 1.0f;
    size *= 1.0001f;  // keep the maximum strictly inside the last cell
    const glm::vec3 centre = 0.5f * (lo + hi);
    cube.originMm = centre - glm::vec3(0.5f * size);
    cube.sizeMm = size;
    return cube;
}

std::uint64_t mortonCode(const MortonCube& cube, const glm::vec3& pointMm) {
    constexpr double cells = double(1u << kMortonBitsPerAxis);
    std::uint64_t c[3];
    for (int a = 0; a < 3; ++a) {
        double t = (double(pointMm[a]) - double(cube.originMm[a])) / double(cube.sizeMm) * cells;
        t = std::clamp(t, 0.0, cells - 1.0);
        c[a] = std::uint64_t(t);
    }
    return spreadBits(c[0]) << 2 | spreadBits(c[1]) << 1 | spreadBits(c[2]);
}

std::vector<std::uint32_t> mortonOrder(const std::vector<glm::vec3>& pointsMm, const MortonCube& cube) {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(pointsMm.size());
    for (std::uint32_t i = 0; i < pointsMm.size(); ++i) keyed[i] = {mortonCode(cube, pointsMm[i]), i};
    std::sort(keyed.begin(), keyed.end());
    std::vector<std::uint32_t> order(pointsMm.size());
    for (std::size_t i = 0; i < keyed.size(); ++i) order[i] = keyed[i].second;
    return order;
}

}  // namespace palpate
