// Family g of docs/reliability.md: kill -9 at seeded random moments during `run --record`,
// `mesh generate` and an atomic save (`calibrate --out` replacing a preset). Nothing can clean up
// after SIGKILL, so the promise is about what is on disk: the output is absent, the previous
// file, or a file the product's reader accepts -- a recording loses at most its last chunk.
// (A save that writes in place would show here; an atomic one leaves the target untouched.)

#include "WriterCases.h"

#include <random>
#include <thread>

#include <gtest/gtest.h>

namespace palpate::fault {
namespace {

constexpr int kMomentsPerWriter = 10;
constexpr unsigned kSeed = 20;  // fixed: a failure names its moment and can be run again

struct KillCase {
    std::string writer;  ///< run_record, mesh_generate, atomic_save
    int index;
    double killAfterS;
    bool fromFirstFile;  ///< counted from the moment a file appears in out/, not from the start
};

void PrintTo(const KillCase& c, std::ostream* os) { *os << c.writer << " killed after " << c.killAfterS << " s"; }

std::vector<KillCase> killCases() {
    // A recording is written during the whole session, so its moments span the run (a 1 s session
    // takes about 1.1 s, start-up included). A mesh or a preset is written only at the end of its
    // run, in a few milliseconds: counted from the start, most moments would miss the write, so
    // theirs count from the moment the first file appears in out/ (the target or its temporary)
    // and span the write (100 000 vertices: about 60 ms; a preset: well under 1 ms).
    struct Window {
        std::string writer;
        double seconds;
        bool fromFirstFile;
    };
    const std::vector<Window> windows{{"run_record", 1.2, false}, {"mesh_generate", 0.08, true}, {"atomic_save", 0.002, true}};
    std::mt19937 generator(kSeed);
    std::vector<KillCase> cases;
    for (const auto& w : windows) {
        std::uniform_real_distribution<double> moment(0.0, w.seconds);
        for (int i = 0; i < kMomentsPerWriter; ++i) cases.push_back({w.writer, i, moment(generator), w.fromFirstFile});
    }
    return cases;
}

class KillNine : public testing::TestWithParam<KillCase> {};

TEST_P(KillNine, OutputAbsentPreviousOrReadable) {
    const KillCase& c = GetParam();
    Scratch scratch;
    std::vector<std::string> args;
    fs::path output;
    std::optional<std::string> previous;
    std::vector<fs::path> inputs;
    if (c.writer == "run_record") {
        const Writer& w = writerNamed("run_record");
        inputs = prepareInputs(scratch, w);
        output = scratch.out(w.outputName);
        args = writerArgs(scratch, w, output);
        args[2] = "1.0";  // --seconds: long enough to be killed while it writes
    } else if (c.writer == "mesh_generate") {
        output = scratch.out("generated.off");
        args = {"mesh", "generate", "--shape", "sphere", "--vertices", "100000", "--out", output.string()};
    } else {
        const Writer& w = writerNamed("calibrate_preset");
        inputs = prepareInputs(scratch, w);
        output = scratch.out(w.outputName);
        copyFile(previousOutputFixture(w), output);
        previous = digest(output);
        args = writerArgs(scratch, w, output);
    }
    const auto inputsBefore = digests(inputs);

    Child child(cliSpec(scratch, args));
    ASSERT_TRUE(child.started());
    if (c.fromFirstFile) {
        const auto quiet = previous ? std::size_t{1} : std::size_t{0};  // the previous file is already there
        const double waitUntil = nowS() + 10.0;
        while (filesIn(scratch.outDir()).size() <= quiet && nowS() < waitUntil)
            std::this_thread::sleep_for(std::chrono::microseconds(100));
    }
    const double t0 = nowS();
    while (nowS() - t0 < c.killAfterS) std::this_thread::sleep_for(std::chrono::microseconds(100));
    const ChildResult r = child.kill9();
    SCOPED_TRACE(c.writer + " killed after " + std::to_string(c.killAfterS) + " s: " + r.describe());

    for (const auto& [path, before] : inputsBefore) {
        EXPECT_EQ(digest(path), before) << "input changed: " << path;
    }
    if (!fs::exists(output) || (previous && digest(output) == *previous)) return;  // absent, or the previous file
    if (c.writer == "run_record") {
        const RecordingVerdict v = recordInfo(scratch, output);
        EXPECT_TRUE(v.accepted) << "a recording cut by kill -9 must stay readable: " << v.problem;
        // A torn last chunk is one damaged region at most; everything before it is recovered.
        EXPECT_LE(v.damagedRegions, 1) << "more than the last chunk is lost";
    } else if (c.writer == "mesh_generate") {
        std::string problem;
        EXPECT_TRUE(meshAccepted(scratch, output, &problem)) << "a mesh cut by kill -9 is on disk: " << problem;
    } else {
        std::string problem;
        EXPECT_TRUE(presetAccepted(scratch, output, &problem)) << "an atomic save left a broken preset: " << problem;
    }
}

INSTANTIATE_TEST_SUITE_P(FamilyG, KillNine, testing::ValuesIn(killCases()),
                         [](const testing::TestParamInfo<KillCase>& info) {
                             return info.param.writer + "__moment_" + std::to_string(info.param.index);
                         });

}  // namespace
}  // namespace palpate::fault
