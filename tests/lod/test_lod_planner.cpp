// The planner on synthetic tables: it picks the coarsest level, then the fewest rings, among the
// candidates that meet both targets; it reports an infeasible request and names the candidate with
// the least shortfall; it ignores failed measurements; bad needs and empty tables are errors.
#include "engine/lod/LodPlanner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace palpate {
namespace {

LodCandidate cand(std::size_t vertices, int rings, double error, double tickUs) {
    LodCandidate c;
    c.vertices = vertices;
    c.level = vertices == 8000 ? 0 : vertices == 4000 ? 1 : vertices == 2000 ? 2 : 3;
    c.rings = rings;
    c.errorFraction = error;
    c.tickUs = tickUs;
    return c;
}

/// A table shaped like a real one: error falls with rings and (here) with vertices, tick grows
/// with rings; vertices 8000/4000/2000/1000, rings 1..4.
std::vector<LodCandidate> table() {
    std::vector<LodCandidate> t;
    for (std::size_t v : {8000u, 4000u, 2000u, 1000u})
        for (int r = 1; r <= 4; ++r)
            t.push_back(cand(v, r, 0.4 / r * (1.0 + 1000.0 / double(v)), 1.0 * r * r + double(v) / 4000.0));
    return t;
}

TEST(LodPlanner, PicksTheCoarsestLevelThenTheFewestRings) {
    const auto t = table();
    // error(1000, r) = 0.8 / r; error(2000, r) = 0.6 / r; error(4000, r) = 0.5 / r; error(8000, r) = 0.45 / r.
    const LodPlan plan = planLod(t, LodNeeds{0.31, 100.0});
    ASSERT_EQ(plan.error, "");
    ASSERT_TRUE(plan.feasible);
    ASSERT_TRUE(plan.chosen);
    EXPECT_EQ(t[*plan.chosen].vertices, 1000u);
    EXPECT_EQ(t[*plan.chosen].rings, 3);  // 0.8/3 = 0.267 <= 0.31; 0.8/2 = 0.4 is not
    EXPECT_FALSE(plan.closest);
    EXPECT_NE(plan.reason.find("1000 vertices"), std::string::npos) << plan.reason;
    EXPECT_NE(plan.reason.find("3 rings"), std::string::npos) << plan.reason;
}

TEST(LodPlanner, TheBudgetPushesToFewerRingsOnAFinerLevel) {
    const auto t = table();
    // Tick budget 4.9 us allows 2 rings at most (4 + v/4000 <= 4.9 for v <= 3600; 8000 gives 6).
    // With error <= 0.31: 1000 needs 3 rings (too slow), 2000 needs 2 rings (0.3, tick 4.5): chosen.
    const LodPlan plan = planLod(t, LodNeeds{0.31, 4.9});
    ASSERT_TRUE(plan.chosen);
    EXPECT_EQ(t[*plan.chosen].vertices, 2000u);
    EXPECT_EQ(t[*plan.chosen].rings, 2);
}

TEST(LodPlanner, TheChoiceIsTheCheapestFeasibleOnRandomTablesWhateverTheirOrder) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<LodCandidate> t;
        for (std::size_t v : {8000u, 4000u, 2000u, 1000u})
            for (int r = 1; r <= 5; ++r) t.push_back(cand(v, r, u(rng), 10.0 * u(rng)));
        const LodNeeds needs{0.2 + 0.5 * u(rng), 1.0 + 8.0 * u(rng)};
        const LodPlan plan = planLod(t, needs);
        ASSERT_EQ(plan.error, "");
        const bool anyFeasible = std::any_of(t.begin(), t.end(), [&](const LodCandidate& c) {
            return c.errorFraction <= needs.maxErrorFraction && c.tickUs <= needs.budgetUs;
        });
        ASSERT_EQ(plan.feasible, anyFeasible);
        if (!anyFeasible) continue;
        const LodCandidate& chosen = t[*plan.chosen];
        EXPECT_LE(chosen.errorFraction, needs.maxErrorFraction);
        EXPECT_LE(chosen.tickUs, needs.budgetUs);
        for (const LodCandidate& c : t) {
            if (c.errorFraction > needs.maxErrorFraction || c.tickUs > needs.budgetUs) continue;
            // No feasible candidate is coarser, or as coarse with fewer rings.
            EXPECT_FALSE(c.vertices < chosen.vertices || (c.vertices == chosen.vertices && c.rings < chosen.rings));
        }
        // The same candidate whatever the table's order.
        std::vector<LodCandidate> shuffled = t;
        std::shuffle(shuffled.begin(), shuffled.end(), rng);
        const LodPlan again = planLod(shuffled, needs);
        ASSERT_TRUE(again.chosen);
        EXPECT_EQ(shuffled[*again.chosen].vertices, chosen.vertices);
        EXPECT_EQ(shuffled[*again.chosen].rings, chosen.rings);
    }
}

TEST(LodPlanner, TiesOnLevelAndRingsGoToTheFasterModel) {
    std::vector<LodCandidate> t{cand(1000, 2, 0.1, 3.0), cand(1000, 2, 0.05, 2.0), cand(2000, 1, 0.1, 1.0)};
    t[0].model = "coherent";
    t[1].model = "mass-spring-local";
    const LodPlan plan = planLod(t, LodNeeds{0.2, 10.0});
    ASSERT_TRUE(plan.chosen);
    EXPECT_EQ(*plan.chosen, 1u);
}

TEST(LodPlanner, AnInfeasibleRequestIsReportedWithTheClosestCandidate) {
    const auto t = table();
    // Error 0.05 is beyond every candidate (best: 0.45 / 4 = 0.1125 at 8000 vertices).
    const LodPlan plan = planLod(t, LodNeeds{0.05, 100.0});
    ASSERT_EQ(plan.error, "");
    EXPECT_FALSE(plan.feasible);
    EXPECT_FALSE(plan.chosen);
    ASSERT_TRUE(plan.closest);
    EXPECT_EQ(t[*plan.closest].vertices, 8000u);
    EXPECT_EQ(t[*plan.closest].rings, 4);
    EXPECT_NE(plan.reason.find("nothing meets"), std::string::npos) << plan.reason;
    EXPECT_NE(plan.reason.find("Closest"), std::string::npos) << plan.reason;
    EXPECT_NE(plan.reason.find("x the target"), std::string::npos) << plan.reason;
    EXPECT_EQ(plan.reason.find("x the budget"), std::string::npos) << plan.reason;  // the tick fits

    // Both missed: the shortfall adds the relative excesses. A: error 2x target (1), tick fits;
    // B: error 1.2x (0.2) and tick 1.5x (0.5) -> 0.7: B is closer.
    const std::vector<LodCandidate> two{cand(1000, 1, 0.2, 1.0), cand(2000, 1, 0.12, 3.0)};
    const LodNeeds needs{0.1, 2.0};
    EXPECT_DOUBLE_EQ(shortfall(two[0], needs), 1.0);
    EXPECT_DOUBLE_EQ(shortfall(two[1], needs), 0.7);
    const LodPlan p2 = planLod(two, needs);
    ASSERT_TRUE(p2.closest);
    EXPECT_EQ(*p2.closest, 1u);
    EXPECT_NE(p2.reason.find("x the budget"), std::string::npos) << p2.reason;
}

TEST(LodPlanner, FailedMeasurementsAreNeverChosen) {
    std::vector<LodCandidate> t{cand(1000, 1, std::nan(""), std::nan("")), cand(2000, 1, 0.1, 1.0)};
    t[0].note = "ring 1 is empty";
    const LodPlan plan = planLod(t, LodNeeds{0.2, 10.0});
    ASSERT_TRUE(plan.chosen);
    EXPECT_EQ(*plan.chosen, 1u);
    EXPECT_EQ(shortfall(t[0], LodNeeds{0.2, 10.0}), INFINITY);
    const LodPlan none = planLod({t[0]}, LodNeeds{0.2, 10.0});
    EXPECT_FALSE(none.feasible);
    EXPECT_FALSE(none.closest);
    EXPECT_NE(none.reason.find("No candidate was measured"), std::string::npos) << none.reason;
}

TEST(LodPlanner, BadNeedsAndEmptyTablesAreErrors) {
    const auto t = table();
    const LodPlan negative = planLod(t, LodNeeds{-0.1, 10.0});
    EXPECT_NE(negative.error.find("needs.max_error"), std::string::npos) << negative.error;
    EXPECT_FALSE(negative.chosen);
    const LodPlan zero = planLod(t, LodNeeds{0.1, 0.0});
    EXPECT_NE(zero.error.find("needs.budget_us"), std::string::npos) << zero.error;
    const LodPlan empty = planLod({}, LodNeeds{0.1, 10.0});
    EXPECT_NE(empty.error.find("no candidates"), std::string::npos) << empty.error;
}

TEST(LodPlanner, BoundariesAreInclusive) {
    const std::vector<LodCandidate> t{cand(1000, 1, 0.1, 5.0)};
    EXPECT_TRUE(planLod(t, LodNeeds{0.1, 5.0}).feasible);
    EXPECT_FALSE(planLod(t, LodNeeds{0.0999, 5.0}).feasible);
    EXPECT_FALSE(planLod(t, LodNeeds{0.1, 4.999}).feasible);
}

}  // namespace
}  // namespace palpate
