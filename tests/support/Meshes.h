#pragma once
// The generated meshes tests use (MeshGenerator's closed spheres and stomachs of an exact vertex
// count), made once per process and shared: a test that needs its own copy takes one.

#include "engine/core/MeshGenerator.h"
#include "engine/core/TissueMesh.h"

#include <cstddef>

namespace palpate::test {

/// The generated mesh, made on first use (fails the test and throws when it cannot be made).
const TissueMesh& generatedMesh(GeneratedShape shape, std::size_t vertices);
/// A copy of the generated sphere of `vertices` vertices.
TissueMesh sphereMesh(std::size_t vertices);
/// The vertex furthest along +x at rest (where the simulated devices aim from the side).
VertexId sideVertex(const TissueMesh& mesh);

}  // namespace palpate::test
