// Family f of docs/reliability.md: several `run --record` onto one file. A recording being written
// is locked and an existing one is not replaced without an explicit choice, so at most one session
// may succeed, the others must fail naming the file, and the file must be a valid recording of
// the one that succeeded (its note and its tick count), never a mix.

#include "OutputChecks.h"

#include <thread>

#include <gtest/gtest.h>

namespace palpate::fault {
namespace {

struct ConcurrentCase {
    std::string name;
    std::vector<double> startDelaysS;  ///< one writer per entry, started this long after the first
    double sessionS;
};

void PrintTo(const ConcurrentCase& c, std::ostream* os) { *os << c.name; }

const std::vector<ConcurrentCase>& concurrentCases() {
    static const std::vector<ConcurrentCase> all{
        {"two_started_together", {0.0, 0.0}, 0.5},
        {"three_started_together", {0.0, 0.0, 0.0}, 0.5},
        {"second_starts_while_the_first_writes", {0.0, 0.25}, 0.6},
    };
    return all;
}

class ConcurrentWriters : public testing::TestWithParam<ConcurrentCase> {};

TEST_P(ConcurrentWriters, AtMostOneWinsAndTheFileIsItsSession) {
    const ConcurrentCase& c = GetParam();
    Scratch scratch;
    const Writer& writer = writerNamed("run_record");
    const auto inputsBefore = digests(prepareInputs(scratch, writer));
    const fs::path output = scratch.out(writer.outputName);

    std::vector<std::unique_ptr<Child>> children;
    const double t0 = nowS();
    for (std::size_t i = 0; i < c.startDelaysS.size(); ++i) {
        while (nowS() - t0 < c.startDelaysS[i]) std::this_thread::sleep_for(std::chrono::milliseconds(5));
        std::vector<std::string> args = writerArgs(scratch, writer, output);
        args[2] = std::to_string(c.sessionS);  // --seconds
        args.insert(args.end(), {"--note", "session " + std::to_string(i)});
        children.push_back(std::make_unique<Child>(cliSpec(scratch, args)));
    }
    std::vector<ChildResult> results;
    for (auto& child : children) results.push_back(child->wait());

    std::string all;
    int winners = 0;
    std::size_t winner = 0;
    for (std::size_t i = 0; i < results.size(); ++i) {
        all += "\n  session " + std::to_string(i) + ": " + results[i].describe();
        EXPECT_TRUE(results[i].exited) << "session " << i << " must end by itself";
        if (results[i].succeeded()) {
            ++winners;
            winner = i;
        } else {
            EXPECT_TRUE(namesPath(results[i].err, output)) << "session " << i << " must name " << output;
        }
    }
    SCOPED_TRACE(c.name + ":" + all);
    EXPECT_LE(winners, 1) << "two sessions cannot both have recorded into one file";
    for (const auto& [path, before] : inputsBefore) {
        EXPECT_EQ(digest(path), before) << "input changed: " << path;
    }
    if (winners == 1) {
        const RecordingVerdict v = recordInfo(scratch, output);
        ASSERT_TRUE(v.accepted) << "the winner's recording is refused: " << v.problem;
        EXPECT_TRUE(v.intact && v.closedCleanly) << "the winner's recording is damaged or not closed";
        EXPECT_NE(v.note.find("session " + std::to_string(winner)), std::string::npos)
            << "the file holds another session than the one that succeeded: note '" << v.note << "'";
        const auto printed = printedRecordedTicks(results[winner].out + results[winner].err, output);
        if (printed) {
            EXPECT_EQ(v.ticks, *printed) << "the file does not hold the ticks the winner reported";
        }
    } else if (fs::exists(output)) {
        EXPECT_TRUE(recordInfo(scratch, output).accepted) << "no session succeeded, and the file left is refused";
    }
}

INSTANTIATE_TEST_SUITE_P(FamilyF, ConcurrentWriters, testing::ValuesIn(concurrentCases()),
                         [](const testing::TestParamInfo<ConcurrentCase>& info) { return info.param.name; });

}  // namespace
}  // namespace palpate::fault
