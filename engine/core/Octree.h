#pragma once
// Octree over the rest positions of a mesh whose vertices are in Morton order (TissueMesh does
// that), so every node is a contiguous vertex range [begin, end). Three nearest-vertex searches:
// linear (the paper's "previous"), the paper's searchNode kept as written, and our exact one.

#include "engine/core/TissueMesh.h"
#include "base/params/FieldTable.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace palpate {

struct OctreeDef {
    int maxDepth = 10;      ///< levels below the root, 1..20
    int leafCapacity = 16;  ///< a node with at most this many vertices is not split, >= 1
};

/// The fields of OctreeDef in file order (base/params/FieldTable.h).
FieldTable<OctreeDef> octreeFields();
/// Every problem of the definition, each naming the field; empty when usable.
Problems validateOctreeDef(const OctreeDef& def);

class Octree {
public:
    struct Node {
        glm::vec3 cellMinMm;  ///< the node's cube (the paper's OSP boundaries)
        float cellSizeMm;
        glm::vec3 tightMinMm;  ///< bounding box of the rest positions inside (for pruning)
        glm::vec3 tightMaxMm;
        std::uint32_t begin;  ///< vertex range in Morton order
        std::uint32_t end;
        std::int32_t child[8];  ///< -1 where the octant holds no vertex (the paper's NULL)
        bool leaf;
    };

    /// Builds over the mesh's rest positions. The mesh must be in Morton order (TissueMesh's default).
    Octree(const TissueMesh& mesh, const OctreeDef& def);

    const std::vector<Node>& nodes() const { return mNodes; }
    int depth() const { return mDepth; }
    std::size_t leafCount() const { return mLeafCount; }
    const OctreeDef& def() const { return mDef; }

    /// The paper's searchNode, as written: descends into every child whose cube holds the point and
    /// scans one leaf. Returns kNoVertex when the point is outside the root or lands in an empty
    /// octant; can miss the true nearest vertex when it lies in a neighbouring leaf.
    VertexId searchNodeFaithful(const glm::vec3& pointMm, std::span<const glm::vec3> positionsMm) const;

    /// Exact nearest vertex over `positionsMm` (current positions). Correct outside the root box and
    /// across leaf borders. The tree bounds rest positions; vertices that may have left their rest
    /// position must be listed in `displaced` (they are checked directly). `warmStart` (or kNoVertex)
    /// seeds the bound. Ties go to the lower index. Allocation-free.
    VertexId nearestExact(const glm::vec3& pointMm, std::span<const glm::vec3> positionsMm,
                          std::span<const VertexId> displaced, VertexId warmStart = kNoVertex) const;

    /// The `count` rest positions nearest to the point, ascending: fills ids and squared distances
    /// (both of length >= count) and, if given, the positions; returns how many were found (fewer
    /// on tiny meshes). `seedCount` ids already in `ids` (e.g. last query's answer) seed the
    /// bound, which makes a query near the previous one cheap. Allocation-free; for our
    /// touched-vertex search's cache.
    int nearestRestK(const glm::vec3& pointMm, int count, VertexId* ids, float* distance2Mm2, int seedCount = 0,
                     glm::vec3* positionsMm = nullptr) const;

    /// The searches (nearestExact, nearestRestK) scan a subtree of at most this many vertices
    /// whole instead of descending into it.
    static constexpr std::uint32_t kSearchLeafVertices = 32;

private:
    void build(std::uint32_t nodeIndex, const std::vector<std::uint64_t>& codes, int depth);

    /// Depth-first, nearest child first, over tight boxes of rest positions: calls scanLeaf(begin, end)
    /// for every leaf whose box is within sqrt(bound()) of the point (bound() may shrink as leaves
    /// are scanned). A fixed stack: each level pushes at most 8 entries and the depth is at most 21.
    template <typename Bound, typename ScanLeaf>
    void visitNearestFirst(const glm::vec3& pointMm, Bound bound, ScanLeaf scanLeaf) const;

    /// What the searches read of a node, packed (two per cache line, siblings side by side): its
    /// tight box, and its children (first index, count) or, for a leaf, its vertex range.
    struct SearchNode {
        glm::vec3 tightMinMm;
        glm::vec3 tightMaxMm;
        std::uint32_t a;  ///< first child, or first vertex of a leaf
        std::uint32_t b;  ///< child count, or end vertex of a leaf | kLeafBit
    };
    static constexpr std::uint32_t kLeafBit = 0x80000000u;
    void buildSearchNodes();

    OctreeDef mDef;
    std::vector<Node> mNodes;
    std::vector<SearchNode> mSearch;  // parallel to mNodes
    std::vector<glm::vec3> mRestMm;   // copy: the tree must not depend on the mesh's lifetime
    int mDepth = 0;
    std::size_t mLeafCount = 0;
};

/// Brute-force nearest vertex (the paper's "previous" search); ties go to the lower index.
VertexId nearestLinear(const glm::vec3& pointMm, std::span<const glm::vec3> positionsMm);

}  // namespace palpate
