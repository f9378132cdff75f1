// palpate-cli exercise bundle|import: an exercise as one file, to hand to a trainee's computer
// (docs/scoring.md, "Exercise bundles"): its mesh, preset and scripted paths go with it.
#include "app/cli/Commands.h"
#include "base/resources/ShippedResources.h"
#include "engine/exercise/ExerciseBundle.h"

#include <filesystem>
#include <iostream>

namespace palpate::cli {

namespace {

int bundleCommand(const Given& args) {
    const std::string exercise = args.positional().at(0);
    const auto out = args.option("out");
    if (!out) {
        std::cerr << "exercise bundle: --out FILE is required (the bundle to write)\n";
        return 2;
    }
    if (const std::string error = writeExerciseBundle(exercise, *out, findResource); !error.empty()) {
        std::cerr << "exercise bundle: " << error << "\n";
        return 1;
    }
    std::cout << "wrote " << *out << " (" << std::filesystem::file_size(*out) << " bytes): " << exercise
              << " with its mesh, its preset and its scripted paths\n";
    return 0;
}

int importCommand(const Given& args) {
    const std::string bundle = args.positional().at(0);
    const std::string folder = args.option("into").value_or(".");
    std::string error;
    const auto imported = importExerciseBundle(bundle, folder, error);
    if (!imported) {
        std::cerr << "exercise import: " << error << "\n";
        return 1;
    }
    std::cout << "imported " << imported->exercisePath << "\n";
    for (const std::string& name : imported->files) std::cout << "  " << name << "\n";
    return 0;
}

}  // namespace

void defineExerciseCommands(CommandLine& cli) {
    CLI::App* exercise = cli.group(cli.root(), "exercise", "exercise files as bundles (docs/scoring.md)");
    CLI::App* bundle = cli.command(*exercise, "bundle",
                                   "write an exercise with its mesh, preset and scripted paths as one file",
                                   bundleCommand);
    addPositional(*bundle, "exercise", "the exercise file (JSON)")->required();
    addValue(*bundle, "out", "FILE", "the bundle to write (required; never one of its inputs)");
    CLI::App* import = cli.command(*exercise, "import",
                                   "write a bundle's exercise, mesh, preset and paths into a folder", importCommand);
    addPositional(*import, "bundle", "the bundle file")->required();
    addValue(*import, "into", "FOLDER",
             "where to write them (default: the current folder); nothing there is overwritten");
}

}  // namespace palpate::cli
