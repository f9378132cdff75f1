#pragma once
// Closed test meshes with an exact vertex count: the sphere and the stomach-like tube of the
// paper's Table 1. Both are rings of vertices between two poles, zipped into triangles, so any
// count >= 8 is reachable and the surface is closed, manifold and genus 0 (F = 2V - 4).

#include "engine/core/TissueMesh.h"
#include "base/io/FileLimits.h"

#include <optional>
#include <string>
#include <string_view>

namespace palpate {

enum class GeneratedShape { Sphere, Stomach };

std::optional<GeneratedShape> parseShape(std::string_view name);
std::string_view shapeName(GeneratedShape shape);

inline constexpr std::size_t kMinGeneratedVertices = 8;

/// Generates the shape with exactly `vertexCount` vertices (kMinGeneratedVertices to
/// kMaxMeshVertices, the most a mesh may have). The sphere
/// has radius 50 mm; the stomach is about 230 mm long. Returns the load result (validated).
TissueMesh::LoadResult generateMesh(GeneratedShape shape, std::size_t vertexCount);

}  // namespace palpate
