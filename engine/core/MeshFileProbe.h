#pragma once
// A quick structural read of a mesh file before the polygon-soup reader (engine/core/PolygonSoup.h)
// hands it to CGAL or OpenMesh: those readers accept truncated files silently, trust declared
// counts, and crash on some malformed headers, so the format's structure is checked here first
// (docs/meshes.md, "Reading").

#include <string>

namespace palpate {

/// Returns "" when the file looks structurally whole, else the problem (without the path). The file
/// is read through the bounded reader (base/io/InputFile.h): a FIFO, a device, a directory or a
/// file beyond kMeshFile's limit is refused before it is read; declared vertex and face counts
/// beyond kMaxMeshVertices / kMaxMeshFaces (base/io/FileLimits.h) are refused too.
std::string probeMeshFile(const std::string& path);

/// The same for a file's bytes; `extension` is lower case without the dot ("off").
std::string probeMeshBytes(const std::string& bytes, const std::string& extension);

}  // namespace palpate
