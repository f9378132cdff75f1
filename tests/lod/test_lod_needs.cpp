// What a scene needs: the targets are checked, and every absurd value names its key.
#include "engine/lod/LodNeeds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace palpate {
namespace {

std::string joined(const std::vector<std::string>& errors) {
    std::string all;
    for (const auto& e : errors) all += e + "\n";
    return all;
}

TEST(LodNeeds, SensibleTargetsPass) {
    EXPECT_TRUE(validateLodNeeds(LodNeeds{0.1, 100.0}).empty());
    EXPECT_TRUE(validateLodNeeds(LodNeeds{kMaxLodErrorFraction, kMaxLodBudgetUs}).empty());
    EXPECT_TRUE(validateLodNeeds(LodNeeds{1e-6, 0.01}).empty());
}

TEST(LodNeeds, AbsurdTargetsNameTheKey) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    struct Case {
        LodNeeds needs;
        const char* key;
        const char* words;
    };
    for (const Case& c : {Case{{-0.1, 100.0}, "needs.max_error", "must be above 0"},
                          Case{{0.0, 100.0}, "needs.max_error", "must be above 0"},
                          Case{{nan, 100.0}, "needs.max_error", "finite"},
                          Case{{20.0, 100.0}, "needs.max_error", "absurd"},
                          Case{{0.1, 0.0}, "needs.budget_us", "must be above 0"},
                          Case{{0.1, -5.0}, "needs.budget_us", "must be above 0"},
                          Case{{0.1, inf}, "needs.budget_us", "finite"},
                          Case{{0.1, 2e6}, "needs.budget_us", "absurd"}}) {
        const auto errors = messagesOf(validateLodNeeds(c.needs));
        ASSERT_TRUE(hasProblem(validateLodNeeds(c.needs), c.key));
        ASSERT_EQ(errors.size(), 1u) << joined(errors);
        EXPECT_EQ(errors.front().rfind(std::string(c.key) + ": ", 0), 0u) << errors.front();
        EXPECT_NE(errors.front().find(c.words), std::string::npos) << errors.front();
    }
    // Both wrong: both named; the prefix is the caller's.
    const auto both = messagesOf(validateLodNeeds(LodNeeds{-1.0, 0.0}, "exercise.needs."));
    ASSERT_EQ(both.size(), 2u);
    EXPECT_EQ(both[0].rfind("exercise.needs.max_error", 0), 0u);
    EXPECT_EQ(both[1].rfind("exercise.needs.budget_us", 0), 0u);
}

}  // namespace
}  // namespace palpate
