// Family d of docs/reliability.md: a FIFO (no writer: an open without O_NONBLOCK blocks forever),
// /dev/zero and /dev/full (endless zeros), /dev/null (empty), a directory and a 2 GB sparse file,
// given as every input the CLI reads: mesh, preset, exercise, waypoint file and recording. Every
// input is read through one bounded reader that takes regular files only, so each must be refused
// quickly (well within 10 s), with a non-zero exit and a message naming it, without growing
// memory (the child's address space is capped at 2 GB, which turns a runaway into a failure).

#include "OutputChecks.h"

#include <cstdlib>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

namespace palpate::fault {
namespace {

enum class Kind { Fifo, DevZero, DevNull, DevFull, Directory, Sparse2GB };

const std::vector<std::pair<std::string, Kind>>& kinds() {
    static const std::vector<std::pair<std::string, Kind>> all{
        {"fifo", Kind::Fifo},           {"dev_zero", Kind::DevZero},    {"dev_null", Kind::DevNull},
        {"dev_full", Kind::DevFull},    {"directory", Kind::Directory}, {"sparse_2GB", Kind::Sparse2GB}};
    return all;
}

// An input slot: the extension its file would have and the command line reading it.
struct Slot {
    std::string name;
    std::string extension;
    std::function<std::vector<std::string>(const Scratch&, const std::string& input)> args;
};

const std::vector<Slot>& slots() {
    static const std::vector<Slot> all{
        {"mesh_check", ".off", [](const Scratch&, const std::string& p) { return std::vector<std::string>{"mesh", "check", p}; }},
        {"mesh_import", ".obj",
         [](const Scratch& s, const std::string& p) {
             return std::vector<std::string>{"mesh", "import", p, "--out", s.out("imported.off").string(), "--repair"};
         }},
        {"run_mesh", ".off",
         [](const Scratch&, const std::string& p) { return std::vector<std::string>{"run", "--seconds", "0.1", "--mesh", p}; }},
        {"run_preset", ".json",
         [](const Scratch&, const std::string& p) { return std::vector<std::string>{"run", "--seconds", "0.1", "--preset", p}; }},
        {"calibrate_preset", ".json",
         [](const Scratch&, const std::string& p) { return std::vector<std::string>{"calibrate", "--preset", p}; }},
        {"run_exercise", ".json",
         [](const Scratch&, const std::string& p) { return std::vector<std::string>{"run", "--seconds", "0.1", "--exercise", p}; }},
        {"score_exercise", ".json",
         [](const Scratch& s, const std::string& p) {
             return std::vector<std::string>{"score", "--recording", s.in("session.rec").string(), "--exercise", p};
         }},
        {"run_waypoints", ".path",
         [](const Scratch&, const std::string& p) {
             return std::vector<std::string>{"run", "--seconds", "0.1", "--device", "sim:path:" + p};
         }},
        {"run_replay_device", ".rec",
         [](const Scratch&, const std::string& p) {
             return std::vector<std::string>{"run", "--seconds", "0.1", "--device", "replay:" + p};
         }},
        {"record_info", ".rec", [](const Scratch&, const std::string& p) { return std::vector<std::string>{"record", "info", p}; }},
        {"record_verify", ".rec", [](const Scratch&, const std::string& p) { return std::vector<std::string>{"record", "verify", p}; }},
        {"record_export_csv", ".rec",
         [](const Scratch& s, const std::string& p) {
             return std::vector<std::string>{"record", "export-csv", p, "--out", s.out("export.csv").string()};
         }},
        {"record_replay", ".rec", [](const Scratch&, const std::string& p) { return std::vector<std::string>{"record", "replay", p}; }},
        {"score_recording", ".rec", [](const Scratch&, const std::string& p) { return std::vector<std::string>{"score", "--recording", p}; }},
    };
    return all;
}

struct SpecialCase {
    std::string slot;
    std::string kind;
};

void PrintTo(const SpecialCase& c, std::ostream* os) { *os << c.slot << " " << c.kind; }

std::vector<SpecialCase> specialCases() {
    std::vector<SpecialCase> cases;
    for (const auto& slot : slots())
        for (const auto& [kind, _] : kinds()) cases.push_back({slot.name, kind});
    return cases;
}

std::string makeInput(const Scratch& scratch, Kind kind, const std::string& extension) {
    const fs::path path = scratch.in("input" + extension);
    switch (kind) {
    case Kind::Fifo: EXPECT_EQ(::mkfifo(path.c_str(), 0644), 0); return path.string();
    case Kind::DevZero: return "/dev/zero";
    case Kind::DevNull: return "/dev/null";
    case Kind::DevFull: return "/dev/full";
    case Kind::Directory: fs::create_directories(path); return path.string();
    case Kind::Sparse2GB: {
        const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        EXPECT_GE(fd, 0);
        EXPECT_EQ(::ftruncate(fd, 2ll << 30), 0);
        ::close(fd);
        return path.string();
    }
    }
    return {};
}

class SpecialInputs : public testing::TestWithParam<SpecialCase> {};

TEST_P(SpecialInputs, RefusedQuicklyWithTheFileNamed) {
    const SpecialCase& c = GetParam();
    const Slot* slot = nullptr;
    for (const auto& s : slots())
        if (s.name == c.slot) slot = &s;
    Kind kind{};
    for (const auto& [name, k] : kinds())
        if (name == c.kind) kind = k;
    ASSERT_NE(slot, nullptr);

    Scratch scratch;
    copyFile(fixtureRecording(), scratch.in("session.rec"));
    const std::string input = makeInput(scratch, kind, slot->extension);
    // A device's times move with every other process's writes: only our own files are compared.
    std::vector<fs::path> owned{scratch.in("session.rec")};
    if (input.rfind("/dev/", 0) != 0) owned.push_back(input);
    const auto before = digests(owned);
    ChildSpec spec = cliSpec(scratch, slot->args(scratch, input));
    spec.timeoutS = 10.0;
    if (!sanitized()) {
        spec.addressSpaceBytes = 2ull << 30;
    } else {
        // A sanitizer's shadow memory rules out RLIMIT_AS; its own resident-memory cap does the job.
        spec.env["ASAN_OPTIONS"] += ":hard_rss_limit_mb=2048";
        spec.env["TSAN_OPTIONS"] = std::string(std::getenv("TSAN_OPTIONS") ? std::getenv("TSAN_OPTIONS") : "") + ":memory_limit_mb=2048";
    }
    const ChildResult r = runChild(spec);
    SCOPED_TRACE(c.slot + " with " + c.kind + " " + input + ": " + r.describe());

    EXPECT_TRUE(r.exited) << "must end by itself well within 10 s (no blocking open, no endless read)";
    EXPECT_NE(r.exitCode, 0) << "a " << c.kind << " is no " << slot->extension << " file: it must be refused";
    // `mesh check` reports on stdout by design (its verdict is its output); the others on stderr.
    const std::string message = c.slot == "mesh_check" ? r.out + r.err : r.err;
    EXPECT_TRUE(namesPath(message, input)) << "the message must name " << input;
    EXPECT_FALSE(fs::exists(scratch.out("export.csv"))) << "nothing may be exported from it";
    for (const auto& [path, digestBefore] : before) {
        EXPECT_EQ(digest(path), digestBefore) << "input changed: " << path;
    }
}

INSTANTIATE_TEST_SUITE_P(FamilyD, SpecialInputs, testing::ValuesIn(specialCases()),
                         [](const testing::TestParamInfo<SpecialCase>& info) {
                             return info.param.slot + "__" + info.param.kind;
                         });

}  // namespace
}  // namespace palpate::fault
