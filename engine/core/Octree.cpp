#include "engine/core/Octree.h"

#include "engine/core/SpaceFillingCurve.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cassert>
#include <limits>
#include <stdexcept>

namespace palpate {

namespace {

inline float distance2(const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 d = a - b;
    return d.x * d.x + d.y * d.y + d.z * d.z;
}

inline float boxDistance2(const glm::vec3& p, const glm::vec3& lo, const glm::vec3& hi) {
    const glm::vec3 below = glm::max(lo - p, glm::vec3(0.0f));
    const glm::vec3 above = glm::max(p - hi, glm::vec3(0.0f));
    const glm::vec3 d = below + above;
    return d.x * d.x + d.y * d.y + d.z * d.z;
}

inline bool closer(float d2, VertexId v, float bestD2, VertexId best) {
    return d2 < bestD2 || (d2 == bestD2 && v < best);
}

}  // namespace

namespace {
constexpr FieldDef<OctreeDef> kOctreeFields[] = {
    field<&OctreeDef::maxDepth>({.key = "maxDepth",
                                 .jsonKey = "max_depth",
                                 .lo = 1,
                                 .hi = 20,
                                 .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Max depth:"),
                                 .name = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "octree depth"),
                                 .tip = PALPATE_TRANSLATE_NOOP("palpate::Parameters",
                                                               "Levels below the octree's root (1..20).")}),
    field<&OctreeDef::leafCapacity>(
        {.key = "leafCapacity",
         .jsonKey = "leaf_capacity",
         .unit = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "vertices"),
         .lo = 1,
         .hi = 100000,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Leaf capacity:"),
         .name = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "leaf capacity"),
         .tip = PALPATE_TRANSLATE_NOOP("palpate::Parameters",
                                       "A node with at most this many vertices is not split (1..100000).")}),
};
}  // namespace

FieldTable<OctreeDef> octreeFields() { return kOctreeFields; }

Problems validateOctreeDef(const OctreeDef& def) {
    Problems problems;
    checkFields(octreeFields(), def, problems);
    for (Problem& p : problems) p.message = "octree " + p.message;
    return problems;
}

Octree::Octree(const TissueMesh& mesh, const OctreeDef& def) : mDef(def), mRestMm(mesh.restPositionsMm()) {
    if (const Problems problems = validateOctreeDef(def); !problems.empty())
        throw std::invalid_argument(joinedMessages(problems));
    const MortonCube cube = mortonCubeFor(mRestMm);
    std::vector<std::uint64_t> codes(mRestMm.size());
    for (std::size_t i = 0; i < mRestMm.size(); ++i) codes[i] = mortonCode(cube, mRestMm[i]);
    if (!std::is_sorted(codes.begin(), codes.end()))
        throw std::invalid_argument("Octree: mesh vertices are not in Morton order");
    Node root{};
    root.cellMinMm = cube.originMm;
    root.cellSizeMm = cube.sizeMm;
    root.begin = 0;
    root.end = std::uint32_t(mRestMm.size());
    mNodes.reserve(2 * mRestMm.size() / std::max(1, def.leafCapacity) + 16);
    mNodes.push_back(root);
    build(0, codes, 0);
    buildSearchNodes();
}

void Octree::buildSearchNodes() {
    mSearch.resize(mNodes.size());
    for (std::size_t i = 0; i < mNodes.size(); ++i) {
        const Node& node = mNodes[i];
        SearchNode& s = mSearch[i];
        s.tightMinMm = node.tightMinMm;
        s.tightMaxMm = node.tightMaxMm;
        // The searches stop at subtrees of at most kSearchLeafVertices vertices and scan them
        // whole (one contiguous range): fewer nodes to visit on fine meshes, where the paper's
        // leaves (def.leafCapacity) hold a handful of vertices each.
        if (node.leaf || node.end - node.begin <= kSearchLeafVertices) {
            s.a = node.begin;
            s.b = node.end | kLeafBit;
            continue;
        }
        // build() allocates a node's children side by side, in octant order.
        std::int32_t first = -1, count = 0;
        for (std::int32_t c : node.child) {
            if (c < 0) continue;
            if (first < 0) first = c;
            if (c != first + count) throw std::logic_error("Octree: children are not contiguous");
            ++count;
        }
        s.a = std::uint32_t(first);
        s.b = std::uint32_t(count);
    }
}

void Octree::build(std::uint32_t nodeIndex, const std::vector<std::uint64_t>& codes, int depth) {
    mDepth = std::max(mDepth, depth);
    {
        Node& node = mNodes[nodeIndex];
        std::fill(std::begin(node.child), std::end(node.child), -1);
        node.tightMinMm = glm::vec3(std::numeric_limits<float>::max());
        node.tightMaxMm = glm::vec3(-std::numeric_limits<float>::max());
        for (std::uint32_t v = node.begin; v < node.end; ++v) {
            node.tightMinMm = glm::min(node.tightMinMm, mRestMm[v]);
            node.tightMaxMm = glm::max(node.tightMaxMm, mRestMm[v]);
        }
        node.leaf = int(node.end - node.begin) <= mDef.leafCapacity || depth >= mDef.maxDepth ||
                    depth >= kMortonBitsPerAxis;
        if (node.leaf) {
            ++mLeafCount;
            return;
        }
    }
    // Children are allocated side by side before any is split, so that a search reading all
    // siblings' boxes touches consecutive memory.
    const int shift = 3 * (kMortonBitsPerAxis - 1 - depth);
    const std::uint32_t begin = mNodes[nodeIndex].begin, end = mNodes[nodeIndex].end;
    std::int32_t created[8];
    int createdCount = 0;
    std::uint32_t at = begin;
    for (int octant = 0; octant < 8; ++octant) {
        std::uint32_t stop = at;
        while (stop < end && int((codes[stop] >> shift) & 7u) == octant) ++stop;
        if (stop == at) continue;
        const Node& parent = mNodes[nodeIndex];
        Node child{};
        child.cellSizeMm = parent.cellSizeMm * 0.5f;
        // Morton interleaves x as the highest of each bit triple.
        child.cellMinMm = parent.cellMinMm + child.cellSizeMm * glm::vec3(float((octant >> 2) & 1),
                                                                          float((octant >> 1) & 1), float(octant & 1));
        child.begin = at;
        child.end = stop;
        const auto childIndex = std::int32_t(mNodes.size());
        mNodes.push_back(child);
        mNodes[nodeIndex].child[octant] = childIndex;
        created[createdCount++] = childIndex;
        at = stop;
    }
    assert(at == end);
    for (int i = 0; i < createdCount; ++i) build(std::uint32_t(created[i]), codes, depth + 1);
}

VertexId Octree::searchNodeFaithful(const glm::vec3& p, std::span<const glm::vec3> positionsMm) const {
    // Written recursively like the paper's pseudocode: every child whose cube holds the point is
    // visited; the last leaf scanned wins.
    VertexId touched = kNoVertex;
    auto search = [&](auto&& self, std::int32_t nodeIndex) -> void {
        if (nodeIndex < 0) return;  // octreeNode == NULL
        const Node& node = mNodes[std::size_t(nodeIndex)];
        const glm::vec3 hi = node.cellMinMm + glm::vec3(node.cellSizeMm);
        if (p.x < node.cellMinMm.x || p.y < node.cellMinMm.y || p.z < node.cellMinMm.z || p.x > hi.x || p.y > hi.y ||
            p.z > hi.z)
            return;  // point outside the boundaries of octreeNode
        if (!node.leaf) {
            for (int i = 0; i < 8; ++i) self(self, node.child[i]);
            return;
        }
        float bestD2 = std::numeric_limits<float>::infinity();
        VertexId best = kNoVertex;
        for (std::uint32_t v = node.begin; v < node.end; ++v) {
            const float d2 = distance2(positionsMm[v], p);
            if (d2 < bestD2) {
                bestD2 = d2;
                best = v;
            }
        }
        touched = best;
    };
    search(search, 0);
    return touched;
}

template <typename Bound, typename ScanLeaf>
void Octree::visitNearestFirst(const glm::vec3& p, Bound bound, ScanLeaf scanLeaf) const {
    struct Entry {
        std::uint32_t node;
        float d2;
    };
    Entry stack[8 * 24];
    int top = 0;
    const SearchNode* nodes = mSearch.data();
    stack[top++] = {0, boxDistance2(p, nodes[0].tightMinMm, nodes[0].tightMaxMm)};
    while (top > 0) {
        const Entry e = stack[--top];
        if (e.d2 > bound()) continue;
        const SearchNode& node = nodes[e.node];
        if (node.b & kLeafBit) {
            scanLeaf(node.a, node.b & ~kLeafBit);
            continue;
        }
        Entry children[8];
        int count = 0;
        for (std::uint32_t c = node.a, end = node.a + node.b; c < end; ++c) {
            const float d2 = boxDistance2(p, nodes[c].tightMinMm, nodes[c].tightMaxMm);
            if (d2 > bound()) continue;
            // Start fetching what visiting it will read (its children, or its vertices), so that
            // the cache misses of siblings overlap instead of queueing.
            if (nodes[c].b & kLeafBit) __builtin_prefetch(mRestMm.data() + nodes[c].a);
            else __builtin_prefetch(nodes + nodes[c].a);
            // insertion sort, farthest first, so the nearest is popped first
            int k = count++;
            while (k > 0 && children[k - 1].d2 < d2) {
                children[k] = children[k - 1];
                --k;
            }
            children[k] = {c, d2};
        }
        for (int i = 0; i < count; ++i) stack[top++] = children[i];
    }
}

VertexId Octree::nearestExact(const glm::vec3& p, std::span<const glm::vec3> positionsMm,
                              std::span<const VertexId> displaced, VertexId warmStart) const {
    VertexId best = kNoVertex;
    float bestD2 = std::numeric_limits<float>::infinity();
    if (warmStart != kNoVertex && warmStart < positionsMm.size()) {
        best = warmStart;
        bestD2 = distance2(positionsMm[warmStart], p);
    }
    for (VertexId v : displaced) {
        const float d2 = distance2(positionsMm[v], p);
        if (closer(d2, v, bestD2, best)) {
            bestD2 = d2;
            best = v;
        }
    }
    visitNearestFirst(
        p, [&] { return bestD2; },
        [&](std::uint32_t begin, std::uint32_t end) {
            for (std::uint32_t v = begin; v < end; ++v) {
                const float d2 = distance2(positionsMm[v], p);
                if (closer(d2, v, bestD2, best)) {
                    bestD2 = d2;
                    best = v;
                }
            }
        });
    return best;
}

int Octree::nearestRestK(const glm::vec3& p, int count, VertexId* ids, float* d2s, int seedCount,
                         glm::vec3* positionsMm) const {
    int found = 0;
    auto bound = [&] { return found < count ? std::numeric_limits<float>::infinity() : d2s[count - 1]; };
    auto insert = [&](VertexId v, float d2) {
        if (found == count && !(d2 < d2s[count - 1])) return;
        int k = found < count ? found++ : count - 1;
        while (k > 0 && d2s[k - 1] > d2) {
            d2s[k] = d2s[k - 1];
            ids[k] = ids[k - 1];
            --k;
        }
        d2s[k] = d2;
        ids[k] = v;
    };
    VertexId seeds[64];
    seedCount = std::clamp(seedCount, 0, std::min(count, 64));
    std::copy(ids, ids + seedCount, seeds);
    for (int i = 0; i < seedCount; ++i) insert(seeds[i], distance2(mRestMm[seeds[i]], p));
    visitNearestFirst(p, bound, [&](std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t v = begin; v < end; ++v) {
            const float d2 = distance2(mRestMm[v], p);
            if (found == count && !(d2 < d2s[count - 1])) continue;
            if (std::find(seeds, seeds + seedCount, v) != seeds + seedCount) continue;  // already in
            insert(v, d2);
        }
    });
    if (positionsMm)
        for (int i = 0; i < found; ++i) positionsMm[i] = mRestMm[ids[i]];
    return found;
}

VertexId nearestLinear(const glm::vec3& p, std::span<const glm::vec3> positionsMm) {
    VertexId best = kNoVertex;
    float bestD2 = std::numeric_limits<float>::infinity();
    for (std::size_t v = 0; v < positionsMm.size(); ++v) {
        const float d2 = distance2(positionsMm[v], p);
        if (d2 < bestD2) {
            bestD2 = d2;
            best = VertexId(v);
        }
    }
    return best;
}

}  // namespace palpate
