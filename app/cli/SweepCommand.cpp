// palpate-cli sweep: speed against accuracy for every model (docs/calibration.md), as a table, CSV, JSON and
// (in builds with Qt) the chart as a PNG.
#include "app/cli/Commands.h"
#include "app/cli/ToolContactOptions.h"
#include "engine/accuracy/AccuracySweep.h"
#include "engine/accuracy/OrganSweep.h"

#ifdef PALPATE_HAVE_CHARTS
#include "report/SweepChartImage.h"
#endif

#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace palpate::cli {

namespace {

void printTable(std::ostream& out, const SweepResult& result) {
    out << std::left << std::setw(9) << "shape" << std::right << std::setw(9) << "vertices" << "  " << std::left
        << std::setw(20) << "model" << std::right << std::setw(10) << "tick us" << std::setw(12) << "displ err"
        << std::setw(11) << "force err" << std::setw(8) << "pareto" << "\n";
    for (const SweepPoint& p : result.points)
        out << std::left << std::setw(9) << shapeName(p.shape) << std::right << std::setw(9) << p.vertices << "  "
            << std::left << std::setw(20) << p.series << std::right << std::fixed << std::setprecision(4)
            << std::setw(10) << p.tickUs << std::setprecision(3) << std::setw(12) << p.error.displacementError
            << std::setw(11) << p.error.forceError << std::setw(8) << (p.pareto ? "*" : "") << "\n";
}

void printOrganTable(std::ostream& out, const OrganSweepResult& result) {
    for (const OrganSiteSummary& s : result.sites)
        out << "site " << s.site.name << " (" << s.vertices << " vertices, vertex " << s.site.vertex << "): " << s.site.reason
            << "; pressed to " << std::setprecision(3) << s.depthMm << " mm: linear FEM " << s.linearForceN
            << " N, hyperelastic " << s.hyperelasticForceN << " N at " << s.hyperelasticDepthMm << " mm"
            << (s.hyperelasticCompleted ? "" : " (stopped: " + s.failure + ")") << "\n";
    out << std::left << std::setw(9) << "vertices" << std::setw(8) << "site" << std::setw(30) << "model" << std::right
        << std::setw(10) << "tick us" << std::setw(11) << "displ lin" << std::setw(11) << "force lin" << std::setw(12)
        << "displ hyper" << std::setw(12) << "force hyper" << std::setw(8) << "pareto" << "\n";
    for (const SweepPoint& p : result.sweep.points)
        out << std::left << std::setw(9) << p.vertices << std::setw(8) << p.site << std::setw(30) << p.series << std::right
            << std::fixed << std::setprecision(4) << std::setw(10) << p.tickUs << std::setprecision(3) << std::setw(11)
            << p.error.displacementError << std::setw(11) << p.error.forceError << std::setw(12)
            << p.hyperelasticDisplacementError << std::setw(12) << p.hyperelasticForceError << std::setw(8)
            << (p.pareto ? "*" : "") << "\n";
}

int sweepCommand(const Given& args) {
    const std::string reference = args.option("reference").value_or("punch");  // punch or fem, as defined
    const bool organ = reference == "fem";
    if (organ && args.option("shapes")) {
        std::cerr << "palpate-cli sweep: --shapes goes with --reference punch (the FEM reference is the stomach's)\n";
        return 2;
    }
    const ToolContactChoice choice = toolContactFromArgs(args);
    if (!choice.error.empty()) {
        std::cerr << "palpate-cli sweep: " << choice.error << "\n";
        return 2;
    }
    SweepDef def;
    def.contact = choice.contact;
    def.paperMethods = !args.flag("no-paper");
    def.otherModels = !args.flag("no-others");
    if (organ) def.sizes = {1442, 3970};
    if (args.flag("quick")) {
        def.shapes = {GeneratedShape::Sphere};
        def.sizes = organ ? std::vector<std::size_t>{1442} : std::vector<std::size_t>{1442, 3970};
        def.maxRings = 4;
        def.timingRepeats = 1;
        def.minMeasureMs = 2.0;
    }
    if (const auto shapes = args.option("shapes")) {
        def.shapes.clear();
        for (const std::string& s : splitList(*shapes)) {
            if (s == "sphere") def.shapes.push_back(GeneratedShape::Sphere);
            else if (s == "stomach") def.shapes.push_back(GeneratedShape::Stomach);
            else {
                std::cerr << "palpate-cli sweep: --shapes: unknown shape '" << s << "' (use sphere, stomach)\n";
                return 2;
            }
        }
    }
    if (const auto sizes = args.option("sizes")) {
        def.sizes.clear();
        for (const std::string& s : splitList(*sizes)) {
            const auto n = parsePositiveInt(s);
            if (!n || *n < 8 || *n > 2'000'000) {
                std::cerr << "palpate-cli sweep: --sizes: '" << s << "' is not a vertex count in 8..2000000\n";
                return 2;
            }
            def.sizes.push_back(std::size_t(*n));
        }
    }
    // Their ranges are checked by their definitions (defineSweepCommand).
    if (const auto rings = args.option("max-rings")) def.maxRings = int(*parsePositiveInt(*rings));
    if (const auto repeats = args.option("repeats")) def.timingRepeats = int(*parsePositiveInt(*repeats));
#ifndef PALPATE_HAVE_CHARTS
    if (args.option("png")) {
        std::cerr << "palpate-cli sweep: --png needs a build with the GUI (Qt Charts); this one has none\n";
        return 2;
    }
#endif
    const bool json = args.flag("json");
    def.progress = [&](double fraction, const std::string& line) {
        std::cerr << "[" << std::setw(3) << int(fraction * 100.0 + 0.5) << "%] " << line << "\n";
    };
    std::cerr << "sweep: E = " << def.contact.material.youngsModulusNPerMm2 * 1000.0 << " kPa, nu = "
              << def.contact.material.poissonRatio << ", tool radius " << def.contact.toolRadiusMm << " mm ("
              << choice.source << "); reference: "
              << (organ ? "the FEM of the filled stomach (linear and " +
                              std::string(hyperelasticLawName(hyperelasticMaterialOf(def.contact).law)) + ")"
                        : std::string("flat punch on a half-space"))
              << "\n";
    OrganSweepDef organDef;
    OrganSweepResult organResult;
    if (organ) {
        organDef.sweep = def;
        organDef.sizes = def.sizes;
        try {
            organResult = runOrganSweep(organDef);
        } catch (const std::exception& e) {
            std::cerr << "palpate-cli sweep: " << e.what() << "\n";
            return 1;
        }
    }
    const SweepResult result = organ ? organResult.sweep : runSweep(def);

    if (const auto csv = args.option("csv")) {
        std::ofstream out(*csv);
        out << sweepToCsv(result.points);
        if (!out) {
            std::cerr << "palpate-cli sweep: " << *csv << ": cannot be written\n";
            return 1;
        }
    }
#ifdef PALPATE_HAVE_CHARTS
    if (const auto png = args.option("png")) {
        std::string error;
        // One pane per shape, or per site of the organ sweep (three): each needs its height.
        if (!(error = renderSweepChartPng(result.points, def.contact, *png, 1400, organ ? 2400 : 1500)).empty()) {
            std::cerr << "palpate-cli sweep: " << *png << ": " << error << "\n";
            return 1;
        }
    }
#endif
    if (organ) {
        if (json) std::cout << organSweepToJson(organResult, organDef);
        else printOrganTable(std::cout, organResult);
    } else if (json) {
        std::cout << sweepToJson(result, def);
    } else {
        printTable(std::cout, result);
    }
    return 0;
}

}  // namespace

void defineSweepCommand(CommandLine& cli) {
    CLI::App* sweep = cli.command(cli.root(), "sweep",
                                  "tick time against error of every model and ring count (docs/accuracy.md)",
                                  sweepCommand);
    addValue(
        *sweep, "reference", "REF",
        "punch (default), or fem: the filled stomach's FEM (linear and hyperelastic) at its thin, thick and curved sites")
        ->check(oneOf({"punch", "fem"}));
    addFlag(*sweep, "json", "print JSON");
    addValue(*sweep, "csv", "FILE", "also write the points as CSV");
    addValue(*sweep, "png", "FILE", "also draw the chart");
    addFlag(*sweep, "quick", "a smoke run: small spheres, 4 rings, one repeat");
    addValue(*sweep, "shapes", "sphere,stomach", "the shapes (with --reference punch)");
    addValue(*sweep, "sizes", "N,..", "the vertex counts, each 8..2000000");
    addValue(*sweep, "max-rings", "N", "the most rings")->check(wholeNumberIn(1, kMaxRings));
    addFlag(*sweep, "no-paper", "leave out the paper's methods");
    addFlag(*sweep, "no-others", "leave out the other models");
    addValue(*sweep, "repeats", "N", "timing repeats")->check(wholeNumberIn(1, 100));
    addToolContactOptions(*sweep);
}

}  // namespace palpate::cli
