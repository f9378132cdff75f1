// Detection scoring (engine/exercise/LumpDetection.h): hits, misses, false alarms, sensitivity,
// positive predictive value and localisation, with answers worked out by hand.

#include "engine/exercise/LumpDetection.h"

#include <gtest/gtest.h>

namespace palpate {
namespace {

const std::vector<HiddenLump> kThreeLumps{{{0, 0, 0}, 5.0}, {{50, 0, 0}, 5.0}, {{100, 0, 0}, 3.0}};

TEST(LumpDetection, AThoroughExaminerFindsEveryLump) {
    const auto r = scoreDetection(kThreeLumps, {{1, 0, 0}, {50, 2, 0}, {100, 0, 3}}, {5.0});
    EXPECT_EQ(r.hits, 3u);
    EXPECT_EQ(r.misses, 0u);
    EXPECT_EQ(r.falseAlarms, 0u);
    EXPECT_DOUBLE_EQ(*r.sensitivity, 1.0);
    EXPECT_DOUBLE_EQ(*r.positivePredictive, 1.0);
    EXPECT_DOUBLE_EQ(r.localisationMm[0], 1.0);
    EXPECT_DOUBLE_EQ(r.localisationMm[1], 2.0);
    EXPECT_DOUBLE_EQ(r.localisationMm[2], 3.0);
}

TEST(LumpDetection, TwoMarksOnOneLumpAreOneHitAndOneFalseAlarm) {
    const auto r = scoreDetection(kThreeLumps, {{3, 0, 0}, {1, 0, 0}}, {5.0});
    EXPECT_EQ(r.hits, 1u);
    EXPECT_EQ(r.misses, 2u);
    EXPECT_EQ(r.falseAlarms, 1u);
    EXPECT_DOUBLE_EQ(*r.sensitivity, 1.0 / 3.0);
    EXPECT_DOUBLE_EQ(*r.positivePredictive, 0.5);
    EXPECT_EQ(r.findingOfLump[0], 1);  // the nearer mark
    EXPECT_DOUBLE_EQ(r.localisationMm[0], 1.0);
    EXPECT_EQ(r.findingOfLump[1], -1);
    EXPECT_DOUBLE_EQ(r.localisationMm[1], -1.0);
}

TEST(LumpDetection, TheMatchingPairsAsManyAsCanBePairedNotTheNearestFirst) {
    // Lumps at x = 0 and x = 10, each reached within 6 mm. Mark A (x = 6) is nearer the second
    // lump (4 mm) but also reaches the first (6 mm); mark B (x = 15.5) reaches only the second
    // (5.5 mm). Pairing the nearest first (A with the second) would leave B and the first lump
    // unmatched; the right answer pairs both.
    const std::vector<HiddenLump> lumps{{{0, 0, 0}, 6.0}, {{10, 0, 0}, 6.0}};
    const auto r = scoreDetection(lumps, {{6, 0, 0}, {15.5, 0, 0}}, {0.0});
    EXPECT_EQ(r.hits, 2u);
    EXPECT_EQ(r.falseAlarms, 0u);
    EXPECT_EQ(r.findingOfLump[0], 0);
    EXPECT_EQ(r.findingOfLump[1], 1);
    EXPECT_DOUBLE_EQ(r.localisationMm[0], 6.0);
    EXPECT_DOUBLE_EQ(r.localisationMm[1], 5.5);
}

TEST(LumpDetection, AMarkOutOfReachIsAFalseAlarm) {
    // 8 mm from the first lump's centre: beyond its 5 mm radius and 2 mm tolerance.
    const auto r = scoreDetection(kThreeLumps, {{8, 0, 0}}, {2.0});
    EXPECT_EQ(r.hits, 0u);
    EXPECT_EQ(r.misses, 3u);
    EXPECT_EQ(r.falseAlarms, 1u);
    EXPECT_DOUBLE_EQ(*r.positivePredictive, 0.0);
    // At 3 mm tolerance it reaches (8 <= 5 + 3).
    EXPECT_EQ(scoreDetection(kThreeLumps, {{8, 0, 0}}, {3.0}).hits, 1u);
}

TEST(LumpDetection, NoLumpsMeansEveryMarkIsAFalseAlarmAndSensitivityIsUndefined) {
    const auto r = scoreDetection({}, {{0, 0, 0}, {5, 5, 5}});
    EXPECT_EQ(r.hits, 0u);
    EXPECT_EQ(r.misses, 0u);
    EXPECT_EQ(r.falseAlarms, 2u);
    EXPECT_FALSE(r.sensitivity);
    EXPECT_DOUBLE_EQ(*r.positivePredictive, 0.0);
    const auto clean = scoreDetection({}, {});
    EXPECT_EQ(clean.falseAlarms, 0u);
    EXPECT_FALSE(clean.sensitivity);
    EXPECT_FALSE(clean.positivePredictive);
}

TEST(LumpDetection, NoMarksMissesEveryLump) {
    const auto r = scoreDetection(kThreeLumps, {});
    EXPECT_EQ(r.misses, 3u);
    EXPECT_DOUBLE_EQ(*r.sensitivity, 0.0);
    EXPECT_FALSE(r.positivePredictive);
}

TEST(LumpDetection, ManyMarksAndLumpsMatchOneToOne) {
    // 12 lumps on a line 30 mm apart, 20 marks: one 1 mm beside each lump, 8 far away.
    std::vector<HiddenLump> lumps;
    std::vector<glm::dvec3> marks;
    for (int i = 0; i < 12; ++i) {
        lumps.push_back({{30.0 * i, 0, 0}, 4.0});
        marks.push_back({30.0 * i, 1.0, 0});
    }
    for (int i = 0; i < 8; ++i) marks.push_back({30.0 * i + 15.0, 40.0, 0});
    const auto r = scoreDetection(lumps, marks, {2.0});
    EXPECT_EQ(r.hits, 12u);
    EXPECT_EQ(r.falseAlarms, 8u);
    for (int i = 0; i < 12; ++i) {
        EXPECT_EQ(r.findingOfLump[i], i);
        EXPECT_DOUBLE_EQ(r.localisationMm[i], 1.0);
    }
}

}  // namespace
}  // namespace palpate
