// The scorer on synthetic tick streams whose answers are worked out by hand (tests/scoring/
// SyntheticTicks.h: a flat 10 mm grid, ticks of exactly 2^-10 s).
#include "engine/scoring/Scorer.h"
#include "tests/scoring/SyntheticTicks.h"
#include "tests/support/AllocationCounter.h"
#include "engine/exercise/ExerciseKind.h"

#include <gtest/gtest.h>

#include <cmath>

namespace palpate {
namespace {

using test::kTickS;
using test::sampleAt;

constexpr double kExact = 1e-12;

/// Only these rubric lines weigh; every other line of the type gets weight 0.
void onlyLines(Exercise& e, std::initializer_list<std::pair<Metric, RubricItem>> lines) {
    for (std::size_t i = 0; i < kMetricCount; ++i)
        if (exerciseKind(e.type).measures(Metric(i))) e.rubric[i] = RubricItem{0.0, 1.0, 0.0};
    for (const auto& [m, item] : lines) e.rubric[std::size_t(m)] = item;
}

std::shared_ptr<const ExerciseGeometry> place(const Exercise& e) {
    std::string error;
    auto g = ExerciseGeometry::build(e, test::gridMesh(), error);
    EXPECT_EQ(error, "");
    return g;
}

double value(const ScoreReport& r, Metric m) {
    const MetricResult* line = r.find(m);
    EXPECT_NE(line, nullptr) << metricName(m);
    return line ? line->value : std::nan("");
}

Exercise twoTargets() {
    Exercise e = test::gridExercise(ExerciseType::PressTargets);
    PressTarget a;  // vertex 12 at (20, 20, 0)
    a.at.vertex = 12;
    a.forceMinN = 1.0;
    a.forceMaxN = 2.0;
    a.holdS = 0.5;
    a.toleranceMm = 3.0;
    PressTarget b = a;  // vertex 14 at (40, 20, 0)
    b.at.vertex = 14;
    b.holdS = 0.2;
    e.pressTargets.targets = {a, b};
    e.displacementLimitMm = 8.0;
    e.excessiveForceN = 3.0;
    onlyLines(e, {{Metric::Completion, {2.0, 1.0, 0.0}},
                  {Metric::HoldInWindowFraction, {1.0, 1.0, 0.6}},
                  {Metric::ExcessiveForceFraction, {1.0, 0.0, 0.5}}});
    return e;
}

TEST(Scorer, PressTargetsWorkedByHand) {
    const Exercise e = twoTargets();
    Scorer scorer(place(e), kTickS);
    const glm::vec3 aboveA(20, 20, 5), inA(20, 20, -1), aboveB(40, 20, 5), inB(41, 20, -1);
    for (std::uint64_t t = 1; t <= 1600; ++t) {
        ScoreSample s;
        if (t <= 100) s = sampleAt(t, aboveA, 12, false, 0.0f);
        else if (t <= 200) s = sampleAt(t, inA, 12, true, 0.5f);        // pressing in: below the window
        else if (t <= 300) s = sampleAt(t, inA, 12, true, 1.5f);        // in the window: hold 100 ticks
        else if (t <= 350) s = sampleAt(t, inA, 12, true, 2.5f);        // above it: the hold restarts
        else if (t <= 900) s = sampleAt(t, inA, 12, true, 1.5f);        // 512 ticks = 0.5 s: A at 862
        else if (t <= 1000) s = sampleAt(t, aboveB, 14, false, 0.0f);
        else if (t <= 1300) s = sampleAt(t, inB, 14, true, 3.5f);       // excessive, 1 mm off B
        else s = sampleAt(t, inB, 14, true, 1.2f);                      // 205 ticks >= 0.2 s: B at 1505
        s.damage.maxDisplacementMm = t > 1000 && t <= 1300 ? 9.0f : 4.0f;
        s.damage.areaAboveLimitMm2 = t > 1000 && t <= 1300 ? 150.0f : 0.0f;
        scorer.addSample(s);
        if (t == 300) {
            EXPECT_EQ(scorer.guidance().targetIndex, 0);
            EXPECT_NEAR(scorer.guidance().holdProgress, 100 * kTickS / 0.5, kExact);
            EXPECT_TRUE(scorer.guidance().onTarget);
        }
        if (t == 862) {
            EXPECT_EQ(scorer.guidance().targetIndex, 1);
            EXPECT_DOUBLE_EQ(scorer.guidance().forceMinN, 1.0);
        }
    }
    const ScoreReport r = scorer.report();
    const double P = kTickS;
    EXPECT_TRUE(r.guidance.completed);
    EXPECT_EQ(r.ticksScored, 1505u);
    EXPECT_EQ(r.ticksAfterEnd, 95u);
    ASSERT_EQ(r.targets.size(), 2u);
    EXPECT_NEAR(r.targets[0].achievedAtS, 862 * P, kExact);
    EXPECT_NEAR(r.targets[0].inWindowS, 612 * P, kExact);
    EXPECT_NEAR(r.targets[0].onTargetS, 662 * P, kExact);  // from the first tick in its window
    EXPECT_NEAR(r.targets[0].errorMm, 0.0, kExact);
    EXPECT_NEAR(r.targets[1].achievedAtS, 1505 * P, kExact);
    EXPECT_NEAR(r.targets[1].onTargetS, 205 * P, kExact);  // the excessive press never entered the window
    EXPECT_NEAR(r.targets[1].errorMm, 1.0, kExact);        // ticks 863..900 pressed A: not B's press

    EXPECT_NEAR(value(r, Metric::Completion), 1.0, kExact);
    EXPECT_NEAR(value(r, Metric::TimeS), 1505 * P, kExact);
    EXPECT_NEAR(value(r, Metric::TargetErrorMm), 0.5, kExact);
    EXPECT_NEAR(value(r, Metric::HoldInWindowFraction), 817.0 / 867.0, kExact);
    EXPECT_NEAR(value(r, Metric::PeakForceN), 3.5, kExact);
    const double impulse =
        P * (100 * 0.5 + 100 * 1.5 + 50 * 2.5 + 512 * 1.5 + 38 * 1.5 + 300 * 3.5 + 205 * double(1.2f));
    EXPECT_NEAR(value(r, Metric::ImpulseNs), impulse, kExact);
    EXPECT_NEAR(value(r, Metric::MeanForceN), impulse / (1305 * P), kExact);
    EXPECT_NEAR(value(r, Metric::ExcessiveForceEvents), 1.0, kExact);
    EXPECT_NEAR(value(r, Metric::ExcessiveForceFraction), 300.0 / 1305.0, kExact);
    EXPECT_NEAR(value(r, Metric::DamageTimeS), 300 * P, kExact);
    EXPECT_NEAR(value(r, Metric::DamageAreaMm2), 150.0, kExact);
    EXPECT_NEAR(value(r, Metric::MaxDisplacementMm), 9.0, kExact);
    const double path = 6.0 + std::sqrt(436.0) + std::sqrt(37.0);
    EXPECT_NEAR(value(r, Metric::PathLengthMm), path, 1e-9);
    EXPECT_NEAR(value(r, Metric::Economy), (5.0 + 20.0) / path, 1e-9);  // start 5 mm above A, then A to B

    // The rubric: completion (weight 2), hold fraction (1; 1 full, 0.6 zero), excessive fraction
    // (1; 0 full, 0.5 zero).
    const double hold = (817.0 / 867.0 - 0.6) / 0.4, excessive = (300.0 / 1305.0 - 0.5) / -0.5;
    EXPECT_NEAR(r.score, 100.0 * (2.0 + hold + excessive) / 4.0, 1e-9);
    EXPECT_NEAR(r.find(Metric::HoldInWindowFraction)->contribution, 100.0 * hold / 4.0, 1e-9);
    EXPECT_NEAR(r.find(Metric::HoldInWindowFraction)->subScore, hold, 1e-9);
    EXPECT_DOUBLE_EQ(r.find(Metric::PeakForceN)->weight, 0.0);
    EXPECT_DOUBLE_EQ(r.find(Metric::PeakForceN)->contribution, 0.0);
}

TEST(Scorer, FindLumpMarkEventAndButton) {
    Exercise e = test::gridExercise(ExerciseType::FindLump);
    e.findLump.inclusion.centre.vertex = 12;  // (20, 20, 0)
    e.findLump.inclusion.radiusMm = 10.0;
    e.findLump.inclusion.stiffnessFactor = 0.5;
    const auto geometry = place(e);
    // Vertices 7, 11, 12, 13, 17 are within 10 mm of the centre.
    EXPECT_EQ(geometry->inclusionVertexCount(), 5u);
    EXPECT_FLOAT_EQ(geometry->compliance()[12], 0.5f);
    EXPECT_FLOAT_EQ(geometry->compliance()[6], 1.0f);

    {  // A Mark event at tick 150: the contact point then is (31, 20, 0), 11 mm from the centre.
        Scorer scorer(geometry, kTickS);
        for (std::uint64_t t = 1; t <= 200; ++t) {
            if (t == 150) scorer.addMark(150);
            scorer.addSample(t <= 100 ? sampleAt(t, {0, 0, -1}, 0, true, 0.4f) : sampleAt(t, {31, 20, -2}, 13, true, 0.4f));
        }
        const ScoreReport r = scorer.report();
        EXPECT_TRUE(r.guidance.completed);
        EXPECT_TRUE(r.guidance.marked);
        EXPECT_EQ(r.marks, 1u);
        EXPECT_NEAR(value(r, Metric::LumpErrorMm), 11.0, kExact);
        EXPECT_NEAR(value(r, Metric::TimeS), 150 * kTickS, kExact);
        EXPECT_EQ(r.ticksAfterEnd, 50u);
        // Ideal path: from the start (0, 0, -1) straight to the centre; travelled: (0,0,-1) to (31,20,-2).
        EXPECT_NEAR(value(r, Metric::Economy), std::sqrt(20.0 * 20 + 20 * 20 + 1) / std::sqrt(31.0 * 31 + 20 * 20 + 1), 1e-9);
    }
    {  // A button pressed at tick 120 (a rising bit); a mark before the first tick counts at it.
        Scorer scorer(geometry, kTickS);
        for (std::uint64_t t = 1; t <= 200; ++t)
            scorer.addSample(sampleAt(t, {21, 22, -1}, 12, true, 0.4f, t >= 120 ? 2u : 0u));
        EXPECT_NEAR(value(scorer.report(), Metric::LumpErrorMm), std::sqrt(5.0), kExact);
        EXPECT_NEAR(value(scorer.report(), Metric::TimeS), 120 * kTickS, kExact);

        Scorer early(geometry, kTickS);
        early.addMark(0);
        early.addSample(sampleAt(1, {20, 20, 3}, 12, false, 0.0f));
        EXPECT_TRUE(early.guidance().completed);
        EXPECT_NEAR(value(early.report(), Metric::LumpErrorMm), 0.0, kExact);
    }
}

TEST(Scorer, TraceWorkedByHand) {
    Exercise e = test::gridExercise(ExerciseType::Trace);
    e.trace.path.resize(2);
    e.trace.path[0].vertex = 10;  // (0, 20, 0)
    e.trace.path[1].pointMm = glm::vec3(39.0f, 21.0f, 0.0f);  // snaps to vertex 14 (40, 20, 0)
    e.trace.forceMinN = 0.5;
    e.trace.forceMaxN = 1.5;
    e.trace.toleranceMm = 2.0;
    const auto geometry = place(e);
    EXPECT_DOUBLE_EQ(geometry->pathLengthMm(), 40.0);
    ASSERT_EQ(geometry->coverageSamplesMm().size(), 41u);  // every mm, both ends

    Scorer scorer(geometry, kTickS);
    for (std::uint64_t t = 1; t <= 501; ++t) {
        if (t <= 100) {
            scorer.addSample(sampleAt(t, {0, 20, 5}, 10, false, 0.0f));
            continue;
        }
        // 1 mm beside the line, 0.1 mm per tick, x = 0 .. 40.
        const float x = 0.1f * float(t - 101);
        const glm::vec3 tool(x, 21.0f, -1.0f);
        const VertexId touched = VertexId(10 + int(std::lround(x / 10.0f)));
        if (t <= 300) scorer.addSample(sampleAt(t, tool, touched, true, 1.0f));
        else if (t <= 400) scorer.addSample(sampleAt(t, tool, touched, true, 2.0f));  // out of the band
        else if (t <= 450) scorer.addSample(sampleAt(t, tool, touched, false, 0.0f)); // contact lost
        else scorer.addSample(sampleAt(t, tool, touched, true, 1.0f));
    }
    const ScoreReport r = scorer.report();
    // Covered: samples within 2 mm of a contact point (x, 21): |x - s| <= sqrt(3). Contact had
    // x in [0, 29.9] and [35, 40]: samples 0..31 and 34..40, 39 of 41.
    EXPECT_FALSE(r.guidance.completed);
    EXPECT_NEAR(value(r, Metric::Completion), 39.0 / 41.0, kExact);
    // Tracing from the first contact (tick 101) to the end (501): 401 ticks; in contact 351; in
    // the band 251; always 1 mm from the line.
    EXPECT_NEAR(value(r, Metric::ContactFraction), 351.0 / 401.0, kExact);
    EXPECT_NEAR(value(r, Metric::BandFraction), 251.0 / 401.0, kExact);
    EXPECT_NEAR(value(r, Metric::PathDistanceMm), 1.0, 1e-6);
    EXPECT_NEAR(value(r, Metric::TimeS), 501 * kTickS, kExact);
}

TEST(Scorer, TimeLimitAndPauseAndLateMark) {
    Exercise e = test::gridExercise(ExerciseType::FindLump);
    e.findLump.inclusion.centre.vertex = 12;
    e.timeLimitS = 0.25;  // 256 ticks
    Scorer scorer(place(e), kTickS);
    for (std::uint64_t t = 1; t <= 400; ++t) {
        ScoreSample s = sampleAt(t, {20, 20, 1}, 12, false, 0.0f);
        s.tick.paused = t > 10 && t <= 20;  // ten paused ticks: no exercise time
        scorer.addSample(s);
    }
    const ScoreReport r = scorer.report();
    EXPECT_TRUE(r.guidance.timeUp);
    EXPECT_FALSE(r.guidance.completed);
    EXPECT_EQ(r.ticksScored, 256u);
    EXPECT_EQ(r.ticksAfterEnd, 400u - 256u - 10u);
    EXPECT_NEAR(value(r, Metric::TimeS), 0.25, kExact);
    EXPECT_DOUBLE_EQ(r.score, 0.0);  // nothing done
    // A mark after the end does not count.
    Scorer later(place(e), kTickS);
    for (std::uint64_t t = 1; t <= 300; ++t) {
        if (t == 290) later.addMark(290);
        later.addSample(sampleAt(t, {20, 20, 1}, 12, false, 0.0f));
    }
    EXPECT_FALSE(later.guidance().marked);
}

TEST(Scorer, SamplesAllocateNothing) {
    Exercise e = test::gridExercise(ExerciseType::Trace);
    e.trace.path.resize(2);
    e.trace.path[0].vertex = 10;
    e.trace.path[1].vertex = 14;
    Scorer scorer(place(e), kTickS);
    std::vector<ScoreSample> samples;
    for (std::uint64_t t = 1; t <= 2000; ++t)
        samples.push_back(sampleAt(t, {float(t % 400) * 0.1f, 21.0f, -1.0f}, 12, t % 7 != 0, 1.0f, t > 1000 ? 1u : 0u));
    scorer.addMark(1500);
    test::AllocationCounter counter;
    for (const ScoreSample& s : samples) scorer.addSample(s);
    EXPECT_EQ(counter.count(), 0u);
}

}  // namespace
}  // namespace palpate
