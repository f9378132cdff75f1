#include "app/cli/Commands.h"
#include "engine/bench/Table1Bench.h"
#include "engine/scene/TissuePreset.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace palpate::cli {

namespace {

constexpr SlopeRingMethod kMethods[] = {SlopeRingMethod::Previous, SlopeRingMethod::Hybrid, SlopeRingMethod::Proposed,
                                        SlopeRingMethod::Coherent};

/// The paper's Table 1 (microseconds per haptic loop), by vertex count.
struct PaperRow {
    std::size_t vertices;
    double previousUs, hybridUs, proposedUs;
};
constexpr PaperRow kPaper[] = {{1442, 4.8, 3.8, 0.90}, {3970, 13.50, 10.10, 1.40}, {5762, 19.50, 12.50, 1.85},
                               {8664, 30.10, 21.50, 2.70}};

nlohmann::json optionalNumber(const std::optional<MethodMeasurement>& m, double MethodMeasurement::*field) {
    return m ? nlohmann::json((*m).*field) : nlohmann::json(nullptr);
}

nlohmann::json rowJson(const Table1Row& row) {
    nlohmann::json j{{"shape", std::string(shapeName(row.shape))},
                     {"vertices", row.vertices},
                     {"triangles", row.triangles},
                     {"ticks", row.ticks}};
    for (auto m : kMethods) {
        const std::string name(methodName(m));
        const auto& measurement = row.methods[std::size_t(m)];
        j[name + "_us"] = optionalNumber(measurement, &MethodMeasurement::tickUs);
        j[name + "_step_us"] = optionalNumber(measurement, &MethodMeasurement::stepUs);
        j[name + "_wrong_pct"] = measurement && std::isnan(measurement->wrongPct)
                                     ? nlohmann::json(nullptr)
                                     : optionalNumber(measurement, &MethodMeasurement::wrongPct);
        j[name + "_max_off_mm"] = optionalNumber(measurement, &MethodMeasurement::maxOffMm);
    }
    j["coherent_eager_us"] = optionalNumber(row.coherentEager, &MethodMeasurement::tickUs);
    return j;
}

double us(const Table1Row& row, SlopeRingMethod m) {
    const auto& x = row.methods[std::size_t(m)];
    return x ? x->tickUs : 0.0;
}

std::string cell(const std::optional<MethodMeasurement>& m, int precision, bool wrong = false) {
    if (!m || (wrong && std::isnan(m->wrongPct))) return "-";
    std::ostringstream s;
    s << std::fixed << std::setprecision(precision) << (wrong ? m->wrongPct : m->tickUs);
    return s.str();
}

std::string ratio(double a, double b) {
    if (a <= 0.0 || b <= 0.0) return "-";
    std::ostringstream s;
    s << std::fixed << std::setprecision(a / b >= 100 ? 0 : 1) << a / b << "x";
    return s.str();
}

void printTable(const std::vector<Table1Row>& rows, std::ostream& out) {
    out << "Table 1 (measured): one haptic tick as the loop runs it, in microseconds (the model's search,\n"
           "deformation and force, the divergence guard, the snapshot copy); 'step' columns: the model's step alone\n";
    out << std::left << std::setw(9) << "shape" << std::right << std::setw(9) << "vertices" << std::setw(10)
        << "triangles" << std::setw(11) << "previous" << std::setw(10) << "hybrid" << std::setw(10) << "proposed"
        << std::setw(10) << "coherent" << std::setw(12) << "prev/ours" << std::setw(12) << "hyb/ours" << std::setw(12)
        << "prop/ours" << std::setw(10) << "eager" << std::setw(12) << "prop step" << std::setw(12) << "ours step"
        << std::setw(13) << "prop/ours st" << "   wrong % (prev/hyb/prop)\n";
    for (const auto& r : rows) {
        out << std::left << std::setw(9) << shapeName(r.shape) << std::right << std::setw(9) << r.vertices
            << std::setw(10) << r.triangles;
        for (auto m : kMethods) out << std::setw(m == SlopeRingMethod::Previous ? 11 : 10) << cell(r.methods[std::size_t(m)], 3);
        const double ours = us(r, SlopeRingMethod::Coherent);
        out << std::setw(12) << ratio(us(r, SlopeRingMethod::Previous), ours) << std::setw(12)
            << ratio(us(r, SlopeRingMethod::Hybrid), ours) << std::setw(12)
            << ratio(us(r, SlopeRingMethod::Proposed), ours) << std::setw(10)
            << (r.coherentEager ? cell(r.coherentEager, 3) : std::string("-"));
        const auto& prop = r.methods[std::size_t(SlopeRingMethod::Proposed)];
        const auto& coh = r.methods[std::size_t(SlopeRingMethod::Coherent)];
        const auto stepCell = [](const std::optional<MethodMeasurement>& m) {
            if (!m) return std::string("-");
            std::ostringstream s;
            s << std::fixed << std::setprecision(3) << m->stepUs;
            return s.str();
        };
        out << std::setw(12) << stepCell(prop) << std::setw(12) << stepCell(coh) << std::setw(13)
            << ratio(prop ? prop->stepUs : 0.0, coh ? coh->stepUs : 0.0) << "   ";
        for (auto m : {SlopeRingMethod::Previous, SlopeRingMethod::Hybrid, SlopeRingMethod::Proposed})
            out << cell(r.methods[std::size_t(m)], 1, true) << (m == SlopeRingMethod::Proposed ? "" : "/");
        out << "\n";
    }
    out << "\neager: ours (as the loop runs it) with the active rings' positions written every tick by the model.\n"
           "ours: a sphere of the default tissue's tool radius with its friction; the paper's methods: a point.\n"
           "wrong %: ticks whose touched vertex is not the nearest (ours has no nearest-vertex search in contact).\n";
    out << "\nThe paper's Table 1 (2012 hardware, OpenHaptics), microseconds:\n";
    for (const auto& p : kPaper)
        out << "  " << std::setw(5) << p.vertices << " vertices: previous " << p.previousUs << ", hybrid "
            << p.hybridUs << ", proposed " << p.proposedUs << "  (previous/proposed "
            << ratio(p.previousUs, p.proposedUs) << ")\n";
}

void writeCsv(const std::vector<Table1Row>& rows, std::ostream& out) {
    out << "shape,vertices,triangles,ticks";
    for (auto m : kMethods) out << "," << methodName(m) << "_us";
    for (auto m : kMethods) out << "," << methodName(m) << "_step_us";
    for (auto m : kMethods) out << "," << methodName(m) << "_wrong_pct";
    for (auto m : kMethods) out << "," << methodName(m) << "_max_off_mm";
    out << ",coherent_eager_us\n";
    for (const auto& r : rows) {
        out << shapeName(r.shape) << "," << r.vertices << "," << r.triangles << "," << r.ticks;
        for (double MethodMeasurement::*field : {&MethodMeasurement::tickUs, &MethodMeasurement::stepUs,
                                                 &MethodMeasurement::wrongPct, &MethodMeasurement::maxOffMm})
            for (auto m : kMethods) {
                const auto& x = r.methods[std::size_t(m)];
                out << ",";
                if (x && !std::isnan((*x).*field)) out << std::setprecision(6) << (*x).*field;
            }
        out << ",";
        if (r.coherentEager) out << std::setprecision(6) << r.coherentEager->tickUs;
        out << "\n";
    }
}

int table1Command(const Given& args) {
    Table1Def options;
    options.contact = presetModelDef(TissuePreset{}).contact;  // ours as the product runs it
    if (args.flag("quick")) {  // a smoke run: small meshes, one repeat
        options.paperSizes = {1442};
        options.largeSphereSizes = {20000};
        options.repeats = 1;
        options.minMeasureMs = 2.0;
    }
    if (auto r = args.option("repeats")) options.repeats = int(*parsePositiveInt(*r));  // 1..100, as defined below
    const bool json = args.flag("json");
    options.progress = [](const std::string& line) { std::cerr << line << "\n"; };
    const auto rows = runTable1(options);

    if (auto csvPath = args.option("csv")) {
        std::ofstream csv(*csvPath);
        if (!csv) {
            std::cerr << "bench table1: cannot write " << *csvPath << "\n";
            return 1;
        }
        writeCsv(rows, csv);
    }
    if (json) {
        nlohmann::json j{{"rows", nlohmann::json::array()}};
        for (const auto& r : rows) j["rows"].push_back(rowJson(r));
        std::cout << j.dump(2) << "\n";
    } else {
        printTable(rows, std::cout);
    }
    return 0;
}

}  // namespace

void defineBenchCommands(CommandLine& cli) {
    CLI::App* bench = cli.group(cli.root(), "bench", "time the deformation models (docs/bench)");
    CLI::App* table1 = cli.command(*bench, "table1", "the tick times of Table 1", table1Command);
    addFlag(*table1, "json", "print JSON");
    addValue(*table1, "csv", "FILE", "also write the rows as CSV");
    addFlag(*table1, "quick", "a smoke run: small meshes, one repeat");
    addValue(*table1, "repeats", "N", "repeats of each measurement")->check(wholeNumberIn(1, 100));
    defineBenchModelsOptions(*cli.command(*bench, "models", "every model's tick at the Table 1 sizes and 100k",
                                          benchModelsCommand));
    defineBenchFeelOptions(*cli.command(*bench, "feel", "what the hand feels of a slide at constant depth, every model",
                                        benchFeelCommand));
}

}  // namespace palpate::cli
