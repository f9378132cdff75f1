// palpate-cli lod: levels of detail (docs/lod.md). "lod levels" makes (or reads from the
// cache beside the mesh) the decimated levels and checks them; "lod plan" measures every level and
// ring count on this machine and picks the cheapest that meets an accuracy target and a tick budget.
#include "app/cli/Commands.h"
#include "base/resources/ShippedResources.h"
#include "app/cli/MeshOption.h"
#include "app/cli/ToolContactOptions.h"
#include "engine/scene/TissuePreset.h"
#include "engine/lod/LevelCache.h"
#include "engine/lod/LodMeasure.h"
#include "engine/lod/LodPlanner.h"
#include "engine/exercise/ExerciseDemands.h"
#include "engine/exercise/ExerciseFile.h"
#include "engine/lod/StiffeningChoice.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace palpate::cli {

namespace {

using Json = nlohmann::ordered_json;

/// --min-vertices, --max-levels, --ratio into `options`; "" or the problem naming the option.
std::string levelOptionsFromArgs(const Given& args, LevelDef& options) {
    // Each is a number in its range, as defined (addLevelOptions); validateLevelDef checks the ratio.
    if (const auto text = args.option("min-vertices")) options.minVertices = std::size_t(*parsePositiveInt(*text));
    if (const auto text = args.option("max-levels")) options.maxCoarseLevels = std::stoi(*text);
    if (const auto text = args.option("ratio")) options.vertexRatio = *parseNumber(*text);
    if (const std::string e = joinedMessages(validateLevelDef(options)); !e.empty()) return e;
    return {};
}

void progressLine(double fraction, const std::string& stage) {
    std::cerr << "[" << std::setw(3) << int(fraction * 100.0 + 0.5) << "%] " << stage << "\n";
}

/// Loads the mesh and its levels (cache or generation), printing where they came from on stderr.
/// Returns an exit code (0: go on).
int loadLevels(const std::string& command, const std::string& meshPath, const MeshUnit& unit,
               const MeshUnitSource& unitSource, const LevelDef& options, bool useCache,
               std::optional<TissueMesh>& mesh, LevelCacheResult& levels) {
    auto loaded = loadMeshFile("palpate-cli lod " + command + ": ", meshPath, unit, unitSource);
    if (!loaded.mesh) {
        std::cerr << "palpate-cli lod " << command << ": " << loaded.error() << "\n";
        return 1;
    }
    mesh = std::move(loaded.mesh);
    std::string lastStage;
    int lastTenth = -1;
    levels = loadOrGenerateLevels(meshPath, *mesh, options, [&](double f, const std::string& stage) {
        // One line per stage and per tenth, so a log stays readable.
        const int tenth = int(f * 10.0);
        if (stage != lastStage || tenth != lastTenth) progressLine(f, stage);
        lastStage = stage;
        lastTenth = tenth;
    }, nullptr, useCache);
    std::cerr << "levels: " << levels.cacheStatus << "\n";
    if (!levels.writeError.empty()) std::cerr << "levels: cache not written: " << levels.writeError << "\n";
    for (const std::string& note : levels.levels.notes) std::cerr << "levels: " << note << "\n";
    return 0;
}

Json candidateJson(const LodCandidate& c, const LodNeeds& needs) {
    Json j{{"level", c.level},
           {"vertices", c.vertices},
           {"triangles", c.triangles},
           {"rings", c.rings},
           {"model", c.model},
           {"error", c.errorFraction},
           {"level_error", c.levelErrorFraction},
           {"force_error", c.forceErrorFraction},
           {"tick_us", c.tickUs},
           {"vertices_compared", c.verticesCompared},
           {"meets_error", meetsError(c, needs)},
           {"meets_budget", meetsBudget(c, needs)}};
    if (!c.note.empty()) j["note"] = c.note;
    return j;
}

int levelsCommand(const Given& args) {
    const auto meshPath = args.option("mesh");
    if (!meshPath) {
        std::cerr << "palpate-cli lod levels: --mesh FILE is required\n";
        return 2;
    }
    LevelDef options;
    if (const std::string e = levelOptionsFromArgs(args, options); !e.empty()) {
        std::cerr << "palpate-cli lod levels: " << e << "\n";
        return 2;
    }
    std::string unitError;
    const auto meshUnit = meshUnitFromArgs(args, unitError);
    if (!meshUnit) {
        std::cerr << "palpate-cli lod levels: " << unitError << "\n";
        return 2;
    }
    std::optional<TissueMesh> mesh;
    LevelCacheResult result;
    if (const int rc = loadLevels("levels", *meshPath, *meshUnit, {}, options, !args.flag("no-cache"), mesh, result))
        return rc;
    const MeshLevels& levels = result.levels;

    bool allGood = true;
    Json rows = Json::array();
    for (std::size_t k = 0; k < levels.levels.size(); ++k) {
        const MeshLevel& l = levels.levels[k];
        const MeshReport& r = l.mesh.report();
        const bool closed = r.boundaryEdgeCount == 0;
        const bool manifold = r.nonManifoldEdgeCount == 0 && r.nonManifoldVertexCount == 0;
        const std::string problem = k == 0 ? std::string() : levelTopologyProblem(levels.levels.front().mesh, l.mesh);
        if (!problem.empty()) allGood = false;
        rows.push_back({{"level", k},
                        {"target_vertices", l.targetVertices},
                        {"vertices", l.mesh.vertexCount()},
                        {"triangles", l.mesh.triangleCount()},
                        {"seconds", l.seconds},
                        {"closed", closed},
                        {"manifold", manifold},
                        {"problem", problem}});
    }
    if (args.flag("json")) {
        Json j{{"mesh", *meshPath},
               {"source_hash", [&] {
                    std::ostringstream s;
                    s << std::hex << std::setw(16) << std::setfill('0') << levels.sourceHash;
                    return s.str();
                }()},
               {"from_cache", result.fromCache},
               {"cache", result.cacheStatus},
               {"cache_dir", levelCacheDir(*meshPath)},
               {"notes", levels.notes},
               {"levels", rows}};
        std::cout << j.dump(2) << "\n";
    } else {
        std::cout << std::left << std::setw(7) << "level" << std::right << std::setw(10) << "target" << std::setw(10)
                  << "vertices" << std::setw(11) << "triangles" << std::setw(10) << "seconds" << "  check\n";
        for (const Json& row : rows)
            std::cout << std::left << std::setw(7) << row["level"].get<std::size_t>() << std::right << std::setw(10)
                      << row["target_vertices"].get<std::size_t>() << std::setw(10) << row["vertices"].get<std::size_t>()
                      << std::setw(11) << row["triangles"].get<std::size_t>() << std::setw(10) << std::fixed
                      << std::setprecision(3) << row["seconds"].get<double>() << "  "
                      << (row["problem"].get<std::string>().empty()
                              ? std::string(row["closed"].get<bool>() ? "closed" : "open") + ", " +
                                    (row["manifold"].get<bool>() ? "manifold" : "NON-MANIFOLD")
                              : row["problem"].get<std::string>())
                      << "\n";
    }
    return allGood ? 0 : 1;
}

/// What lod plan plans for: the needs, the mesh, its unit, and the exercise if one is given.
struct PlanScene {
    std::optional<LodNeeds> needs;
    std::string needsSource;
    std::optional<std::string> meshPath;
    std::optional<MeshUnit> meshUnit;
    MeshUnitSource unitSource;
    std::optional<Exercise> exercise;
};

/// The scene lod plan plans for, from the options: nullopt, or the exit code after saying why not.
std::optional<int> planScene(const Given& args, PlanScene& scene) {
    const char* me = "palpate-cli lod plan: ";
    // The needs: the exercise's, else the preset's; --error and --budget-us override either.
    std::optional<LodNeeds>& needs = scene.needs;
    std::string& needsSource = scene.needsSource;
    std::optional<std::string>& meshPath = scene.meshPath;
    meshPath = args.option("mesh");
    // --mesh-unit goes with --mesh; the exercise's own mesh is in the exercise's unit.
    std::string unitError;
    std::optional<MeshUnit>& meshUnit = scene.meshUnit;
    meshUnit = meshUnitFromArgs(args, unitError);
    if (!meshUnit) {
        std::cerr << me << unitError << "\n";
        return 2;
    }
    MeshUnitSource& unitSource = scene.unitSource;
    if (args.option(kMeshUnitOption) && !meshPath) {
        std::cerr << me << "--mesh-unit goes with --mesh (the exercise's \"mesh_unit\" sets its mesh's unit)\n";
        return 2;
    }
    std::optional<Exercise>& exercise = scene.exercise;
    if (const auto path = args.option("exercise")) {
        const ExerciseLoadResult ex = loadExercise(*path);
        if (!ex.exercise) {
            std::cerr << me << ex.error() << "\n";
            return 2;
        }
        exercise = ex.exercise;
        if (ex.exercise->needs) {
            needs = ex.exercise->needs;
            needsSource = *path;
        }
        if (!meshPath) {
            const std::string resolved = resolveExercisePath(*ex.exercise, ex.exercise->meshPath, findResource);
            if (resolved.empty()) {
                std::cerr << me << *path << ": mesh: '" << ex.exercise->meshPath << "' not found\n";
                return 2;
            }
            meshPath = resolved;
            meshUnit = ex.exercise->meshUnit;
            unitSource.exercisePath = *path;
        }
    }
    if (const auto path = args.option("preset"); path && !needs) {
        const PresetLoadResult preset = loadTissuePreset(*path);  // already loaded once by toolContactFromArgs
        if (preset.preset && preset.preset->needs) {
            needs = preset.preset->needs;
            needsSource = *path;
        }
    }
    for (const char* key : {"error", "budget-us"}) {
        const auto text = args.option(key);
        if (!text) continue;
        if (!needs) needs = LodNeeds{};
        // A number, as defined (defineLodCommands).
        (std::string(key) == "error" ? needs->maxErrorFraction : needs->budgetUs) = *parseNumber(*text);
        if (needsSource.empty()) needsSource = "command line";
        else if (needsSource.find("command line") == std::string::npos) needsSource += " and command line";
    }
    if (!needs || (needsSource == "command line" && (!args.option("error") || !args.option("budget-us")))) {
        std::cerr << me << "give --error E and --budget-us T (or an --exercise or --preset with \"needs\")\n";
        return 2;
    }
    // Name the options the user typed, not the file keys, when the values came from the command line.
    const std::vector<std::string> needsProblems = messagesOf(validateLodNeeds(*needs, ""));
    for (std::string problem : needsProblems) {
        if (args.option("error") && problem.rfind("max_error", 0) == 0) problem = "--error" + problem.substr(9);
        if (args.option("budget-us") && problem.rfind("budget_us", 0) == 0) problem = "--budget-us" + problem.substr(9);
        std::cerr << me << problem << " (" << needsSource << ")\n";
    }
    if (!needsProblems.empty()) return 2;
    if (!meshPath) {
        std::cerr << me << "--mesh FILE (or --exercise FILE) is required\n";
        return 2;
    }
    return std::nullopt;
}

/// The candidates of a plan as a table, each with its verdict.
void printPlanTable(const LodMeasurement& measured, const LodPlan& plan, const LodNeeds& needs) {
    std::cout << std::left << std::setw(7) << "level" << std::right << std::setw(10) << "vertices" << std::setw(7)
              << "rings" << std::setw(10) << "error" << std::setw(12) << "level err" << std::setw(11) << "tick us"
              << "  verdict\n";
    for (std::size_t i = 0; i < measured.candidates.size(); ++i) {
        const LodCandidate& c = measured.candidates[i];
        std::string verdict = plan.chosen == i ? "CHOSEN" : plan.closest == i ? "closest" : "";
        if (verdict.empty()) {
            const bool e = meetsError(c, needs), t = meetsBudget(c, needs);
            verdict = !c.note.empty() ? "not measured: " + c.note
                      : e && t        ? "meets both"
                      : e             ? "over budget"
                      : t             ? "error too high"
                                      : "error too high, over budget";
        }
        std::cout << std::left << std::setw(7) << c.level << std::right << std::setw(10) << c.vertices << std::setw(7)
                  << c.rings << std::fixed << std::setprecision(4) << std::setw(10) << c.errorFraction << std::setw(12)
                  << c.levelErrorFraction << std::setprecision(3) << std::setw(11) << c.tickUs << "  " << verdict
                  << "\n";
    }
}

int planCommand(const Given& args) {
    const char* me = "palpate-cli lod plan: ";
    const ToolContactChoice choice = toolContactFromArgs(args);
    if (!choice.error.empty()) {
        std::cerr << me << choice.error << "\n";
        return 2;
    }
    PlanScene scene;
    if (const std::optional<int> refused = planScene(args, scene)) return *refused;
    const std::optional<LodNeeds>& needs = scene.needs;
    const std::string& needsSource = scene.needsSource;
    const std::optional<std::string>& meshPath = scene.meshPath;
    const std::optional<MeshUnit>& meshUnit = scene.meshUnit;
    const MeshUnitSource& unitSource = scene.unitSource;
    const std::optional<Exercise>& exercise = scene.exercise;

    const bool quick = args.flag("quick");
    LevelDef levelOptions;
    if (quick) levelOptions.maxCoarseLevels = 3;
    if (const std::string e = levelOptionsFromArgs(args, levelOptions); !e.empty()) {
        std::cerr << me << e << "\n";
        return 2;
    }
    LodMeasureDef def;
    def.contact = choice.contact;
    if (quick) {
        def.ringCounts = {1, 2, 3};
        def.timing = {1, 1.0};
        def.path = shortenedTenTimes(def.path);
    }
    if (const auto text = args.option("rings")) {
        def.ringCounts.clear();
        for (const std::string& item : splitList(*text)) {
            const auto n = parsePositiveInt(item);
            if (!n || *n > kMaxRings) {
                std::cerr << me << "--rings: '" << item << "' is not in 1.." << kMaxRings << "\n";
                return 2;
            }
            def.ringCounts.push_back(int(*n));
        }
    }
    if (const auto text = args.option("repeats"))
        def.timing.repeats = int(*parsePositiveInt(*text));  // 1..100, as defined
    if (const std::string e = joinedMessages(validateLodMeasureDef(def)); !e.empty()) {
        std::cerr << me << e << "\n";
        return 2;
    }

    std::optional<TissueMesh> mesh;
    LevelCacheResult levels;
    if (const int rc = loadLevels("plan", *meshPath, *meshUnit, unitSource, levelOptions, !args.flag("no-cache"), mesh,
                                  levels))
        return rc;
    std::cerr << "plan: E = " << def.contact.material.youngsModulusNPerMm2 * 1000.0 << " kPa, nu = "
              << def.contact.material.poissonRatio << ", tool radius " << def.contact.toolRadiusMm << " mm ("
              << choice.source << "); needs from " << needsSource << "\n";
    const LodMeasurement measured = measureLodCandidates(levels.levels, def, progressLine);
    const LodPlan plan = planLod(measured.candidates, *needs);
    if (!plan.error.empty()) {
        std::cerr << me << plan.error << "\n";
        return 1;
    }

    // Linear or stiffening tissue at the scene's depths (docs/lod.md, "Linear or nonlinear"): the
    // hyperelastic punch of this tissue, its knots for the plan's |m1|, judged at the exercise's
    // presses (or the plan's own press without an exercise).
    StiffeningCalibrationDef stiffDef;
    stiffDef.material = hyperelasticMaterialOf(choice.contact);
    stiffDef.toolRadiusMm = choice.contact.toolRadiusMm;
    if (quick) stiffDef.aOverH = 2;
    SlopeRingParams knotted;
    knotted.slopeMagnitudeMmPerN[0] = punchFirstSlopeMmPerN(choice.contact);
    const std::vector<ExerciseDemand> demands = exercise ? exerciseDemands(*exercise) : std::vector<ExerciseDemand>{};
    setStiffeningDepths(stiffDef, stiffeningReferenceDepthOverRadius(
                                      deepestDemandMm(demands, knotted.slopeMagnitudeMmPerN[0], def.press.toolDepthMm),
                                      stiffDef.toolRadiusMm));
    std::cerr << "plan: hyperelastic punch (" << hyperelasticLawName(stiffDef.material.law) << ", b = "
              << stiffDef.material.stiffeningExponent << ") to " << stiffDef.depthsOverRadius.back() * stiffDef.toolRadiusMm
              << " mm for linear or stiffening tissue\n";
    StiffeningCalibration reference, knots;
    try {
        reference = calibrateStiffening(stiffDef);
        knots = knotsFromCurve(reference.curve, knotted.slopeMagnitudeMmPerN[0]);
    } catch (const std::invalid_argument& e) {
        // A reference that stopped before its second depth, or a tissue it refuses: said, not a crash.
        std::cerr << me << "the hyperelastic reference failed: " << e.what() << "\n";
        return 1;
    }
    applyStiffening(knots, knotted);
    std::vector<SceneDepth> depths;
    if (exercise) {
        for (const ExerciseDemand& d : demands)
            depths.push_back({d.what, d.depthMm > 0.0 ? d.depthMm
                                                      : curveDepthAtForceMm(knots.curve, d.forceN, knotted.slopeMagnitudeMmPerN[0])});
    } else {
        depths.push_back({"the plan's press", def.press.toolDepthMm});
    }
    const StiffeningChoice stiffening = chooseStiffening(knots, knotted, depths, *needs);
    const bool stiffeningOk = stiffening.error.empty() && stiffening.feasible;
    const auto stiffeningJson = [&] {
        Json d = Json::array();
        for (const SceneDepth& sd : depths) d.push_back({{"what", sd.what}, {"depth_mm", sd.depthMm}});
        return Json{{"law", std::string(hyperelasticLawName(stiffDef.material.law))},
                    {"stiffening_exponent", stiffDef.material.stiffeningExponent},
                    {"nonlinear", stiffening.nonlinear},
                    {"knots", stiffening.knots},
                    {"feasible", stiffening.feasible},
                    {"linear_error", stiffening.linearErrorFraction},
                    {"nonlinear_error", stiffening.nonlinearErrorFraction},
                    {"depths", d},
                    {"reference_completed", reference.completed},
                    {"reason", stiffening.error.empty() ? stiffening.reason : stiffening.error}};
    };

    if (args.flag("json")) {
        Json j{{"mesh", *meshPath},
               {"needs", {{"max_error", needs->maxErrorFraction}, {"budget_us", needs->budgetUs}, {"source", needsSource}}},
               {"feasible", plan.feasible},
               {"chosen", plan.chosen ? candidateJson(measured.candidates[*plan.chosen], *needs) : Json(nullptr)},
               {"closest", plan.closest ? candidateJson(measured.candidates[*plan.closest], *needs) : Json(nullptr)},
               {"reason", plan.reason},
               {"stiffening", stiffeningJson()},
               {"levels_from_cache", levels.fromCache},
               {"candidates", Json::array()}};
        for (const LodCandidate& c : measured.candidates) j["candidates"].push_back(candidateJson(c, *needs));
        std::cout << j.dump(2) << "\n";
    } else {
        printPlanTable(measured, plan, *needs);
        std::cout << plan.reason << "\n";
        std::cout << (stiffening.error.empty() ? stiffening.reason : stiffening.error) << "\n";
    }
    if (!plan.feasible) {
        std::cerr << me << "nothing fits: " << plan.reason << "\n";
        return 1;
    }
    if (!stiffeningOk) {
        std::cerr << me << "nothing fits: " << (stiffening.error.empty() ? stiffening.reason : stiffening.error) << "\n";
        return 1;
    }
    return 0;
}

void addLevelOptions(CLI::App& command) {
    addValue(command, "min-vertices", "N", "the coarsest level's fewest vertices")->check(wholeNumberIn(8, 50'000'000));
    addValue(command, "max-levels", "N", "the most coarser levels")->check(wholeNumberIn(0, 20));
    addValue(command, "ratio", "R", "the vertex ratio of one level to the next")->check(anyNumber());
    addFlag(command, "no-cache", "do not read or write the level cache beside the mesh");
}

}  // namespace

void defineLodCommands(CommandLine& cli) {
    CLI::App* lod = cli.group(cli.root(), "lod",
                              "mesh levels of detail and the cheapest model a scene needs (docs/lod.md)");
    CLI::App* levels = cli.command(*lod, "levels", "the mesh's levels of detail", levelsCommand);
    addValue(*levels, "mesh", "FILE", "the tissue mesh (required)");
    addMeshUnitOption(*levels);
    addFlag(*levels, "json", "print JSON");
    addLevelOptions(*levels);

    CLI::App* plan = cli.command(*lod, "plan", "the cheapest level and model that meet the error and the tick budget",
                                 planCommand);
    plan->footer("Without --error/--budget-us the exercise's, then the preset's, \"needs\" are used.");
    addValue(*plan, "mesh", "FILE", "the tissue mesh (or --exercise)");
    addMeshUnitOption(*plan);
    addValue(*plan, "exercise", "FILE", "the exercise: its mesh and its \"needs\"");
    addValue(*plan, "error", "E", "the displacement error allowed (RMS / peak, 0.1 = 10 %)")->check(anyNumber());
    addValue(*plan, "budget-us", "T", "the tick budget, microseconds")->check(anyNumber());
    addFlag(*plan, "json", "print JSON");
    addFlag(*plan, "quick", "a smoke run: 3 levels, 1 to 3 rings, one short timing");
    addValue(*plan, "rings", "N,..", "the ring counts to try, each 1.." + std::to_string(kMaxRings));
    addValue(*plan, "repeats", "N", "timing repeats")->check(wholeNumberIn(1, 100));
    addLevelOptions(*plan);
    addToolContactOptions(*plan);
}

}  // namespace palpate::cli
