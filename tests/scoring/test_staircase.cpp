// The staircase of adaptive difficulty (docs/scoring.md, "Staircase"): moves worked by hand (two
// passes one step harder, one fail one step easier, the clamps, the reversals and the estimate),
// its JSON state round trip and malformed states, the exercise at a level, the trial decision from
// metric names; and a simulated observer with a known psychometric function, whose 70.7 % point
// a 2-down-1-up staircase must find (Levitt 1971).
#include "engine/scoring/Staircase.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <random>

namespace palpate {
namespace {

StaircaseDef contrastDef() {
    StaircaseDef d;
    d.parameter = StaircaseDef::Parameter::Contrast;
    d.start = 4.0;
    d.step = 0.5;
    d.easiest = 6.0;
    d.hardest = 1.2;
    d.down = 2;
    d.up = 1;
    return d;
}

TEST(Staircase, TwoPassesOneStepHarderOneFailOneStepEasier) {
    Staircase s(contrastDef());
    EXPECT_DOUBLE_EQ(s.level(), 4.0);
    s.record(true);
    EXPECT_DOUBLE_EQ(s.level(), 4.0);  // one pass is not enough
    EXPECT_EQ(s.consecutivePasses(), 1);
    s.record(true);
    EXPECT_DOUBLE_EQ(s.level(), 3.5);  // contrast: harder is lower
    EXPECT_EQ(s.consecutivePasses(), 0);
    EXPECT_TRUE(s.reversals().empty());
    s.record(false);
    EXPECT_DOUBLE_EQ(s.level(), 4.0);
    ASSERT_EQ(s.reversals().size(), 1u);  // harder, then easier: turned at 3.5
    EXPECT_DOUBLE_EQ(s.reversals()[0], 3.5);
    s.record(true);
    s.record(false);  // a pass then a fail: easier again, no turn
    EXPECT_DOUBLE_EQ(s.level(), 4.5);
    EXPECT_EQ(s.reversals().size(), 1u);
    s.record(true);
    s.record(true);
    EXPECT_DOUBLE_EQ(s.level(), 4.0);
    ASSERT_EQ(s.reversals().size(), 2u);  // easier, then harder: turned at 4.5
    EXPECT_DOUBLE_EQ(s.reversals()[1], 4.5);
    EXPECT_DOUBLE_EQ(*s.thresholdEstimate(), (3.5 + 4.5) / 2.0);
    EXPECT_DOUBLE_EQ(*s.thresholdEstimate(1), 4.5);
    ASSERT_EQ(s.history().size(), 7u);
    const double levels[] = {4.0, 4.0, 3.5, 4.0, 4.0, 4.5, 4.5};
    const bool passed[] = {true, true, false, true, false, true, true};
    for (std::size_t i = 0; i < 7; ++i) {
        EXPECT_DOUBLE_EQ(s.history()[i].level, levels[i]) << i;
        EXPECT_EQ(s.history()[i].passed, passed[i]) << i;
    }
}

TEST(Staircase, EstimateAveragesTheLastSixReversals) {
    StaircaseDef d = contrastDef();
    d.down = 1;  // 1-down-1-up: every trial moves, so pass/fail alternation turns every time
    Staircase s(d);
    EXPECT_FALSE(s.thresholdEstimate());
    // pass 4 -> 3.5, fail -> 4 (turn at 3.5), pass -> 3.5 (turn at 4), ... eight turns.
    for (int i = 0; i < 9; ++i) s.record(i % 2 == 0);
    ASSERT_EQ(s.reversals().size(), 8u);
    // Turns alternate 3.5, 4, 3.5, ...: the last six are three of each.
    EXPECT_DOUBLE_EQ(*s.thresholdEstimate(), 3.75);
    EXPECT_DOUBLE_EQ(*s.thresholdEstimate(3), (4.0 + 3.5 + 4.0) / 3.0);
}

TEST(Staircase, ClampsAtTheHardestAndTheEasiest) {
    StaircaseDef d = contrastDef();
    d.start = 1.5;
    Staircase s(d);
    s.record(true);
    s.record(true);
    EXPECT_DOUBLE_EQ(s.level(), 1.2);  // 1.0 would be past the hardest
    s.record(true);
    s.record(true);
    EXPECT_DOUBLE_EQ(s.level(), 1.2);
    s.record(false);
    EXPECT_DOUBLE_EQ(s.level(), 1.7);
    EXPECT_EQ(s.reversals().size(), 1u);

    d.start = 5.8;
    Staircase e(d);
    e.record(false);
    EXPECT_DOUBLE_EQ(e.level(), 6.0);
    e.record(false);
    EXPECT_DOUBLE_EQ(e.level(), 6.0);
    EXPECT_TRUE(e.reversals().empty());  // easier twice: no turn
}

TEST(Staircase, DepthIsHarderDeeper) {
    StaircaseDef d;
    d.parameter = StaircaseDef::Parameter::DepthMm;
    d.start = 2.0;
    d.step = 1.0;
    d.easiest = 1.0;  // shallow is easy
    d.hardest = 8.0;
    d.down = 3;
    d.up = 2;
    Staircase s(d);
    s.record(true);
    s.record(true);
    EXPECT_DOUBLE_EQ(s.level(), 2.0);
    s.record(true);
    EXPECT_DOUBLE_EQ(s.level(), 3.0);  // three passes: one step deeper
    s.record(false);
    EXPECT_DOUBLE_EQ(s.level(), 3.0);  // up = 2: one fail is not enough
    s.record(false);
    EXPECT_DOUBLE_EQ(s.level(), 2.0);
    s.record(false);
    s.record(false);
    EXPECT_DOUBLE_EQ(s.level(), 1.0);
    s.record(false);
    s.record(false);
    EXPECT_DOUBLE_EQ(s.level(), 1.0);  // clamped at the easiest (shallowest)
}

TEST(Staircase, InvalidDefinitionsNameTheKey) {
    StaircaseDef d = contrastDef();
    d.step = 0.0;
    EXPECT_NE(staircaseDefProblem(d).find("staircase.step"), std::string::npos);
    EXPECT_THROW(Staircase{d}, std::invalid_argument);
    d = contrastDef();
    d.hardest = d.easiest;
    EXPECT_NE(staircaseDefProblem(d).find("staircase.hardest"), std::string::npos);
    d = contrastDef();
    d.start = 7.0;
    EXPECT_NE(staircaseDefProblem(d).find("staircase.start"), std::string::npos);
    d = contrastDef();
    d.up = 0;
    EXPECT_NE(staircaseDefProblem(d).find("staircase.up"), std::string::npos);
    EXPECT_EQ(staircaseDefProblem(contrastDef()), "");
}

TEST(Staircase, JsonRoundTrip) {
    Staircase s(contrastDef());
    for (bool p : {true, true, false, true}) s.record(p);
    std::string error;
    const auto back = Staircase::fromJson(s.toJson(), error);
    ASSERT_TRUE(back) << error;
    EXPECT_DOUBLE_EQ(back->level(), s.level());
    EXPECT_EQ(back->consecutivePasses(), 1);
    EXPECT_EQ(back->history().size(), 4u);
    EXPECT_EQ(back->reversals(), s.reversals());
    EXPECT_EQ(back->def().parameter, StaircaseDef::Parameter::Contrast);
    EXPECT_DOUBLE_EQ(back->def().hardest, 1.2);
    // It goes on as the original would: one more pass is the second in a row.
    Staircase copy = *back;
    copy.record(true);
    s.record(true);
    EXPECT_DOUBLE_EQ(copy.level(), s.level());
    EXPECT_DOUBLE_EQ(copy.level(), 3.5);
    EXPECT_EQ(copy.toJson(), s.toJson());
}

TEST(Staircase, MalformedJsonNamesTheProblem) {
    Staircase s(contrastDef());
    s.record(true);
    const nlohmann::json good = nlohmann::json::parse(s.toJson());
    std::string error;
    auto expectError = [&](const std::string& text, const std::string& part) {
        EXPECT_FALSE(Staircase::fromJson(text, error)) << text;
        EXPECT_NE(error.find(part), std::string::npos) << "error: " << error << "\nwanted: " << part;
    };
    expectError("{not json", "not JSON");
    expectError("[1, 2]", "not a JSON object");
    auto with = [&](const std::string& key, const nlohmann::json& value) {
        nlohmann::json j = good;
        if (value.is_discarded()) j.erase(key);
        else j[key] = value;
        return j.dump();
    };
    expectError(with("format", "other"), "format");
    expectError(with("version", 9), "version: 9 is not supported");
    expectError(with("parameter", "colour"), "parameter: 'colour'");
    expectError(with("step", -1), "staircase.step");
    expectError(with("level", 9.0), "level: 9");
    expectError(with("level", "high"), "level: must be a number");
    expectError(with("consecutive_passes", 2), "consecutive_passes");
    expectError(with("history", nlohmann::json::array({nlohmann::json{{"level", 4}}})), "history[0]");
    expectError(with("reversals", nlohmann::json::array({1.0, 2.0})), "more reversals (2) than trials (1)");
    expectError(with("down", nlohmann::json(nlohmann::json::value_t::discarded)), "down: missing");
    expectError(with("extra", 1), "extra: unknown key");
}

TEST(Staircase, ExerciseAtLevelSetsEveryLump) {
    Exercise e;
    e.type = ExerciseType::DetectLumps;
    e.detectLumps.lumps.resize(3);
    e.detectLumps.staircase = contrastDef();
    const Exercise c = exerciseAtLevel(e, 2.5);
    for (const LumpDef& l : c.detectLumps.lumps) {
        EXPECT_DOUBLE_EQ(l.contrast, 2.5);
        EXPECT_DOUBLE_EQ(l.depthMm, LumpDef{}.depthMm);
    }
    e.detectLumps.staircase->parameter = StaircaseDef::Parameter::DepthMm;
    const Exercise d = exerciseAtLevel(e, 7.0);
    for (const LumpDef& l : d.detectLumps.lumps) {
        EXPECT_DOUBLE_EQ(l.depthMm, 7.0);
        EXPECT_DOUBLE_EQ(l.contrast, LumpDef{}.contrast);
    }
    EXPECT_DOUBLE_EQ(e.detectLumps.lumps[0].depthMm, LumpDef{}.depthMm);  // the input is unchanged
}

TEST(Staircase, TrialPassesWithEveryLumpFoundAndNoFalseAlarm) {
    EXPECT_EQ(staircaseTrialPassed(MetricValues{{"sensitivity", 1.0}, {"false_alarms", 0.0}}), true);
    EXPECT_EQ(staircaseTrialPassed(MetricValues{{"sensitivity", 0.5}, {"false_alarms", 0.0}}), false);
    EXPECT_EQ(staircaseTrialPassed(MetricValues{{"sensitivity", 1.0}, {"false_alarms", 1.0}}), false);
    // Without both metrics (another exercise type, or not measured) it is not a trial.
    EXPECT_EQ(staircaseTrialPassed(MetricValues{{"completion", 1.0}}), std::nullopt);
    EXPECT_EQ(staircaseTrialPassed(MetricValues{{"sensitivity", 1.0}}), std::nullopt);
    EXPECT_EQ(staircaseTrialPassed(MetricValues{{"sensitivity", std::nullopt}, {"false_alarms", 0.0}}), std::nullopt);
    ScoreReport r;
    r.type = ExerciseType::DetectLumps;
    MetricResult s;
    s.metric = Metric::Sensitivity;
    s.value = 1.0;
    MetricResult f;
    f.metric = Metric::FalseAlarms;
    f.value = 0.0;
    r.metrics = {s, f};
    EXPECT_EQ(staircaseTrialPassed(r), true);
    r.metrics[1].value = 2.0;
    EXPECT_EQ(staircaseTrialPassed(r), false);
    r.metrics.pop_back();
    EXPECT_EQ(staircaseTrialPassed(r), std::nullopt);
}

/// A trainee whose chance of passing a trial at contrast c is logistic around `midpoint` with
/// spread `spread`: P(c) = 1 / (1 + exp(-(c - midpoint) / spread)).
double runObserver(const StaircaseDef& def, double midpoint, double spread, unsigned seed, int trials) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    Staircase s(def);
    for (int i = 0; i < trials; ++i) {
        const double p = 1.0 / (1.0 + std::exp(-(s.level() - midpoint) / spread));
        s.record(uniform(rng) < p);
    }
    return s.thresholdEstimate().value_or(std::nan(""));
}

// 2-down-1-up moves harder and easier equally often where P(pass)^2 = 1/2, P = 0.7071: contrast
// c = midpoint + spread * ln(P / (1 - P)) = 3 + 0.3 * ln(2.41421) = 3 + 0.3 * 0.88137 = 3.2644.
// The estimate, averaged over 20 seeds of 200 trials, lies within one step (0.1) of it; 1-down-1-up
// finds the 50 % point (3.0) instead, which is more than a step away.
TEST(Staircase, SimulatedObserverConvergesOnThe707Point) {
    StaircaseDef d = contrastDef();
    d.start = 5.0;
    d.step = 0.1;
    const double midpoint = 3.0, spread = 0.3;
    const double target707 = midpoint + spread * std::log(std::sqrt(0.5) / (1.0 - std::sqrt(0.5)));
    EXPECT_NEAR(target707, 3.2644, 1e-4);
    auto mean = [&](const StaircaseDef& def) {
        double sum = 0.0;
        for (unsigned seed = 1; seed <= 20; ++seed) {
            const double estimate = runObserver(def, midpoint, spread, seed, 200);
            EXPECT_TRUE(std::isfinite(estimate)) << seed;
            sum += estimate;
        }
        return sum / 20.0;
    };
    const double twoDown = mean(d);
    EXPECT_NEAR(twoDown, target707, 0.1);
    d.down = 1;
    const double oneDown = mean(d);
    EXPECT_NEAR(oneDown, midpoint, 0.1);
    EXPECT_GT(twoDown - oneDown, 0.1);
}

}  // namespace
}  // namespace palpate
