#pragma once
// The feel bench (docs/bench/README.md, "Feel"): what the hand feels while the tool slides across the
// tissue at constant depth, for every model on the Table 1 meshes. Per model and mesh: the largest
// tick-to-tick force step and the ripple against the mean force, the friction ratio against the
// model's dynamic coefficient, the tick's cost against the paper's faithful "previous" method
// measured in the same run, and (for the models asked for) the force dropouts and overruns of the
// real threaded haptic loop under normal scheduling, quiet and beside busy processes. Each figure is
// printed with the goal it is held to.

#include "engine/bench/FeelMetrics.h"
#include "engine/bench/SlidePath.h"
#include "engine/core/MeshGenerator.h"
#include "engine/models/ModelRegistry.h"
#include "engine/scene/TissuePreset.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

/// The goals (docs/bench/README.md, "Feel").
inline constexpr double kFeelStepGoalPct = 1.0;              ///< largest step <= 1 % of the mean force
inline constexpr double kFeelFrictionGoalPct = 5.0;          ///< friction ratio within 5 % of the coefficient
inline constexpr double kFeelSpeedGoalRatio = 200.0;         ///< coherent >= 200x faster than previous ...
inline constexpr std::size_t kFeelSpeedGoalVertices = 8664;  ///< ... at 8664 vertices
/// The model the speed goal is about (the one the haptic loop runs by default).
inline constexpr const char* kFeelSpeedGoalModel = "coherent";
/// The baseline tick costs are divided by.
inline constexpr const char* kFeelBaselineModel = "previous";

/// The threaded run (engine/loop/HapticLoop.h) of a slide: normal scheduling, never SCHED_FIFO.
struct LoopFeelDef {
    int passes = 2;          ///< the slide played this many times in one run
    double restS = 0.05;     ///< above the surface between passes
    double rateHz = 1000.0;  ///< the loop's rate (the slide's ticks are played at it)
};

/// What a threaded run felt, over the statistics window of each pass.
struct LoopFeel {
    int loadProcesses = 0;       ///< busy processes spinning beside the loop
    bool schedFifo = false;      ///< always false here (asked for normal scheduling)
    std::uint64_t ticks = 0;     ///< the loop's ticks in the run
    std::uint64_t overruns = 0;  ///< ticks that missed their deadline (whole run)
    std::uint64_t missedDeadlines = 0;
    std::size_t windowTicks = 0;   ///< ticks inside the statistics windows
    std::size_t contactTicks = 0;  ///< of which in contact
    std::size_t dropouts = 0;      ///< contact ticks with |F| below half its neighbours' mean (countDropouts)
    /// Largest |F_t - F_t-1| between ticks of a window, % of the windows' mean |F| (after the safety
    /// filter): what a late tick (the tool moved on by the missed periods) does to the force.
    double maxStepPct = 0.0;
    double seconds = 0.0;
};

struct FeelRow {
    GeneratedShape shape = GeneratedShape::Sphere;
    std::size_t vertices = 0;
    std::string model;
    double toolRadiusMm = 0.0;  ///< DeformationModel::toolRadiusMm (0: a point tool)
    double depthMm = 0.0;
    double speedMmPerS = 0.0;
    double slideLengthMm = 0.0;
    std::size_t contactTicks = 0;  ///< of metrics.ticks (the statistics window of the stepped slide)
    FeelMetrics metrics;
    /// The dynamic friction coefficient the model renders (renderedFriction); nullopt: none.
    std::optional<double> dynamicFriction;
    double tickNs = 0.0;          ///< mean tick as the loop runs it: step, divergence guard, snapshot copy
    double previousTickNs = 0.0;  ///< the same for "previous" on the same mesh, same run
    int timingPasses = 0;
    std::optional<LoopFeel> quiet;   ///< threaded, nothing beside it
    std::optional<LoopFeel> loaded;  ///< threaded, with busy processes beside it
    std::string note;                ///< why figures are missing, when they are

    /// previousTickNs / tickNs (0 when either is unknown).
    double speedupVsPrevious() const;
    /// (frictionRatio / dynamicFriction - 1) in %; nullopt without a coefficient.
    std::optional<double> frictionDeviationPct() const;
};

enum class GoalVerdict { NotApplicable, Pass, Fail };
/// "PASS", "FAIL", or "-" when the goal does not apply to the row.
const char* goalVerdictName(GoalVerdict verdict);
/// Largest step <= kFeelStepGoalPct (no force at all: FAIL).
GoalVerdict stepGoal(const FeelRow& row);
/// No dropout in the loaded threaded run (not applicable without one).
GoalVerdict dropoutGoal(const FeelRow& row);
/// Friction ratio within kFeelFrictionGoalPct of the coefficient (not applicable without friction).
GoalVerdict frictionGoal(const FeelRow& row);
/// kFeelSpeedGoalModel at kFeelSpeedGoalVertices: speedup >= kFeelSpeedGoalRatio.
GoalVerdict speedGoal(const FeelRow& row);

struct FeelBenchDef {
    std::vector<GeneratedShape> shapes{GeneratedShape::Sphere, GeneratedShape::Stomach};
    std::vector<std::size_t> sizes{1442, 3970, 5762, 8664};
    std::vector<std::string> models;  ///< registry names; empty: every model (modelNames())
    /// Every model is built from this preset (feelModelDef): its parameters, and its tissue's tool
    /// radius and friction (ModelDef::contact).
    TissuePreset preset;
    SlideDef slide;
    int timingRepeats = 3;        ///< timed passes over the slide (median of their means) ...
    double onePassAboveS = 0.25;  ///< ... or one, for a model whose slide takes longer than this
    /// Models also run in the threaded loop (registry names, among `models`).
    std::vector<std::string> loopModels{"coherent"};
    LoopFeelDef loop;
    int loadProcesses = 2;
    /// Starts `processes` busy processes beside the loop and returns what stops them (the command
    /// line forks spinning children). Unset, or loadProcesses 0: only the quiet run.
    std::function<std::function<void()>(int processes)> startLoad;
    std::function<void(const std::string&)> progress;  ///< optional, a line per step
};

/// Every problem of the definition (sizes, model names, slide, loop), each naming the field.
Problems validateFeelBenchDef(const FeelBenchDef& def);

/// The registry model `name` with the preset's parameters, tool and friction (as palpate-cli run
/// --model builds it). Throws std::invalid_argument for an unknown name.
ModelDef feelModelDef(const TissuePreset& preset, const std::string& name);
/// The dynamic friction coefficient a definition's model renders: ModelDef::contact is the coherent
/// slope-ring method's (the others touch with a point, without friction); nullopt when it has none.
std::optional<double> renderedFriction(const ModelDef& def);

/// Runs the bench. Throws std::invalid_argument on an invalid definition.
std::vector<FeelRow> runFeelBench(const FeelBenchDef& def);

/// One threaded run of `path` on a fresh scene of `mesh` with `model` (a simulated device plays the
/// path; the loop under normal scheduling). `loadProcesses` is only recorded: whoever calls this
/// starts them. Takes about passes x (path duration + rest) seconds.
LoopFeel measureLoopFeel(const TissueMesh& mesh, const ModelDef& model, const SlidePath& path, const LoopFeelDef& def,
                         int loadProcesses = 0);

}  // namespace palpate
