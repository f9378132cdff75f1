// palpate-cli loop: the real haptic thread on the default scene with a simulated device, and an
// observer thread reading snapshots the way the GUI does; prints the loop's timing.
#include "app/cli/Commands.h"
#include "app/cli/MeshOption.h"
#include "base/resources/ShippedResources.h"
#include "device/open/DeviceUri.h"
#include "engine/loop/HapticLoop.h"
#include "engine/core/SceneTarget.h"

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <system_error>
#include <thread>

namespace palpate::cli {

namespace {

int loopCommand(const Given& args) {
    const auto seconds = parseNumber(args.option("seconds").value_or("5"));
    const auto rate = parseNumber(args.option("rate").value_or("1000"));
    const auto observerHz = parseNumber(args.option("observer-hz").value_or("60"));
    const auto spinFraction = parseNumber(args.option("spin-fraction").value_or("0.6"));
    HapticLoopDef def;
    def.rateHz = rate.value_or(-1.0);
    def.spinFraction = spinFraction.value_or(-1.0);
    def.trySchedFifo = !args.flag("no-fifo");
    if (const std::string problem = joinedMessages(validateHapticLoopDef(def)); !problem.empty()) {
        std::cerr << "loop: " << problem << "\n";
        return 2;
    }

    const std::string meshPath = args.option("mesh").value_or(findResource(kDefaultMesh));
    std::string unitError;
    const auto meshUnit = meshUnitFromArgs(args, unitError);
    if (!meshUnit) {
        std::cerr << "loop: " << unitError << "\n";
        return 2;
    }
    auto loaded = loadMeshFile("loop: ", meshPath, *meshUnit);
    if (!loaded.mesh) {
        std::cerr << loaded.report.text();
        return 1;
    }
    const std::string uri = args.option("device").value_or("sim:sine");
    if (const auto csvPath = args.option("csv")) {
        if (const std::string problem = outputIsAnInput("csv", *csvPath, {{meshPath, "mesh"}}); !problem.empty()) {
            std::cerr << "loop: " << problem << "\n";
            return 2;
        }
    }
    std::string error;
    auto device = openDeviceUri(uri, error);
    if (!device) {
        std::cerr << "loop: " << error << "\n";
        return 1;
    }
    aimAtDefaultTarget(*device, *loaded.mesh);

    HapticLoop loop(def, HapticScene::create(std::move(*loaded.mesh), ModelDef{}), std::move(device));
    std::atomic<bool> observing{true};
    std::uint64_t snapshotsSeen = 0, torn = 0, contactSnapshots = 0, lastPublish = 0;
    // A thread that cannot be created (a process or memory limit) is a message, not an abort.
    std::thread observer;
    try {
        observer = std::thread([&] {
            const auto period = std::chrono::duration<double>(1.0 / *observerHz);
            auto next = std::chrono::steady_clock::now();
            while (observing.load(std::memory_order_acquire)) {
                const HapticSnapshot& s = loop.newestSnapshot();
                if (s.publishCount != lastPublish) {
                    ++snapshotsSeen;
                    if (s.closingTick != s.tick || s.publishCount < lastPublish ||
                        s.displacedCount > HapticSnapshot::kMaxDisplaced)
                        ++torn;
                    if (s.contact) ++contactSnapshots;
                    lastPublish = s.publishCount;
                }
                next += std::chrono::duration_cast<std::chrono::steady_clock::duration>(period);
                std::this_thread::sleep_until(next);
            }
        });
    } catch (const std::system_error& e) {
        std::cerr << "loop: could not start the observer thread: " << e.what() << "\n";
        return 1;
    }
    if (error = loop.start(); !error.empty()) {
        observing = false;
        observer.join();
        std::cerr << "loop: " << error << "\n";
        return 1;
    }
    std::this_thread::sleep_for(std::chrono::duration<double>(*seconds));
    loop.stop();
    observing = false;
    observer.join();
    const LoopReport r = loop.report();

    if (auto csvPath = args.option("csv")) {
        // One row per run, appended, so several rates build one table.
        const bool fresh = !std::ifstream(*csvPath).good();
        std::ofstream csv(*csvPath, std::ios::app);
        if (!csv) {
            std::cerr << "loop: cannot write " << *csvPath << "\n";
            return 1;
        }
        if (fresh)
            csv << "rate_hz,seconds,ticks,missed,overruns,achieved_rate_hz,jitter_p50_us,jitter_p99_us,jitter_p999_us,"
                   "jitter_max_us,compute_p50_us,compute_p99_us,compute_max_us,sched_fifo,observer_hz,"
                   "observer_snapshots,observer_torn_snapshots\n";
        csv << def.rateHz << "," << r.elapsedS << "," << r.counters.ticks << "," << r.counters.missedDeadlines << ","
            << r.counters.overruns << "," << r.counters.achievedRateHz << "," << r.jitter.p50Us << ","
            << r.jitter.p99Us << "," << r.jitter.p999Us << "," << r.jitter.maxUs << "," << r.compute.p50Us << ","
            << r.compute.p99Us << "," << r.compute.maxUs << "," << (r.counters.schedFifo ? 1 : 0) << ","
            << *observerHz << "," << snapshotsSeen << "," << torn << "\n";
    }
    if (args.flag("json")) {
        nlohmann::json j{
            {"rate_hz", def.rateHz},
            {"ticks", r.counters.ticks},
            {"missed", r.counters.missedDeadlines},
            {"jitter_us", {{"p50", r.jitter.p50Us}, {"p99", r.jitter.p99Us}, {"p999", r.jitter.p999Us}, {"max", r.jitter.maxUs}}},
            {"compute_us", {{"p50", r.compute.p50Us}, {"p99", r.compute.p99Us}, {"max", r.compute.maxUs}, {"mean", r.compute.meanUs}}},
            {"sched_fifo", r.counters.schedFifo},
            {"overruns", r.counters.overruns},
            {"achieved_rate_hz", r.counters.achievedRateHz},
            {"seconds", r.elapsedS},
            {"device", uri},
            {"mesh", meshPath},
            {"observer_hz", *observerHz},
            {"observer_snapshots", snapshotsSeen},
            {"observer_torn_snapshots", torn},
            {"observer_contact_snapshots", contactSnapshots},
        };
        std::cout << j.dump(2) << "\n";
    } else {
        std::cout << "haptic loop: " << r.counters.ticks << " ticks in " << r.elapsedS << " s at " << def.rateHz
                  << " Hz (achieved " << r.counters.achievedRateHz << " Hz), "
                  << (r.counters.schedFifo ? "SCHED_FIFO" : "normal scheduling (SCHED_FIFO not permitted)") << "\n"
                  << "  missed deadlines " << r.counters.missedDeadlines << ", overruns " << r.counters.overruns << "\n"
                  << "  jitter us: p50 " << r.jitter.p50Us << ", p99 " << r.jitter.p99Us << ", p99.9 " << r.jitter.p999Us
                  << ", max " << r.jitter.maxUs << "\n"
                  << "  compute us: p50 " << r.compute.p50Us << ", p99 " << r.compute.p99Us << ", max "
                  << r.compute.maxUs << "\n"
                  << "  observer at " << *observerHz << " Hz saw " << snapshotsSeen << " snapshots (" << torn
                  << " inconsistent, " << contactSnapshots << " in contact)\n";
    }
    return torn == 0 ? 0 : 1;
}

}  // namespace

void defineLoopCommand(CommandLine& cli) {
    CLI::App* loop = cli.command(cli.root(), "loop", "the real haptic thread and an observer; prints the loop's timing",
                                 loopCommand);
    addValue(*loop, "seconds", "S", "how long to run (default 5)")->check(numberIn(0, 86400, true));
    // The rate and the spin fraction are checked by validateHapticLoopDef (docs/haptic-loop.md).
    addValue(*loop, "rate", "HZ", "the haptic rate (default 1000)")->check(anyNumber());
    addValue(*loop, "observer-hz", "HZ", "the observer's rate (default 60)")->check(numberIn(0, 10000, true));
    addValue(*loop, "device", "URI", "the device (default sim:sine, docs/devices.md)");
    addValue(*loop, "mesh", "FILE", "the tissue mesh (default: the shipped one)");
    addMeshUnitOption(*loop);
    addValue(*loop, "spin-fraction", "F", "the part of a tick spent spinning (default 0.6)")->check(anyNumber());
    addFlag(*loop, "no-fifo", "do not try SCHED_FIFO");
    addFlag(*loop, "json", "print JSON");
    addValue(*loop, "csv", "FILE", "also write the tick times as CSV");
}

}  // namespace palpate::cli
