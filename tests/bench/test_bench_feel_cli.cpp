// palpate-cli bench feel, run as a separate process: a --quick run succeeds and writes a CSV with
// every column and one row per model and mesh, and JSON with the same figures and the goals; bad
// options are refused with exit 2. The figures themselves are not asserted here (timings are noisy).
#include "engine/bench/FeelCsv.h"
#include "tests/engine/TestMeshes.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <filesystem>

namespace palpate {
namespace {

class BenchFeelCli : public ::testing::Test {
protected:
    void SetUp() override {
        cli = test::cliPath();
        if (cli.empty()) GTEST_SKIP() << "built without PALPATE_CLI_PATH";
        ASSERT_TRUE(std::filesystem::exists(cli)) << cli;
    }
    test::CommandResult run(const std::string& args) const {
        return test::runCommand(test::shellQuote(cli) + " " + args);
    }
    std::string cli;
};

TEST_F(BenchFeelCli, AQuickRunWritesTheCsvAndTheJson) {
    test::TempDir dir;
    const std::string csvPath = dir.file("feel bench.csv");  // a space, on purpose
    const std::string jsonPath = dir.file("feel.json");
    // In a subshell, so that the JSON alone goes to the file and the progress lines to the output.
    std::string command = "(";
    command += test::shellQuote(cli);
    command += " bench feel --quick --models coherent,previous --load 1 --csv " + test::shellQuote(csvPath);
    command += " --json > " + test::shellQuote(jsonPath) + ")";
    const auto r = test::runCommand(command);
    ASSERT_EQ(r.exitCode, 0) << r.output;

    std::string error;
    const auto rows = parseFeelCsv(test::readFile(csvPath), &error);
    ASSERT_TRUE(error.empty()) << error;
    ASSERT_EQ(rows.size(), 4u);  // sphere and stomach at 1442 vertices, two models
    for (const FeelRow& row : rows) {
        EXPECT_EQ(row.vertices, 1442u);
        EXPECT_GT(row.tickNs, 0.0);
        EXPECT_TRUE(row.model == "coherent" || row.model == "previous") << row.model;
        // The threaded runs are the coherent model's: quiet, and beside the one busy process.
        EXPECT_EQ(bool(row.quiet), row.model == "coherent");
        EXPECT_EQ(bool(row.loaded), row.model == "coherent");
        if (row.loaded) {
            EXPECT_EQ(row.loaded->loadProcesses, 1);
        }
    }
    const std::string header = test::readFile(csvPath).substr(0, test::readFile(csvPath).find('\n'));
    for (const std::string& column : feelCsvColumns()) EXPECT_NE(header.find(column), std::string::npos) << column;

    const auto j = nlohmann::json::parse(test::readFile(jsonPath));
    ASSERT_EQ(j.at("rows").size(), 4u);
    for (const char* key : {"shape", "vertices", "model", "tool_radius_mm", "max_step_pct", "max_normal_step_pct",
                            "ripple_pct", "friction_ratio", "dynamic_friction", "tick_ns", "speedup_vs_previous",
                            "quiet", "loaded", "step_goal", "dropout_goal", "friction_goal", "speed_goal"})
        EXPECT_TRUE(j.at("rows")[0].contains(key)) << key;
    EXPECT_EQ(j.at("loop").at("sched_fifo"), false);
    EXPECT_EQ(j.at("loop").at("load_processes"), 1);
    EXPECT_DOUBLE_EQ(j.at("goals").at("max_step_pct").get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(j.at("slide").at("depth_mm").get<double>(), 1.0);
}

TEST_F(BenchFeelCli, TheTextTableShowsTheGoals) {
    const auto r = run("bench feel --quick --models previous --loop-models none");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("step drop fric speed"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("Goals:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("previous"), std::string::npos) << r.output;
}

TEST_F(BenchFeelCli, BadOptionsAreRefused) {
    EXPECT_EQ(run("bench feel --models nope").exitCode, 2);
    EXPECT_EQ(run("bench feel --load -1").exitCode, 2);
    EXPECT_EQ(run("bench feel --load 65").exitCode, 2);
    EXPECT_EQ(run("bench feel --models previous --loop-models coherent").exitCode, 2);
    EXPECT_EQ(run("bench feel --frobnicate").exitCode, 2);
    EXPECT_EQ(run("bench feel --preset /nonexistent/preset.json").exitCode, 1);
}

}  // namespace
}  // namespace palpate
