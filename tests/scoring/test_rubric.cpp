// The rubric's rules and its edge cases: the sub-score in both directions, weights, a session
// with no time, one without contact, one where all the force is excessive.
#include "engine/exercise/Rubric.h"
#include "engine/scoring/Scorer.h"
#include "tests/scoring/SyntheticTicks.h"
#include "engine/exercise/ExerciseKind.h"

#include <gtest/gtest.h>

#include <cmath>

namespace palpate {
namespace {

using test::kTickS;
using test::sampleAt;

std::shared_ptr<const ExerciseGeometry> place(const Exercise& e) {
    std::string error;
    auto g = ExerciseGeometry::build(e, test::gridMesh(), error);
    EXPECT_EQ(error, "");
    return g;
}

Exercise lumpAt12() {
    Exercise e = test::gridExercise(ExerciseType::FindLump);
    e.findLump.inclusion.centre.vertex = 12;
    e.findLump.inclusion.radiusMm = 10.0;
    return e;
}

TEST(Rubric, SubScoreIsLinearBetweenZeroAndFullEitherWay) {
    const RubricItem higherBetter{1.0, 0.9, 0.3};
    EXPECT_DOUBLE_EQ(subScore(higherBetter, 0.9), 1.0);
    EXPECT_DOUBLE_EQ(subScore(higherBetter, 1.5), 1.0);
    EXPECT_DOUBLE_EQ(subScore(higherBetter, 0.3), 0.0);
    EXPECT_DOUBLE_EQ(subScore(higherBetter, -4.0), 0.0);
    EXPECT_NEAR(subScore(higherBetter, 0.6), 0.5, 1e-15);
    const RubricItem lowerBetter{1.0, 2.0, 10.0};
    EXPECT_DOUBLE_EQ(subScore(lowerBetter, 0.0), 1.0);
    EXPECT_DOUBLE_EQ(subScore(lowerBetter, 6.0), 0.5);
    EXPECT_DOUBLE_EQ(subScore(lowerBetter, 12.0), 0.0);
    EXPECT_DOUBLE_EQ(subScore(lowerBetter, std::nan("")), 0.0);
    EXPECT_DOUBLE_EQ(subScore(lowerBetter, INFINITY), 0.0);
}

TEST(Rubric, DefaultsAreDocumentedOnes) {
    Exercise e = lumpAt12();
    e.timeLimitS = 80.0;
    const Rubric r = effectiveRubric(e);
    double total = 0.0;
    for (std::size_t i = 0; i < kMetricCount; ++i) total += r[i].weight;
    EXPECT_DOUBLE_EQ(total, 100.0);
    EXPECT_DOUBLE_EQ(r[std::size_t(Metric::TimeS)].fullMarks, 40.0);
    EXPECT_DOUBLE_EQ(r[std::size_t(Metric::TimeS)].zeroMarks, 80.0);
    EXPECT_DOUBLE_EQ(r[std::size_t(Metric::LumpErrorMm)].fullMarks, 5.0);
    EXPECT_DOUBLE_EQ(r[std::size_t(Metric::LumpErrorMm)].zeroMarks, 30.0);
    EXPECT_DOUBLE_EQ(r[std::size_t(Metric::HoldInWindowFraction)].weight, 0.0);  // not this type's
    for (ExerciseType t : {ExerciseType::PressTargets, ExerciseType::Trace}) {
        Exercise other = e;
        other.type = t;
        const Rubric o = effectiveRubric(other);
        double sum = 0.0;
        for (std::size_t i = 0; i < kMetricCount; ++i) sum += o[i].weight;
        EXPECT_DOUBLE_EQ(sum, 100.0) << exerciseTypeName(t);
    }
}

TEST(Rubric, ZeroDurationScoresZeroWithAWarning) {
    Scorer scorer(place(lumpAt12()), kTickS);
    const ScoreReport r = scorer.report();
    EXPECT_DOUBLE_EQ(r.score, 0.0);
    EXPECT_EQ(r.ticksScored, 0u);
    ASSERT_FALSE(r.warnings.empty());
    EXPECT_NE(r.warnings.back().find("no tick was scored"), std::string::npos);
    for (const MetricResult& m : r.metrics) {
        EXPECT_TRUE(std::isfinite(m.value)) << metricName(m.metric);
        EXPECT_DOUBLE_EQ(m.contribution, 0.0) << metricName(m.metric);
    }
}

TEST(Rubric, NoContactAtAllScoresZero) {
    Exercise e = test::gridExercise(ExerciseType::PressTargets);
    e.pressTargets.targets.resize(1);
    e.pressTargets.targets[0].at.vertex = 12;
    Scorer scorer(place(e), kTickS);
    for (std::uint64_t t = 1; t <= 1000; ++t) scorer.addSample(sampleAt(t, {20, 20, 5}, 12, false, 0.0f));
    const ScoreReport r = scorer.report();
    EXPECT_DOUBLE_EQ(r.score, 0.0);
    EXPECT_FALSE(r.find(Metric::MeanForceN)->measured);
    EXPECT_FALSE(r.find(Metric::HoldInWindowFraction)->measured);
    EXPECT_FALSE(r.find(Metric::TargetErrorMm)->measured);
    EXPECT_FALSE(r.find(Metric::Economy)->measured);
    EXPECT_DOUBLE_EQ(r.find(Metric::PeakForceN)->value, 0.0);
    EXPECT_DOUBLE_EQ(r.find(Metric::ExcessiveForceFraction)->value, 0.0);
    // Safe because nothing was done earns nothing: every line is 0 when completion is 0.
    EXPECT_DOUBLE_EQ(r.find(Metric::DamageTimeS)->subScore, 0.0);
}

TEST(Rubric, AllForceExcessive) {
    // The lump found and marked exactly, in 0.1 s, but every tick in contact at 4 N (excessive 3 N).
    Scorer scorer(place(lumpAt12()), kTickS);
    for (std::uint64_t t = 1; t <= 100; ++t) scorer.addSample(sampleAt(t, {20, 20, -1}, 12, true, 4.0f, t == 100 ? 1u : 0u));
    const ScoreReport r = scorer.report();
    EXPECT_TRUE(r.guidance.completed);
    EXPECT_DOUBLE_EQ(r.find(Metric::ExcessiveForceFraction)->value, 1.0);
    EXPECT_DOUBLE_EQ(r.find(Metric::ExcessiveForceEvents)->value, 1.0);
    EXPECT_DOUBLE_EQ(r.find(Metric::ExcessiveForceFraction)->subScore, 0.0);
    // Default find-the-lump rubric: completion 20, lump error 40, time 10 (0.1 s <= 30 s), excessive
    // events 5 x (5 - 1) / 5, excessive fraction 10 x 0, damage 15 (none given).
    EXPECT_NEAR(r.score, 20.0 + 40.0 + 10.0 + 5.0 * 0.8 + 0.0 + 15.0, 1e-9);
}

TEST(Rubric, WeightsAndCompletionGate) {
    ScoreReport r;
    r.metrics = {{Metric::Completion, 0.5}, {Metric::TimeS, 10.0}, {Metric::PeakForceN, 1.0}};
    r.guidance.completed = false;
    Rubric rubric{};
    rubric[std::size_t(Metric::Completion)] = {3.0, 1.0, 0.0};
    rubric[std::size_t(Metric::TimeS)] = {1.0, 5.0, 20.0};
    rubric[std::size_t(Metric::PeakForceN)] = {1.0, 0.0, 4.0};
    applyRubric(rubric, r);
    // Completion 0.5 * 3; time not graded (task not completed); peak force 0.75.
    EXPECT_NEAR(r.score, 100.0 * (1.5 + 0.0 + 0.75) / 5.0, 1e-12);
    r.guidance.completed = true;
    applyRubric(rubric, r);
    EXPECT_NEAR(r.score, 100.0 * (1.5 + (10.0 - 20.0) / (5.0 - 20.0) + 0.75) / 5.0, 1e-12);
    double sum = 0.0;
    for (const MetricResult& m : r.metrics) sum += m.contribution;
    EXPECT_NEAR(sum, r.score, 1e-12);
    r.metrics[0].value = 0.0;  // nothing done: everything 0
    applyRubric(rubric, r);
    EXPECT_DOUBLE_EQ(r.score, 0.0);
}

}  // namespace
}  // namespace palpate
