#include "engine/models/OctreeQueries.h"

#include <glm/common.hpp>

#include <cmath>
#include <limits>

namespace palpate {

namespace {

// Relative margin that keeps the pruning valid for float-rounded distances (they are within a
// few ulps, ~1e-7, of the true ones), as in CandidateCache (engine/models/slopering).
constexpr float kRoundingMargin = 1e-5f;

inline float distance2(const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 d = a - b;
    return d.x * d.x + d.y * d.y + d.z * d.z;
}

inline float boxDistance(const glm::vec3& p, const glm::vec3& lo, const glm::vec3& hi) {
    const glm::vec3 d = glm::max(lo - p, glm::vec3(0.0f)) + glm::max(p - hi, glm::vec3(0.0f));
    return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}

// Each level pushes at most 8 entries; the octree is at most 21 levels deep (maxDepth <= 20).
constexpr int kStackCapacity = 8 * 24;

}  // namespace

VertexId nearestWithBoundedDisplacement(const Octree& octree, const glm::vec3& p, std::span<const glm::vec3> positions,
                                        float maxDisplacementMm, VertexId hint) {
    const auto& nodes = octree.nodes();
    if (nodes.empty() || positions.empty()) return kNoVertex;
    VertexId best = kNoVertex;
    float bestD2 = std::numeric_limits<float>::infinity();
    if (hint < positions.size()) {
        best = hint;
        bestD2 = distance2(positions[hint], p);
    }
    const float bound = std::max(0.0f, maxDisplacementMm) * (1.0f + kRoundingMargin);
    // A node can hold the answer only if (box distance) - bound <= best distance.
    auto mayHold = [&](float boxD) {
        const float lower = boxD * (1.0f - kRoundingMargin) - bound;
        return lower <= 0.0f || lower * lower <= bestD2;
    };
    struct Entry {
        std::int32_t node;
        float boxD;
    };
    Entry stack[kStackCapacity];
    int top = 0;
    stack[top++] = {0, boxDistance(p, nodes[0].tightMinMm, nodes[0].tightMaxMm)};
    while (top > 0) {
        const Entry e = stack[--top];
        if (!mayHold(e.boxD)) continue;
        const Octree::Node& node = nodes[std::size_t(e.node)];
        if (node.leaf) {
            for (std::uint32_t v = node.begin; v < node.end; ++v) {
                const float d2 = distance2(positions[v], p);
                if (d2 < bestD2 || (d2 == bestD2 && v < best)) {
                    bestD2 = d2;
                    best = v;
                }
            }
            continue;
        }
        Entry children[8];
        int count = 0;
        for (int i = 0; i < 8; ++i) {
            const std::int32_t c = node.child[i];
            if (c < 0) continue;
            const Octree::Node& child = nodes[std::size_t(c)];
            const float d = boxDistance(p, child.tightMinMm, child.tightMaxMm);
            if (!mayHold(d)) continue;
            int k = count++;  // farthest first, so the nearest is popped first
            while (k > 0 && children[k - 1].boxD < d) {
                children[k] = children[k - 1];
                --k;
            }
            children[k] = {c, d};
        }
        for (int i = 0; i < count; ++i) stack[top++] = children[i];
    }
    return best;
}

std::size_t restVerticesWithinRadius(const Octree& octree, std::span<const glm::vec3> rest, const glm::vec3& c,
                                     float radiusMm, VertexId* out, std::size_t capacity) {
    const auto& nodes = octree.nodes();
    if (nodes.empty() || !(radiusMm >= 0.0f)) return 0;
    const float r2 = radiusMm * radiusMm;
    std::size_t count = 0;
    auto put = [&](VertexId v) {
        if (count < capacity) out[count] = v;
        ++count;
    };
    std::int32_t stack[kStackCapacity];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Octree::Node& node = nodes[std::size_t(stack[--top])];
        if (boxDistance(c, node.tightMinMm, node.tightMaxMm) > radiusMm) continue;
        if (node.leaf) {
            for (std::uint32_t v = node.begin; v < node.end; ++v)
                if (distance2(rest[v], c) <= r2) put(v);
            continue;
        }
        for (int i = 7; i >= 0; --i)
            if (node.child[i] >= 0) stack[top++] = node.child[i];
    }
    return count;
}

}  // namespace palpate
