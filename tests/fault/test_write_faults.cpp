// Families a and b of docs/reliability.md: every command that writes a file, under a full disk
// (ENOSPC after 0 .. 64 KiB), write errors (EIO), short writes and fsync failure from the shim,
// and under a small RLIMIT_FSIZE; with no previous output and with one to replace.

#include "OutputChecks.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace palpate::fault {
namespace {

const std::vector<WriteFault>& writeFaults() {
    static const std::vector<WriteFault> all{
        {"enospc_after_0", 0, {}, false, false},      {"enospc_after_1", 1, {}, false, false},
        {"enospc_after_100", 100, {}, false, false},  {"enospc_after_4096", 4096, {}, false, false},
        {"enospc_after_65536", 65536, {}, false, false}, {"eio_after_0", {}, 0, false, false},
        {"eio_after_4096", {}, 4096, false, false},  {"short_writes", {}, {}, true, false},
        {"fsync_eio", {}, {}, false, true},
    };
    return all;
}

// The faults also tried with a previous output in place (an atomic replace must keep it).
bool alsoWithPrevious(const WriteFault& f) {
    return f.name == "enospc_after_1" || f.name == "enospc_after_4096" || f.name == "eio_after_0" ||
           f.name == "fsync_eio";
}

struct WriteCase {
    std::string writer;
    WriteFault fault;
    bool withPrevious;
};

std::vector<WriteCase> writeCases() {
    std::vector<WriteCase> cases;
    for (const auto& w : writers())
        for (const auto& f : writeFaults()) {
            cases.push_back({w.name, f, false});
            if (alsoWithPrevious(f)) cases.push_back({w.name, f, true});
        }
    return cases;
}

void PrintTo(const WriteCase& c, std::ostream* os) { *os << c.writer << " " << c.fault.name << (c.withPrevious ? " replacing" : ""); }

class WriteFaults : public testing::TestWithParam<WriteCase> {};

TEST_P(WriteFaults, LeavesNoBrokenFileAndTellsTheTruth) {
    const WriteCase& c = GetParam();
    const Writer& writer = writerNamed(c.writer);
    if (writer.kind == OutputKind::Pdf && !havePdf()) GTEST_SKIP() << "this build has no score --pdf (PALPATE_BUILD_GUI=OFF)";
    Scratch scratch;
    WriterCaseRun run;
    run.writer = &writer;
    run.output = scratch.out(writer.outputName);
    run.context = c.writer + " under " + c.fault.name + (c.withPrevious ? " replacing a previous file" : "");
    baselineOutput(writer);  // built before the faulted run, outside its timing
    const auto inputs = prepareInputs(scratch, writer);
    run.inputsBefore = digests(inputs);
    if (c.withPrevious) {
        copyFile(previousOutputFixture(writer), run.output);
        run.previousDigest = digest(run.output);
    }
    ChildSpec spec = cliSpec(scratch, writerArgs(scratch, writer, run.output));
    applyWriteFault(spec, scratch, c.fault);
    run.result = runChild(spec);

    const auto met = injectedFaults(scratch);
    const bool failingFaultMet = std::any_of(met.begin(), met.end(), [](const std::string& kind) {
        return kind == "enospc" || kind == "eio" || kind == "fsync";
    });
    // A short write is no error (POSIX allows it; the writer writes the rest), so nothing may fail.
    run.expect = failingFaultMet ? Expect::MustFail : c.withPrevious ? Expect::MayFail : Expect::MustSucceed;
    checkWriterRun(scratch, run);
}

std::string writeCaseName(const testing::TestParamInfo<WriteCase>& info) {
    return info.param.writer + "__" + info.param.fault.name + (info.param.withPrevious ? "__replacing" : "__fresh");
}

INSTANTIATE_TEST_SUITE_P(FamilyA, WriteFaults, testing::ValuesIn(writeCases()), writeCaseName);

// Family b: RLIMIT_FSIZE. Past the limit the kernel sends SIGXFSZ (default: death without a word)
// and the write fails with EFBIG; the process must survive it and say which file it could not write.
struct SizeLimitCase {
    std::string writer;
    unsigned long long limitBytes;
};

std::vector<SizeLimitCase> sizeLimitCases() {
    std::vector<SizeLimitCase> cases;
    for (const auto& w : writers())
        for (unsigned long long limit : {1ull, 4096ull, 1ull << 20}) cases.push_back({w.name, limit});
    return cases;
}

void PrintTo(const SizeLimitCase& c, std::ostream* os) { *os << c.writer << " fsize " << c.limitBytes; }

class FileSizeLimit : public testing::TestWithParam<SizeLimitCase> {};

TEST_P(FileSizeLimit, NoSignalAndAMessage) {
    const SizeLimitCase& c = GetParam();
    const Writer& writer = writerNamed(c.writer);
    if (writer.kind == OutputKind::Pdf && !havePdf()) GTEST_SKIP() << "this build has no score --pdf (PALPATE_BUILD_GUI=OFF)";
    Scratch scratch;
    WriterCaseRun run;
    run.writer = &writer;
    run.output = scratch.out(writer.outputName);
    run.context = c.writer + " under RLIMIT_FSIZE " + std::to_string(c.limitBytes);
    const auto baselineBytes = fs::file_size(baselineOutput(writer));
    const auto inputs = prepareInputs(scratch, writer);
    run.inputsBefore = digests(inputs);
    ChildSpec spec = cliSpec(scratch, writerArgs(scratch, writer, run.output));
    spec.fileSizeBytes = c.limitBytes;
    run.result = runChild(spec);
    // A recording's size varies a little from run to run; the limits are far from it.
    run.expect = baselineBytes > c.limitBytes ? Expect::MustFail : Expect::MustSucceed;
    checkWriterRun(scratch, run);
}

std::string sizeLimitName(const testing::TestParamInfo<SizeLimitCase>& info) {
    return info.param.writer + "__fsize_" + std::to_string(info.param.limitBytes);
}

INSTANTIATE_TEST_SUITE_P(FamilyB, FileSizeLimit, testing::ValuesIn(sizeLimitCases()), sizeLimitName);

}  // namespace
}  // namespace palpate::fault
