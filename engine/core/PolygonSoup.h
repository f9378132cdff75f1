#pragma once
// A mesh file read as a polygon soup: points and polygons, with no topology imposed, so that a
// faulty file's real faults can be named (engine/core/MeshFaults.h) and repaired
// (engine/meshimport) instead of being hidden by a reader that splits or drops faces. Tolerant
// where other tools are tolerant (docs/meshes.md, "Reading").

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace palpate {

struct PolygonSoup {
    std::vector<glm::dvec3> points;                       ///< in the file's unit
    std::vector<std::vector<std::uint32_t>> polygons;     ///< 0-based indices into points
    /// What the reader tolerated, one line each ("1 trailing NUL byte ignored", "mixed line ends
    /// (CR LF and LF)", "12 quads and 3 polygons triangulated", "texture and normal indices ignored").
    std::vector<std::string> notes;
};

/// Reads OBJ, OFF (plain ASCII), PLY (ASCII and binary), STL (ASCII and binary) or OM through the
/// bounded reader (base/io/InputFile.h, kMeshFile). The bytes are sanitised first (trailing NULs,
/// line ends, tabs, a byte-order mark; OBJ corner syntax and records), then checked by
/// probeMeshBytes (engine/core/MeshFileProbe.h). Returns "" on success, else the problem without
/// the path ("line 12: a face refers to vertex 40, but the file has 38"); the soup is then empty.
/// Never throws.
std::string readPolygonSoup(const std::string& path, PolygonSoup& soup);

/// The same for a file's bytes; `extension` is lower case without the dot ("obj").
std::string readPolygonSoupBytes(const std::string& bytes, const std::string& extension, PolygonSoup& soup);

/// Splits every polygon of more than three corners into triangles (a fan from its first corner,
/// as OpenMesh does, for convex polygons; ear clipping in the polygon's best-fit plane otherwise)
/// and appends a note counting them. Polygons of fewer than three corners are dropped, counted too.
std::vector<std::array<std::uint32_t, 3>> triangulatePolygons(const PolygonSoup& soup, std::vector<std::string>& notes);

}  // namespace palpate
