// palpate-cli run: a headless session on the real-time threaded haptic loop (the GUI's loop without
// the GUI), optionally recorded to a file for info/verify/export/replay (RecordCommand.cpp).
#include "app/cli/Args.h"
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

}  // namespace

int runCommand(const std::vector<std::string>& words) {
    Args args(words, {"json", "no-fifo", "overwrite"},
              {"mesh", "device", "seconds", "record", "rate", "method", "model", "preset", "note", "exercise",
               "mark-at", "done-at", "level", kMeshUnitOption});
    if (!args.ok()) {
        std::cerr << "run: " << args.error() << "\n";
        return 2;
    }
    if (!args.positional().empty()) {
        std::cerr << "run: unexpected argument '" << args.positional().front() << "'\n";
        return 2;
    }
    // --exercise FILE: a session of a graded exercise on its mesh, preset and physics, recorded with
    // the exercise in the note and scored live (ExerciseRun.h, docs/scoring.md).
    std::unique_ptr<ExerciseRun> exerciseRun;
    if (auto path = args.option("exercise")) {
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
    } else if (args.option("mark-at") || args.option("done-at") || args.option("level")) {
        std::cerr << "run: " << (args.option("mark-at") ? "--mark-at" : args.option("done-at") ? "--done-at" : "--level")
                  << " needs --exercise\n";
        return 2;
    }
    const auto seconds = parseNumber(args.option("seconds").value_or(
        exerciseRun ? std::to_string(exerciseRun->exercise().timeLimitS + 1.0) : std::string("10")));
    if (!seconds || *seconds <= 0.0 || *seconds > 86400.0) {
        std::cerr << "run: --seconds must be a number in (0, 86400]\n";
        return 2;
    }
    TissuePreset preset;
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
    if (auto rate = args.option("rate")) {
        const auto hz = parseNumber(*rate);
        if (!hz) {
            std::cerr << "run: --rate must be a number\n";
            return 2;
        }
        preset.hapticRateHz = *hz;
    }
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
    std::string error;
    const auto recordPath = args.option("record");
    if (recordPath) {
        // The recording is never written over an input, nor over another recording unasked.
        std::vector<std::pair<std::string, std::string>> inputs{{meshPath, "mesh"},
                                                                {args.option("preset").value_or(""), "preset"}};
        if (exerciseRun) {
            inputs.push_back({*args.option("exercise"), "exercise"});
            inputs.push_back({exerciseRun->presetPath(), "exercise's tissue preset"});
        }
        DeviceUri parsedUri;
        std::string ignored;
        if ((ignored = parseDeviceUri(uri, parsedUri)).empty() && !parsedUri.path.empty())
            inputs.push_back({parsedUri.path,
                              parsedUri.kind == DeviceKind::Replay ? "replayed recording" : "waypoint"});
        if (const std::string problem = outputIsAnInput("record", *recordPath, inputs); !problem.empty()) {
            std::cerr << "run: " << problem << "\n";
            return 2;
        }
        std::error_code exists;
        if (!args.flag("overwrite") && std::filesystem::exists(*recordPath, exists)) {
            std::cerr << "run: " << *recordPath
                      << " already exists; give --overwrite to replace it (or choose another file)\n";
            return 2;
        }
    }
    auto device = openDeviceUri(uri, error);
    if (!device) {
        std::cerr << "run: " << error << "\n";
        return 1;
    }
    aimAtDefaultTarget(*device, *loaded.mesh, float(presetToolRadiusMm(preset)));
    RecordingHeader header =
        makeRecordingHeader(*loaded.mesh, meshPath, preset, uri, device->spec(), def.safety);
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
        loop = std::make_unique<HapticLoop>(
            def, HapticScene::create(std::move(*loaded.mesh), preset), std::move(device));
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
    // The haptic thread first, then the recorder: a thread that cannot start costs no file (the
    // recording begins at the tick that picks the recorder up, HapticLoop::attachRecorder).
    gInterrupted = false;
    auto previousInt = std::signal(SIGINT, onInterrupt);
    auto previousTerm = std::signal(SIGTERM, onInterrupt);
    if (error = loop->start(); !error.empty()) {
        std::cerr << "run: " << error << "\n";
        return 1;
    }
    std::unique_ptr<RecordingSession> session;
    if (recordPath) {
        RecordingWriterDef writerDef;
        writerDef.replaceExisting = args.flag("overwrite");
        session = RecordingSession::start(*loop, *recordPath, header, error, writerDef);
        if (!session) {
            loop->stop();
            std::cerr << "run: " << error << "\n";
            return 1;
        }
    }
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(*seconds);
    if (exerciseRun && session) exerciseRun->follow(*recordPath);
    while (!gInterrupted.load() && std::chrono::steady_clock::now() < end) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        if (exerciseRun) {
            exerciseRun->poll(*loop, session.get());
            if (exerciseRun->over()) break;  // completed or out of time
        }
        if (session && !session->stats().error.empty()) break;  // a full disk: nothing more is recorded
    }
    loop->stop();
    std::signal(SIGINT, previousInt);
    std::signal(SIGTERM, previousTerm);
    const LoopReport r = loop->report();
    RecordingStats stats;
    std::string recordError;
    if (session) {
        recordError = session->stop();
        stats = session->stats();
    }
    std::optional<ScoreReport> score;
    std::string scoreError;
    if (exerciseRun) score = exerciseRun->finish(scoreError);

    if (args.flag("json")) {
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
        if (!meshUnit->isMillimetres()) j["mesh_unit"] = meshUnit->text();
        if (session)
            j["recording"] = {{"path", *recordPath},
                              {"ticks", stats.ticks},
                              {"bytes", stats.bytes},
                              {"bytes_per_tick", stats.bytesPerTick()},
                              {"chunks", stats.chunks},
                              {"events", stats.events},
                              {"dropped_ticks", stats.droppedTicks},
                              {"gaps", stats.gaps},
                              {"duration_s", stats.elapsedS},
                              {"hash", stats.hash},
                              {"error", recordError}};
        if (score) j["score"] = nlohmann::json::parse(scoreReportToJson(*score));
        else if (exerciseRun) j["score_error"] = scoreError;
        std::cout << j.dump(2) << "\n";
    } else {
        std::cout << "session: " << r.counters.ticks << " ticks in " << r.elapsedS << " s at " << def.rateHz
                  << " Hz (" << presetModelName(preset) << ", " << uri << "), overruns " << r.counters.overruns
                  << ", missed deadlines " << r.counters.missedDeadlines << "\n";
        if (session) {
            std::cout << "recorded " << stats.ticks << " ticks (" << stats.elapsedS << " s) to " << *recordPath << ": "
                      << stats.bytes << " bytes, " << stats.bytesPerTick() << " bytes/tick, " << stats.chunks
                      << " chunks, " << stats.events << " events, " << stats.droppedTicks << " ticks dropped\n";
            if (!recordError.empty())
                std::cerr << "run: " << recordError << "\n"
                          << "run: " << *recordPath << " holds the " << stats.ticks
                          << " ticks above (whole chunks; it has no end chunk)\n";
        }
        if (score) std::cout << scoreReportToText(*score);
        else if (exerciseRun) std::cerr << "run: no score: " << scoreError << "\n";
    }
    return recordError.empty() ? 0 : 1;
}

}  // namespace palpate::cli
