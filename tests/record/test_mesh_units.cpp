// A mesh's unit in recordings (format 4) and on palpate-cli (--mesh-unit): a session on a mesh
// written in cm records the unit, replays on the same-sized mesh (its hashes match), and an older
// recording, which has no unit, reads as mm (docs/recording.md, docs/meshes.md "Units").
#include "engine/core/MeshHash.h"
#include "engine/record/Crc32.h"
#include "engine/record/RecordingReader.h"
#include "engine/record/RecordingSession.h"
#include "engine/replay/RecordingPlayer.h"
#include "tests/record/RecordTestRig.h"
#include "tests/record/UnitMeshFiles.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>

using namespace palpate;
using namespace palpate::test;

namespace {

std::string resource(const std::string& relative) { return std::string(PALPATE_SOURCE_DIR) + "/resources/" + relative; }

MeshUnit unitNamed(const std::string& text) {
    std::string problem;
    const auto unit = parseMeshUnit(text, problem);
    if (!unit) throw std::runtime_error(problem);
    return *unit;
}

TissueMesh loadIn(const std::string& path, const MeshUnit& unit) {
    auto loaded = TissueMesh::load(path, unit);
    if (!loaded.mesh) throw std::runtime_error(loaded.error());
    return std::move(*loaded.mesh);
}

std::string decodeError(const std::vector<std::uint8_t>& bytes, RecordingHeader* out = nullptr) {
    RecordingHeader h;
    std::size_t used = 0;
    std::string error;
    const bool ok = (error = decodeRecordingHeader(bytes.data(), bytes.size(), h, used)).empty();
    if (ok && out) *out = h;
    return ok ? std::string() : error;
}

}  // namespace

TEST(RecordMeshUnit, TheHeaderCarriesTheUnit) {
    for (const MeshUnit& unit : {unitNamed("cm"), unitNamed("m"), unitNamed("in"), unitNamed("2.5"), kMillimetres}) {
        RecordingHeader h;
        h.scene.meshPath = "tissue.off";
        h.scene.meshUnit = unit;
        std::vector<std::uint8_t> bytes;
        encodeRecordingHeader(h, bytes);
        RecordingHeader back;
        ASSERT_EQ(decodeError(bytes, &back), "") << unit.text();
        EXPECT_EQ(back.scene.meshUnit.name, unit.name);
        EXPECT_EQ(back.scene.meshUnit.mmPerUnit, unit.mmPerUnit);
        EXPECT_EQ(back.formatVersion, kRecordingFormatVersion);
    }
}

TEST(RecordMeshUnit, AUnitThatIsNoneIsRefusedNamingTheField) {
    struct Case {
        MeshUnit unit;
        const char* field;
    };
    const Case cases[] = {{{"", 0.0}, "header.scene.meshUnit.mmPerUnit"},
                          {{"", -10.0}, "header.scene.meshUnit.mmPerUnit"},
                          {{"", std::nan("")}, "header.scene.meshUnit.mmPerUnit"},
                          {{"", 1e9}, "header.scene.meshUnit.mmPerUnit"},
                          {{"cm", 25.4}, "header.scene.meshUnit.name"},  // a name that is not its factor
                          {{"furlong", 201168.0}, "header.scene.meshUnit.name"}};
    for (const Case& c : cases) {
        RecordingHeader h;
        h.scene.meshUnit = c.unit;
        std::vector<std::uint8_t> bytes;
        encodeRecordingHeader(h, bytes);
        const std::string error = decodeError(bytes);
        EXPECT_EQ(error.rfind(c.field, 0), 0u) << c.unit.name << " " << c.unit.mmPerUnit << ": " << error;
    }
}

TEST(RecordMeshUnit, ASessionOnAMeshInCmReplaysOnTheSameSizedMesh) {
    TempDir dir;
    const UnitMeshFiles sphere =
        writeUnitMeshFiles(resource("meshes/sphere_1442.off"), 10.0, "cm", dir.path().string(), "sphere");
    const UnitMeshFiles stomach =
        writeUnitMeshFiles(resource("meshes/stomach_1442.off"), 1000.0, "m", dir.path().string(), "stomach");
    const MeshUnit cm = unitNamed("cm"), m = unitNamed("m");
    const TissueMesh sphereMm = loadIn(sphere.mmPath, kMillimetres);
    const TissueMesh stomachMm = loadIn(stomach.mmPath, kMillimetres);

    // A stepped session on the cm file read in cm, switching to the stomach written in metres.
    TissueMesh mesh = loadIn(sphere.unitPath, cm);
    ASSERT_EQ(meshHash(mesh), meshHash(sphereMm));  // the same mesh, to the bit
    const TissuePreset preset;
    auto device = aimedDevice(mesh, SimTrajectory::Stroke);
    HapticLoopDef def;
    def.rateHz = preset.hapticRateHz;
    def.trySchedFifo = false;
    const RecordingHeader header = makeRecordingHeader(mesh, sphere.unitPath, preset, "sim:stroke", device->spec(), def.safety);
    EXPECT_EQ(header.scene.meshUnit.name, "cm");
    HapticLoop loop(def, HapticScene::create(std::move(mesh), preset), std::move(device));
    const std::string path = dir.file("cm.palprec");
    std::string error;
    auto session = RecordingSession::start(loop, path, header, error);
    ASSERT_TRUE(session) << error;
    for (int i = 1; i <= 1600; ++i) {
        loop.stepOnce();
        if (i == 800) {
            TissueMesh next = loadIn(stomach.unitPath, m);
            const RecordedScene description = describeScene(next, stomach.unitPath, preset);
            ASSERT_EQ(session->swapScene(HapticScene::create(std::move(next), preset), description), "");
        }
        if (i % 400 == 0) {
            ASSERT_EQ(session->flush(), "");
        }
    }
    ASSERT_EQ(session->stop(), "");
    loop.collectRetired();

    const RecordingReader reader = RecordingReader::open(path);
    ASSERT_TRUE(reader.headerOk()) << reader.headerError();
    EXPECT_EQ(reader.header().scene.meshUnit.name, "cm");
    EXPECT_EQ(reader.header().scene.meshUnit.mmPerUnit, 10.0);
    EXPECT_EQ(reader.header().scene.meshHash, meshHash(sphereMm));
    int scenes = 0;
    for (const RecordingEvent& e : reader.events())
        if (e.kind == EventKind::SceneChanged) {
            ++scenes;
            ASSERT_TRUE(e.scene);
            EXPECT_EQ(e.scene->meshUnit.name, "m");
            EXPECT_EQ(e.scene->meshHash, meshHash(stomachMm));
            EXPECT_NE(e.text.find("in m"), std::string::npos) << e.text;
        }
    EXPECT_EQ(scenes, 1);

    // The replay loads both meshes in their recorded units: every force and chunk hash matches.
    const ReplayStatus status = replayRecording(reader, error);
    EXPECT_EQ(error, "");
    EXPECT_TRUE(status.ok()) << status.firstMismatch << " / " << status.stopReason;
    EXPECT_GT(status.hashChecks, 10u);
    EXPECT_EQ(status.hashMismatches, 0u);
    EXPECT_EQ(status.ticksReplayed, 1600u);

    // The same file read in mm is another (ten times smaller) mesh: refused, naming the unit.
    ReplayDef inMm;
    inMm.meshUnit = kMillimetres;
    const ReplayStatus refused = replayRecording(reader, error, inMm);
    EXPECT_FALSE(refused.ok());
    EXPECT_NE(error.find("is not the recorded mesh"), std::string::npos) << error;
    // The mm file, named instead, is the recorded mesh when read in mm.
    ReplayDef mmFile;
    mmFile.meshPath = sphere.mmPath;
    mmFile.meshUnit = kMillimetres;
    error.clear();
    EXPECT_TRUE(replayRecording(reader, error, mmFile).ok()) << error;
}

TEST(RecordMeshUnit, OlderFormatsReadAsMm) {
    // A format-3 file: what this build writes, without the unit the header appends, labelled 3.
    TempDir dir;
    RecordRig rig = makeRecordRig(SimTrajectory::Stroke);
    const std::string path = dir.file("v3.palprec");
    std::string error;
    auto session = RecordingSession::start(*rig.loop, path, rig.header, error);
    ASSERT_TRUE(session) << error;
    for (int i = 0; i < 600; ++i) rig.loop->stepOnce();
    ASSERT_EQ(session->stop(), "");
    std::vector<std::uint8_t> bytes = readBytes(path);
    std::uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 8, 4);  // little-endian, as written
    // The unit is the body's last bytes but format 5's stiffening knots: f64 1.0, then the name
    // "mm" (a varint length and 2 bytes). Both are cut.
    std::vector<std::uint8_t> unit;
    ByteWriter w(unit);
    encodeMeshUnit(w, kMillimetres);
    encodeStiffening(w, rig.header.scene.params);
    ASSERT_GE(length, unit.size());
    const std::size_t unitAt = kPreambleBytes + length - unit.size();
    ASSERT_EQ(std::memcmp(bytes.data() + unitAt, unit.data(), unit.size()), 0);
    bytes.erase(bytes.begin() + std::ptrdiff_t(unitAt), bytes.begin() + std::ptrdiff_t(unitAt + unit.size()));
    length -= std::uint32_t(unit.size());
    std::memcpy(bytes.data() + 8, &length, 4);
    const std::uint32_t crc = crc32(bytes.data() + kPreambleBytes, length);
    std::memcpy(bytes.data() + kPreambleBytes + length, &crc, 4);
    bytes[7] = 3;
    const std::string old = dir.file("v3-old.palprec");
    writeBytes(old, bytes);
    const RecordingReader reader = RecordingReader::open(old);
    ASSERT_TRUE(reader.headerOk()) << reader.headerError();
    EXPECT_EQ(reader.header().formatVersion, 3);
    EXPECT_TRUE(reader.header().scene.meshUnit.isMillimetres());
    EXPECT_EQ(reader.header().scene.meshUnit.name, "mm");
    EXPECT_TRUE(reader.summary().intact);
    const ReplayStatus status = replayRecording(reader, error);
    EXPECT_TRUE(status.ok()) << error << status.firstMismatch << " / " << status.stopReason;

    // The corpus' format-1 files too.
    const RecordingReader v1 = RecordingReader::open(std::string(PALPATE_RECORD_CORPUS_DIR) + "/press.palprec");
    ASSERT_TRUE(v1.headerOk()) << v1.headerError();
    EXPECT_EQ(v1.header().formatVersion, 1);
    EXPECT_TRUE(v1.header().scene.meshUnit.isMillimetres());
}

namespace {

/// stderr alone of a palpate-cli run (runShell merges the streams).
CommandResult cliStderr(const std::string& args) {
    return runCommand("{ " + shellQuote(PALPATE_CLI_PATH) + " " + args + " 2>&1 >/dev/null; }");
}

std::size_t countOf(const std::string& text, const std::string& word) {
    std::size_t n = 0;
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
    return n;
}

/// The sphere in cm and in mm, written once per process.
const UnitMeshFiles& cliMeshes() {
    static TempDir dir;
    static const UnitMeshFiles files =
        writeUnitMeshFiles(resource("meshes/sphere_1442.off"), 10.0, "cm", dir.path().string(), "cli sphere");
    return files;
}

}  // namespace

TEST(MeshUnitCli, EveryCommandThatReadsAMeshTakesTheOptionAndNamesItWhenBad) {
    const std::string mesh = shellQuote(cliMeshes().unitPath);
    TempDir dir;
    const std::string commands[] = {
        "demo --mesh " + mesh,
        "loop --seconds 0.2 --no-fifo --mesh " + mesh,
        "run --seconds 0.2 --no-fifo --mesh " + mesh,
        "calibrate --mesh " + mesh,
        "lod levels --no-cache --mesh " + mesh,
        "lod plan --no-cache --error 0.1 --budget-us 100 --mesh " + mesh,
        "record replay " + shellQuote(std::string(PALPATE_RECORD_CORPUS_DIR) + "/press.palprec") + " --mesh " + mesh,
        "score --recording " + shellQuote(std::string(PALPATE_RECORD_CORPUS_DIR) + "/press.palprec") + " --mesh " + mesh,
    };
    for (const std::string& command : commands)
        for (const char* bad : {"furlong", "0", "-1", "1e9"}) {
            const auto r = runCli(command + " --mesh-unit " + bad);
            EXPECT_EQ(r.exitCode, 2) << command << " --mesh-unit " << bad << ":\n" << r.output;
            EXPECT_NE(r.output.find(std::string("--mesh-unit: '") + bad + "' is not a mesh unit"), std::string::npos)
                << command << " --mesh-unit " << bad << ":\n" << r.output;
        }
}

TEST(MeshUnitCli, AnImplausibleSizeInMmWarnsOnceWithTheOptionToUse) {
    const std::string cmMesh = shellQuote(cliMeshes().unitPath);
    const std::string mmMesh = shellQuote(cliMeshes().mmPath);
    for (const std::string& command : {std::string("demo"), std::string("loop --seconds 0.2 --no-fifo")}) {
        const auto read = cliStderr(command + " --mesh " + cmMesh);
        EXPECT_EQ(read.exitCode, 0) << read.output;
        EXPECT_EQ(countOf(read.output, "warning"), 1u) << read.output;
        EXPECT_EQ(countOf(read.output, "\n"), 1u) << read.output;  // one line
        EXPECT_NE(read.output.find("(give --mesh-unit cm)"), std::string::npos) << read.output;
        EXPECT_NE(read.output.find("centimetres"), std::string::npos) << read.output;  // the reason
        for (const std::string& quiet : {command + " --mesh " + cmMesh + " --mesh-unit cm", command + " --mesh " + mmMesh}) {
            const auto r = cliStderr(quiet);
            EXPECT_EQ(r.exitCode, 0) << quiet << ":\n" << r.output;
            EXPECT_EQ(r.output.find("warning"), std::string::npos) << quiet << ":\n" << r.output;
        }
    }
}

TEST(MeshUnitCliThreads, RunRecordsTheUnitAndInfoAndReplaySayIt) {
    TempDir dir;
    const std::string recording = dir.file("cm run.palprec");
    const auto run = runCli("run --mesh " + shellQuote(cliMeshes().unitPath) +
                            " --mesh-unit cm --device sim:stroke --seconds 0.5 --no-fifo --record " + shellQuote(recording));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(run.output.find("warning"), std::string::npos) << run.output;
    const auto info = runCli("record info " + shellQuote(recording));
    ASSERT_EQ(info.exitCode, 0) << info.output;
    EXPECT_NE(info.output.find("cli sphere.cm.off in cm ("), std::string::npos) << info.output;
    const auto json = runCli("record info --json " + shellQuote(recording));
    ASSERT_EQ(json.exitCode, 0) << json.output;
    const auto j = nlohmann::json::parse(json.output);
    EXPECT_EQ(j.value("mesh_unit", ""), "cm");
    const TissueMesh mm = loadIn(cliMeshes().mmPath, kMillimetres);
    char hash[32];
    std::snprintf(hash, sizeof hash, "%llx", static_cast<unsigned long long>(meshHash(mm)));
    EXPECT_EQ(j.value("mesh_hash", ""), hash);  // the same-sized mesh
    const auto replay = runCli("record replay " + shellQuote(recording));
    EXPECT_EQ(replay.exitCode, 0) << replay.output;
    const auto asMm = runCli("record replay " + shellQuote(recording) + " --mesh " + shellQuote(cliMeshes().unitPath) +
                             " --mesh-unit mm");
    EXPECT_EQ(asMm.exitCode, 1) << asMm.output;
    EXPECT_NE(asMm.output.find("is not the recorded mesh"), std::string::npos) << asMm.output;
    const auto mmFile = runCli("record replay " + shellQuote(recording) + " --mesh " + shellQuote(cliMeshes().mmPath) +
                               " --mesh-unit mm");
    EXPECT_EQ(mmFile.exitCode, 0) << mmFile.output;
    // An mm recording says no unit.
    const auto plain = runCli("record info --json " + shellQuote(std::string(PALPATE_RECORD_CORPUS_DIR) + "/press.palprec"));
    EXPECT_FALSE(nlohmann::json::parse(plain.output).contains("mesh_unit"));
}
