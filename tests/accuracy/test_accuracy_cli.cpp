// palpate-cli accuracy, run as a separate process: the JSON it prints with --quick, its exit
// code, and bad usage naming the option.

#include "tests/engine/TestMeshes.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>

namespace palpate {
namespace {

class AccuracyCli : public ::testing::Test {
protected:
    void SetUp() override {
        cli = test::cliPath();
        if (cli.empty()) GTEST_SKIP() << "built without PALPATE_CLI_PATH";
        ASSERT_TRUE(std::filesystem::exists(cli)) << cli;
    }
    test::CommandResult run(const std::string& args) const { return test::runCommand(test::shellQuote(cli) + " " + args); }
    std::string cli;
};

TEST_F(AccuracyCli, QuickJsonHasTheDocumentedKeys) {
    const auto r = run("accuracy --reference punch --quick --json --nu 0.3");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    EXPECT_EQ(j.at("reference"), "punch");
    ASSERT_TRUE(j.at("cases").is_array());
    ASSERT_EQ(j["cases"].size(), 2u);  // a/h = 2 and 4
    for (const auto& c : j["cases"]) {
        for (const char* key : {"a_over_h", "nu", "displacement_error", "force_error"}) EXPECT_TRUE(c.contains(key)) << key;
        EXPECT_DOUBLE_EQ(c["nu"].get<double>(), 0.3);
        EXPECT_GT(c["displacement_error"].get<double>(), 0.0);
        EXPECT_LT(c["displacement_error"].get<double>(), 0.05);
        EXPECT_LT(c["force_error"].get<double>(), 0.05);
    }
    EXPECT_EQ(j["cases"][0]["a_over_h"], 2);
    EXPECT_EQ(j["cases"][1]["a_over_h"], 4);
    EXPECT_TRUE(j.at("convergence").is_array());
    // The documented key order: "reference" first, then "cases".
    EXPECT_LT(r.output.find("\"reference\""), r.output.find("\"cases\""));
}

TEST_F(AccuracyCli, HumanOutputHasTheTableRateAndLockingRemark) {
    const auto r = run("accuracy --reference hertz --levels 2 --nu 0.3,0.499");
    EXPECT_EQ(r.exitCode, 0) << r.output;  // no case at a/h >= 8: nothing to fail
    EXPECT_NE(r.output.find("disp err"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("locking"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("not checked"), std::string::npos) << r.output;
}

TEST_F(AccuracyCli, UniaxialNeoHookeanJsonCarriesTheWorstErrorAndPasses) {
    const auto r = run("accuracy --reference uniaxial-neo-hookean --json --nu 0.45");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    EXPECT_EQ(j.at("reference"), "uniaxial-neo-hookean");
    EXPECT_LT(j.at("worst_error_pct").get<double>(), 0.5);
    ASSERT_EQ(j.at("cases").size(), 5u);
    for (const auto& c : j["cases"]) {
        EXPECT_DOUBLE_EQ(c["nu"].get<double>(), 0.45);
        EXPECT_EQ(c["nominal_stress_fem_kpa"].get<double>() > 0.0, c["stretch"].get<double>() > 1.0);
    }
    EXPECT_TRUE(j["gate"]["passed"].get<bool>());
}

TEST_F(AccuracyCli, IndentationNeoHookeanJsonHasSmallStrainCasesAndTheWorstError) {
    const auto r = run("accuracy --reference indentation-neo-hookean --levels 4 --json");
    const auto j = nlohmann::json::parse(r.output);
    EXPECT_EQ(j.at("reference"), "indentation-neo-hookean");
    EXPECT_LT(j.at("small_strain").at("force_difference").get<double>(), 0.01);
    ASSERT_EQ(j.at("cases").size(), 3u);  // delta/R = 0.1, 0.2, 0.3
    double worst = 0.0;
    for (const auto& c : j["cases"]) {
        EXPECT_EQ(c["a_over_h"], 4);
        worst = std::max(worst, c["error"].get<double>());
        EXPECT_GT(c["force_fem_n"].get<double>(), 0.0);
    }
    EXPECT_NEAR(j.at("worst_error_pct").get<double>(), 100.0 * worst, 1e-9);
    // a/h = 4 is too coarse for the 5 % goal: not checked, so not failed.
    EXPECT_FALSE(j["gate"]["checked"].get<bool>());
    EXPECT_EQ(r.exitCode, 0) << r.output;
}

TEST_F(AccuracyCli, BadUsageExitsTwoNamingTheOption) {
    struct Case {
        const char* args;
        const char* word;
    };
    for (const Case& c : {Case{"accuracy --reference sphere", "--reference"}, Case{"accuracy", "--reference"},
                          Case{"accuracy --reference punch --nu 0.6", "--nu"},
                          Case{"accuracy --reference punch --nu x", "--nu"},
                          Case{"accuracy --reference punch --levels 3.5", "--levels"},
                          Case{"accuracy --reference punch --bogus", "--bogus"},
                          Case{"accuracy --reference uniaxial-neo-hookean --nu 0.5", "--nu"},
                          Case{"accuracy --reference indentation-neo-hookean --levels 1", "--levels"}}) {
        const auto r = run(c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.word), std::string::npos) << c.args << "\n" << r.output;
    }
}

}  // namespace
}  // namespace palpate
