#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "engine/core/MeshGenerator.h"
#include "engine/core/TissueMesh.h"

#include <iostream>

namespace palpate::cli {

namespace {

int generate(const std::vector<std::string>& words) {
    Args args(words, {}, {"shape", "vertices", "out"});
    if (!args.ok()) {
        std::cerr << "mesh generate: " << args.error() << "\n";
        return 2;
    }
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

int check(const std::vector<std::string>& words) {
    Args args(words, {}, {});
    if (!args.ok() || args.positional().size() != 1) {
        std::cerr << "mesh check: needs exactly one FILE" << (args.ok() ? "" : " (" + args.error() + ")") << "\n";
        return 2;
    }
    const auto result = TissueMesh::load(args.positional().front());
    std::cout << result.report.text();
    return result.mesh ? 0 : 1;
}

}  // namespace

int meshCommand(const std::vector<std::string>& words) {
    if (words.empty()) {
        std::cerr << "mesh: needs a subcommand: generate or check\n";
        return 2;
    }
    const std::vector<std::string> rest(words.begin() + 1, words.end());
    if (words.front() == "generate") return generate(rest);
    if (words.front() == "check") return check(rest);
    std::cerr << "mesh: unknown subcommand '" << words.front() << "' (use generate or check)\n";
    return 2;
}

}  // namespace palpate::cli
