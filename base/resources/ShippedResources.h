#pragma once
// Where the shipped resources are (meshes, presets, exercises), and the default scene every front
// end opens.

#include <string>

namespace palpate {

/// Absolute path of a file under resources/, or "" when it cannot be found. Looks in
/// $PALPATE_RESOURCES, next to the executable (../resources, ../share/palpate), then the source tree.
std::string findResource(const std::string& relativePath);

/// The default scene's mesh, relative to resources/.
inline constexpr const char* kDefaultMesh = "meshes/stomach_3970.off";

}  // namespace palpate
