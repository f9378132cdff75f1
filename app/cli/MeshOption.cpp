#include "app/cli/MeshOption.h"

#include <iostream>

namespace palpate::cli {

void addMeshUnitOption(CLI::App& command) {
    addValue(command, kMeshUnitOption, "U",
             "the mesh file's unit: mm (default), cm, m, in, or mm per file unit (docs/meshes.md, \"Units\")");
}

std::optional<MeshUnit> meshUnitFromArgs(const Given& args, std::string& error) {
    const auto text = args.option(kMeshUnitOption);
    if (!text) return kMillimetres;
    std::string problem;
    auto unit = parseMeshUnit(*text, problem);
    if (!unit) error = std::string("--") + kMeshUnitOption + ": " + problem;
    return unit;
}

std::string meshUnitWarning(const std::string& prefix, const std::string& path, const MeshReport& report,
                            const MeshUnitSource& source) {
    // The report's sizes are in mm already: back to the file's own units for the suggestion.
    const auto suggestion = suggestMeshUnit(report.bboxDiagonalMm / report.unit.mmPerUnit, report.unit);
    if (!suggestion) return "";
    const std::string unit = suggestion->unit.text();
    const std::string fix = source.exercisePath.empty()
                                ? "give --" + std::string(kMeshUnitOption) + " " + unit
                                : "set \"mesh_unit\": \"" + unit + "\" in " + source.exercisePath;
    return prefix + "warning: " + path + ": " + suggestion->reason + " (" + fix + ")";
}

TissueMesh::LoadResult loadMeshFile(const std::string& prefix, const std::string& path, const MeshUnit& unit,
                                    const MeshUnitSource& source) {
    TissueMesh::LoadResult loaded = TissueMesh::load(path, unit);
    if (loaded.mesh)
        if (const std::string warning = meshUnitWarning(prefix, path, loaded.mesh->report(), source); !warning.empty())
            std::cerr << warning << "\n";
    return loaded;
}

}  // namespace palpate::cli
