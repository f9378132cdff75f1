#include "app/cli/Commands.h"
#include "engine/core/MeshGenerator.h"
#include "engine/core/RingRoundness.h"
#include "engine/core/TissueMesh.h"
#include "engine/meshimport/MeshImport.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include <iostream>

namespace palpate::cli {

namespace {

int generate(const Given& args) {
    const auto shapeText = args.option("shape");
    const auto countText = args.option("vertices");
    const auto out = args.option("out");
    if (!shapeText || !countText || !out) {
        std::cerr << "mesh generate: needs --shape sphere|stomach --vertices N --out FILE\n";
        return 2;
    }
    const auto shape = parseShape(*shapeText);
    if (!shape) {
        std::cerr << "mesh generate: unknown shape '" << *shapeText << "' (use sphere or stomach)\n";
        return 2;
    }
    const auto count = parsePositiveInt(*countText);
    if (!count || *count < static_cast<long long>(kMinGeneratedVertices) ||
        std::uint64_t(*count) > kMaxMeshVertices) {
        std::cerr << "mesh generate: --vertices '" << *countText << "' must be a whole number from "
                  << kMinGeneratedVertices << " to " << kMaxMeshVertices << " (the most a mesh may have)\n";
        return 2;
    }
    auto result = generateMesh(*shape, std::size_t(*count));
    if (!result.mesh) {
        std::cerr << result.error() << "\n";
        return 1;
    }
    const std::string problem = result.mesh->save(*out);
    if (!problem.empty()) {
        std::cerr << problem << "\n";
        return 1;
    }
    std::cout << "wrote " << *out << ": " << shapeName(*shape) << ", " << result.mesh->vertexCount() << " vertices, "
              << result.mesh->triangleCount() << " triangles\n";
    return 0;
}

/// --unit, default mm; nullopt (and the message printed) when it is not a unit.
std::optional<MeshUnit> unitOption(const Given& args, const char* command) {
    const auto text = args.option("unit");
    if (!text) return kMillimetres;
    std::string error;
    auto unit = parseMeshUnit(*text, error);
    if (!unit) std::cerr << command << ": --unit " << error << "\n";
    return unit;
}

nlohmann::json roundnessJson(const RingRoundness& r) {
    nlohmann::json rings = nlohmann::json::array();
    for (int k = 1; k <= r.ringCount; ++k) rings.push_back(r.ringDistanceCv[k]);
    return {{"ring_distance_cv", rings}, {"edge_length_cv", r.edgeLengthCv}, {"mean_edge_mm", r.meanEdgeMm},
            {"min_edge_mm", r.minEdgeMm}, {"max_edge_mm", r.maxEdgeMm}, {"sampled_centres", r.sampledCentres}};
}

nlohmann::json faultsJson(const MeshFaults& f) {
    return {{"invalid_index_triangles", f.invalidIndexTriangles}, {"non_finite_vertices", f.nonFiniteVertices},
            {"degenerate_triangles", f.degenerateTriangles},      {"duplicate_vertices", f.duplicateVertices},
            {"non_manifold_edges", f.nonManifoldEdges},           {"misoriented_edges", f.misorientedEdges},
            {"bow_tie_vertices", f.bowTieVertices},               {"boundary_edges", f.boundaryEdges},
            {"holes", f.holes},                                   {"components", f.components},
            {"unused_vertices", f.unusedVertices}};
}

std::string roundnessText(const RingRoundness& r) {
    std::ostringstream out;
    out << std::fixed << std::setprecision(3) << "  ring roundness (CV of the distances to ring k; 0 = round):";
    for (int k = 1; k <= r.ringCount; ++k) out << " ring " << k << " " << r.ringDistanceCv[k];
    out << "; edge-length CV " << r.edgeLengthCv << std::setprecision(2) << " (edges " << r.minEdgeMm << " to "
        << r.maxEdgeMm << " mm, mean " << r.meanEdgeMm << ")\n";
    return out.str();
}

int check(const Given& args) {
    if (args.positional().size() != 1) {
        std::cerr << "mesh check: needs exactly one FILE\n";
        return 2;
    }
    const auto unit = unitOption(args, "mesh check");
    if (!unit) return 2;
    const std::string path = args.positional().front();
    const auto result = TissueMesh::load(path, *unit);
    const double diagonalInFileUnits = result.report.bboxDiagonalMm / unit->mmPerUnit;
    const auto suggestion = suggestMeshUnit(diagonalInFileUnits, *unit);
    std::optional<RingRoundness> roundness;
    if (result.mesh) roundness = measureRingRoundness(*result.mesh);
    if (args.flag("json")) {
        const MeshReport& r = result.report;
        nlohmann::json j = {{"file", path},
                            {"valid", result.mesh.has_value()},
                            {"unit", unit->text()},
                            {"size_mm", {r.sizeMm.x, r.sizeMm.y, r.sizeMm.z}},
                            {"diagonal_mm", r.bboxDiagonalMm},
                            {"vertices", r.vertexCount},
                            {"triangles", r.triangleCount},
                            {"holes", r.holeCount},
                            {"components", r.componentCount},
                            {"duplicate_vertices", r.duplicateVertexCount},
                            {"misoriented_edges", r.misorientedEdgeCount},
                            {"non_manifold_edges", r.nonManifoldEdgeCount},
                            {"bow_tie_vertices", r.nonManifoldVertexCount},
                            {"boundary_edges", r.boundaryEdgeCount},
                            {"notes", r.notes},
                            {"errors", r.errors},
                            {"warnings", r.warnings}};
        if (suggestion) j["suggested_unit"] = {{"unit", suggestion->unit.text()}, {"reason", suggestion->reason}};
        if (roundness) j["roundness"] = roundnessJson(*roundness);
        std::cout << j.dump(2) << "\n";
        return result.mesh ? 0 : 1;
    }
    std::cout << result.report.text();
    if (suggestion)
        std::cout << "  suggested unit: " << suggestion->unit.text() << " (" << suggestion->reason << "; use --unit "
                  << suggestion->unit.text() << ")\n";
    if (roundness) std::cout << roundnessText(*roundness);
    return result.mesh ? 0 : 1;
}

int import(const Given& args) {
    if (args.positional().size() != 1 || !args.option("out")) {
        std::cerr << "mesh import: needs IN --out OUT (palpate-cli mesh import --help lists the options)\n";
        return 2;
    }
    const std::string in = args.positional().front();
    const std::string out = *args.option("out");
    MeshImportDef def;
    const auto unit = unitOption(args, "mesh import");
    if (!unit) return 2;
    def.unit = *unit;
    def.repair = args.flag("repair");
    def.keep = args.flag("keep-all") ? KeepComponents::All : KeepComponents::Largest;
    def.fillHoles = !args.flag("no-fill-holes");
    // Their ranges are checked by their definitions (defineMeshCommands).
    if (const auto edge = args.option("remesh-edge-mm")) def.remeshEdgeMm = *parseNumber(*edge);
    if (const auto iterations = args.option("remesh-iterations"))
        def.remeshIterations = int(*parsePositiveInt(*iterations));
    if (const std::string refusal = outputIsAnInput("--out", out, {{in, "mesh being imported"}}); !refusal.empty()) {
        std::cerr << "mesh import: " << refusal << "\n";
        return 2;
    }
    std::error_code ec;
    if (std::filesystem::exists(out, ec) && !args.flag("overwrite")) {
        std::cerr << "mesh import: " << out << " exists; add --overwrite to replace it\n";
        return 2;
    }

    const MeshImportResult result = importMesh(in, def);
    std::string writeProblem;
    if (result.mesh) writeProblem = result.mesh->save(out);
    if (args.flag("json")) {
        nlohmann::json j = {{"file", in},
                            {"out", out},
                            {"written", result.mesh && writeProblem.empty()},
                            {"unit", result.unit.text()},
                            {"size_mm", {result.sizeMm.x, result.sizeMm.y, result.sizeMm.z}},
                            {"source_vertices", result.sourceVertices},
                            {"source_faces", result.sourcePolygons},
                            {"notes", result.notes},
                            {"faults", faultsJson(result.faults)},
                            {"fault_texts", result.faults.errorTexts()},
                            {"found_texts", result.faults.warningTexts()},
                            {"changes", result.changes},
                            {"warnings", result.warnings},
                            {"errors", result.errors}};
        if (result.suggestion)
            j["suggested_unit"] = {{"unit", result.suggestion->unit.text()}, {"reason", result.suggestion->reason}};
        if (result.roundnessBefore) j["roundness_before"] = roundnessJson(*result.roundnessBefore);
        if (result.roundnessAfter) j["roundness_after"] = roundnessJson(*result.roundnessAfter);
        if (result.mesh) j["result"] = {{"vertices", result.mesh->vertexCount()}, {"triangles", result.mesh->triangleCount()}};
        if (!writeProblem.empty()) j["errors"].push_back(writeProblem);
        std::cout << j.dump(2) << "\n";
    } else {
        std::cout << result.text();
        if (result.suggestion)
            std::cout << "  (to import in " << result.suggestion->unit.text() << ": --unit " << result.suggestion->unit.text()
                      << ")\n";
        if (result.mesh && writeProblem.empty()) std::cout << "wrote " << out << " (in mm)\n";
    }
    if (!writeProblem.empty()) std::cerr << writeProblem << "\n";
    if (!result.mesh) {
        for (const std::string& e : result.errors) std::cerr << e << "\n";
        return 1;
    }
    return writeProblem.empty() ? 0 : 1;
}

}  // namespace

void defineMeshCommands(CommandLine& cli) {
    CLI::App* mesh = cli.group(cli.root(), "mesh", "generate, check and import tissue meshes (docs/meshes.md)");
    const std::string unitText = "the file's unit: mm (default), cm, m, in, or mm per file unit";

    CLI::App* gen = cli.command(*mesh, "generate", "write a generated mesh", generate);
    addValue(*gen, "shape", "SHAPE", "the shape to generate")->check(oneOf({"sphere", "stomach"}));
    // The vertex count's range is checked by generate(), which names the most a mesh may have.
    addValue(*gen, "vertices", "N",
             "the vertex count, a whole number from " + std::to_string(kMinGeneratedVertices) + " to " +
                 std::to_string(kMaxMeshVertices));
    addValue(*gen, "out", "FILE", "the mesh file to write");

    CLI::App* chk = cli.command(*mesh, "check", "check a mesh file and report its faults", check);
    addPositional(*chk, "FILE", "the mesh file");
    addValue(*chk, "unit", "U", unitText);
    addFlag(*chk, "json", "print JSON");

    CLI::App* imp = cli.command(*mesh, "import", "repair, remesh and convert a mesh file", import);
    addPositional(*imp, "IN", "the mesh file to import");
    addValue(*imp, "out", "OUT", "the mesh file to write");
    addValue(*imp, "unit", "U", unitText);
    addFlag(*imp, "repair", "repair what can be repaired");
    addFlag(*imp, "keep-all", "keep every component (default: the largest)");
    addFlag(*imp, "no-fill-holes", "leave holes open");
    addValue(*imp, "remesh-edge-mm", "E", "remesh to this edge length, mm")->check(numberIn(kMinRemeshEdgeMm, 1e4));
    addValue(*imp, "remesh-iterations", "N", "remeshing iterations")->check(wholeNumberIn(1, kMaxRemeshIterations));
    addFlag(*imp, "overwrite", "replace OUT if it exists");
    addFlag(*imp, "json", "print JSON");
}

}  // namespace palpate::cli
