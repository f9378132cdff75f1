// palpate-cli record info|verify|export-csv|replay FILE: what is in a session recording, whether it
// is intact (and what a damaged one still holds), its ticks as CSV, and a bit-exact replay check.
#include "app/cli/Commands.h"
#include "app/cli/MeshOption.h"
#include "engine/replay/RecordingPlayer.h"
#include "engine/record/RecordingReader.h"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

namespace palpate::cli {

namespace {

std::string hex(std::uint64_t v) {
    char text[20];
    std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(v));
    return text;
}

std::string isoTime(std::int64_t unixUs) {
    const std::time_t t = std::time_t(unixUs / 1000000);
    std::tm tm{};
    if (!gmtime_r(&t, &tm)) return "?";
    char text[32];
    std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &tm);
    return text;
}

nlohmann::json summaryJson(const RecordingReader& reader) {
    const RecordingSummary& s = reader.summary();
    std::map<std::string, std::uint64_t> kinds;
    nlohmann::json divergences = nlohmann::json::array();  // the guard's events (format 2)
    for (const auto& e : reader.events()) {
        ++kinds[eventKindName(e.kind)];
        if (e.kind == EventKind::Divergence)
            divergences.push_back({{"tick", e.tick}, {"time_s", e.timeS}, {"kind", divergenceKindName(e.divergence)}});
    }
    nlohmann::json damage = nlohmann::json::array();
    for (const auto& d : reader.damage())
        damage.push_back({{"offset", d.offset}, {"bytes", d.bytes}, {"reason", d.reason}});
    nlohmann::json j{{"file", reader.name()},
                     {"ticks", s.ticks},
                     {"duration_s", s.durationS},
                     {"chunks", s.chunks},
                     {"bytes", s.fileBytes},
                     {"events", s.events},
                     {"intact", s.intact},
                     {"bytes_per_tick", s.bytesPerTick()},
                     {"first_tick", s.firstTick},
                     {"last_tick", s.lastTick},
                     {"gaps", s.gaps},
                     {"dropped_ticks", s.droppedTicks},
                     {"lost_ticks", s.lostTicks},
                     {"damaged_regions", s.damagedRegions},
                     {"damaged_bytes", s.damagedBytes},
                     {"hash_mismatches", s.hashMismatches},
                     {"closed_cleanly", s.closedCleanly},
                     {"header_ok", s.headerOk},
                     {"event_kinds", kinds},
                     {"divergences", divergences},
                     {"damage", damage}};
    if (s.headerOk) {
        const RecordingHeader& h = reader.header();
        j["engine_version"] = h.engineVersion;
        j["format_version"] = h.formatVersion;
        j["start_utc"] = isoTime(h.startUnixUs);
        j["rate_hz"] = h.rateHz;
        j["mesh"] = h.scene.meshPath;
        if (!h.scene.meshUnit.isMillimetres()) j["mesh_unit"] = h.scene.meshUnit.text();
        j["mesh_hash"] = hex(h.scene.meshHash);
        j["method"] = std::string(methodName(h.scene.method));
        j["device"] = h.device.uri;
        j["note"] = h.note;
    } else {
        j["header_error"] = reader.headerError();
    }
    return j;
}

void printDamage(const RecordingReader& reader, std::ostream& out) {
    for (const auto& d : reader.damage())
        out << "  damaged: offset " << d.offset << ", " << d.bytes << " bytes: " << d.reason << "\n";
}

int info(const RecordingReader& reader, bool json) {
    const RecordingSummary& s = reader.summary();
    if (json) {
        std::cout << summaryJson(reader).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
        return 0;
    }
    std::cout << reader.name() << "\n";
    if (s.headerOk) {
        const RecordingHeader& h = reader.header();
        std::cout << "  recorded " << isoTime(h.startUnixUs) << " by Palpate " << h.engineVersion << "\n"
                  << "  mesh " << h.scene.meshPath
                  << (h.scene.meshUnit.isMillimetres() ? std::string() : " in " + h.scene.meshUnit.description())
                  << " (" << h.scene.vertexCount << " vertices, hash "
                  << hex(h.scene.meshHash) << "), model " << methodName(h.scene.method) << "\n"
                  << "  device " << h.device.uri << " (" << h.device.spec.name << ", max " << h.device.spec.maxForceN
                  << " N), " << h.rateHz << " Hz\n";
        if (!h.note.empty()) std::cout << "  note: " << h.note << "\n";
    } else {
        std::cout << "  header damaged: " << reader.headerError() << "\n";
    }
    std::cout << "  " << s.ticks << " ticks (" << s.firstTick << ".." << s.lastTick << "), " << s.durationS << " s, "
              << s.chunks << " chunks, " << s.fileBytes << " bytes (" << s.bytesPerTick() << " bytes/tick), "
              << s.events << " events\n";
    if (s.gaps > 0) std::cout << "  " << s.gaps << " gaps: " << s.droppedTicks << " ticks dropped while recording\n";
    std::cout << "  " << (s.intact ? "intact" : "NOT intact") << (s.closedCleanly ? "" : ", not closed cleanly")
              << "\n";
    printDamage(reader, std::cout);
    for (const auto& e : reader.events())
        if (e.kind == EventKind::Mark || e.kind == EventKind::Exercise || e.kind == EventKind::ParamsApplied ||
            e.kind == EventKind::SceneChanged || e.kind == EventKind::DeviceChanged || e.kind == EventKind::Divergence)
            std::cout << "  t=" << e.timeS << " s (tick " << e.tick << ") " << eventKindName(e.kind) << ": " << e.text
                      << "\n";
    return 0;
}

int verify(const RecordingReader& reader, bool json) {
    const RecordingSummary& s = reader.summary();
    if (json) {
        std::cout << summaryJson(reader).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
        return s.intact ? 0 : 1;
    }
    if (s.intact) {
        std::cout << reader.name() << ": intact: " << s.chunks << " chunks, " << s.ticks << " ticks, " << s.events
                  << " events, every CRC and chunk hash checked\n";
        if (s.gaps > 0)
            std::cout << "  note: " << s.droppedTicks << " ticks were dropped while recording (" << s.gaps
                      << " gaps; the file says so)\n";
        return 0;
    }
    std::cout << reader.name() << ": DAMAGED\n";
    if (!s.headerOk) std::cout << "  header: " << reader.headerError() << "\n";
    std::cout << "  recovered " << s.chunks << " intact chunks (" << s.ticks << " ticks, " << s.durationS << " s, "
              << s.events << " events)\n"
              << "  lost: " << s.damagedRegions << " damaged regions (" << s.damagedBytes << " bytes), " << s.lostTicks
              << " ticks\n";
    if (s.hashMismatches > 0) std::cout << "  " << s.hashMismatches << " chunks disagree with their determinism hash\n";
    if (!s.closedCleanly) std::cout << "  no end chunk: the recording did not close (crash or kill?)\n";
    printDamage(reader, std::cout);
    return 1;
}

int exportCsv(const RecordingReader& reader, const std::optional<std::string>& outPath) {
    // Written beside the target and renamed at the end: a failed export leaves no half file, and
    // what was at --out stays until the new CSV is whole.
    const std::string tempPath = outPath ? *outPath + ".partial-" + std::to_string(::getpid()) : std::string();
    std::ofstream file;
    if (outPath) {
        file.open(tempPath, std::ios::binary | std::ios::trunc);
        if (!file) {
            std::cerr << "record export-csv: " << *outPath << ": cannot write: " << std::strerror(errno) << "\n";
            return 1;
        }
    }
    std::ostream& out = outPath ? static_cast<std::ostream&>(file) : std::cout;
    out << "tick,time_s,read_ok,sequence,sample_time_s,x_mm,y_mm,z_mm,buttons,device_state,paused,overran,"
           "force_x_n,force_y_n,force_z_n,touched,contact,divergence\n";
    char line[512];
    // The divergence column: the guard's event at that tick (events are in tick order), else empty.
    const auto& events = reader.events();
    std::size_t nextEvent = 0;
    reader.forEachTick([&](const RecordedTick& t) {
        while (nextEvent < events.size() && events[nextEvent].tick < t.tick) ++nextEvent;
        const char* divergence = "";
        for (std::size_t i = nextEvent; i < events.size() && events[i].tick == t.tick; ++i)
            if (events[i].kind == EventKind::Divergence) divergence = divergenceKindName(events[i].divergence);
        // %.17g and %.9g print doubles and floats exactly (they read back to the same bits).
        std::snprintf(line, sizeof(line), "%llu,%.17g,%d,%llu,%.17g,%.9g,%.9g,%.9g,%u,%s,%d,%d,%.9g,%.9g,%.9g,%lld,%d,%s\n",
                      static_cast<unsigned long long>(t.tick), t.nowS, t.readOk ? 1 : 0,
                      static_cast<unsigned long long>(t.sample.sequence), t.sample.timeS, double(t.sample.positionMm.x),
                      double(t.sample.positionMm.y), double(t.sample.positionMm.z), t.sample.buttons,
                      deviceStateName(t.deviceState), t.paused ? 1 : 0, t.tickOverran ? 1 : 0, double(t.forceN.x),
                      double(t.forceN.y), double(t.forceN.z),
                      t.touched == kNoVertex ? -1LL : static_cast<long long>(t.touched), t.contact ? 1 : 0, divergence);
        out << line;
        return bool(out);
    });
    out.flush();
    if (outPath) file.close();
    if (!out || (outPath && !file)) {
        const int why = errno;
        std::cerr << "record export-csv: " << (outPath ? *outPath : std::string("standard output"))
                  << ": writing failed: " << std::strerror(why) << "\n";
        if (outPath) std::remove(tempPath.c_str());
        return 1;
    }
    if (outPath && std::rename(tempPath.c_str(), outPath->c_str()) != 0) {
        std::cerr << "record export-csv: " << *outPath << ": cannot write: " << std::strerror(errno) << "\n";
        std::remove(tempPath.c_str());
        return 1;
    }
    if (!reader.summary().intact)
        std::cerr << "record export-csv: " << reader.name() << " is damaged; exported the " << reader.summary().ticks
                  << " recovered ticks\n";
    return 0;
}

int replay(const RecordingReader& reader, const std::optional<std::string>& meshPath,
           const std::optional<MeshUnit>& meshUnit, bool json) {
    ReplayDef options;
    if (meshPath) options.meshPath = *meshPath;
    options.meshUnit = meshUnit;
    std::string error;
    const ReplayStatus s = replayRecording(reader, error, options);
    const bool match = error.empty() && !s.mismatch && s.hashMismatches == 0 && s.ticksReplayed > 0;
    if (json) {
        nlohmann::json j{{"file", reader.name()},
                         {"ticks_replayed", s.ticksReplayed},
                         {"forces_match", error.empty() && !s.mismatch},
                         {"hash_checks", s.hashChecks},
                         {"hash_mismatches", s.hashMismatches},
                         {"hash_match", s.hashMismatches == 0 && s.hashChecks > 0},
                         {"complete", s.complete},
                         {"final_hash", hex(s.finalHash)},
                         {"match", match}};
        if (s.mismatch) {
            j["first_mismatch_tick"] = s.firstMismatchTick;
            j["first_mismatch"] = s.firstMismatch;
        }
        if (!s.stopReason.empty()) j["stop_reason"] = s.stopReason;
        if (!error.empty()) j["error"] = error;
        std::cout << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
        return match ? 0 : 1;
    }
    if (!error.empty()) {
        std::cerr << "record replay: " << error << "\n";
        return 1;
    }
    std::cout << reader.name() << ": replayed " << s.ticksReplayed << " ticks in stepped mode\n";
    if (s.mismatch) {
        std::cout << "  MISMATCH: first at tick " << s.firstMismatchTick << " (" << s.mismatches
                  << " ticks differ)\n  " << s.firstMismatch << "\n";
    } else {
        std::cout << "  forces, touched vertices and contact match the recording bit for bit\n";
    }
    std::cout << "  determinism hash: " << (s.hashMismatches == 0 ? "match" : "MISMATCH") << " ("
              << s.hashChecks - s.hashMismatches << "/" << s.hashChecks << " chunks), final " << hex(s.finalHash)
              << "\n";
    if (!s.complete) std::cout << "  stopped before the end: " << s.stopReason << "\n";
    return match ? 0 : 1;
}

int recordCommand(const std::string& action, const Given& args) {
    const auto pos = args.positional();
    if (pos.size() != 1) {
        std::cerr << "record " << action << ": needs one FILE, the recording\n";
        return 2;
    }
    const std::string& file = pos[0];
    if (const auto out = args.option("out")) {
        if (const std::string problem = outputIsAnInput("out", *out, {{file, "recording"}}); !problem.empty()) {
            std::cerr << "record export-csv: " << problem << "\n";
            return 2;
        }
    }
    // --mesh-unit: the unit of the --mesh file, when it is not the recorded one's.
    std::optional<MeshUnit> meshUnit;
    if (args.option(kMeshUnitOption)) {
        if (!args.option("mesh")) {
            std::cerr << "record replay: --mesh-unit is for replay with --mesh (the recording says its mesh's unit)\n";
            return 2;
        }
        std::string unitError;
        meshUnit = meshUnitFromArgs(args, unitError);
        if (!meshUnit) {
            std::cerr << "record replay: " << unitError << "\n";
            return 2;
        }
    }
    const RecordingReader reader = RecordingReader::open(file);
    if (!reader.fileError().empty()) {
        std::cerr << "record " << action << ": " << reader.fileError() << "\n";
        return 1;
    }
    // Nothing recovered and no header: not a recording at all (verify says so in its own report).
    if (action != "verify" && !reader.headerOk() && reader.summary().chunks == 0) {
        const bool noMagic = reader.headerError().rfind("header.magic", 0) == 0;
        std::cerr << "record " << action << ": " << reader.name() << ": not a Palpate recording ("
                  << (noMagic ? "it does not start with \"PALPREC\"" : reader.headerError())
                  << ", and no intact chunk)\n";
        return 1;
    }
    if (action == "info") return info(reader, args.flag("json"));
    if (action == "verify") return verify(reader, args.flag("json"));
    if (action == "export-csv") return exportCsv(reader, args.option("out"));
    return replay(reader, args.option("mesh"), meshUnit, args.flag("json"));
}

}  // namespace

void defineRecordCommands(CommandLine& cli) {
    CLI::App* record = cli.group(cli.root(), "record", "read, check, export and replay recordings (docs/recording.md)");
    const auto action = [&cli, record](const std::string& name, const std::string& description) {
        CLI::App* command = cli.command(*record, name, description,
                                        [name](const Given& args) { return recordCommand(name, args); });
        addPositional(*command, "FILE", "the recording");
        return command;
    };
    addFlag(*action("info", "what a recording holds"), "json", "print JSON");
    addFlag(*action("verify", "check every chunk and the determinism hash"), "json", "print JSON");
    addValue(*action("export-csv", "the ticks as CSV"), "out", "CSV", "the CSV file (default: standard output)");
    CLI::App* replay = action("replay", "replay the recording on its scene and compare");
    addValue(*replay, "mesh", "FILE", "replay on this mesh instead of the recorded one");
    addMeshUnitOption(*replay);
    addFlag(*replay, "json", "print JSON");
}

}  // namespace palpate::cli
