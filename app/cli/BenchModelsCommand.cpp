// palpate-cli bench models: one haptic tick of every deformation model (engine/models/ModelRegistry.h)
// at the paper's Table 1 sphere resolutions and at 100k vertices, over the benchmark's
// press-and-stroke path; and each model's error against the flat punch at 1442 and 8664 vertices.
// A model whose full path would take longer than the time budget is timed over the same path
// shortened 10x (the same phases and stroke speed), or if even that is too long, over a few ticks
// of a held press; one that cannot do 5 ticks within the budget is reported with a null time and
// the reason.
#include "app/cli/Commands.h"
#include "engine/core/MeshGenerator.h"
#include "engine/core/Octree.h"
#include "engine/core/SceneTarget.h"
#include "engine/models/TickTimer.h"
#include "engine/core/ToolPath.h"
#include "engine/accuracy/ModelError.h"
#include "engine/models/ModelRegistry.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

namespace palpate::cli {

namespace {

struct ModelRow {
    std::string model;
    std::size_t vertices = 0;
    std::optional<double> tickUs;
    std::string note;    ///< how it was timed, when not over the full path
    std::string reason;  ///< why there is no time
    std::optional<ModelError> error;
    int repeats = 0;     ///< passes over the path the median is of (0: not timed)
};

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string fixed(double v, int precision) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(precision) << v;
    return s.str();
}

void printTable(const std::vector<ModelRow>& rows, std::ostream& out) {
    out << "One haptic tick of every model (sphere, press-and-stroke path), microseconds; error against the flat punch\n";
    out << std::left << std::setw(24) << "model" << std::right << std::setw(9) << "vertices" << std::setw(12) << "tick us"
        << std::setw(12) << "displ err" << std::setw(11) << "force err" << "  note\n";
    for (const ModelRow& r : rows) {
        out << std::left << std::setw(24) << r.model << std::right << std::setw(9) << r.vertices << std::setw(12)
            << (r.tickUs ? fixed(*r.tickUs, *r.tickUs < 100 ? 3 : 1) : std::string("null")) << std::setw(12)
            << (r.error ? fixed(r.error->displacementError, 3) : std::string("-")) << std::setw(11)
            << (r.error ? fixed(r.error->forceError, 3) : std::string("-")) << "  "
            << (r.tickUs ? r.note : r.reason) << "\n";
    }
    out << "\nError: RMS surface displacement error within 5 tool radii / indentation, and relative force error, at\n"
           "3 mm tool depth with default parameters (E = 10 kPa, nu = 0.45, a = 5 mm); see docs/models.md.\n";
}

}  // namespace

void defineBenchModelsOptions(CLI::App& command) {
    addFlag(command, "json", "print JSON");
    addValue(command, "csv", "FILE", "also write the rows as CSV");
    addFlag(command, "quick", "a smoke run: the smallest mesh, one repeat, a 2 s budget");
    addValue(command, "sizes", "N,..",
             "the spheres' vertex counts, each 8..2000000 (default 1442,3970,5762,8664,100000)");
    addValue(command, "models", "NAME,..", "the models to time (default: every model, docs/models.md)");
    addValue(command, "repeats", "N", "passes over the path (default 3)")->check(wholeNumberIn(1, 100));
    addValue(command, "budget-s", "S", "seconds one model may take at one size (default 10)")
        ->check(wholeNumberIn(1, 3600));
}

int benchModelsCommand(const Given& args) {
    std::vector<std::size_t> sizes{1442, 3970, 5762, 8664, 100'000};
    std::vector<std::string> models = modelNames();
    int repeats = 3;
    double budgetS = 10.0;
    if (args.flag("quick")) {
        sizes = {1442};
        repeats = 1;
        budgetS = 2.0;
    }
    if (auto s = args.option("sizes")) {
        sizes.clear();
        for (const std::string& item : splitList(*s)) {
            const auto n = parsePositiveInt(item);
            if (!n || *n < 8 || *n > 2'000'000) {
                std::cerr << "bench models: --sizes: '" << item << "' must be a vertex count in 8..2000000\n";
                return 2;
            }
            sizes.push_back(std::size_t(*n));
        }
    }
    if (auto m = args.option("models")) {
        models = splitList(*m);
        for (const std::string& name : models)
            if (!modelDefForName(name)) {
                std::cerr << "bench models: --models: unknown model '" << name << "'\n";
                return 2;
            }
    }
    // Their ranges are checked by their definitions (defineBenchModelsOptions).
    if (auto r = args.option("repeats")) repeats = int(*parsePositiveInt(*r));
    if (auto b = args.option("budget-s")) budgetS = double(*parsePositiveInt(*b));

    const ToolContact contact;  // the default tissue and tool, as the sweep's
    std::vector<ModelRow> rows;
    for (std::size_t size : sizes) {
        std::cerr << "sphere with " << size << " vertices\n";
        auto generated = generateMesh(GeneratedShape::Sphere, size);
        if (!generated.mesh) {
            std::cerr << "bench models: " << generated.error() << "\n";
            return 1;
        }
        const TissueMesh& mesh = *generated.mesh;
        const Octree octree(mesh, OctreeDef{});
        const auto path = makePressAndStrokePath(mesh);
        const auto shortPath = makePressAndStrokePath(mesh, shortenedTenTimes());
        const bool measureError = size == 1442 || size == 8664;
        for (const std::string& name : models) {
            ModelRow row;
            row.model = name;
            row.vertices = mesh.vertexCount();
            std::cerr << "  " << name << std::flush;
            std::unique_ptr<DeformationModel> model;
            const auto built = std::chrono::steady_clock::now();
            try {
                model = makeModel(*modelDefForName(name), mesh, octree);
            } catch (const std::exception& e) {
                row.reason = std::string("cannot be built: ") + e.what();
                std::replace(row.reason.begin(), row.reason.end(), '\n', ' ');
                std::cerr << ": " << row.reason << "\n";
                rows.push_back(row);
                continue;
            }
            const double buildS = secondsSince(built);
            // Probe: one pass of the short path estimates a tick's cost.
            const auto probe = std::chrono::steady_clock::now();
            model->reset();
            for (const glm::vec3& tool : shortPath) model->step(tool, 0.001);
            const double perTickS = secondsSince(probe) / double(shortPath.size());
            if (perTickS * double(path.size()) * repeats <= budgetS) {
                row.tickUs = medianTickUs(*model, path, {repeats, 10.0});
                row.repeats = repeats;
            } else if (perTickS * double(shortPath.size()) <= budgetS) {
                row.tickUs = medianTickUs(*model, shortPath, {1, 0.0});
                row.repeats = 1;
                row.note = "path shortened 10x (the full path would take ~" + fixed(perTickS * double(path.size()), 0) + " s)";
            } else if (perTickS * 5.0 <= budgetS) {
                // Still timed: ticks of a held press at the path's full depth (contact on every
                // tick, so no cheaper approach ticks in the mean), as many as the budget allows.
                const int ticks = int(std::clamp(budgetS / perTickS, 5.0, 200.0));
                const VertexId target = defaultTargetVertex(mesh);
                const glm::vec3 tool = mesh.restPositionsMm()[target] - float(ToolPathDef{}.depthMm) * mesh.restNormals()[target];
                const std::vector<glm::vec3> press(std::size_t(ticks), tool);
                row.tickUs = medianTickUs(*model, press, {1, 0.0});
                row.repeats = 1;
                row.note = "held press, " + std::to_string(ticks) + " ticks (one pass of the shortened path would take ~" +
                           fixed(perTickS * double(shortPath.size()), 0) + " s)";
            } else {
                row.reason = "5 ticks would take ~" + fixed(perTickS * 5.0, 0) + " s (over the " + fixed(budgetS, 0) + " s budget)";
            }
            if (measureError) {
                try {
                    row.error = measureModelError(*model, mesh, defaultTargetVertex(mesh), contact);
                } catch (const std::exception& e) {
                    row.note += std::string(row.note.empty() ? "" : "; ") + "error not measured: " + e.what();
                }
            }
            if (buildS > 1.0) row.note += std::string(row.note.empty() ? "" : "; ") + "built in " + fixed(buildS, 1) + " s";
            std::cerr << ": " << (row.tickUs ? fixed(*row.tickUs, 3) + " us" : row.reason) << "\n";
            rows.push_back(row);
        }
    }

    if (const auto csvPath = args.option("csv")) {
        // One row per model and size; empty cells where a figure was not measured. Text quoted.
        auto quoted = [](const std::string& s) {
            std::string q = "\"";
            for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
            return q + "\"";
        };
        std::ofstream csv(*csvPath);
        csv << std::setprecision(9) << "model,vertices,tick_us,displacement_error,force_error,repeats,note,reason\n";
        for (const ModelRow& r : rows) {
            csv << r.model << "," << r.vertices << ",";
            if (r.tickUs) csv << *r.tickUs;
            csv << ",";
            if (r.error) csv << r.error->displacementError << "," << r.error->forceError;
            else csv << ",";
            csv << "," << r.repeats << "," << quoted(r.note) << "," << quoted(r.reason) << "\n";
        }
        if (!csv) {
            std::cerr << "bench models: " << *csvPath << ": cannot be written\n";
            return 1;
        }
    }
    if (args.flag("json")) {
        nlohmann::ordered_json j{{"rows", nlohmann::ordered_json::array()}};
        for (const ModelRow& r : rows) {
            nlohmann::ordered_json row{{"model", r.model},
                                       {"vertices", r.vertices},
                                       {"tick_us", r.tickUs ? nlohmann::ordered_json(*r.tickUs) : nlohmann::ordered_json(nullptr)}};
            if (!r.note.empty()) row["note"] = r.note;
            if (!r.reason.empty()) row["reason"] = r.reason;
            if (r.error) {
                row["displacement_error"] = r.error->displacementError;
                row["force_error"] = r.error->forceError;
            }
            j["rows"].push_back(row);
        }
        std::cout << j.dump(2) << "\n";
    } else {
        printTable(rows, std::cout);
    }
    return 0;
}

}  // namespace palpate::cli
