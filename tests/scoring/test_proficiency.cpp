// The proficiency standard from experts' sessions (docs/scoring.md, "Proficiency"), with numbers
// worked by hand: mean, sample SD and the mark two SD to the worse side, the direction from the
// rubric, unweighted metrics shown but not deciding, too few experts, and when two passing
// sessions in a row make a trainee proficient.
#include "engine/scoring/Proficiency.h"

#include <gtest/gtest.h>

#include <cmath>

namespace palpate {
namespace {

// A trace exercise graded on completion (higher is better), the path distance (lower is better)
// and, with no weight, the peak force (lower is better).
Exercise traceExercise() {
    Exercise e;
    e.name = "Trace the line";
    e.type = ExerciseType::Trace;
    e.rubric[std::size_t(Metric::Completion)] = RubricItem{3.0, 1.0, 0.0};
    e.rubric[std::size_t(Metric::PathDistanceMm)] = RubricItem{1.0, 1.0, 5.0};
    e.rubric[std::size_t(Metric::PeakForceN)] = RubricItem{0.0, 1.0, 3.0};
    return e;
}

MetricValues values(std::optional<double> completion, std::optional<double> distance, std::optional<double> peak) {
    return {{"completion", completion}, {"path_distance_mm", distance}, {"peak_force_n", peak}};
}

std::vector<MetricValues> experts() {
    // completion 1, 1, 1: mean 1, SD 0, mark 1.
    // path distance 1, 2, 3: mean 2, SD sqrt((1 + 0 + 1) / 2) = 1, mark 2 + 2 * 1 = 4 (at most).
    // peak force 2, 4, 6: mean 4, SD sqrt((4 + 0 + 4) / 2) = 2, mark 4 + 2 * 2 = 8, not deciding.
    return {values(1, 1, 2), values(1, 2, 4), values(1, 3, 6)};
}

TEST(Proficiency, StandardIsExpertMeanTwoSdToTheWorseSide) {
    const ProficiencyStandard s = buildProficiencyStandard(traceExercise(), experts());
    ASSERT_TRUE(s.valid()) << s.problem;
    EXPECT_EQ(s.expertSessions, 3u);
    ASSERT_EQ(s.metrics.size(), 3u);  // only what the experts measured
    const MetricStandard* completion = s.find("completion");
    ASSERT_TRUE(completion);
    EXPECT_DOUBLE_EQ(completion->mean, 1.0);
    EXPECT_DOUBLE_EQ(completion->sd, 0.0);
    EXPECT_DOUBLE_EQ(completion->passMark, 1.0);
    EXPECT_TRUE(completion->higherIsBetter);
    EXPECT_TRUE(completion->deciding);
    const MetricStandard* distance = s.find("path_distance_mm");
    ASSERT_TRUE(distance);
    EXPECT_DOUBLE_EQ(distance->mean, 2.0);
    EXPECT_DOUBLE_EQ(distance->sd, 1.0);
    EXPECT_DOUBLE_EQ(distance->passMark, 4.0);
    EXPECT_FALSE(distance->higherIsBetter);
    EXPECT_TRUE(distance->deciding);
    const MetricStandard* peak = s.find("peak_force_n");
    ASSERT_TRUE(peak);
    EXPECT_DOUBLE_EQ(peak->mean, 4.0);
    EXPECT_DOUBLE_EQ(peak->sd, 2.0);
    EXPECT_DOUBLE_EQ(peak->passMark, 8.0);
    EXPECT_FALSE(peak->deciding);  // zero weight: shown, does not decide
    EXPECT_FALSE(s.find("time_s"));
}

TEST(Proficiency, HigherIsBetterMarkIsBelowTheMean) {
    Exercise e = traceExercise();
    e.rubric[std::size_t(Metric::BandFraction)] = RubricItem{2.0, 0.9, 0.2};
    std::vector<MetricValues> ex = experts();
    // band fraction 0.8, 0.9, 1.0: mean 0.9, SD 0.1, mark 0.9 - 0.2 = 0.7.
    ex[0]["band_fraction"] = 0.8;
    ex[1]["band_fraction"] = 0.9;
    ex[2]["band_fraction"] = 1.0;
    const ProficiencyStandard s = buildProficiencyStandard(e, ex);
    const MetricStandard* band = s.find("band_fraction");
    ASSERT_TRUE(band);
    EXPECT_NEAR(band->sd, 0.1, 1e-12);
    EXPECT_NEAR(band->passMark, 0.7, 1e-12);
    EXPECT_TRUE(band->passes(0.71));
    EXPECT_FALSE(band->passes(0.69));
}

TEST(Proficiency, TooFewExpertsIsNoStandard) {
    const ProficiencyStandard none = buildProficiencyStandard(traceExercise(), {});
    EXPECT_FALSE(none.valid());
    EXPECT_NE(none.problem.find("0 expert sessions"), std::string::npos) << none.problem;
    const ProficiencyStandard one = buildProficiencyStandard(traceExercise(), {values(1, 2, 3)});
    EXPECT_FALSE(one.valid());
    EXPECT_NE(one.problem.find("1 expert session of 'Trace the line', at least 2 needed"), std::string::npos)
        << one.problem;
    EXPECT_TRUE(judgeSessions(one, {values(1, 1, 1)}).sessions.empty());
    // A weighted metric only one expert measured cannot decide.
    std::vector<MetricValues> ex = experts();
    ex[1]["path_distance_mm"] = std::nullopt;
    ex[2]["path_distance_mm"] = std::nullopt;
    const ProficiencyStandard s = buildProficiencyStandard(traceExercise(), ex);
    ASSERT_TRUE(s.valid());
    EXPECT_FALSE(s.find("path_distance_mm")->deciding);
    EXPECT_EQ(s.find("path_distance_mm")->expertSessions, 1u);
}

TEST(Proficiency, ProficientAfterTwoPassingSessionsInARow) {
    const ProficiencyStandard s = buildProficiencyStandard(traceExercise(), experts());
    const std::vector<MetricValues> sessions = {
        values(1, 4.5, 9),           // 1: distance above its mark 4: fails
        values(1, 4.0, 10),          // 2: at the mark passes; the peak force fails but does not decide
        values(0.5, 1.0, 2),         // 3: completion below 1: fails
        values(1, 3.0, 2),           // 4: passes
        values(1, 2.0, 2),           // 5: passes: the second in a row, proficient
        values(1, std::nullopt, 2),  // 6: the deciding distance not measured: fails
    };
    const ProficiencyProgress p = judgeSessions(s, sessions);
    ASSERT_EQ(p.sessions.size(), 6u);
    const bool passed[] = {false, true, false, true, true, false};
    const int inARow[] = {0, 1, 0, 1, 2, 0};
    for (std::size_t i = 0; i < 6; ++i) {
        EXPECT_EQ(p.sessions[i].passed, passed[i]) << "session " << i + 1;
        EXPECT_EQ(p.sessions[i].consecutivePasses, inARow[i]) << "session " << i + 1;
    }
    ASSERT_TRUE(p.proficientAt);
    EXPECT_EQ(*p.proficientAt, 4u);  // the fifth session, after the fourth
    EXPECT_TRUE(p.proficient());
    EXPECT_EQ(p.consecutivePasses(), 0);
    // Per metric of session 2: distance passed, peak force failed.
    const auto& m = p.sessions[1].metrics;
    ASSERT_EQ(m.size(), 3u);
    for (const auto& [name, ok] : m) {
        if (name == "peak_force_n") EXPECT_EQ(ok, false);
        else EXPECT_EQ(ok, true) << name;
    }
    for (const auto& [name, ok] : p.sessions[5].metrics)
        if (name == "path_distance_mm") {
            EXPECT_EQ(ok, std::nullopt);
        }
    // Passes that are not in a row do not make a trainee proficient.
    const ProficiencyProgress q = judgeSessions(s, {sessions[1], sessions[0], sessions[3]});
    EXPECT_FALSE(q.proficient());
    EXPECT_EQ(q.consecutivePasses(), 1);
}

}  // namespace
}  // namespace palpate
