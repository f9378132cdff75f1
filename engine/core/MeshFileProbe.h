#pragma once
// A quick structural read of a mesh file before OpenMesh parses it: OpenMesh's readers accept
// truncated files and garbage silently in places, so counts declared by the format are checked here.

#include <string>

namespace palpate {

/// Returns "" when the file looks structurally whole, else the problem (without the path).
std::string probeMeshFile(const std::string& path);

}  // namespace palpate
