// palpate-cli run --record and record info|verify|export-csv|replay, as a user runs them.
#include "engine/record/RecordingFormat.h"
#include "tests/record/RecordTestRig.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <random>
#include <sstream>

using namespace palpate;
using namespace palpate::test;

namespace {

std::size_t lineCount(const std::string& text) { return std::size_t(std::count(text.begin(), text.end(), '\n')); }

/// One real-time CLI recording per process (1 s of sim:stroke on the sphere), shared by the tests.
const std::string& cliRecording() {
    static TempDir dir;
    static const std::string path = [] {
        const std::string p = dir.file("cli run.palprec");  // a space on purpose
        const auto r = runCli("run --mesh " + shellQuote(sphereMeshPath()) +
                              " --device sim:stroke --seconds 1 --no-fifo --note 'cli test' --record " + shellQuote(p));
        if (r.exitCode != 0) throw std::runtime_error(r.output);
        return p;
    }();
    return path;
}

}  // namespace

TEST(RecordCliThreads, RunRecordsAndInfoDescribesIt) {
    const std::string& path = cliRecording();
    const auto info = runCli("record info --json " + shellQuote(path));
    ASSERT_EQ(info.exitCode, 0) << info.output;
    const auto j = nlohmann::json::parse(info.output);
    for (const char* key : {"ticks", "duration_s", "chunks", "bytes", "events", "intact"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_TRUE(j["intact"].get<bool>());
    // Loop time: about a second; a loaded machine skips deadlines (fewer ticks) and starts late, so
    // only what no load can change is checked tightly (duration covers the ticks, below).
    EXPECT_GT(j["ticks"].get<std::uint64_t>(), 100u);
    EXPECT_GT(j["duration_s"].get<double>(), 0.5);
    EXPECT_LT(j["duration_s"].get<double>(), 2.0);
    // Ticks are stamped with the loop clock when they run: the first may wake up to a period late
    // (a later one that late skips its deadline), so the span covers all but about one period.
    EXPECT_GE(j["duration_s"].get<double>(), double(j["ticks"].get<std::uint64_t>() - 2) * 0.001);
    EXPECT_EQ(j["bytes"].get<std::uint64_t>(), readBytes(path).size());
    EXPECT_LE(j["bytes_per_tick"].get<double>(), 40.0);
    EXPECT_EQ(j["note"].get<std::string>(), "cli test");
    EXPECT_EQ(j["device"].get<std::string>(), "sim:stroke");
    const auto text = runCli("record info " + shellQuote(path));
    EXPECT_EQ(text.exitCode, 0);
    EXPECT_NE(text.output.find("intact"), std::string::npos) << text.output;
}

TEST(RecordCliThreads, VerifyExportAndReplay) {
    const std::string& path = cliRecording();
    const auto verify = runCli("record verify " + shellQuote(path));
    EXPECT_EQ(verify.exitCode, 0) << verify.output;
    EXPECT_NE(verify.output.find("intact"), std::string::npos);

    TempDir dir;
    const auto exported = runCli("record export-csv " + shellQuote(path) + " --out " + shellQuote(dir.file("t.csv")));
    ASSERT_EQ(exported.exitCode, 0) << exported.output;
    std::ifstream csv(dir.file("t.csv"));
    std::stringstream content;
    content << csv.rdbuf();
    const auto info = nlohmann::json::parse(runCli("record info --json " + shellQuote(path)).output);
    EXPECT_EQ(lineCount(content.str()), info["ticks"].get<std::uint64_t>() + 1);
    EXPECT_EQ(content.str().rfind("tick,time_s,", 0), 0u);
    const auto toStdout = runCli("record export-csv " + shellQuote(path));
    EXPECT_EQ(toStdout.exitCode, 0);
    EXPECT_EQ(toStdout.output, content.str());

    const auto replay = runCli("record replay " + shellQuote(path));
    EXPECT_EQ(replay.exitCode, 0) << replay.output;
    EXPECT_NE(replay.output.find("bit for bit"), std::string::npos) << replay.output;
    const auto replayJson = nlohmann::json::parse(runCli("record replay --json " + shellQuote(path)).output);
    EXPECT_TRUE(replayJson["match"].get<bool>());
    EXPECT_TRUE(replayJson["hash_match"].get<bool>());
    EXPECT_EQ(replayJson["ticks_replayed"].get<std::uint64_t>(), info["ticks"].get<std::uint64_t>());
}

TEST(RecordCliThreads, DamagedForgedAndGarbageFiles) {
    const std::string& path = cliRecording();
    TempDir dir;
    auto bytes = readBytes(path);
    // Damaged: a byte flipped in the middle, and the end cut off.
    auto damaged = bytes;
    damaged[damaged.size() / 2] ^= 0x20;
    damaged.resize(damaged.size() - 30);
    writeBytes(dir.file("damaged.palprec"), damaged);
    const auto verify = runCli("record verify " + shellQuote(dir.file("damaged.palprec")));
    EXPECT_EQ(verify.exitCode, 1) << verify.output;
    EXPECT_NE(verify.output.find("recovered"), std::string::npos) << verify.output;
    EXPECT_NE(verify.output.find("damaged: offset"), std::string::npos) << verify.output;
    const auto info = nlohmann::json::parse(runCli("record info --json " + shellQuote(dir.file("damaged.palprec"))).output);
    EXPECT_FALSE(info["intact"].get<bool>());
    EXPECT_GE(info["damaged_regions"].get<int>(), 2);

    // Forged header parameters: intact, but the replay disagrees and names the tick.
    RecordingHeader header;
    std::size_t headerBytes = 0;
    std::string error;
    ASSERT_TRUE((error = decodeRecordingHeader(bytes.data(), bytes.size(), header, headerBytes)).empty());
    header.scene.params.springStiffnessNPerMm *= 1.5;
    std::vector<std::uint8_t> forged;
    const std::uint32_t forgedCrc = encodeRecordingHeader(header, forged);
    const std::size_t forgedHeaderBytes = forged.size();
    forged.insert(forged.end(), bytes.begin() + std::ptrdiff_t(headerBytes), bytes.end());
    // Spliced as it is (the chunks still name the old header): verify says so.
    writeBytes(dir.file("spliced.palprec"), forged);
    const auto spliced = runCli("record verify " + shellQuote(dir.file("spliced.palprec")));
    EXPECT_EQ(spliced.exitCode, 1) << spliced.output;
    EXPECT_NE(spliced.output.find("chunk of another recording"), std::string::npos) << spliced.output;
    retagChunks(forged, forgedHeaderBytes, forgedCrc);  // a forger who retags the chunks
    writeBytes(dir.file("forged.palprec"), forged);
    EXPECT_EQ(runCli("record verify " + shellQuote(dir.file("forged.palprec"))).exitCode, 0);
    const auto replay = runCli("record replay " + shellQuote(dir.file("forged.palprec")));
    EXPECT_EQ(replay.exitCode, 1) << replay.output;
    EXPECT_NE(replay.output.find("first at tick"), std::string::npos) << replay.output;

    // Garbage and missing files: clear messages, no crash.
    std::string garbage(5000, '\0');
    std::mt19937 rng(3);
    for (char& c : garbage) c = char(rng());
    std::ofstream(dir.file("garbage.palprec"), std::ios::binary) << garbage;
    for (const char* action : {"info", "verify", "export-csv", "replay"}) {
        const auto r = runCli(std::string("record ") + action + " " + shellQuote(dir.file("garbage.palprec")));
        EXPECT_LT(r.exitCode, 128) << action << ": " << r.output;
        const auto missing = runCli(std::string("record ") + action + " " + shellQuote(dir.file("missing.palprec")));
        EXPECT_EQ(missing.exitCode, 1) << action;
        EXPECT_NE(missing.output.find("missing.palprec"), std::string::npos) << missing.output;
    }
    EXPECT_EQ(runCli("record verify " + shellQuote(dir.file("garbage.palprec"))).exitCode, 1);
    EXPECT_EQ(runCli("record frobnicate x").exitCode, 2);
    EXPECT_EQ(runCli("run --seconds -1").exitCode, 2);
}
