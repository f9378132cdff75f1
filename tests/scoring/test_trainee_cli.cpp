// palpate-cli trainee and score --db --trainee (docs/scoring.md, "Proficiency"): sessions of the
// shipped press-targets exercise (good and bad scripted paths) stored for an instructor (expert)
// and a trainee; the learning curve's standard, verdicts and the session that made the trainee
// proficient; the PNG; the proficiency object of `score --json`; errors that name the thing.
#include "tests/record/RecordTestRig.h"
#include "tests/scoring/ScoringTestRig.h"

#include <QColor>
#include <QImage>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace palpate {
namespace {

using test::runCli;
using test::shellQuote;

std::string exampleFile(const std::string& name) { return test::resourcesDir() + "/exercises/" + name; }

std::string recordExample(test::TempDir& dir, const std::string& name, const std::string& quality) {
    const std::string path = dir.file(name + "." + quality + ".palprec");
    // Run to the time limit: an incomplete session is then timed up, a scored attempt (a stopped
    // one is kept but is not a score, and the curve leaves it out).
    const Exercise exercise = test::loadExampleExercise(name);
    test::SessionRunDef def;
    def.seconds = exercise.timeLimitS + 0.5;
    test::runScriptedSession(exercise, test::loadTraineeScript(exampleFile(name + "." + quality + ".path")), path, def);
    return path;
}

TEST(TraineeCli, CurveStandardProficiencyPngAndErrors) {
    test::TempDir dir;
    const std::string bad = recordExample(dir, "press_targets", "bad");
    const std::string good = recordExample(dir, "press_targets", "good");
    const std::string exercise = shellQuote(exampleFile("press_targets.json"));
    const std::string db = shellQuote(dir.file("results.sqlite"));
    auto add = [&](const std::string& trainee, const std::string& recording, bool expert) {
        const auto r = runCli("trainee add-session --db " + db + " --trainee " + trainee + " --recording " +
                              shellQuote(recording) + " --exercise " + exercise + (expert ? " --expert" : "") +
                              " --json");
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_EQ(nlohmann::json::parse(r.output)["expert"].get<bool>(), expert);
    };
    add("Ida", good, true);
    add("Ida", good, true);
    // Bo: bad (recorded first), then good twice.
    add("Bo", bad, false);
    add("Bo", good, false);
    add("Bo", good, false);

    auto r = runCli("trainee list --db " + db + " --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto j = nlohmann::json::parse(r.output);
    ASSERT_EQ(j["trainees"].size(), 2u);
    EXPECT_EQ(j["trainees"][0]["name"], "Bo");
    EXPECT_EQ(j["trainees"][0]["sessions"], 3);
    EXPECT_EQ(j["trainees"][1]["expert_sessions"], 2);

    const std::string png = dir.file("curve.png");
    r = runCli("trainee curve --db " + db + " --trainee Bo --exercise " + exercise + " --png " + shellQuote(png) +
               " --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    j = nlohmann::json::parse(r.output);
    // Two identical expert sessions: completion mean 1, SD 0, mark 1 (higher is better); the time
    // is lower-is-better (its rubric line has full marks below zero marks).
    const auto& completion = j["standard"]["completion"];
    EXPECT_DOUBLE_EQ(completion["mean"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(completion["sd"].get<double>(), 0.0);
    EXPECT_DOUBLE_EQ(completion["pass_mark"].get<double>(), 1.0);
    EXPECT_TRUE(completion["higher_is_better"].get<bool>());
    EXPECT_TRUE(completion["deciding"].get<bool>());
    EXPECT_FALSE(j["standard"]["time_s"]["higher_is_better"].get<bool>());
    ASSERT_EQ(j["sessions"].size(), 3u);
    EXPECT_FALSE(j["sessions"][0]["passed"].get<bool>());  // the bad path does not complete
    EXPECT_FALSE(j["sessions"][0]["metric_passed"]["completion"].get<bool>());
    EXPECT_TRUE(j["sessions"][1]["passed"].get<bool>());   // the experts' own path
    EXPECT_TRUE(j["sessions"][2]["passed"].get<bool>());
    EXPECT_EQ(j["sessions"][2]["consecutive_passes"], 2);
    EXPECT_TRUE(j["proficient"].get<bool>());
    EXPECT_EQ(j["proficient_at_session"], 3);  // sessions 2 and 3

    // The PNG: the default size, with more than the white page on it.
    QImage image(QString::fromStdString(png));
    ASSERT_FALSE(image.isNull()) << png;
    EXPECT_EQ(image.width(), 1200);
    EXPECT_EQ(image.height(), 800);
    int coloured = 0;
    for (int y = 0; y < image.height(); y += 4)
        for (int x = 0; x < image.width(); x += 4)
            if (QColor(image.pixel(x, y)).saturation() > 15) ++coloured;
    EXPECT_GT(coloured, 500);  // the shaded bands, the lines and the points

    // --metric narrows the curve; a wrong name is named.
    r = runCli("trainee curve --db " + db + " --trainee Bo --exercise " + exercise + " --metric completion --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(nlohmann::json::parse(r.output)["sessions"][0]["metrics"].size(), 1u);
    r = runCli("trainee curve --db " + db + " --trainee Bo --exercise " + exercise + " --metric speed");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("speed"), std::string::npos) << r.output;

    // score --db --trainee: Bo's two passing sessions and this one make three in a row.
    r = runCli("score --recording " + shellQuote(good) + " --exercise " + exercise + " --db " + db +
               " --trainee Bo --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    j = nlohmann::json::parse(r.output);
    ASSERT_TRUE(j.contains("proficiency")) << r.output;
    EXPECT_TRUE(j["proficiency"]["passed"].get<bool>());
    EXPECT_EQ(j["proficiency"]["consecutive_passes"], 3);
    EXPECT_TRUE(j["proficiency"]["proficient"].get<bool>());
    EXPECT_TRUE(j["proficiency"]["metrics"]["completion"].get<bool>());
    EXPECT_DOUBLE_EQ(j["proficiency"]["standard"]["completion"]["pass_mark"].get<double>(), 1.0);
    r = runCli("score --recording " + shellQuote(bad) + " --exercise " + exercise + " --db " + db +
               " --trainee Bo --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    j = nlohmann::json::parse(r.output);
    EXPECT_FALSE(j["proficiency"]["passed"].get<bool>());
    EXPECT_EQ(j["proficiency"]["consecutive_passes"], 0);
    EXPECT_TRUE(j["proficiency"]["proficient"].get<bool>());  // reached before, kept

    // Errors name the thing.
    r = runCli("trainee curve --db " + db + " --trainee Zed --exercise " + exercise);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("no trainee 'Zed'"), std::string::npos) << r.output;
    r = runCli("trainee curve --db " + db + " --trainee Bo --exercise " + shellQuote(exampleFile("trace.json")));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("no scored sessions of"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("trace.json"), std::string::npos) << r.output;
    const std::string garbage = dir.file("garbage.sqlite");
    test::writeBytes(garbage, std::vector<std::uint8_t>(4096, 'x'));
    r = runCli("trainee list --db " + shellQuote(garbage));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("garbage.sqlite"), std::string::npos) << r.output;
    EXPECT_EQ(test::readBytes(garbage).size(), 4096u);  // left as it was
    // score --trainee stores: a new trainee is added, with nothing earlier to judge against.
    r = runCli("score --recording " + shellQuote(good) + " --db " + db + " --trainee Zed --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    j = nlohmann::json::parse(r.output);
    EXPECT_FALSE(j.contains("proficiency")) << r.output;
    EXPECT_EQ(j["stored"]["trainee"], "Zed");
    r = runCli("trainee curve --db " + db + " --trainee Zed --exercise " + exercise + " --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(nlohmann::json::parse(r.output)["sessions"].size(), 1u);
    r = runCli("trainee staircase --db " + db + " --trainee Bo --exercise " + exercise);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("has no staircase"), std::string::npos) << r.output;
    // The chart is never written over its database.
    const auto before = test::readBytes(dir.file("results.sqlite"));
    r = runCli("trainee curve --db " + db + " --trainee Bo --exercise " + exercise + " --png " + db);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("results database"), std::string::npos) << r.output;
    EXPECT_EQ(test::readBytes(dir.file("results.sqlite")), before);
    EXPECT_EQ(runCli("trainee").exitCode, 2);
    EXPECT_EQ(runCli("trainee frobnicate").exitCode, 2);
    EXPECT_EQ(runCli("trainee curve --db " + db + " --exercise " + exercise).exitCode, 2);
}

// Without expert sessions of the exercise the score has no proficiency object, and the curve says
// there is no standard and why.
TEST(TraineeCli, NoExpertsNoStandard) {
    test::TempDir dir;
    const std::string good = recordExample(dir, "press_targets", "good");
    const std::string exercise = shellQuote(exampleFile("press_targets.json"));
    const std::string db = shellQuote(dir.file("results.sqlite"));
    ASSERT_EQ(runCli("trainee add-session --db " + db + " --trainee Bo --recording " + shellQuote(good) +
                     " --exercise " + exercise).exitCode, 0);
    auto r = runCli("score --recording " + shellQuote(good) + " --exercise " + exercise + " --db " + db +
                    " --trainee Bo --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_FALSE(nlohmann::json::parse(r.output).contains("proficiency"));
    r = runCli("trainee curve --db " + db + " --trainee Bo --exercise " + exercise + " --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    EXPECT_TRUE(j["standard"].is_null());
    EXPECT_NE(j["no_standard"].get<std::string>().find("0 expert sessions"), std::string::npos);
    EXPECT_FALSE(j["proficient"].get<bool>());
}

}  // namespace
}  // namespace palpate
