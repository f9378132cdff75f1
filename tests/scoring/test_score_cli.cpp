// palpate-cli score (and run --exercise): the breakdown as text and JSON, the recorded exercise
// used when none is given, errors that name the problem; and a recording with gaps scored on what
// is there, with a warning.
#include "engine/record/RecordingReader.h"
#include "engine/scoring/ReplayScorer.h"
#include "tests/record/RecordTestRig.h"
#include "tests/scoring/ScoringTestRig.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace palpate {
namespace {

using test::runCli;
using test::shellQuote;

std::string exampleFile(const std::string& name) { return test::resourcesDir() + "/exercises/" + name; }

std::string recordExample(test::TempDir& dir, const std::string& name, const std::string& quality) {
    const std::string path = dir.file(name + "." + quality + ".palprec");
    test::runScriptedSession(test::loadExampleExercise(name),
                             test::loadTraineeScript(exampleFile(name + "." + quality + ".path")), path);
    return path;
}

TEST(ScoreCli, JsonHasScoreMetricsAndRubric) {
    test::TempDir dir;
    const std::string recording = recordExample(dir, "press_targets", "good");
    const auto result = runCli("score --exercise " + shellQuote(exampleFile("press_targets.json")) + " --recording " +
                               shellQuote(recording) + " --json");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const auto j = nlohmann::json::parse(result.output);
    ASSERT_TRUE(j.contains("score") && j.contains("metrics") && j.contains("rubric"));
    // The same numbers as scoring in process.
    const Exercise exercise = test::loadExampleExercise("press_targets");
    std::string error;
    ReplayScorerDef options;
    options.findResource = test::testResourceFinder();
    const ScoreReport report = scoreRecording(RecordingReader::open(recording), &exercise, error, options);
    EXPECT_DOUBLE_EQ(j["score"].get<double>(), report.score);
    for (const MetricResult& m : report.metrics) {
        const std::string name(metricName(m.metric));
        ASSERT_TRUE(j["metrics"].contains(name)) << name;
        EXPECT_DOUBLE_EQ(j["metrics"][name].get<double>(), m.value) << name;
        EXPECT_DOUBLE_EQ(j["rubric"][name]["weight"].get<double>(), m.weight) << name;
        EXPECT_DOUBLE_EQ(j["rubric"][name]["contribution"].get<double>(), m.contribution) << name;
        EXPECT_DOUBLE_EQ(j["rubric"][name]["sub_score"].get<double>(), m.subScore) << name;
    }
    EXPECT_GT(j["score"].get<double>(), 80.0);
    EXPECT_EQ(j["targets"].size(), 3u);

    // Text, and the exercise taken from the recording when none is given.
    const auto text = runCli("score " + shellQuote(recording));
    ASSERT_EQ(text.exitCode, 0) << text.output;
    EXPECT_NE(text.output.find("Press three targets (press_targets): score"), std::string::npos) << text.output;
    EXPECT_NE(text.output.find("hold_in_window_fraction"), std::string::npos);
}

TEST(ScoreCli, ErrorsNameTheProblem) {
    test::TempDir dir;
    const std::string recording = recordExample(dir, "find_lump", "bad");
    // A recording of another mesh.
    auto r = runCli("score --exercise " + shellQuote(exampleFile("trace.json")) + " --recording " + shellQuote(recording));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("was recorded on"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("sphere_1442.off"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("stomach_3970.off"), std::string::npos) << r.output;
    // An exercise with a mistake.
    const std::string bad = dir.file("bad.json");
    {
        auto e = nlohmann::json::parse(test::readBytes(exampleFile("find_lump.json")));
        e["find_lump"]["inclusion"]["radius"] = 3;
        const std::string text = e.dump();
        test::writeBytes(bad, std::vector<std::uint8_t>(text.begin(), text.end()));
    }
    r = runCli("score --exercise " + shellQuote(bad) + " --recording " + shellQuote(recording));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("find_lump.inclusion.radius: unknown key"), std::string::npos) << r.output;
    // A recording without an exercise and none given; no recording at all; usage.
    auto rig = test::makeRecordRig(SimTrajectory::PressHold);
    std::string error;
    const std::string plain = dir.file("plain.palprec");
    {
        auto session = RecordingSession::start(*rig.loop, plain, rig.header, error);
        for (int i = 0; i < 100; ++i) rig.loop->stepOnce();
        session->stop();
    }
    r = runCli("score --recording " + shellQuote(plain));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("does not say which exercise"), std::string::npos) << r.output;
    r = runCli("score --recording " + shellQuote(dir.file("none.palprec")));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("none.palprec"), std::string::npos) << r.output;
    EXPECT_EQ(runCli("score").exitCode, 2);
    EXPECT_EQ(runCli("score --recording a b").exitCode, 2);
}

TEST(ScoreCli, GapsAreScoredOnWhatIsThereWithAWarning) {
    test::TempDir dir;
    const Exercise exercise = test::loadExampleExercise("trace");
    const std::string path = dir.file("gaps.palprec");
    test::SessionRunDef def;
    def.writer.ringCapacityTicks = 512;  // ticks are dropped between the rare flushes
    def.flushEveryTicks = 3000;
    test::runScriptedSession(exercise, test::loadTraineeScript(exampleFile("trace.good.path")), path, def);
    const RecordingReader reader = RecordingReader::open(path);
    ASSERT_GT(reader.summary().gaps, 0u);
    std::string error;
    ReplayScorerDef options;
    options.findResource = test::testResourceFinder();
    const ScoreReport report = scoreRecording(reader, &exercise, error, options);
    EXPECT_EQ(error, "");
    EXPECT_GT(report.ticksScored, 0u);
    EXPECT_LT(report.ticksScored, reader.summary().ticks);
    bool warned = false;
    for (const std::string& w : report.warnings) warned |= w.find("only: gap of") != std::string::npos;
    EXPECT_TRUE(warned) << (report.warnings.empty() ? "no warning" : report.warnings.front());
}

TEST(ScoreCliThreads, RunExerciseRecordsAndScoresLive) {
    test::TempDir dir;
    const std::string recording = dir.file("run.palprec");
    const auto r = runCli("run --exercise " + shellQuote(exampleFile("trace.json")) + " --device " +
                          shellQuote("sim:path:" + exampleFile("trace.good.path")) + " --record " +
                          shellQuote(recording) + " --no-fifo --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    ASSERT_TRUE(j.contains("score")) << r.output;
    EXPECT_TRUE(j["score"]["completed"].get<bool>());
    EXPECT_GT(j["score"]["score"].get<double>(), 80.0);
    EXPECT_LT(j["seconds"].get<double>(), 20.0);  // stopped when the exercise was over
    // The file scores the same afterwards; `record replay` reproduces it (the note's exercise).
    const auto again = runCli("score --recording " + shellQuote(recording) + " --json");
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_EQ(nlohmann::json::parse(again.output)["metrics"], j["score"]["metrics"]);
    EXPECT_EQ(runCli("record replay " + shellQuote(recording)).exitCode, 0);
    // Usage errors.
    EXPECT_EQ(runCli("run --mark-at 3").exitCode, 2);
    EXPECT_EQ(runCli("run --exercise " + shellQuote(exampleFile("trace.json")) + " --mesh x.off").exitCode, 2);
}

// A scripted trainee's path presses its own Mark and Finish ("# mark-at", "# done-at") unless
// the command line gives its own; a malformed button line is named.
TEST(ScoreCliThreads, RunExercisePlaysThePathFilesMarkAndFinish) {
    test::TempDir dir;
    const std::string path = dir.write("trainee.path", "# mark-at 0.8\n# done-at 1.2\n0 8.38 0 89.5\n3 8.38 0 89.5\n");
    const std::string command = "run --exercise " + shellQuote(exampleFile("no_lump.json")) + " --device " +
                                shellQuote("sim:path:" + path) + " --no-fifo --json --overwrite --record " +
                                shellQuote(dir.file("session.palprec"));
    auto jsonOf = [](const std::string& output) { return nlohmann::json::parse(output.substr(output.find('{'))); };
    const auto r = runCli(command);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto j = jsonOf(r.output);
    EXPECT_TRUE(j["score"]["completed"].get<bool>()) << r.output;
    EXPECT_EQ(j["score"]["marks"], 1);
    EXPECT_LT(j["seconds"].get<double>(), 10.0);  // finished at 1.2 s, not at the 150 s limit
    const auto own = runCli(command + " --mark-at 0.3,0.5 --done-at 0.9");
    ASSERT_EQ(own.exitCode, 0) << own.output;
    EXPECT_EQ(jsonOf(own.output)["score"]["marks"], 2);
    const std::string broken = dir.write("broken.path", "0 8.38 0 89.5\n# done-at soon\n");
    const auto bad = runCli("run --exercise " + shellQuote(exampleFile("no_lump.json")) + " --device " +
                            shellQuote("sim:path:" + broken) + " --no-fifo --json");
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.output.find(broken + ":2:"), std::string::npos) << bad.output;
}

}  // namespace
}  // namespace palpate
