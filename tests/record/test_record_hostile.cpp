// Hostile cases for the recorder and the commands that write or read recordings: headers at the
// format's limits, a second writer, a file that is already there, an output that is an input, a
// file-size limit, threads that cannot be created, and inputs that are not recordings at all
// (docs/recording.md, "Format limits and refusals").
#include "engine/record/RecordingReader.h"
#include "engine/record/RecordingWriter.h"
#include "tests/record/RecordTestRig.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace palpate;
using namespace palpate::test;

namespace {

// Sanitizers reserve terabytes of address space: a lowered RLIMIT_AS stops such a build at start-up,
// before it reaches the thread it is meant to fail, so those checks run in plain builds only.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

void writeText(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

/// palpate-cli under a timeout: a hang fails the test instead of stopping it (exit 124).
CommandResult runCliWithin(const std::string& args) {
    return runCommand("timeout 60 " + shellQuote(PALPATE_CLI_PATH) + " " + args);
}

nlohmann::json infoJson(const std::string& path) {
    const auto r = runCliWithin("record info --json " + shellQuote(path));
    return nlohmann::json::parse(r.output, nullptr, false);
}

std::string resource(const std::string& relative) { return std::string(PALPATE_SOURCE_DIR) + "/resources/" + relative; }

/// A short real-time run recorded to `path`, with `extra` arguments.
CommandResult runRecorded(const std::string& path, const std::string& extra = "", double seconds = 0.5) {
    return runCli("run --mesh " + shellQuote(sphereMeshPath()) + " --device sim:stroke --no-fifo --seconds " +
                  std::to_string(seconds) + " " + extra + " --record " + shellQuote(path));
}

}  // namespace

// --- the header's limits: what the writer writes, the reader reads ---

TEST(RecorderLimits, WriterRefusesAHeaderTheReaderWouldRefuse) {
    TempDir dir;
    RecordRig rig = makeRecordRig(SimTrajectory::Stroke);
    std::string error;
    RecordingHeader tooLong = rig.header;
    tooLong.note.assign(kMaxNoteBytes + 1, 'n');
    EXPECT_FALSE(RecordingWriter::create(dir.file("note.palprec"), tooLong, error));
    EXPECT_NE(error.find("header.note"), std::string::npos) << error;
    EXPECT_NE(error.find("note.palprec"), std::string::npos) << error;
    EXPECT_FALSE(std::filesystem::exists(dir.file("note.palprec")));  // nothing written

    RecordingHeader bigPreset = rig.header;
    bigPreset.scene.presetJson.assign(kMaxPresetJsonBytes + 1, 'p');
    EXPECT_FALSE(RecordingWriter::create(dir.file("preset.palprec"), bigPreset, error));
    EXPECT_NE(error.find("header.scene.presetJson"), std::string::npos) << error;

    // At the limits, the file reads back with every text whole.
    RecordingHeader atLimits = rig.header;
    atLimits.note.assign(kMaxNoteBytes, 'n');
    atLimits.scene.presetJson.assign(kMaxPresetJsonBytes, 'p');
    auto writer = RecordingWriter::create(dir.file("limits.palprec"), atLimits, error);
    ASSERT_TRUE(writer) << error;
    EXPECT_EQ(writer->close(), "");
    const RecordingReader reader = RecordingReader::open(dir.file("limits.palprec"));
    ASSERT_TRUE(reader.headerOk()) << reader.headerError();
    EXPECT_EQ(reader.header().note.size(), kMaxNoteBytes);
    EXPECT_EQ(reader.header().scene.presetJson.size(), kMaxPresetJsonBytes);
}

// --- the writer's file: one writer, nothing replaced unasked ---

TEST(RecorderFiles, OneWriterPerFileAndReplacingOnlyWhenAsked) {
    TempDir dir;
    RecordRig rig = makeRecordRig(SimTrajectory::Stroke);
    const std::string path = dir.file("r.palprec");
    std::string error;
    auto first = RecordingWriter::create(path, rig.header, error);
    ASSERT_TRUE(first) << error;
    const auto firstBytes = readBytes(path);

    // Not asked to replace: refused, the file as it was.
    EXPECT_FALSE(RecordingWriter::create(path, rig.header, error));
    EXPECT_NE(error.find("r.palprec: already exists"), std::string::npos) << error;
    // Asked to replace, but it is being written (a lock is per open file, so this process counts).
    RecordingWriterDef replace;
    replace.replaceExisting = true;
    EXPECT_FALSE(RecordingWriter::create(path, rig.header, error, replace));
    EXPECT_NE(error.find("r.palprec: is being written by another Palpate (process " + std::to_string(::getpid()) + ")"),
              std::string::npos)
        << error;
    EXPECT_EQ(readBytes(path), firstBytes);
    ASSERT_EQ(first->close(), "");

    // Closed: now it may be replaced, and nothing is left beside it.
    RecordingHeader second = rig.header;
    second.note = "the second session";
    auto writer = RecordingWriter::create(path, second, error, replace);
    ASSERT_TRUE(writer) << error;
    EXPECT_EQ(writer->close(), "");
    EXPECT_EQ(RecordingReader::open(path).header().note, "the second session");
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path())) ++files;
    EXPECT_EQ(files, 1u);
}

TEST(RecordCliThreads, LongNoteAndLargePresetDescriptionReadBack) {
    TempDir dir;
    const std::string note(100000, 'a');
    const auto r = runRecorded(dir.file("note.palprec"), "--note " + note);
    ASSERT_EQ(r.exitCode, 0) << r.output.substr(0, 500);
    const auto info = infoJson(dir.file("note.palprec"));
    ASSERT_TRUE(info["header_ok"].get<bool>()) << info.dump().substr(0, 500);
    EXPECT_EQ(info["note"].get<std::string>(), note);
    EXPECT_TRUE(info["intact"].get<bool>());

    auto preset = nlohmann::json::parse(readText(resource("presets/default.json")));
    preset["description"] = std::string(300000, 'd');
    writeText(dir.file("wordy.json"), preset.dump(2));
    const auto p = runRecorded(dir.file("preset.palprec"), "--preset " + shellQuote(dir.file("wordy.json")));
    ASSERT_EQ(p.exitCode, 0) << p.output.substr(0, 500);
    EXPECT_TRUE(infoJson(dir.file("preset.palprec"))["header_ok"].get<bool>());
    const auto replay = runCli("record replay " + shellQuote(dir.file("preset.palprec")));
    EXPECT_EQ(replay.exitCode, 0) << replay.output;
}

TEST(RecordCliThreads, TheDocumentedExerciseLimitsRunAndScore) {
    TempDir dir;
    // 1000 press targets and 10 000 trace points (docs/scoring.md), built from the examples.
    auto targets = nlohmann::json::parse(readText(resource("exercises/press_targets.json")));
    const int vertices[] = {3599, 3537, 3728, 1090, 1188};
    nlohmann::json list = nlohmann::json::array();
    for (int i = 0; i < 1000; ++i)
        list.push_back({{"vertex", vertices[i % 5]}, {"force_min_n", 1.0 + 0.001 * (i % 100)}, {"force_max_n", 2.5}});
    targets["press_targets"]["targets"] = list;
    targets["mesh"] = resource("meshes/stomach_3970.off");
    targets["tissue_preset"] = resource("presets/tissues/skin.json");
    writeText(dir.file("targets.json"), targets.dump(1));

    auto trace = nlohmann::json::parse(readText(resource("exercises/trace.json")));
    const nlohmann::json path = trace["trace"]["path"];
    nlohmann::json points = nlohmann::json::array();
    for (std::size_t i = 0; i < 10000; ++i) points.push_back(path[i % path.size()]);
    trace["trace"]["path"] = points;
    trace["mesh"] = resource("meshes/stomach_3970.off");
    trace["tissue_preset"] = resource("presets/tissues/muscle.json");
    writeText(dir.file("trace.json"), trace.dump(1));

    for (const char* name : {"targets", "trace"}) {
        const std::string recording = dir.file(std::string(name) + ".palprec");
        const auto r = runCli("run --exercise " + shellQuote(dir.file(std::string(name) + ".json")) +
                              " --seconds 0.5 --no-fifo --record " + shellQuote(recording));
        ASSERT_EQ(r.exitCode, 0) << name << ": " << r.output.substr(0, 1000);
        const auto info = infoJson(recording);
        ASSERT_TRUE(info["header_ok"].get<bool>()) << name;
        EXPECT_GT(info["note"].get<std::string>().size(), kMaxEventTextBytes) << name;  // beyond the old cap
        const auto score = runCli("score " + shellQuote(recording));
        EXPECT_EQ(score.exitCode, 0) << name << ": " << score.output.substr(0, 1000);
    }
}

// --- one writer, nothing replaced unasked, an input is never an output ---

TEST(RecordCliThreads, ASecondWriterIsRefusedAndTheFirstRecordingSurvives) {
    TempDir dir;
    const std::string path = dir.file("r.palprec");
    const std::string cli = shellQuote(PALPATE_CLI_PATH);
    const std::string run = cli + " run --mesh " + shellQuote(sphereMeshPath()) + " --device sim:stroke --no-fifo";
    // The second starts once the first has written its header (the file is not empty).
    const auto r = runCommand("(" + run + " --seconds 3 --record " + shellQuote(path) + " >/dev/null 2>&1 &" +
                            " for i in $(seq 200); do [ -s " + shellQuote(path) + " ] && break; sleep 0.05; done;" +
                            " " + run + " --seconds 0.5 --overwrite --record " + shellQuote(path) +
                            "; echo second=$?;" + " wait)");
    EXPECT_NE(r.output.find("second=1"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("is being written by another Palpate (process "), std::string::npos) << r.output;
    const auto verify = runCli("record verify " + shellQuote(path));
    EXPECT_EQ(verify.exitCode, 0) << verify.output;
    const auto info = infoJson(path);
    EXPECT_GT(info["duration_s"].get<double>(), 2.0);  // the first session's three seconds, whole
}

TEST(RecordCliThreads, AnExistingFileIsReplacedOnlyWithOverwrite) {
    TempDir dir;
    const std::string path = dir.file("old.palprec");
    writeText(path, "an earlier session");
    const auto refused = runRecorded(path);
    EXPECT_EQ(refused.exitCode, 2) << refused.output;
    EXPECT_NE(refused.output.find("--overwrite"), std::string::npos) << refused.output;
    EXPECT_EQ(readText(path), "an earlier session");

    // A start that fails (no thread can be created: a 4 GB stack each under a 3 GB address space)
    // costs neither the old file nor a new one.
    if (!kSanitized) {
        const auto failed = runCommand("(ulimit -s 4000000 && ulimit -v 3000000 && exec timeout 60 " +
                                     shellQuote(PALPATE_CLI_PATH) + " run --mesh " + shellQuote(sphereMeshPath()) +
                                     " --no-fifo --seconds 0.5 --overwrite --record " + shellQuote(path) + ")");
        EXPECT_EQ(failed.exitCode, 1) << failed.output;
        EXPECT_EQ(readText(path), "an earlier session");
    }

    const auto replaced = runRecorded(path, "--overwrite");
    EXPECT_EQ(replaced.exitCode, 0) << replaced.output;
    EXPECT_EQ(runCli("record verify " + shellQuote(path)).exitCode, 0);
    for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
        EXPECT_EQ(entry.path().filename(), "old.palprec") << "left behind: " << entry.path();
}

TEST(RecordCliThreads, AnOutputIsNeverAnInput) {
    TempDir dir;
    std::filesystem::copy_file(sphereMeshPath(), dir.file("m.off"));
    std::filesystem::create_symlink(dir.file("m.off"), dir.file("link.off"));
    const std::string mesh = readText(dir.file("m.off"));
    for (const char* target : {"m.off", "link.off"}) {
        const auto r = runCli("run --mesh " + shellQuote(dir.file("m.off")) + " --no-fifo --seconds 0.2 --overwrite" +
                              " --record " + shellQuote(dir.file(target)));
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find("is the mesh file"), std::string::npos) << r.output;
    }
    EXPECT_EQ(readText(dir.file("m.off")), mesh);

    writeText(dir.file("p.json"), readText(resource("presets/default.json")));
    const auto preset = runRecorded(dir.file("p.json"), "--overwrite --preset " + shellQuote(dir.file("p.json")));
    EXPECT_EQ(preset.exitCode, 2) << preset.output;
    EXPECT_NE(preset.output.find("is the preset file"), std::string::npos) << preset.output;

    ASSERT_EQ(runRecorded(dir.file("r.palprec")).exitCode, 0);
    const std::string recording = readText(dir.file("r.palprec"));
    const auto replayed = runCli("run --mesh " + shellQuote(sphereMeshPath()) + " --no-fifo --seconds 0.2 --device " +
                                 shellQuote("replay:" + dir.file("r.palprec")) + " --overwrite --record " +
                                 shellQuote(dir.file("r.palprec")));
    EXPECT_EQ(replayed.exitCode, 2) << replayed.output;
    EXPECT_NE(replayed.output.find("is the replayed recording file"), std::string::npos) << replayed.output;

    const auto csv = runCli("record export-csv " + shellQuote(dir.file("r.palprec")) + " --out " +
                            shellQuote(dir.file("r.palprec")));
    EXPECT_EQ(csv.exitCode, 2) << csv.output;
    EXPECT_NE(csv.output.find("is the recording file"), std::string::npos) << csv.output;
    EXPECT_EQ(readText(dir.file("r.palprec")), recording);

    const auto loopCsv = runCli("loop --seconds 0.2 --no-fifo --mesh " + shellQuote(dir.file("m.off")) + " --csv " +
                                shellQuote(dir.file("link.off")));
    EXPECT_EQ(loopCsv.exitCode, 2) << loopCsv.output;
    EXPECT_EQ(readText(dir.file("m.off")), mesh);
}

// --- a file-size limit, a full disk, threads that cannot start ---

TEST(RecordCliThreads, AFileSizeLimitIsNamedAndTheSummaryIsWhatTheFileHolds) {
    TempDir dir;
    const std::string path = dir.file("limited.palprec");
    // 20 KiB: the limit is reached after about a second of sim:stroke. The CLI ignores SIGXFSZ, so
    // write(2) fails with EFBIG instead of the signal killing it.
    const auto r = runCommand("(ulimit -f 20 && exec " + shellQuote(PALPATE_CLI_PATH) + " run --mesh " +
                            shellQuote(sphereMeshPath()) + " --device sim:stroke --no-fifo --seconds 4 --json" +
                            " --record " + shellQuote(path) + " 2>/dev/null)");
    ASSERT_EQ(r.exitCode, 1) << r.output;  // not 128 + SIGXFSZ
    const auto run = nlohmann::json::parse(r.output, nullptr, false);
    ASSERT_FALSE(run.is_discarded()) << r.output;
    const std::string error = run["recording"]["error"].get<std::string>();
    EXPECT_NE(error.find("limited.palprec: file size limit reached after"), std::string::npos) << error;
    const auto info = infoJson(path);
    EXPECT_EQ(run["recording"]["ticks"].get<std::uint64_t>(), info["ticks"].get<std::uint64_t>());
    EXPECT_EQ(run["recording"]["bytes"].get<std::uint64_t>(), info["bytes"].get<std::uint64_t>());
    EXPECT_GT(info["ticks"].get<std::uint64_t>(), 0u);
    EXPECT_EQ(info["damaged_regions"].get<int>(), 0);  // cut back to the last whole chunk
    EXPECT_NE(error.find(std::to_string(info["ticks"].get<std::uint64_t>()) + " ticks"), std::string::npos) << error;
    // The text summary says so too, on stderr.
    const auto text = runCommand("(ulimit -f 20 && exec " + shellQuote(PALPATE_CLI_PATH) + " run --mesh " +
                               shellQuote(sphereMeshPath()) + " --device sim:stroke --no-fifo --seconds 4" +
                               " --overwrite --record " + shellQuote(path) + ")");
    EXPECT_EQ(text.exitCode, 1) << text.output;
    EXPECT_NE(text.output.find("file size limit reached"), std::string::npos) << text.output;
}

TEST(RecordCliThreads, AFullDiskIsNamedAndTheSummaryIsWhatTheFileHolds) {
    // A 16 KiB tmpfs, mounted in a private mount namespace (it goes with the shell), fills after
    // about a second of sim:stroke.
    if (runCommand("unshare -rm true").exitCode != 0) GTEST_SKIP() << "no user and mount namespaces here";
    TempDir dir;
    std::filesystem::create_directory(dir.file("small"));
    const std::string cli = shellQuote(PALPATE_CLI_PATH);
    const std::string path = dir.file("small") + "/full.palprec";
    const auto r = runCommand("unshare -rm sh -c " +
                            shellQuote("mount -t tmpfs -o size=16k tmpfs " + shellQuote(dir.file("small")) +
                                       " || exit 99; timeout 60 " + cli + " run --mesh " +
                                       shellQuote(sphereMeshPath()) + " --device sim:stroke --no-fifo --seconds 4" +
                                       " --json --record " + shellQuote(path) + " 2>/dev/null; echo \"exit=$?\";" +
                                       " timeout 60 " + cli + " record info --json " + shellQuote(path)));
    if (r.exitCode == 99 && r.output.find("exit=") == std::string::npos) GTEST_SKIP() << "tmpfs not mountable";
    const std::size_t split = r.output.find("exit=");
    ASSERT_NE(split, std::string::npos) << r.output;
    EXPECT_EQ(r.output.substr(split, 7), "exit=1\n") << r.output;
    const auto run = nlohmann::json::parse(r.output.substr(0, split), nullptr, false);
    const auto info = nlohmann::json::parse(r.output.substr(split + 7), nullptr, false);
    ASSERT_FALSE(run.is_discarded() || info.is_discarded()) << r.output;
    const std::string error = run["recording"]["error"].get<std::string>();
    EXPECT_NE(error.find("full.palprec: writing the recording failed after "), std::string::npos) << error;
    EXPECT_NE(error.find("No space left on device"), std::string::npos) << error;
    EXPECT_GT(info["ticks"].get<std::uint64_t>(), 0u);
    EXPECT_EQ(run["recording"]["ticks"].get<std::uint64_t>(), info["ticks"].get<std::uint64_t>());
    EXPECT_EQ(run["recording"]["bytes"].get<std::uint64_t>(), info["bytes"].get<std::uint64_t>());
    EXPECT_EQ(info["damaged_regions"].get<int>(), 0);
}

TEST(RecordCliThreads, AFailedExportLeavesTheOldCsvAndNoHalfFile) {
    TempDir dir;
    ASSERT_EQ(runRecorded(dir.file("r.palprec")).exitCode, 0);
    writeText(dir.file("t.csv"), "an earlier export\n");
    // 8 KiB: the CSV of half a second (about 100 bytes a tick) does not fit.
    const auto r = runCommand("(ulimit -f 8 && exec " + shellQuote(PALPATE_CLI_PATH) + " record export-csv " +
                            shellQuote(dir.file("r.palprec")) + " --out " + shellQuote(dir.file("t.csv")) + ")");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("t.csv: writing failed: File too large"), std::string::npos) << r.output;
    EXPECT_EQ(readText(dir.file("t.csv")), "an earlier export\n");
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path())) ++files;
    EXPECT_EQ(files, 2u);  // the recording and the old CSV, nothing beside them
    const auto missing = runCli("record export-csv " + shellQuote(dir.file("r.palprec")) + " --out " +
                                shellQuote(dir.file("no-such-dir/t.csv")));
    EXPECT_EQ(missing.exitCode, 1) << missing.output;
    EXPECT_NE(missing.output.find("no-such-dir/t.csv: cannot write: No such file or directory"), std::string::npos)
        << missing.output;
}

TEST(RecordCliThreads, NotARegularFileIsRefusedAsARecordingTarget) {
    const auto r = runRecorded("/dev/full", "--overwrite");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("/dev/full: is not a regular file"), std::string::npos) << r.output;
}

TEST(RecordCliThreads, ThreadsThatCannotStartAreAMessageNotAHangOrAnAbort) {
    if (kSanitized) GTEST_SKIP() << "a sanitizer build does not start under a lowered RLIMIT_AS";
    TempDir dir;
    const std::string cli = "exec timeout 60 " + shellQuote(PALPATE_CLI_PATH);
    // Every thread asks for a 4 GB stack under a 3 GB address space: none can be created.
    const std::string noThreads = "ulimit -s 4000000 && ulimit -v 3000000 && ";
    const std::string mesh = " --mesh " + shellQuote(sphereMeshPath()) + " --no-fifo --seconds 0.5";
    const auto run = runCommand("(" + noThreads + cli + " run" + mesh + " --record " + shellQuote(dir.file("a.palprec")) +
                              ")");
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("could not start the haptic thread"), std::string::npos) << run.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("a.palprec")));  // no header-only file left
    const auto loop = runCommand("(" + noThreads + cli + " loop" + mesh + ")");
    EXPECT_EQ(loop.exitCode, 1) << loop.output;
    EXPECT_NE(loop.output.find("could not start the observer thread"), std::string::npos) << loop.output;
    // One 1 GB stack fits in 1.7 GB, a second does not: the haptic thread runs, the writer cannot.
    const auto writer = runCommand("(ulimit -s 1048576 && ulimit -v 1700000 && " + cli + " run" + mesh + " --record " +
                                 shellQuote(dir.file("b.palprec")) + ")");
    EXPECT_EQ(writer.exitCode, 1) << writer.output;
    EXPECT_NE(writer.output.find("b.palprec: cannot start the recording's writer thread"), std::string::npos)
        << writer.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("b.palprec")));
}

// --- what is not a recording ---

TEST(RecordCliThreads, DirectoriesFifosDevicesAndOtherFilesAreNamed) {
    TempDir dir;
    std::filesystem::create_directory(dir.file("dir.palprec"));
    ASSERT_EQ(::mkfifo(dir.file("fifo.palprec").c_str(), 0644), 0);
    writeText(dir.file("text.palprec"), "tick,time_s\n0,0\n");
    const struct {
        std::string path, says;
    } cases[] = {{dir.file("dir.palprec"), "is a directory"},
                 {dir.file("fifo.palprec"), "is a FIFO"},
                 {"/dev/zero", "is a device"},
                 {dir.file("text.palprec"), "not a Palpate recording"}};
    for (const auto& c : cases) {
        for (const char* action : {"info", "export-csv", "replay"}) {
            const auto r = runCliWithin("record " + std::string(action) + " " + shellQuote(c.path));
            EXPECT_EQ(r.exitCode, 1) << action << " " << c.path << ": " << r.output;
            EXPECT_NE(r.output.find(c.path + ": " + c.says), std::string::npos) << action << ": " << r.output;
        }
        const auto verify = runCliWithin("record verify " + shellQuote(c.path));
        EXPECT_EQ(verify.exitCode, 1) << c.path << ": " << verify.output;
        const auto score = runCliWithin("score " + shellQuote(c.path));
        EXPECT_EQ(score.exitCode, 1) << c.path << ": " << score.output;
        EXPECT_NE(score.output.find(c.path), std::string::npos) << score.output;
    }
}
