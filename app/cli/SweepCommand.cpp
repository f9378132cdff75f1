// palpate-cli sweep: speed against accuracy for every model (docs/calibration.md), as a table, CSV, JSON and
// (in builds with Qt) the chart as a PNG.
#include "app/cli/Args.h"
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

}  // namespace

int sweepCommand(const std::vector<std::string>& words) {
    std::vector<std::string> options{"csv", "png", "shapes", "sizes", "max-rings", "repeats", "reference"};
    for (const std::string& o : toolContactOptionNames()) options.push_back(o);
    const Args args(words, {"json", "quick", "no-paper", "no-others"}, options);
    if (!args.ok()) {
        std::cerr << "palpate-cli sweep: " << args.error() << "\n";
        return 2;
    }
    const std::string reference = args.option("reference").value_or("punch");
    if (reference != "punch" && reference != "fem") {
        std::cerr << "palpate-cli sweep: --reference: '" << reference << "' is not a reference (punch, fem)\n";
        return 2;
    }
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
    if (const auto rings = args.option("max-rings")) {
        const auto n = parsePositiveInt(*rings);
        if (!n || *n > kMaxRings) {
            std::cerr << "palpate-cli sweep: --max-rings: '" << *rings << "' is not in 1.." << kMaxRings << "\n";
            return 2;
        }
        def.maxRings = int(*n);
    }
    if (const auto repeats = args.option("repeats")) {
        const auto n = parsePositiveInt(*repeats);
        if (!n || *n > 100) {
            std::cerr << "palpate-cli sweep: --repeats: '" << *repeats << "' is not in 1..100\n";
            return 2;
        }
        def.timingRepeats = int(*n);
    }
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
        if (!renderSweepChartPng(result.points, def.contact, *png, &error, 1400, organ ? 2400 : 1500)) {
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

}  // namespace palpate::cli
