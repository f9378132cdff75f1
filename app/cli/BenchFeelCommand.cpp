// palpate-cli bench feel: what the hand feels while the tool slides across the tissue at constant
// depth (engine/bench/FeelBench.h, docs/bench/README.md "Feel"), for every model on the Table 1
// meshes: force steps, ripple, friction, tick cost against "previous" in the same run, and the
// threaded loop's dropouts under normal scheduling beside busy processes; each with its goal.
#include "app/cli/BusyProcesses.h"
#include "app/cli/Commands.h"
#include "base/resources/ShippedResources.h"
#include "engine/bench/FeelBench.h"
#include "engine/bench/FeelCsv.h"

#ifdef PALPATE_HAVE_CHARTS
#include "report/FeelChartImage.h"
#endif

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace palpate::cli {

namespace {

std::string fixed(double v, int precision) {
    if (!std::isfinite(v)) return "-";
    std::ostringstream s;
    s << std::fixed << std::setprecision(precision) << v;
    return s.str();
}

std::string ratioText(double r) {
    if (!(r > 0.0)) return "-";
    return fixed(r, r >= 100.0 ? 0 : 1) + "x";
}

std::string loopPair(const FeelRow& r, std::size_t LoopFeel::*dropouts) {
    auto one = [&](const std::optional<LoopFeel>& run) {
        return run ? std::to_string((*run).*dropouts) : std::string("-");
    };
    return one(r.quiet) + "/" + one(r.loaded);
}

std::string loopStepPair(const FeelRow& r) {
    auto one = [](const std::optional<LoopFeel>& run) { return run ? fixed(run->maxStepPct, 1) : std::string("-"); };
    return one(r.quiet) + "/" + one(r.loaded);
}

std::string overrunPair(const FeelRow& r) {
    auto one = [](const std::optional<LoopFeel>& run) {
        return run ? std::to_string(run->overruns) : std::string("-");
    };
    return one(r.quiet) + "/" + one(r.loaded);
}

void printTable(const std::vector<FeelRow>& rows, const FeelBenchDef& def, double seconds, std::ostream& out) {
    out << "Feel: a slide at " << def.slide.depthMm << " mm depth, " << def.slide.speedMmPerS << " mm/s for "
        << def.slide.slideS << " s at " << def.slide.rateHz << " Hz (statistics after the first "
        << def.slide.breakawayS * 1000.0 << " ms of sliding)\n";
    out << std::left << std::setw(8) << "shape" << std::right << std::setw(6) << "verts"
        << "  " << std::left << std::setw(23) << "model" << std::right << std::setw(5) << "a mm" << std::setw(8)
        << "mean N" << std::setw(8) << "step %" << std::setw(9) << "Fn st %" << std::setw(9) << "ripple %"
        << std::setw(7) << "Ft/Fn" << std::setw(6) << "mu_d" << std::setw(8) << "dev %" << std::setw(10) << "tick ns"
        << std::setw(9) << "vs prev" << std::setw(10) << "drop q/L" << std::setw(13) << "overrun q/L" << std::setw(13)
        << "lstep % q/L"
        << "  step drop fric speed\n";
    for (const FeelRow& r : rows) {
        const auto deviation = r.frictionDeviationPct();
        out << std::left << std::setw(8) << shapeName(r.shape) << std::right << std::setw(6) << r.vertices << "  "
            << std::left << std::setw(23) << r.model << std::right << std::setw(5) << fixed(r.toolRadiusMm, 1)
            << std::setw(8) << fixed(r.metrics.meanForceN, 3) << std::setw(8) << fixed(r.metrics.maxStepPct, 2)
            << std::setw(9) << fixed(r.metrics.maxNormalStepPct, 2) << std::setw(9) << fixed(r.metrics.ripplePct, 1)
            << std::setw(7) << fixed(r.metrics.frictionRatio, 3) << std::setw(6)
            << (r.dynamicFriction ? fixed(*r.dynamicFriction, 2) : "-") << std::setw(8)
            << (deviation ? fixed(*deviation, 1) : "-") << std::setw(10) << fixed(r.tickNs, r.tickNs < 1000.0 ? 1 : 0)
            << std::setw(9) << ratioText(r.speedupVsPrevious()) << std::setw(10) << loopPair(r, &LoopFeel::dropouts)
            << std::setw(13) << overrunPair(r) << std::setw(13) << loopStepPair(r) << "  " << std::left << std::setw(5)
            << goalVerdictName(stepGoal(r)) << std::setw(5) << goalVerdictName(dropoutGoal(r)) << std::setw(5)
            << goalVerdictName(frictionGoal(r)) << goalVerdictName(speedGoal(r)) << std::right;
        if (!r.note.empty()) out << "  (" << r.note << ")";
        out << "\n";
    }
    out << "\nstep %: largest |F_t - F_t-1| over the slide, % of the mean |F|; Fn st %: the same for the normal part\n"
           "alone (F . TickResult::normal; a model without a normal renders all of its force as normal); ripple %:\n"
           "(max - min) / mean of |F|. Ft/Fn: mean tangential / mean normal force; mu_d: the dynamic friction coefficient\n"
           "the model renders (ModelDef::contact, from the preset's tissue; '-': none); dev %: Ft/Fn against mu_d.\n"
           "a mm: the tool's radius (0: a point tool, its tip 1 mm deep; > 0: a sphere penetrating 1 mm).\n"
           "tick ns: the tick as the haptic loop runs it (the model's step, the divergence guard, the snapshot copy),\n"
           "mean over the slide, median of passes; vs prev: \"previous\"'s tick on the same mesh\n"
           "in this run divided by this one. drop q/L: dropouts (contact ticks with |F| below half the mean of the +-3\n"
           "ticks around them) in the real threaded loop under normal scheduling (not SCHED_FIFO), quiet / beside "
        << def.loadProcesses << " busy processes,\n"
        << def.loop.passes
        << " slide(s) per run; overrun q/L: the loop's ticks that missed their deadline; lstep % q/L: the largest\n"
           "force step there (after the safety filter), % of the mean |F|.\n";
    out << "Goals: step <= " << kFeelStepGoalPct << " % of the mean force on every mesh; 0 dropouts beside "
        << def.loadProcesses << " busy processes; friction ratio within " << kFeelFrictionGoalPct << " % of mu_d; "
        << kFeelSpeedGoalModel << " >= " << kFeelSpeedGoalRatio << "x faster than previous at "
        << kFeelSpeedGoalVertices << " vertices.\n";
    out << "(" << fixed(seconds, 0) << " s)\n";
}

nlohmann::ordered_json numberOrNull(double v) {
    return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json loopJson(const std::optional<LoopFeel>& run) {
    if (!run) return nullptr;
    return {{"load_processes", run->loadProcesses},
            {"sched_fifo", run->schedFifo},
            {"ticks", run->ticks},
            {"overruns", run->overruns},
            {"missed_deadlines", run->missedDeadlines},
            {"window_ticks", run->windowTicks},
            {"contact_ticks", run->contactTicks},
            {"dropouts", run->dropouts},
            {"max_step_pct", numberOrNull(run->maxStepPct)},
            {"seconds", run->seconds}};
}

nlohmann::ordered_json verdictJson(GoalVerdict v) {
    return v == GoalVerdict::NotApplicable ? nlohmann::ordered_json(nullptr)
                                           : nlohmann::ordered_json(goalVerdictName(v));
}

std::string toJson(const std::vector<FeelRow>& rows, const FeelBenchDef& def, const std::string& presetPath) {
    nlohmann::ordered_json j;
    j["slide"] = {{"depth_mm", def.slide.depthMm}, {"speed_mm_per_s", def.slide.speedMmPerS},
                  {"slide_s", def.slide.slideS},   {"approach_s", def.slide.approachS},
                  {"settle_s", def.slide.settleS}, {"breakaway_s", def.slide.breakawayS},
                  {"lift_s", def.slide.liftS},     {"rate_hz", def.slide.rateHz}};
    j["preset"] = presetPath;
    j["loop"] = {{"passes", def.loop.passes},
                 {"rest_s", def.loop.restS},
                 {"sched_fifo", false},
                 {"load_processes", def.loadProcesses},
                 {"models", def.loopModels}};
    j["goals"] = {{"max_step_pct", kFeelStepGoalPct},
                  {"loaded_dropouts", 0},
                  {"friction_deviation_pct", kFeelFrictionGoalPct},
                  {"speedup_vs_previous", kFeelSpeedGoalRatio},
                  {"speedup_model", kFeelSpeedGoalModel},
                  {"speedup_vertices", kFeelSpeedGoalVertices}};
    j["rows"] = nlohmann::ordered_json::array();
    for (const FeelRow& r : rows) {
        const auto deviation = r.frictionDeviationPct();
        nlohmann::ordered_json row{
            {"shape", std::string(shapeName(r.shape))},
            {"vertices", r.vertices},
            {"model", r.model},
            {"tool_radius_mm", r.toolRadiusMm},
            {"depth_mm", r.depthMm},
            {"speed_mm_per_s", r.speedMmPerS},
            {"slide_length_mm", r.slideLengthMm},
            {"stats_ticks", r.metrics.ticks},
            {"contact_ticks", r.contactTicks},
            {"mean_force_n", numberOrNull(r.metrics.meanForceN)},
            {"max_step_pct", numberOrNull(r.metrics.maxStepPct)},
            {"max_normal_step_pct", numberOrNull(r.metrics.maxNormalStepPct)},
            {"ripple_pct", numberOrNull(r.metrics.ripplePct)},
            {"mean_normal_force_n", numberOrNull(r.metrics.meanNormalN)},
            {"mean_tangential_force_n", numberOrNull(r.metrics.meanTangentialN)},
            {"friction_ratio", numberOrNull(r.metrics.frictionRatio)},
            {"dynamic_friction",
             r.dynamicFriction ? nlohmann::ordered_json(*r.dynamicFriction) : nlohmann::ordered_json(nullptr)},
            {"friction_deviation_pct",
             deviation ? nlohmann::ordered_json(*deviation) : nlohmann::ordered_json(nullptr)},
            {"tick_ns", numberOrNull(r.tickNs)},
            {"previous_tick_ns", numberOrNull(r.previousTickNs)},
            {"speedup_vs_previous", r.speedupVsPrevious() > 0.0 ? nlohmann::ordered_json(r.speedupVsPrevious())
                                                                : nlohmann::ordered_json(nullptr)},
            {"timing_passes", r.timingPasses},
            {"quiet", loopJson(r.quiet)},
            {"loaded", loopJson(r.loaded)},
            {"step_goal", verdictJson(stepGoal(r))},
            {"dropout_goal", verdictJson(dropoutGoal(r))},
            {"friction_goal", verdictJson(frictionGoal(r))},
            {"speed_goal", verdictJson(speedGoal(r))},
        };
        if (!r.note.empty()) row["note"] = r.note;
        j["rows"].push_back(row);
    }
    return j.dump(2) + "\n";
}

}  // namespace

void defineBenchFeelOptions(CLI::App& command) {
    addFlag(command, "json", "print JSON");
    addValue(command, "csv", "FILE", "also write the rows as CSV");
    addValue(command, "png", "FILE", "also draw the force along the slide");
    addFlag(command, "quick", "a smoke run: the smallest mesh of each shape, a short slide, one pass");
    addValue(command, "models", "NAME,..", "the models to measure (default: every model)");
    addValue(command, "load", "N", "busy processes beside the threaded runs")->check(wholeNumberIn(0, 64));
    addValue(command, "loop-models", "NAME,..|all|none", "the measured models that also run on the threaded loop");
    addValue(command, "preset", "FILE", "the tissue preset the models are built from (default presets/default.json)");
    addValue(command, "repeats", "N", "timing repeats")->check(wholeNumberIn(1, 100));
}

int benchFeelCommand(const Given& args) {
    FeelBenchDef def;
    if (args.flag("quick")) {  // a smoke run: the smallest mesh of each shape, a short slide, one pass
        def.sizes = {1442};
        def.slide.slideS = 0.5;
        def.timingRepeats = 1;
        def.loop.passes = 1;
    }
    if (const auto models = args.option("models")) {
        def.models = splitList(*models);
        if (def.models.empty()) {
            std::cerr << "bench feel: --models needs at least one name\n";
            return 2;
        }
    }
    if (const auto loopModels = args.option("loop-models")) {
        // "all": every model measured also runs threaded; "none": no threaded run.
        if (*loopModels == "all") def.loopModels = def.models.empty() ? modelNames() : def.models;
        else if (*loopModels == "none") def.loopModels.clear();
        else def.loopModels = splitList(*loopModels);
    }
    if (!def.models.empty()) {  // the threaded runs are of measured models only
        std::vector<std::string> kept;
        for (const std::string& m : def.loopModels)
            if (std::find(def.models.begin(), def.models.end(), m) != def.models.end()) kept.push_back(m);
        if (args.option("loop-models") && kept.size() != def.loopModels.size()) {
            std::cerr << "bench feel: --loop-models names a model that --models leaves out\n";
            return 2;
        }
        def.loopModels = kept;
    }
    // Their ranges are checked by their definitions (defineBenchFeelOptions).
    if (const auto load = args.option("load")) def.loadProcesses = std::stoi(*load);
    if (const auto repeats = args.option("repeats")) def.timingRepeats = int(*parsePositiveInt(*repeats));
    // The models are built from the default preset (its parameters; its tissue's tool and friction,
    // or the defaults of TissueProperties when it names none), or from --preset FILE.
    std::string presetPath = args.option("preset").value_or(findResource("presets/default.json"));
    if (presetPath.empty()) {
        std::cerr
            << "bench feel: the default preset presets/default.json was not found (set PALPATE_RESOURCES or use --preset)\n";
        return 1;
    }
    const auto loaded = loadTissuePreset(presetPath);
    if (!loaded.preset) {
        for (const std::string& e : loaded.errors) std::cerr << "bench feel: " << e << "\n";
        return 1;
    }
    def.preset = *loaded.preset;
    if (const Problems problems = validateFeelBenchDef(def); !problems.empty()) {
        for (const Problem& p : problems) std::cerr << "bench feel: " << p.message << "\n";
        return 2;
    }
#ifndef PALPATE_HAVE_CHARTS
    if (args.option("png")) {
        std::cerr << "bench feel: --png needs a build with the GUI (Qt Charts); this one has none\n";
        return 2;
    }
#endif
    def.startLoad = [](int processes) -> std::function<void()> {
        auto busy = std::make_shared<BusyProcesses>(processes);
        if (busy->started() != processes)
            std::cerr << "bench feel: only " << busy->started() << " of " << processes << " busy processes started\n";
        return [busy] { busy->stop(); };
    };
    def.progress = [](const std::string& line) { std::cerr << line << "\n"; };

    const auto start = std::chrono::steady_clock::now();
    std::vector<FeelRow> rows;
    try {
        rows = runFeelBench(def);
    } catch (const std::exception& e) {
        std::cerr << "bench feel: " << e.what() << "\n";
        return 1;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    if (const auto csvPath = args.option("csv")) {
        std::ofstream csv(*csvPath);
        csv << feelToCsv(rows);
        if (!csv) {
            std::cerr << "bench feel: " << *csvPath << ": cannot be written\n";
            return 1;
        }
    }
#ifdef PALPATE_HAVE_CHARTS
    if (const auto png = args.option("png")) {
        std::string error;
        if (!(error = renderFeelChartPng(rows, *png)).empty()) {
            std::cerr << "bench feel: " << *png << ": " << error << "\n";
            return 1;
        }
    }
#endif
    if (args.flag("json")) std::cout << toJson(rows, def, presetPath);
    else printTable(rows, def, seconds, std::cout);
    return 0;
}

}  // namespace palpate::cli
