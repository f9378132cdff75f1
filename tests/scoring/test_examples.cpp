// The shipped example exercises are achievable: a scripted trainee that does each one well scores
// above 80, one that does it badly below 40, end to end (stepped session recorded with the
// exercise in its note, then replayed and scored from the file).
#include "engine/record/RecordingReader.h"
#include "engine/scoring/ReplayScorer.h"
#include "tests/record/RecordTestRig.h"
#include "tests/scoring/ScoringTestRig.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace palpate {
namespace {

ScoreReport scoreExample(const std::string& name, const std::string& quality, test::TempDir& dir,
                         const test::SessionRunDef& run = {}) {
    const Exercise exercise = test::loadExampleExercise(name);
    const auto script = test::loadTraineeScript(test::resourcesDir() + "/exercises/" + name + "." + quality + ".path");
    const std::string recording = dir.file(name + "." + quality + (run.tickOverran ? ".late" : "") + ".palprec");
    test::runScriptedSession(exercise, script, recording, run);
    const RecordingReader reader = RecordingReader::open(recording);
    std::string error;
    ReplayScorerDef options;
    options.findResource = test::testResourceFinder();
    const ScoreReport report = scoreRecording(reader, &exercise, error, options);
    EXPECT_EQ(error, "");
    std::printf("[ figures  ] %s, %s trainee: score %.1f\n%s", name.c_str(), quality.c_str(), report.score,
                scoreReportToText(report).c_str());
    for (const std::string& w : report.warnings) ADD_FAILURE() << name << "." << quality << ": warning: " << w;
    return report;
}

class Examples : public ::testing::TestWithParam<const char*> {};

TEST_P(Examples, GoodTraineeScoresAbove80AndBadBelow40) {
    test::TempDir dir;
    const ScoreReport good = scoreExample(GetParam(), "good", dir);
    const ScoreReport bad = scoreExample(GetParam(), "bad", dir);
    EXPECT_TRUE(good.guidance.completed);
    EXPECT_GT(good.score, 80.0);
    EXPECT_LT(bad.score, 40.0);
}

// A loaded machine makes ticks late: a third of them, and bursts of 40 in a row. The good trainee's
// score must not depend on it (a late tick keeps its force, docs/devices.md).
TEST_P(Examples, TheScoreDoesNotDependOnLateTicks) {
    test::TempDir dir;
    const ScoreReport onTime = scoreExample(GetParam(), "good", dir);
    test::SessionRunDef loaded;
    loaded.tickOverran = [](std::uint64_t tick) { return tick % 3 == 0 || tick % 500 < 40; };
    const ScoreReport late = scoreExample(GetParam(), "good", dir, loaded);
    EXPECT_TRUE(late.guidance.completed);
    EXPECT_NEAR(late.score, onTime.score, 1.0) << "on time " << onTime.score << ", with late ticks " << late.score;
}

INSTANTIATE_TEST_SUITE_P(Shipped, Examples, ::testing::Values("press_targets", "find_lump", "trace"));

}  // namespace
}  // namespace palpate
