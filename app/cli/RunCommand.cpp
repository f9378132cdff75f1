// palpate-cli run: a headless session on the real-time threaded haptic loop (the GUI's loop without
// the GUI), optionally recorded to a file for info/verify/export/replay (RecordCommand.cpp).
#include "app/cli/Commands.h"
#include "device/WaypointFile.h"
#include "base/resources/ShippedResources.h"
#include "app/cli/ExerciseRun.h"
#include "app/cli/MeshOption.h"
#include "device/open/DeviceUri.h"
#include "engine/loop/HapticLoop.h"
#include "engine/core/SceneTarget.h"
#include "engine/scene/TissuePreset.h"

#include <cstdio>
#include "engine/record/RecordingSession.h"

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <thread>

namespace palpate::cli {

namespace {

std::atomic<bool> gInterrupted{false};
extern "C" void onInterrupt(int) { gInterrupted.store(true); }

/// Exit code of a step that refused to go on; nullopt when it went well.
using Refusal = std::optional<int>;

/// --exercise FILE: a session of a graded exercise on its mesh, preset and physics, recorded with
/// the exercise in the note and scored live (ExerciseRun.h, docs/scoring.md).
Refusal loadExercise(const Given& args, std::unique_ptr<ExerciseRun>& exerciseRun) {
    const auto path = args.option("exercise");
    if (!path) {
        if (args.option("mark-at") || args.option("done-at") || args.option("level")) {
            std::cerr << "run: "
                      << (args.option("mark-at")   ? "--mark-at"
                          : args.option("done-at") ? "--done-at"
                                                   : "--level")
                      << " needs --exercise\n";
            return 2;
        }
        return std::nullopt;
    }
    if (args.option("mesh") || args.option("preset") || args.option(kMeshUnitOption)) {
        std::cerr << "run: --exercise sets the mesh, its unit and the tissue preset; drop --mesh, --mesh-unit "
                     "and --preset\n";
        return 2;
    }
    std::string problem;
    std::string markAt = args.option("mark-at").value_or(""), doneAt = args.option("done-at").value_or("");
    // A scripted trainee's path carries its own Mark and Finish presses ("# mark-at",
    // "# done-at"): played unless the command line gives its own.
    const std::string device = args.option("device").value_or("");
    if (device.starts_with("sim:path:") && !args.option("mark-at") && !args.option("done-at")) {
        WaypointButtons buttons;
        if (!(problem = loadWaypointButtons(device.substr(9), buttons)).empty()) {
            std::cerr << "run: " << problem << "\n";
            return 1;
        }
        char number[32];
        for (double t : buttons.marksS) {
            std::snprintf(number, sizeof(number), "%.17g", t);
            markAt += (markAt.empty() ? "" : ",") + std::string(number);
        }
        if (buttons.doneS) {
            std::snprintf(number, sizeof(number), "%.17g", *buttons.doneS);
            doneAt = number;
        }
        if (!buttons.marksS.empty() || buttons.doneS)
            std::cerr << "run: " << buttons.marksS.size() << " mark(s)" << (buttons.doneS ? " and Finish" : "")
                      << " from the path file (--mark-at or --done-at replaces them)\n";
    }
    exerciseRun = ExerciseRun::load(*path, markAt, doneAt, args.option("level").value_or(""), problem);
    if (!exerciseRun) {
        std::cerr << "run: " << problem << "\n";
        return 1;
    }
    return std::nullopt;
}

/// The tissue preset of the session: the exercise's or --preset's, with --method, --model and --rate.
Refusal choosePreset(const Given& args, const ExerciseRun* exerciseRun, TissuePreset& preset) {
    if (exerciseRun) preset = exerciseRun->preset();
    if (auto path = args.option("preset")) {
        auto loaded = loadTissuePreset(*path);
        if (!loaded.preset) {
            for (const auto& e : loaded.errors) std::cerr << "run: " << e << "\n";
            return 1;
        }
        preset = *loaded.preset;
    }
    if (auto name = args.option("method")) {
        const auto method = parseMethod(*name);
        if (!method) {
            std::cerr << "run: unknown --method '" << *name << "' (use previous, hybrid, proposed or coherent)\n";
            return 2;
        }
        preset.model.slopeRingMethod = *method;
        preset.model.kind = ModelKind::SlopeRing;
    }
    // --model NAME: any registry model (docs/models.md), with the preset's parameters for it.
    if (auto name = args.option("model")) {
        const auto model = modelDefForName(*name);
        if (!model) {
            std::string names;
            for (const std::string& n : modelNames()) names += (names.empty() ? "" : ", ") + n;
            std::cerr << "run: unknown --model '" << *name << "' (use one of " << names << ")\n";
            return 2;
        }
        if (args.option("method") && (model->kind != ModelKind::SlopeRing || model->slopeRingMethod != preset.model.slopeRingMethod)) {
            std::cerr << "run: --model " << *name << " and --method " << *args.option("method") << " disagree\n";
            return 2;
        }
        preset.model.kind = model->kind;
        if (model->kind == ModelKind::SlopeRing) preset.model.slopeRingMethod = model->slopeRingMethod;
    }
    if (auto rate = args.option("rate")) preset.hapticRateHz = *parseNumber(*rate);  // a number, as defined
    return std::nullopt;
}

/// The recording is never written over an input, nor over another recording unasked.
Refusal checkRecordingTarget(const Given& args, const ExerciseRun* exerciseRun, const std::string& meshPath,
                             const std::string& uri, const std::string& recordPath) {
    std::vector<std::pair<std::string, std::string>> inputs{{meshPath, "mesh"},
                                                            {args.option("preset").value_or(""), "preset"}};
    if (exerciseRun) {
        inputs.push_back({*args.option("exercise"), "exercise"});
        inputs.push_back({exerciseRun->presetPath(), "exercise's tissue preset"});
    }
    DeviceUri parsedUri;
    std::string ignored;
    if ((ignored = parseDeviceUri(uri, parsedUri)).empty() && !parsedUri.path.empty())
        inputs.push_back({parsedUri.path, parsedUri.kind == DeviceKind::Replay ? "replayed recording" : "waypoint"});
    if (const std::string problem = outputIsAnInput("record", recordPath, inputs); !problem.empty()) {
        std::cerr << "run: " << problem << "\n";
        return 2;
    }
    std::error_code exists;
    if (!args.flag("overwrite") && std::filesystem::exists(recordPath, exists)) {
        std::cerr << "run: " << recordPath
                  << " already exists; give --overwrite to replace it (or choose another file)\n";
        return 2;
    }
    return std::nullopt;
}

/// What a finished session reports.
struct SessionResult {
    LoopReport loop;
    RecordingStats stats;
    std::string recordError;
    bool recorded = false;
    std::optional<ScoreReport> score;
    std::string scoreError;
};

/// Runs the started loop for `seconds` (or until the exercise is over or the run is interrupted),
/// recording to `recordPath` when given.
Refusal runSession(HapticLoop& loop, ExerciseRun* exerciseRun, const std::optional<std::string>& recordPath,
                   const RecordingHeader& header, bool overwrite, double seconds, SessionResult& result) {
    // The haptic thread first, then the recorder: a thread that cannot start costs no file (the
    // recording begins at the tick that picks the recorder up, HapticLoop::attachRecorder).
    gInterrupted = false;
    auto previousInt = std::signal(SIGINT, onInterrupt);
    auto previousTerm = std::signal(SIGTERM, onInterrupt);
    std::string error;
    if (error = loop.start(); !error.empty()) {
        std::cerr << "run: " << error << "\n";
        return 1;
    }
    std::unique_ptr<RecordingSession> session;
    if (recordPath) {
        RecordingWriterDef writerDef;
        writerDef.replaceExisting = overwrite;
        session = RecordingSession::start(loop, *recordPath, header, error, writerDef);
        if (!session) {
            loop.stop();
            std::cerr << "run: " << error << "\n";
            return 1;
        }
    }
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    if (exerciseRun && session) exerciseRun->follow(*recordPath);
    while (!gInterrupted.load() && std::chrono::steady_clock::now() < end) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        if (exerciseRun) {
            exerciseRun->poll(loop, session.get());
            if (exerciseRun->over()) break;  // completed or out of time
        }
        if (session && !session->stats().error.empty()) break;  // a full disk: nothing more is recorded
    }
    loop.stop();
    std::signal(SIGINT, previousInt);
    std::signal(SIGTERM, previousTerm);
    result.loop = loop.report();
    if (session) {
        result.recordError = session->stop();
        result.stats = session->stats();
        result.recorded = true;
    }
    if (exerciseRun) result.score = exerciseRun->finish(result.scoreError);
    return std::nullopt;
}

void printJson(const SessionResult& s, const std::string& meshPath, const MeshUnit& meshUnit, const std::string& uri,
               const TissuePreset& preset, const HapticLoopDef& def, const std::optional<std::string>& recordPath,
               bool exercise) {
    const LoopReport& r = s.loop;
    nlohmann::json j{{"mesh", meshPath},
                     {"device", uri},
                     {"method", std::string(methodName(preset.model.slopeRingMethod))},
                     {"model", presetModelName(preset)},
                     {"rate_hz", def.rateHz},
                     {"seconds", r.elapsedS},
                     {"ticks", r.counters.ticks},
                     {"overruns", r.counters.overruns},
                     {"missed", r.counters.missedDeadlines},
                     {"sched_fifo", r.counters.schedFifo},
                     {"determinism_hash", r.determinismHash},
                     {"interrupted", gInterrupted.load()}};
    if (!meshUnit.isMillimetres()) j["mesh_unit"] = meshUnit.text();
    if (s.recorded)
        j["recording"] = {{"path", *recordPath},
                          {"ticks", s.stats.ticks},
                          {"bytes", s.stats.bytes},
                          {"bytes_per_tick", s.stats.bytesPerTick()},
                          {"chunks", s.stats.chunks},
                          {"events", s.stats.events},
                          {"dropped_ticks", s.stats.droppedTicks},
                          {"gaps", s.stats.gaps},
                          {"duration_s", s.stats.elapsedS},
                          {"hash", s.stats.hash},
                          {"error", s.recordError}};
    if (s.score) j["score"] = nlohmann::json::parse(scoreReportToJson(*s.score));
    else if (exercise) j["score_error"] = s.scoreError;
    std::cout << j.dump(2) << "\n";
}

void printText(const SessionResult& s, const std::string& uri, const TissuePreset& preset, const HapticLoopDef& def,
               const std::optional<std::string>& recordPath, bool exercise) {
    const LoopReport& r = s.loop;
    std::cout << "session: " << r.counters.ticks << " ticks in " << r.elapsedS << " s at " << def.rateHz << " Hz ("
              << presetModelName(preset) << ", " << uri << "), overruns " << r.counters.overruns
              << ", missed deadlines " << r.counters.missedDeadlines << "\n";
    if (s.recorded) {
        std::cout << "recorded " << s.stats.ticks << " ticks (" << s.stats.elapsedS << " s) to " << *recordPath << ": "
                  << s.stats.bytes << " bytes, " << s.stats.bytesPerTick() << " bytes/tick, " << s.stats.chunks
                  << " chunks, " << s.stats.events << " events, " << s.stats.droppedTicks << " ticks dropped\n";
        if (!s.recordError.empty())
            std::cerr << "run: " << s.recordError << "\n"
                      << "run: " << *recordPath << " holds the " << s.stats.ticks
                      << " ticks above (whole chunks; it has no end chunk)\n";
    }
    if (s.score) std::cout << scoreReportToText(*s.score);
    else if (exercise) std::cerr << "run: no score: " << s.scoreError << "\n";
}

int runCommand(const Given& args) {
    std::unique_ptr<ExerciseRun> exerciseRun;
    if (const Refusal refused = loadExercise(args, exerciseRun)) return *refused;
    const auto seconds = parseNumber(args.option("seconds").value_or(
        exerciseRun ? std::to_string(exerciseRun->exercise().timeLimitS + 1.0) : std::string("10")));
    if (!seconds || *seconds <= 0.0 || *seconds > 86400.0) {  // the exercise's time limit, too
        std::cerr << "run: --seconds must be a number in (0, 86400]\n";
        return 2;
    }
    TissuePreset preset;
    if (const Refusal refused = choosePreset(args, exerciseRun.get(), preset)) return *refused;
    HapticLoopDef def;
    def.rateHz = preset.hapticRateHz;
    def.trySchedFifo = !args.flag("no-fifo");
    if (const std::string problem = joinedMessages(validateHapticLoopDef(def)); !problem.empty()) {
        std::cerr << "run: " << problem << "\n";
        return 2;
    }

    std::string meshPath = args.option("mesh").value_or(exerciseRun ? exerciseRun->meshPath() : findResource(kDefaultMesh));
    if (meshPath.empty()) {
        std::cerr << "run: the default mesh " << kDefaultMesh << " was not found (set PALPATE_RESOURCES)\n";
        return 1;
    }
    std::error_code ec;
    if (const auto absolute = std::filesystem::absolute(meshPath, ec); !ec) meshPath = absolute.string();
    // The exercise's mesh in the exercise's unit (the one its targets were placed on).
    std::string unitError;
    const std::optional<MeshUnit> meshUnit = exerciseRun ? exerciseRun->exercise().meshUnit : meshUnitFromArgs(args, unitError);
    if (!meshUnit) {
        std::cerr << "run: " << unitError << "\n";
        return 2;
    }
    auto loaded = loadMeshFile("run: ", meshPath, *meshUnit,
                               MeshUnitSource{exerciseRun ? *args.option("exercise") : std::string()});
    if (!loaded.mesh) {
        std::cerr << loaded.report.text();
        return 1;
    }
    const std::string uri = args.option("device").value_or("sim:sine");
    const auto recordPath = args.option("record");
    if (recordPath)
        if (const Refusal refused = checkRecordingTarget(args, exerciseRun.get(), meshPath, uri, *recordPath))
            return *refused;
    std::string error;
    auto device = openDeviceUri(uri, error);
    if (!device) {
        std::cerr << "run: " << error << "\n";
        return 1;
    }
    aimAtDefaultTarget(*device, *loaded.mesh, float(presetToolRadiusMm(preset)));
    RecordingHeader header = makeRecordingHeader(*loaded.mesh, meshPath, preset, uri, device->spec(), def.safety);
    header.note = args.option("note").value_or("");
    if (exerciseRun) {
        header.note = exerciseRun->note(header.note, error);
        if (!error.empty()) {
            std::cerr << "run: " << error << "\n";
            return 1;
        }
    }
    // Refused before the session starts: what the reader would refuse is never recorded.
    if (const std::string problem = joinedMessages(validateRecordingHeader(header)); recordPath && !problem.empty()) {
        std::cerr << "run: " << *recordPath << ": not recorded: " << problem << "\n";
        return 1;
    }

    std::unique_ptr<HapticLoop> loop;
    try {
        loop = std::make_unique<HapticLoop>(def, HapticScene::create(std::move(*loaded.mesh), preset),
                                            std::move(device));
    } catch (const std::exception& e) {
        std::cerr << "run: " << e.what() << "\n";
        return 1;
    }
    if (exerciseRun) {
        if (const std::string problem = exerciseRun->applyTo(loop->scene()); !problem.empty()) {
            std::cerr << "run: " << problem << "\n";
            return 1;
        }
    }
    SessionResult result;
    if (const Refusal refused = runSession(*loop, exerciseRun.get(), recordPath, header, args.flag("overwrite"),
                                           *seconds, result))
        return *refused;
    if (args.flag("json")) printJson(result, meshPath, *meshUnit, uri, preset, def, recordPath, bool(exerciseRun));
    else printText(result, uri, preset, def, recordPath, bool(exerciseRun));
    return result.recordError.empty() ? 0 : 1;
}

}  // namespace

void defineRunCommand(CommandLine& cli) {
    CLI::App* run = cli.command(cli.root(), "run",
                                "a headless session on the real-time haptic loop, optionally recorded", runCommand);
    addValue(*run, "mesh", "FILE", "the tissue mesh (default: the shipped one)");
    addMeshUnitOption(*run);
    addValue(*run, "device", "URI", "the device (default sim:sine, docs/devices.md)");
    // The default is the exercise's time limit and one second when --exercise is given.
    addValue(*run, "seconds", "S", "how long to run (default 10)")->check(numberIn(0, 86400, true));
    addValue(*run, "record", "FILE", "record the session (docs/recording.md)");
    addValue(*run, "rate", "HZ", "the haptic rate (default: the preset's)")->check(anyNumber());
    addValue(*run, "method", "M", "the slope-ring method: previous, hybrid, proposed or coherent");
    addValue(*run, "model", "NAME", "any deformation model (docs/models.md)");
    addValue(*run, "preset", "FILE", "the tissue preset");
    addValue(*run, "note", "TEXT", "a note kept in the recording");
    addFlag(*run, "no-fifo", "do not try SCHED_FIFO");
    addFlag(*run, "json", "print JSON");
    addValue(*run, "exercise", "FILE", "a graded exercise: its mesh, unit, preset and physics (docs/scoring.md)");
    addValue(*run, "mark-at", "S,..", "with --exercise: press Mark at these times, s");
    addValue(*run, "done-at", "S", "with --exercise: press Finish at this time, s");
    addValue(*run, "level", "L", "with --exercise: the level to run");
    addFlag(*run, "overwrite", "replace the --record file if it exists");
}

}  // namespace palpate::cli
