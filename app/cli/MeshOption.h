#pragma once
// --mesh-unit U: the unit of a mesh file's coordinates, taken by every command that reads a mesh
// file (docs/meshes.md, "Units"), and the load that goes with it: scaled to mm, with one warning
// when the size in that unit is implausible for tissue.

#include "app/cli/CommandLine.h"
#include "engine/core/TissueMesh.h"

#include <optional>
#include <string>

namespace palpate::cli {

/// The option's name.
inline constexpr const char* kMeshUnitOption = "mesh-unit";

/// Defines --mesh-unit U on a command that reads a mesh file.
void addMeshUnitOption(CLI::App& command);

/// --mesh-unit's unit (mm when absent). nullopt with `error` ("--mesh-unit: 'furlong' is not a
/// mesh unit: use mm, cm, ...") when it does not parse.
std::optional<MeshUnit> meshUnitFromArgs(const Given& args, std::string& error);

/// What a warning tells the user to change when the unit is wrong: the option by default; for
/// a mesh an exercise names, the exercise's "mesh_unit" key.
struct MeshUnitSource {
    std::string exercisePath;  ///< "" for --mesh-unit
};

/// The warning for a mesh loaded in `unit` whose size is implausible for tissue: "<prefix>warning:
/// <path>: read as mm it is 1.5 mm across, ... (give --mesh-unit cm)". "" when it is plausible.
std::string meshUnitWarning(const std::string& prefix, const std::string& path, const MeshReport& report,
                            const MeshUnitSource& source = {});

/// TissueMesh::load in `unit`, printing meshUnitWarning (if any) as one line to stderr.
TissueMesh::LoadResult loadMeshFile(const std::string& prefix, const std::string& path, const MeshUnit& unit,
                                    const MeshUnitSource& source = {});

}  // namespace palpate::cli
