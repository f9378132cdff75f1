// palpate-cli's staircase across a trainee's detect-lumps trials (docs/scoring.md, "Staircase"):
// run --level runs the exercise at a level, trainee add-session moves the trainee's staircase by
// the trial's result only when the recording ran at the staircase's level, trainee staircase says
// where it is. Sessions are scripted (stepped) and recorded; the level after each is worked out
// from the 2-down-1-up rule.
#include "engine/exercise/ExerciseFile.h"
#include "engine/scoring/Staircase.h"
#include "tests/record/RecordTestRig.h"
#include "tests/scoring/ScoringTestRig.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
namespace palpate {
namespace {

TEST(StaircaseCli, TrialsMoveTheTraineesStaircaseOnlyAtItsLevel) {
    test::TempDir dir;
    Exercise base = test::loadExampleExercise("detect_lumps");
    base.detectLumps.staircase = StaircaseDef{StaircaseDef::Parameter::Contrast, 5.0, 1.0, 6.0, 2.0, 2, 1};
    base.meshPath = test::resourcesDir() + "/meshes/sphere_8664.off";
    base.tissuePresetPath = test::resourcesDir() + "/presets/tissues/muscle.json";
    const std::string exerciseFile = dir.file("stair.json"), db = dir.file("results.sqlite");
    ASSERT_EQ(saveExercise(base, exerciseFile), "");
    int session = 0;
    // One scripted session at `level`, stored for trainee "ana"; returns the staircase's level after it.
    auto trial = [&](double level, const std::string& quality) {
        const std::string recording = dir.file("s" + std::to_string(++session) + ".palprec");
        test::runScriptedSession(exerciseAtLevel(base, level),
                                 test::loadTraineeScript(test::resourcesDir() + "/exercises/detect_lumps." + quality + ".path"),
                                 recording);
        const auto added = test::runCli("trainee add-session --trainee ana --recording " + test::shellQuote(recording) +
                                        " --exercise " + test::shellQuote(exerciseFile) + " --db " + test::shellQuote(db));
        EXPECT_EQ(added.exitCode, 0) << added.output;
        const auto state = test::runCli("trainee staircase --trainee ana --exercise " + test::shellQuote(exerciseFile) +
                                        " --db " + test::shellQuote(db) + " --json");
        EXPECT_EQ(state.exitCode, 0) << state.output;
        return nlohmann::json::parse(state.output.substr(state.output.find('{')))["level"].get<double>();
    };
    EXPECT_EQ(trial(5.0, "good"), 5.0);   // one pass: 2-down waits for the second
    EXPECT_EQ(trial(5.0, "good"), 4.0);   // two in a row: one step harder (lower contrast)
    EXPECT_EQ(trial(5.0, "good"), 4.0);   // run at the old level: stored, not a trial
    EXPECT_EQ(trial(4.0, "light"), 5.0);  // the deep lump missed: a fail, one step easier
    // run --level refuses a level outside the staircase and an exercise without one.
    EXPECT_EQ(test::runCli("run --exercise " + test::shellQuote(exerciseFile) + " --level 9 --seconds 0.1").exitCode, 1);
    EXPECT_EQ(test::runCli("run --exercise " + test::shellQuote(test::resourcesDir() + "/exercises/no_lump.json") +
                           " --level 3 --seconds 0.1")
                  .exitCode,
              1);
}

}  // namespace
}  // namespace palpate
