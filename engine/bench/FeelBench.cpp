#include "engine/bench/FeelBench.h"

#include "device/SimulatedDevice.h"
#include "engine/core/Octree.h"
#include "engine/loop/HapticLoop.h"
#include "engine/loop/HapticSnapshot.h"
#include "engine/stability/DivergenceGuard.h"
#include "engine/loop/RecorderSink.h"
#include "engine/core/HapticRate.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>
#include <thread>

namespace palpate {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string rounded(double v, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, v);
    return text;
}

void say(const FeelBenchDef& def, const std::string& line) {
    if (def.progress) def.progress(line);
}

/// The stepped slide: every tick's force and normal in the statistics window, and how many of them
/// were in contact. Steps the model directly (what the model renders, no safety filter).
void stepSlide(DeformationModel& model, const SlidePath& path, std::vector<FeelTick>& window,
               std::size_t& contactTicks) {
    model.reset();
    window.clear();
    contactTicks = 0;
    const double dtS = 1.0 / path.rateHz;
    for (std::size_t i = 0; i < path.slideEnd; ++i) {
        const TickResult r = model.step(path.toolMm[i], dtS);
        if (i < path.statsBegin) continue;
        window.push_back({r.forceN, r.normal});
        if (r.contact) ++contactTicks;
    }
}

/// Mean time of one tick over the statistics window, as the haptic loop runs it
/// (engine/loop/HapticLoop.cpp): the model's step, the divergence guard (which reads only the few
/// positions it checks) and the copy of the displaced vertices into the published snapshot; the
/// same work for every model. The ticks before the window run untimed.
double timeSlideNs(DeformationModel& model, const TissueMesh& mesh, const SlidePath& path) {
    model.reset();
    DivergenceGuard guard;
    std::vector<VertexId> ids(HapticSnapshot::kMaxDisplaced);
    std::vector<glm::vec3> positions(HapticSnapshot::kMaxDisplaced);
    std::vector<std::uint8_t> rings(HapticSnapshot::kMaxDisplaced);
    const double dtS = 1.0 / path.rateHz;
    for (std::size_t i = 0; i < path.statsBegin; ++i) model.step(path.toolMm[i], dtS);
    std::size_t read = 0;
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = path.statsBegin; i < path.slideEnd; ++i) {
        const TickResult r = model.step(path.toolMm[i], dtS);
        read += std::size_t(guard.check(mesh, model, r).kind);
        read += model.copyDisplaced(ids.data(), positions.data(), rings.data(), ids.size());
    }
    const auto stop = std::chrono::steady_clock::now();
    volatile std::size_t sink = read;
    (void)sink;
    return std::chrono::duration<double, std::nano>(stop - start).count() / double(path.slideEnd - path.statsBegin);
}

/// The median of `repeats` timed passes, or one pass when a pass takes longer than `onePassAboveS`.
double medianSlideNs(DeformationModel& model, const TissueMesh& mesh, const SlidePath& path, int repeats,
                     double onePassAboveS, int& passes) {
    std::vector<double> ns{timeSlideNs(model, mesh, path)};
    const double passS = ns.front() * 1e-9 * double(path.slideEnd - path.statsBegin);
    if (passS <= onePassAboveS)
        while (int(ns.size()) < repeats) ns.push_back(timeSlideNs(model, mesh, path));
    passes = int(ns.size());
    std::sort(ns.begin(), ns.end());
    return ns[ns.size() / 2];
}

/// Every tick of a threaded run, written by the haptic thread into storage sized beforehand
/// (wait-free: no allocation, lock or I/O in onTick; ticks beyond the capacity are not kept).
class TickCapture final : public RecorderSink {
public:
    explicit TickCapture(std::size_t capacity) : mTicks(capacity) {}
    void onTick(const RecordedTick& tick) noexcept override {
        const std::size_t n = mCount.load(std::memory_order_relaxed);
        if (n >= mTicks.size()) return;
        mTicks[n] = tick;
        mCount.store(n + 1, std::memory_order_release);
    }
    void onCommand(const RecordedCommand&) noexcept override {}
    std::span<const RecordedTick> ticks() const { return {mTicks.data(), mCount.load(std::memory_order_acquire)}; }

private:
    std::vector<RecordedTick> mTicks;
    std::atomic<std::size_t> mCount{0};
};

}  // namespace

double FeelRow::speedupVsPrevious() const {
    return tickNs > 0.0 && previousTickNs > 0.0 && std::isfinite(tickNs) && std::isfinite(previousTickNs)
               ? previousTickNs / tickNs
               : 0.0;
}

std::optional<double> FeelRow::frictionDeviationPct() const {
    if (!dynamicFriction || !(*dynamicFriction > 0.0)) return std::nullopt;
    return 100.0 * (metrics.frictionRatio / *dynamicFriction - 1.0);
}

const char* goalVerdictName(GoalVerdict verdict) {
    switch (verdict) {
        case GoalVerdict::Pass: return "PASS";
        case GoalVerdict::Fail: return "FAIL";
        default: return "-";
    }
}

GoalVerdict stepGoal(const FeelRow& row) {
    if (!row.note.empty() && row.metrics.ticks == 0) return GoalVerdict::NotApplicable;         // not measured
    return row.metrics.maxStepPct <= kFeelStepGoalPct ? GoalVerdict::Pass : GoalVerdict::Fail;  // NaN: FAIL
}

GoalVerdict dropoutGoal(const FeelRow& row) {
    if (!row.loaded) return GoalVerdict::NotApplicable;
    return row.loaded->dropouts == 0 && row.loaded->contactTicks > 0 ? GoalVerdict::Pass : GoalVerdict::Fail;
}

GoalVerdict frictionGoal(const FeelRow& row) {
    const auto deviation = row.frictionDeviationPct();
    if (!deviation) return GoalVerdict::NotApplicable;
    return std::abs(*deviation) <= kFeelFrictionGoalPct ? GoalVerdict::Pass : GoalVerdict::Fail;
}

GoalVerdict speedGoal(const FeelRow& row) {
    if (row.model != kFeelSpeedGoalModel || row.vertices != kFeelSpeedGoalVertices) return GoalVerdict::NotApplicable;
    return row.speedupVsPrevious() >= kFeelSpeedGoalRatio ? GoalVerdict::Pass : GoalVerdict::Fail;
}

Problems validateFeelBenchDef(const FeelBenchDef& def) {
    Problems problems = validateSlideDef(def.slide);
    if (def.shapes.empty()) problems.push_back({"shapes", -1, -1, "shapes: at least one shape"});
    if (def.sizes.empty()) problems.push_back({"sizes", -1, -1, "sizes: at least one vertex count"});
    for (std::size_t i = 0; i < def.sizes.size(); ++i)
        if (def.sizes[i] < kMinGeneratedVertices || def.sizes[i] > 2'000'000)
            problems.push_back({"sizes", int(i), -1,
                                "sizes: " + std::to_string(def.sizes[i]) + " must be a vertex count in " +
                                    std::to_string(kMinGeneratedVertices) + "..2000000"});
    for (const auto* list : {&def.models, &def.loopModels})
        for (std::size_t i = 0; i < list->size(); ++i)
            if (!modelDefForName((*list)[i]))
                problems.push_back({list == &def.models ? "models" : "loopModels", int(i), -1,
                                    "unknown model '" + (*list)[i] + "'"});
    if (def.timingRepeats < 1 || def.timingRepeats > 100)
        problems.push_back({"timingRepeats", -1, -1,
                            "timingRepeats = " + std::to_string(def.timingRepeats) + " must be 1..100"});
    if (def.loop.passes < 1 || def.loop.passes > 100)
        problems.push_back({"loop.passes", -1, -1,
                            "loop.passes = " + std::to_string(def.loop.passes) + " must be 1..100"});
    if (!(def.loop.restS >= 0.0 && def.loop.restS <= 10.0))
        problems.push_back({"loop.restS", -1, -1, "loop.restS must be 0..10 s"});
    if (!hapticRateInRange(def.loop.rateHz))
        problems.push_back({"loop.rateHz", -1, -1, "loop.rateHz must be 10..10000 Hz"});
    if (def.loadProcesses < 0 || def.loadProcesses > 64)
        problems.push_back({"loadProcesses", -1, -1,
                            "loadProcesses = " + std::to_string(def.loadProcesses) + " must be 0..64"});
    return problems;
}

ModelDef feelModelDef(const TissuePreset& preset, const std::string& name) {
    const auto model = modelDefForName(name);
    if (!model) throw std::invalid_argument("unknown model '" + name + "'");
    TissuePreset p = preset;
    p.model.kind = model->kind;
    if (model->kind == ModelKind::SlopeRing) p.model.slopeRingMethod = model->slopeRingMethod;
    return presetModelDef(p);
}

std::optional<double> renderedFriction(const ModelDef& def) {
    const bool usesContact = def.kind == ModelKind::SlopeRing && def.slopeRingMethod == SlopeRingMethod::Coherent;
    if (!usesContact || !(def.contact.dynamicFriction > 0.0)) return std::nullopt;
    return def.contact.dynamicFriction;
}

LoopFeel measureLoopFeel(const TissueMesh& mesh, const ModelDef& model, const SlidePath& path, const LoopFeelDef& def,
                         int loadProcesses) {
    LoopFeel feel;
    feel.loadProcesses = loadProcesses;
    std::vector<Waypoint> waypoints(path.toolMm.size());
    for (std::size_t i = 0; i < waypoints.size(); ++i) waypoints[i] = {double(i) / def.rateHz, path.toolMm[i]};
    const double durationS = double(waypoints.size() - 1) / def.rateHz;  // the device's script ends at the last point
    auto device = std::make_unique<SimulatedDevice>(std::move(waypoints));
    device->setRepeat(def.restS);
    if (!device->open()) throw std::runtime_error("the simulated device did not open");

    HapticLoopDef loopDef;
    loopDef.rateHz = def.rateHz;
    loopDef.trySchedFifo = false;  // normal scheduling: what a trainee's desktop gives
    HapticLoop loop(loopDef, HapticScene::create(TissueMesh(mesh), model), std::move(device));
    const double runS = double(def.passes) * (durationS + def.restS);
    TickCapture capture(std::size_t(std::ceil(runS * def.rateHz * 1.5)) + 1000);
    loop.attachRecorder(&capture);  // its first tick restarts the session: tissue at rest, filter re-armed
    if (const std::string problem = loop.start(); !problem.empty()) throw std::runtime_error(problem);
    std::this_thread::sleep_for(std::chrono::duration<double>(runS + 0.02));
    loop.stop();
    loop.detachRecorder();
    const LoopReport report = loop.report();
    feel.schedFifo = report.counters.schedFifo;
    feel.ticks = report.counters.ticks;
    feel.overruns = report.counters.overruns;
    feel.missedDeadlines = report.counters.missedDeadlines;
    feel.seconds = report.elapsedS;

    // Which ticks are in a statistics window: the device's script time (its clock starts at the
    // first tick; passes repeat every duration + rest) gives the path tick it played.
    const auto ticks = capture.ticks();
    if (ticks.empty()) return feel;
    std::vector<FeltTick> felt(ticks.size());
    std::vector<bool> inWindow(ticks.size(), false);
    const double epochS = ticks.front().nowS;
    const double periodS = durationS + def.restS;
    for (std::size_t i = 0; i < ticks.size(); ++i) {
        felt[i] = {double(glm::length(ticks[i].forceN)), ticks[i].contact};
        const double t = ticks[i].nowS - epochS;
        const int pass = t <= durationS ? 0 : int(std::floor(t / periodS));
        const double scriptS = t <= durationS ? t : std::fmod(t, periodS);
        const long long index = std::llround(scriptS * def.rateHz);
        inWindow[i] = pass < def.passes && index >= (long long)(path.statsBegin) && index < (long long)(path.slideEnd);
    }
    double sumForceN = 0.0, maxStepN = 0.0;
    for (std::size_t i = 0; i < ticks.size();) {
        if (!inWindow[i]) {
            ++i;
            continue;
        }
        std::size_t end = i;
        while (end < ticks.size() && inWindow[end]) ++end;
        feel.windowTicks += end - i;
        for (std::size_t k = i; k < end; ++k) {
            feel.contactTicks += felt[k].contact ? 1 : 0;
            sumForceN += felt[k].forceN;
            if (k > i) maxStepN = std::max(maxStepN, double(glm::length(ticks[k].forceN - ticks[k - 1].forceN)));
        }
        feel.dropouts += countDropouts(felt, i, end);
        i = end;
    }
    feel.maxStepPct = sumForceN > 0.0 ? 100.0 * maxStepN / (sumForceN / double(feel.windowTicks)) : kNaN;
    return feel;
}

std::vector<FeelRow> runFeelBench(const FeelBenchDef& def) {
    if (const Problems problems = validateFeelBenchDef(def); !problems.empty())
        throw std::invalid_argument("bench feel: " + joinedMessages(problems));
    const std::vector<std::string> models = def.models.empty() ? modelNames() : def.models;
    auto runsInLoop = [&](const std::string& name) {
        return std::find(def.loopModels.begin(), def.loopModels.end(), name) != def.loopModels.end();
    };

    std::vector<FeelRow> rows;
    for (GeneratedShape shape : def.shapes)
        for (std::size_t size : def.sizes) {
            say(def, std::string(shapeName(shape)) + " with " + std::to_string(size) + " vertices");
            auto generated = generateMesh(shape, size);
            if (!generated.mesh) throw std::runtime_error(generated.error());
            const TissueMesh& mesh = *generated.mesh;
            const Octree octree(mesh, def.preset.octree);
            std::map<double, SlidePath> paths;  // by tool radius
            auto pathFor = [&](double radiusMm) -> const SlidePath& {
                auto it = paths.find(radiusMm);
                if (it == paths.end()) it = paths.emplace(radiusMm, makeSlidePath(mesh, radiusMm, def.slide)).first;
                return it->second;
            };

            // The baseline first: every row of this mesh is divided by it.
            double previousNs = kNaN;
            int baselinePasses = 0;
            {
                const ModelDef baselineDef = feelModelDef(def.preset, kFeelBaselineModel);
                auto baseline = makeModel(baselineDef, mesh, octree);
                previousNs = medianSlideNs(*baseline, mesh, pathFor(baseline->toolRadiusMm()), def.timingRepeats,
                                           def.onePassAboveS, baselinePasses);
            }

            std::vector<FeelTick> window;
            for (const std::string& name : models) {
                FeelRow row;
                row.shape = shape;
                row.vertices = mesh.vertexCount();
                row.model = name;
                row.depthMm = def.slide.depthMm;
                row.speedMmPerS = def.slide.speedMmPerS;
                row.previousTickNs = previousNs;
                row.tickNs = kNaN;
                const ModelDef modelDef = feelModelDef(def.preset, name);
                row.dynamicFriction = renderedFriction(modelDef);
                std::unique_ptr<DeformationModel> model;
                try {
                    model = makeModel(modelDef, mesh, octree);
                } catch (const std::exception& e) {
                    row.note = std::string("cannot be built: ") + e.what();
                    std::replace(row.note.begin(), row.note.end(), '\n', ' ');
                    say(def, "  " + name + ": " + row.note);
                    rows.push_back(row);
                    continue;
                }
                row.toolRadiusMm = model->toolRadiusMm();
                const SlidePath& path = pathFor(row.toolRadiusMm);
                row.slideLengthMm = path.lengthMm;
                stepSlide(*model, path, window, row.contactTicks);
                row.metrics = feelMetrics(window);
                if (name == kFeelBaselineModel) {
                    row.tickNs = previousNs;  // the baseline measured above: one figure for both
                    row.timingPasses = baselinePasses;
                } else {
                    row.tickNs = medianSlideNs(*model, mesh, path, def.timingRepeats, def.onePassAboveS, row.timingPasses);
                }
                say(def, "  " + name + ": step " + rounded(row.metrics.maxStepPct, 2) + " %, tick " +
                             rounded(row.tickNs, 1) + " ns");
                if (runsInLoop(name)) {
                    say(def, "  " + name + ": threaded loop, quiet");
                    row.quiet = measureLoopFeel(mesh, modelDef, path, def.loop, 0);
                    if (def.startLoad && def.loadProcesses > 0) {
                        say(def,
                            "  " + name + ": threaded loop, " + std::to_string(def.loadProcesses) + " busy processes");
                        const std::function<void()> stopLoad = def.startLoad(def.loadProcesses);
                        try {
                            row.loaded = measureLoopFeel(mesh, modelDef, path, def.loop, def.loadProcesses);
                        } catch (...) {
                            if (stopLoad) stopLoad();
                            throw;
                        }
                        if (stopLoad) stopLoad();
                    }
                }
                rows.push_back(row);
            }
        }
    return rows;
}

}  // namespace palpate
