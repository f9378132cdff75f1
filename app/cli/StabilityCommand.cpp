// palpate-cli stability: where each model fails (docs/stability.md). --list names the
// maps; --model NAME runs one: the grid of cells, the measured boundary by bisection, the derived
// boundary, their gap; as a table, JSON, CSV and (in builds with Qt) the map as a PNG.
#include "app/cli/Commands.h"
#include "engine/stability/StabilityModels.h"

#ifdef PALPATE_HAVE_CHARTS
#include "report/StabilityMapImage.h"
#endif

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace palpate::cli {

namespace {

/// JSON has no infinity: an unbounded boundary is null.
nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json axisJson(const StabilityAxis& a) {
    return {{"name", a.name}, {"unit", a.unit}, {"min", a.minValue}, {"max", a.maxValue}, {"log", a.logScale}};
}

nlohmann::json toJson(const StabilityMap& map) {
    nlohmann::json derived = nlohmann::json::array(), measured = nlohmann::json::array(),
                   cells = nlohmann::json::array(), gaps = nlohmann::json::array();
    for (const auto& b : map.boundary) {
        derived.push_back({{"x", b.x}, {"y", number(b.derivedY)}});
        measured.push_back({{"x", b.x}, {"y", number(b.measuredY)}});
        gaps.push_back(number(b.relativeGap));
    }
    for (const auto& c : map.cells) {
        nlohmann::json cell = {{"x", c.x}, {"y", c.y}, {"bounded", c.bounded}, {"growth", number(c.growth)}};
        if (map.hasPassivity) {
            cell["passivity_ratio"] = number(c.passivityRatio);
            cell["passive"] = c.passivityRatio < 1.0;
        }
        cells.push_back(cell);
    }
    nlohmann::json passivity = nullptr;
    if (map.hasPassivity)
        passivity = {{"formula", map.passivityFormula}, {"ratio", "K_eq / K_device, > 1: not passive"}};
    return {{"model", map.model},
            {"registry_models", stabilityMapModels(map.model)},
            {"description", map.description},
            {"criterion", map.criterion},
            {"derived_formula", map.derivedFormula},
            {"x_axis", axisJson(map.x)},
            {"y_axis", axisJson(map.y)},
            {"has_derived_boundary", map.hasDerivedBoundary},
            {"derived_boundary", derived},
            {"measured_boundary", measured},
            {"relative_gaps", gaps},
            {"relative_gap", number(map.relativeGap)},
            {"passivity", passivity},
            {"cells", cells}};
}

std::string csvText(const StabilityMap& map) {
    std::ostringstream out;
    out << std::setprecision(9) << "kind," << map.x.name << "," << map.y.name
        << ",bounded,growth,derived_y,passivity_ratio\n";
    for (const auto& c : map.cells) {
        out << "cell," << c.x << "," << c.y << "," << (c.bounded ? 1 : 0) << "," << c.growth << ",,";
        if (map.hasPassivity) out << c.passivityRatio;
        out << "\n";
    }
    for (const auto& b : map.boundary)
        out << "boundary," << b.x << "," << b.measuredY << ",," << b.relativeGap << "," << b.derivedY << ",\n";
    return out.str();
}

void printTable(std::ostream& out, const StabilityMap& map) {
    out << map.model << ": " << map.description << "\n  derived: " << map.derivedFormula
        << "\n  criterion: " << map.criterion << "\n";
    out << std::setw(12) << map.x.name << std::setw(14) << ("derived " + map.y.name) << std::setw(14)
        << ("measured " + map.y.name) << std::setw(9) << "gap\n";
    for (const auto& b : map.boundary)
        out << std::setw(12) << std::setprecision(4) << b.x << std::setw(14) << b.derivedY << std::setw(14)
            << b.measuredY << std::setw(8) << std::fixed << std::setprecision(2) << 100.0 * b.relativeGap << "%\n"
            << std::defaultfloat;
    out << "  largest gap: " << std::setprecision(3) << 100.0 * map.relativeGap << " %\n";
    if (map.hasPassivity) {
        std::size_t passive = 0;
        for (const auto& c : map.cells) passive += c.passivityRatio < 1.0 ? 1 : 0;
        out << "  passivity: " << map.passivityFormula << "\n  passive cells: " << passive << " of " << map.cells.size()
            << "\n";
    }
}

int stabilityCommand(const Given& args) {
    if (args.flag("list")) {
        for (const auto& name : stabilityModelNames()) std::cout << name << "\n";
        return 0;
    }
    const auto name = args.option("model");
    if (!name) {
        std::cerr << "palpate-cli stability: give --list or --model NAME\n";
        return 2;
    }
    StabilitySceneDef scene;
    StabilityMapDef def;
    if (args.flag("quick")) {
        scene.slopeRingTicks = 1500;
        scene.massSpringTicks = 800;
        scene.implicitTicks = 150;
        scene.deviceTicks = 3000;
        def.columns = 6;
        def.rows = 6;
        def.bisections = 10;
    }
    const auto spec = stabilityMapSpec(*name, scene);
    if (!spec) {
        std::cerr << "palpate-cli stability: unknown model '" << *name << "' (see --list)\n";
        return 2;
    }
    const auto png = args.option("png");
#ifndef PALPATE_HAVE_CHARTS
    if (png) {
        std::cerr << "palpate-cli stability: --png needs a build with the GUI (Qt); this one has none\n";
        return 2;
    }
#endif
    const StabilityMap map = runStabilityMap(*spec, def);
    if (const auto csv = args.option("csv")) {
        std::ofstream out(*csv);
        out << csvText(map);
        if (!out) {
            std::cerr << "palpate-cli stability: " << *csv << ": cannot be written\n";
            return 1;
        }
    }
#ifdef PALPATE_HAVE_CHARTS
    if (png) {
        std::string error;
        if (!(error = renderStabilityMapPng(map, *png)).empty()) {
            std::cerr << "palpate-cli stability: " << *png << ": " << error << "\n";
            return 1;
        }
    }
#endif
    if (args.flag("json")) std::cout << toJson(map).dump(2) << "\n";
    else printTable(std::cout, map);
    return 0;
}

}  // namespace

void defineStabilityCommand(CommandLine& cli) {
    CLI::App* stability = cli.command(cli.root(), "stability",
                                      "a map of where a model fails, derived against measured (docs/stability.md)",
                                      stabilityCommand);
    addFlag(*stability, "list", "list the models that have a map");
    addValue(*stability, "model", "NAME", "the model to map");
    addFlag(*stability, "json", "print JSON");
    addValue(*stability, "csv", "FILE", "also write the map as CSV");
    addValue(*stability, "png", "FILE", "also draw the map");
    addFlag(*stability, "quick", "a smoke run: short runs, a 6 x 6 map");
}

}  // namespace palpate::cli
