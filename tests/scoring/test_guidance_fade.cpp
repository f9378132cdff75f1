// Fading guidance: the force gauge's level from a trainee's previous scores, worked by hand.
#include "engine/scoring/GuidanceFade.h"

#include <gtest/gtest.h>

namespace palpate {
namespace {

TEST(GuidanceFade, FadesByAFifthPerGoodSessionAndComesBackAfterAPoorOne) {
    const GuidanceFadeDef def;  // 5 sessions, good at 80, floor 0
    EXPECT_DOUBLE_EQ(forceGaugeLevel({}, def), 1.0);
    EXPECT_DOUBLE_EQ(forceGaugeLevel({85.0}, def), 0.8);
    EXPECT_DOUBLE_EQ(forceGaugeLevel({85.0, 90.0, 80.0}, def), 1.0 - 3 * 0.2);
    // Good, good, poor: 1 - 0.2 - 0.2 + 0.2.
    EXPECT_NEAR(forceGaugeLevel({85.0, 90.0, 40.0}, def), 0.8, 1e-12);
    // Poor sessions never raise it past full; good ones never below the floor.
    EXPECT_DOUBLE_EQ(forceGaugeLevel({10.0, 10.0, 95.0}, def), 0.8);
    EXPECT_DOUBLE_EQ(forceGaugeLevel(std::vector<double>(9, 99.0), def), 0.0);
    GuidanceFadeDef floor = def;
    floor.floorLevel = 0.3;
    EXPECT_DOUBLE_EQ(forceGaugeLevel(std::vector<double>(9, 99.0), floor), 0.3);
    GuidanceFadeDef off = def;
    off.enabled = false;
    EXPECT_DOUBLE_EQ(forceGaugeLevel({99.0, 99.0}, off), 1.0);
    GuidanceFadeDef two = def;
    two.sessionsToFade = 2;
    EXPECT_DOUBLE_EQ(forceGaugeLevel({80.0}, two), 0.5);
}

}  // namespace
}  // namespace palpate
