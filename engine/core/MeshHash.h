#pragma once
// A 64-bit fingerprint of a mesh as the engine uses it (rest positions in the engine's vertex
// order, then the triangles), stored in a recording so that a replay refuses a different mesh: the
// touched-vertex ids and the forces only reproduce on the very same geometry.

#include "engine/core/TissueMesh.h"

#include <cstdint>

namespace palpate {

/// FNV-1a over the vertex count, the rest positions' float bits, the triangle count and the
/// triangles' vertex ids (little-endian). Equal meshes give equal hashes on every platform.
std::uint64_t meshHash(const TissueMesh& mesh);

}  // namespace palpate
