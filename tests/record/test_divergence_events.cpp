// The divergence guard's events in the recording (format 2), end to end. A loop with
// a recorder attached runs a parameter set beyond its stability bound (symplectic Euler, one step
// per tick, undamped, dt above 2 / omega_max: valid parameters, an unstable step): every tick the
// guard fires renders zero force and leaves the tissue at rest, the session keeps running, the
// tick allocates nothing, and the recording holds one Divergence event per firing with the kind and
// tick the loop published; the replay reproduces them, info --json and export-csv show them, and a
// version-1 file still reads.
#include "engine/scene/HapticScene.h"
#include "engine/models/ModelRegistry.h"
#include "engine/replay/RecordingPlayer.h"
#include "engine/record/RecordingReader.h"
#include "engine/record/RecordingSession.h"
#include "engine/stability/StabilityBounds.h"
#include "tests/record/RecordTestRig.h"
#include "tests/support/AllocationCounter.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <cstdio>
#include <sstream>
#include <utility>
#include <vector>

using namespace palpate;
using namespace palpate::test;

namespace {

struct DivergingRun {
    std::vector<std::pair<std::uint64_t, DivergenceKind>> fired;  // (tick, kind) as the loop published them
    std::uint64_t ticks = 0;
    std::uint64_t forceTicks = 0;  // ticks with a non-zero force (the session goes on rendering)
    std::uint64_t allocations = 0;
};

ModelDef divergingMassSpring() {
    ModelDef def = *modelDefForName("mass-spring-symplectic");
    def.massSpring.substeps = 1;         // no automatic sub-steps...
    def.massSpring.dampingRatio = 0.0;   // ...undamped...
    def.massSpring.edgeStiffnessNPerMm = 1.0;  // ...and stiff: 1 ms is beyond 2 / omega_max
    return def;
}

DivergingRun recordDiverging(const std::string& path, int ticks) {
    DivergingRun run;
    TissuePreset preset;
    const ModelDef def = divergingMassSpring();
    EXPECT_TRUE(messagesOf(validateModelDef(def)).empty()) << "valid parameters, unstable step";
    setPresetModel(preset, def);
    auto loaded = TissueMesh::load(sphereMeshPath());
    EXPECT_TRUE(loaded.mesh) << loaded.error();
    if (!loaded.mesh) return run;
    // The set is beyond the derived bound at the loop's period.
    const double omega = massSpringOmegaGershgorinRadPerS(*loaded.mesh, def.massSpring);
    EXPECT_GT(1e-3, symplecticEulerMaxStepS(omega));
    auto device = aimedDevice(*loaded.mesh, SimTrajectory::PressHold, float(presetToolRadiusMm(preset)));
    HapticLoopDef loopDef;
    loopDef.rateHz = preset.hapticRateHz;
    loopDef.trySchedFifo = false;
    const RecordingHeader header =
        makeRecordingHeader(*loaded.mesh, sphereMeshPath(), preset, "sim:press-hold", device->spec(), loopDef.safety);
    auto loop = std::make_unique<HapticLoop>(loopDef, HapticScene::create(std::move(*loaded.mesh), preset),
                                             std::move(device));
    std::string error;
    auto session = RecordingSession::start(*loop, path, header, error);
    EXPECT_TRUE(session) << error;
    if (!session) return run;
    loop->stepOnce();  // picks the recorder up
    std::uint64_t seen = loop->newestSnapshot().counters.divergences;
    EXPECT_EQ(seen, 0u);
    for (int i = 1; i < ticks; ++i) {
        const auto before = threadAllocationCount();
        loop->stepOnce();
        run.allocations += threadAllocationCount() - before;
        const HapticSnapshot& s = loop->newestSnapshot();
        if (glm::length(s.forceN) > 0.0f) ++run.forceTicks;
        if (s.counters.divergences != seen) {
            EXPECT_EQ(s.counters.divergences, seen + 1) << "one event per tick at most";
            seen = s.counters.divergences;
            EXPECT_EQ(s.counters.lastDivergenceTick, s.tick);
            run.fired.emplace_back(s.tick, s.counters.lastDivergence);
            // The guard's reaction within this tick: zero force, no contact, the tissue at rest.
            EXPECT_EQ(s.forceN, glm::vec3(0.0f));
            EXPECT_EQ(s.commandedForceN, glm::vec3(0.0f));
            EXPECT_FALSE(s.contact);
            EXPECT_EQ(s.displacedTotal, 0u);
            const auto positions = loop->scene().model().positionsMm();
            const auto& rest = loop->scene().mesh().restPositionsMm();
            std::size_t moved = 0;
            for (std::size_t v = 0; v < rest.size(); ++v) moved += positions[v] != rest[v];
            EXPECT_EQ(moved, 0u) << "tick " << s.tick;
        }
        if (i % 4000 == 0) {
            EXPECT_EQ(session->flush(), "");
        }
    }
    run.ticks = loop->newestSnapshot().tick;
    EXPECT_EQ(session->stop(), "");
    return run;
}

std::string textOf(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

TEST(DivergenceEvents, GuardReactionIsRecordedAndTheSessionKeepsRunning) {
    TempDir dir;
    const std::string path = dir.file("diverging.palprec");
    constexpr int kTicks = 3000;
    const DivergingRun run = recordDiverging(path, kTicks);
    ASSERT_FALSE(run.fired.empty()) << "the unstable step must be caught";
    std::printf("%zu divergences in %d ticks, the first at tick %llu (%s), %llu ticks with a force\n", run.fired.size(),
                kTicks, static_cast<unsigned long long>(run.fired.front().first),
                divergenceKindName(run.fired.front().second), static_cast<unsigned long long>(run.forceTicks));
    EXPECT_EQ(run.allocations, 0u) << "the tick with the guard firing and the recorder attached allocates";
    EXPECT_EQ(run.ticks, std::uint64_t(kTicks)) << "the session keeps running";
    EXPECT_GT(run.forceTicks, 0u) << "between events the press renders a force again";

    const RecordingReader reader = RecordingReader::open(path);
    ASSERT_TRUE(reader.headerOk()) << reader.headerError();
    EXPECT_EQ(reader.header().formatVersion, kRecordingFormatVersion);
    EXPECT_TRUE(reader.summary().intact);
    EXPECT_EQ(reader.summary().ticks, std::uint64_t(kTicks));
    std::vector<std::pair<std::uint64_t, DivergenceKind>> recorded;
    for (const RecordingEvent& e : reader.events())
        if (e.kind == EventKind::Divergence) {
            recorded.emplace_back(e.tick, e.divergence);
            EXPECT_NE(e.text.find(divergenceKindName(e.divergence)), std::string::npos) << e.text;
            EXPECT_NEAR(e.timeS, double(e.tick) * 1e-3, 1e-9);
        }
    EXPECT_EQ(recorded, run.fired);
    // The recorded ticks say the same: zero force where the guard fired.
    for (const auto& [tick, kind] : recorded) {
        const auto t = reader.tickAt(tick);
        ASSERT_TRUE(t);
        EXPECT_EQ(t->forceN, glm::vec3(0.0f)) << tick;
        EXPECT_FALSE(t->contact) << tick;
    }

    // The replay's guard fires at the same ticks with the same kinds (compared, not re-applied).
    std::string error;
    const ReplayStatus status = replayRecording(reader, error);
    ASSERT_EQ(error, "");
    EXPECT_TRUE(status.ok()) << status.firstMismatch << " / " << status.stopReason;
    EXPECT_EQ(status.divergencesRecorded, recorded.size());
    EXPECT_EQ(status.divergencesReplayed, recorded.size());
}

TEST(DivergenceEvents, InfoJsonAndExportCsvShowThem) {
    TempDir dir;
    const std::string path = dir.file("diverging cli.palprec");
    const DivergingRun run = recordDiverging(path, 1500);
    ASSERT_FALSE(run.fired.empty());
    const auto info = runCli("record info --json " + shellQuote(path));
    ASSERT_EQ(info.exitCode, 0) << info.output;
    const auto j = nlohmann::json::parse(info.output);
    EXPECT_EQ(j["format_version"].get<int>(), int(kRecordingFormatVersion));
    EXPECT_EQ(j["event_kinds"]["divergence"].get<std::size_t>(), run.fired.size());
    ASSERT_EQ(j["divergences"].size(), run.fired.size());
    for (std::size_t i = 0; i < run.fired.size(); ++i) {
        EXPECT_EQ(j["divergences"][i]["tick"].get<std::uint64_t>(), run.fired[i].first);
        EXPECT_EQ(j["divergences"][i]["kind"].get<std::string>(), divergenceKindName(run.fired[i].second));
    }
    const auto text = runCli("record info " + shellQuote(path));
    EXPECT_NE(text.output.find("divergence: "), std::string::npos) << text.output;

    const std::string csv = dir.file("diverging.csv");
    const auto exported = runCli("record export-csv " + shellQuote(path) + " --out " + shellQuote(csv));
    ASSERT_EQ(exported.exitCode, 0) << exported.output;
    std::istringstream lines(textOf(csv));
    std::string line;
    std::getline(lines, line);
    EXPECT_EQ(line.substr(line.size() - std::string(",contact,divergence").size()), ",contact,divergence");
    std::vector<std::pair<std::uint64_t, std::string>> marked;
    while (std::getline(lines, line)) {
        const std::string last = line.substr(line.rfind(',') + 1);
        if (!last.empty()) marked.emplace_back(std::stoull(line.substr(0, line.find(','))), last);
    }
    ASSERT_EQ(marked.size(), run.fired.size());
    for (std::size_t i = 0; i < marked.size(); ++i) {
        EXPECT_EQ(marked[i].first, run.fired[i].first);
        EXPECT_EQ(marked[i].second, divergenceKindName(run.fired[i].second));
    }
}

TEST(DivergenceEvents, VersionOneFilesStillReadAndReplay) {
    // Versions 1 and 2 share every layout (2 adds an event kind); the version byte is outside the
    // header CRC. A stable session written, then labelled version 1, reads and replays as before.
    TempDir dir;
    RecordRig rig = makeRecordRig(SimTrajectory::Stroke);
    const std::string path = dir.file("v1.palprec");
    std::string error;
    auto session = RecordingSession::start(*rig.loop, path, rig.header, error);
    ASSERT_TRUE(session) << error;
    for (int i = 0; i < 800; ++i) rig.loop->stepOnce();
    ASSERT_EQ(session->stop(), "");
    auto bytes = readBytes(path);
    ASSERT_GT(bytes.size(), 8u);
    EXPECT_EQ(bytes[7], kRecordingFormatVersion);
    bytes[7] = 1;
    writeBytes(path, bytes);
    const RecordingReader reader = RecordingReader::open(path);
    ASSERT_TRUE(reader.headerOk()) << reader.headerError();
    EXPECT_EQ(reader.header().formatVersion, 1);
    EXPECT_TRUE(reader.summary().intact);
    const ReplayStatus status = replayRecording(reader, error);
    EXPECT_TRUE(status.ok()) << status.firstMismatch << " / " << status.stopReason;

    bytes[7] = kRecordingFormatVersion + 1;  // a later format: refused, naming the field
    writeBytes(path, bytes);
    const RecordingReader later = RecordingReader::open(path);
    EXPECT_FALSE(later.headerOk());
    EXPECT_NE(later.headerError().find("header.formatVersion"), std::string::npos) << later.headerError();
}
