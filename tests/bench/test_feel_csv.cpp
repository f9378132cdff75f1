// The feel bench's CSV (engine/bench/FeelCsv.h): every column with its unit in the name, a round
// trip of the figures (empty cells for what was not measured), and errors that name line and column.
#include "engine/bench/FeelCsv.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace palpate {
namespace {

FeelRow sampleRow() {
    FeelRow r;
    r.shape = GeneratedShape::Stomach;
    r.vertices = 8664;
    r.model = "coherent";
    r.toolRadiusMm = 5.0;
    r.depthMm = 1.0;
    r.speedMmPerS = 25.0;
    r.slideLengthMm = 39.975;
    r.contactTicks = 1500;
    r.metrics = {1500, 0.625, 4.25, 4.0, 12.5, 0.61, 0.122, 0.2};
    r.dynamicFriction = 0.2;
    r.tickNs = 41.5;
    r.previousTickNs = 37000.0;
    r.timingPasses = 3;
    r.quiet = LoopFeel{.ticks = 4000,
                       .overruns = 1,
                       .missedDeadlines = 2,
                       .windowTicks = 3000,
                       .contactTicks = 2990,
                       .maxStepPct = 4.5,
                       .seconds = 4.0};
    r.loaded = LoopFeel{.loadProcesses = 2,
                        .ticks = 3900,
                        .overruns = 25,
                        .missedDeadlines = 40,
                        .windowTicks = 2950,
                        .contactTicks = 2950,
                        .dropouts = 3,
                        .maxStepPct = 12.25,
                        .seconds = 4.0};
    r.note = "a \"quoted\" note, with a comma";
    return r;
}

TEST(FeelCsv, TheHeaderNamesEveryColumnWithItsUnit) {
    const std::string csv = feelToCsv({});
    for (const char* column : {"shape",
                               "vertices",
                               "model",
                               "tool_radius_mm",
                               "depth_mm",
                               "speed_mm_per_s",
                               "mean_force_n",
                               "max_step_pct",
                               "max_normal_step_pct",
                               "ripple_pct",
                               "friction_ratio",
                               "dynamic_friction",
                               "friction_deviation_pct",
                               "tick_ns",
                               "previous_tick_ns",
                               "speedup_vs_previous",
                               "load_processes",
                               "quiet_dropouts",
                               "quiet_overruns",
                               "loaded_dropouts",
                               "loaded_overruns",
                               "step_goal",
                               "dropout_goal",
                               "friction_goal",
                               "speed_goal",
                               "note"}) {
        const auto& names = feelCsvColumns();
        EXPECT_NE(std::find(names.begin(), names.end(), column), names.end()) << column;
        EXPECT_NE(csv.find(column), std::string::npos) << column;
    }
    EXPECT_EQ(csv.substr(0, csv.find('\n')).find(' '), std::string::npos);
}

TEST(FeelCsv, ARowGoesThereAndBack) {
    const FeelRow r = sampleRow();
    FeelRow bare;  // nothing measured but the names: empty cells
    bare.model = "ffd";
    bare.vertices = 1442;
    bare.note = "cannot be built: reasons";
    bare.tickNs = std::nan("");
    bare.metrics.maxStepPct = std::nan("");
    const std::string csv = feelToCsv({r, bare});
    EXPECT_NE(csv.find(",FAIL,"), std::string::npos) << csv;  // the step goal of 4.25 %
    std::string error;
    const auto rows = parseFeelCsv(csv, &error);
    ASSERT_TRUE(error.empty()) << error;
    ASSERT_EQ(rows.size(), 2u);
    const FeelRow& back = rows[0];
    EXPECT_EQ(back.shape, r.shape);
    EXPECT_EQ(back.vertices, r.vertices);
    EXPECT_EQ(back.model, r.model);
    EXPECT_DOUBLE_EQ(back.toolRadiusMm, 5.0);
    EXPECT_NEAR(back.metrics.maxStepPct, 4.25, 1e-9);
    EXPECT_NEAR(back.metrics.frictionRatio, 0.2, 1e-9);
    EXPECT_NEAR(*back.dynamicFriction, 0.2, 1e-9);
    EXPECT_NEAR(back.tickNs, 41.5, 1e-9);
    EXPECT_NEAR(back.speedupVsPrevious(), r.speedupVsPrevious(), 1e-3);
    ASSERT_TRUE(back.quiet && back.loaded);
    EXPECT_EQ(back.loaded->loadProcesses, 2);
    EXPECT_EQ(back.loaded->dropouts, 3u);
    EXPECT_EQ(back.quiet->overruns, 1u);
    EXPECT_NEAR(back.loaded->maxStepPct, 12.25, 1e-9);
    EXPECT_EQ(back.note, r.note);
    EXPECT_EQ(stepGoal(back), GoalVerdict::Fail);
    EXPECT_EQ(dropoutGoal(back), GoalVerdict::Fail);

    const FeelRow& none = rows[1];
    EXPECT_TRUE(std::isnan(none.tickNs));
    EXPECT_FALSE(none.dynamicFriction);
    EXPECT_FALSE(none.quiet);
    EXPECT_FALSE(none.loaded);
    EXPECT_EQ(none.note, bare.note);
}

TEST(FeelCsv, ProblemsNameTheLineAndTheColumn) {
    std::string error;
    EXPECT_TRUE(parseFeelCsv("", &error).empty());
    EXPECT_NE(error.find("line 1"), std::string::npos) << error;
    EXPECT_TRUE(parseFeelCsv("shape,vertices,model\nsphere,1442,coherent\n", &error).empty());
    EXPECT_NE(error.find("max_step_pct"), std::string::npos) << error;

    std::string csv = feelToCsv({sampleRow()});
    const std::string good = csv;
    csv.replace(csv.find("stomach"), 7, "cube");
    EXPECT_TRUE(parseFeelCsv(csv, &error).empty());
    EXPECT_NE(error.find("line 2, column shape"), std::string::npos) << error;
    csv = good;
    csv.replace(csv.find(",41.5,"), 6, ",fast,");
    EXPECT_TRUE(parseFeelCsv(csv, &error).empty());
    EXPECT_NE(error.find("column tick_ns"), std::string::npos) << error;
    csv = good + "sphere,1442\n";
    EXPECT_TRUE(parseFeelCsv(csv, &error).empty());
    EXPECT_NE(error.find("line 3"), std::string::npos) << error;
}

}  // namespace
}  // namespace palpate
