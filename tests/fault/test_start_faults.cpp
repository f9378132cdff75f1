// Family c of docs/reliability.md: thread creation fails (the shim's pthread_create returns EAGAIN
// from its (K+1)-th call) or memory runs out at start-up (RLIMIT_AS of 100 MB) for `run`,
// `run --record`, `loop` and the GUI's start. No hang (a thread that never started must not be
// joined or waited for), no abort, and a message that says what failed.

#include "OutputChecks.h"

#include <gtest/gtest.h>

namespace palpate::fault {
namespace {

enum class Starter { Run, RunRecord, Loop, Gui };

struct StartCase {
    std::string name;
    Starter starter;
    std::optional<int> threadFailAfter;
    std::optional<unsigned long long> addressSpaceBytes;
};

void PrintTo(const StartCase& c, std::ostream* os) { *os << c.name; }

std::vector<StartCase> startCases() {
    const std::vector<std::pair<std::string, Starter>> starters{
        {"run", Starter::Run}, {"run_record", Starter::RunRecord}, {"loop", Starter::Loop}, {"gui", Starter::Gui}};
    std::vector<StartCase> cases;
    for (const auto& [name, starter] : starters) {
        for (int k : {0, 1, 2, 5}) cases.push_back({name + "__threads_fail_after_" + std::to_string(k), starter, k, {}});
        // 100 000 KiB, as `ulimit -v 100000`: the libraries still map, thread stacks no longer do.
        cases.push_back({name + "__address_space_100000KiB", starter, {}, 100000ull * 1024});
    }
    return cases;
}

bool looksLikeACrashReport(const std::string& err) {
    for (const char* sign : {"terminate called", "std::bad_alloc", "what():", "Aborted", "core dumped",
                             "Segmentation fault", "AddressSanitizer", "ThreadSanitizer"})
        if (err.find(sign) != std::string::npos) return true;
    return false;
}

class StartFaults : public testing::TestWithParam<StartCase> {};

TEST_P(StartFaults, NoHangNoAbortAMessage) {
    const StartCase& c = GetParam();
    if (c.addressSpaceBytes && sanitized())
        GTEST_SKIP() << "a sanitized child reserves terabytes of shadow memory: RLIMIT_AS cannot apply";
    Scratch scratch;
    ChildSpec spec;
    fs::path output;
    const Writer& recordingWriter = writerNamed("run_record");
    std::map<std::string, std::string> inputsBefore;
    switch (c.starter) {
    case Starter::Run: spec = cliSpec(scratch, {"run", "--seconds", "0.3"}); break;
    case Starter::RunRecord:
        inputsBefore = digests(prepareInputs(scratch, recordingWriter));
        output = scratch.out(recordingWriter.outputName);
        spec = cliSpec(scratch, writerArgs(scratch, recordingWriter, output));
        break;
    case Starter::Loop: spec = cliSpec(scratch, {"loop", "--seconds", "0.3"}); break;
    case Starter::Gui:
        if (!haveGui()) GTEST_SKIP() << "this build has no GUI (PALPATE_BUILD_GUI=OFF)";
        output = scratch.out("shot.png");
        spec = cliSpec(scratch, {guiPath(), "--screenshot", output.string(), "--after-ms", "500"});
        spec.timeoutS = 15.0;  // it starts in about a second
        break;
    }
    if (c.threadFailAfter) applyThreadFault(spec, scratch, *c.threadFailAfter);
    spec.addressSpaceBytes = c.addressSpaceBytes;
    const ChildResult r = runChild(spec);
    SCOPED_TRACE(c.name + ": " + r.describe());

    EXPECT_TRUE(r.exited) << "the process must end by itself, neither killed by a signal nor hung";
    EXPECT_FALSE(looksLikeACrashReport(r.err)) << "an abort or an uncaught exception is no message";
    if (r.exited && r.exitCode != 0) {
        EXPECT_FALSE(r.err.empty()) << "a failure must say what failed";
    }
    for (const auto& [path, before] : inputsBefore) {
        EXPECT_EQ(digest(path), before) << "input changed: " << path;
    }

    if (c.starter == Starter::RunRecord) {
        const OutputVerdict verdict = judgeOutput(scratch, recordingWriter, output, r.out + r.err);
        if (verdict.exists) {
            EXPECT_TRUE(verdict.acceptable) << "a recording the reader refuses: " << verdict.why;
        }
        if (r.succeeded()) {
            EXPECT_TRUE(verdict.complete) << "success, but " << verdict.why;
        }
    }
    if (c.starter == Starter::Gui && r.succeeded()) {
        const std::string png = readText(output);
        EXPECT_EQ(png.substr(0, 4), std::string("\x89PNG")) << "success, but no screenshot";
    }
}

INSTANTIATE_TEST_SUITE_P(FamilyC, StartFaults, testing::ValuesIn(startCases()),
                         [](const testing::TestParamInfo<StartCase>& info) { return info.param.name; });

}  // namespace
}  // namespace palpate::fault
