// palpate-cli accuracy, run as a separate process: the JSON it prints with --quick, its exit
// code, and bad usage naming the option.

#include "tests/engine/TestMeshes.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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

TEST_F(AccuracyCli, BadUsageExitsTwoNamingTheOption) {
    struct Case {
        const char* args;
        const char* word;
    };
    for (const Case& c : {Case{"accuracy --reference sphere", "--reference"}, Case{"accuracy", "--reference"},
                          Case{"accuracy --reference punch --nu 0.6", "--nu"},
                          Case{"accuracy --reference punch --nu x", "--nu"},
                          Case{"accuracy --reference punch --levels 3.5", "--levels"},
                          Case{"accuracy --reference punch --bogus", "--bogus"}}) {
        const auto r = run(c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.word), std::string::npos) << c.args << "\n" << r.output;
    }
}

}  // namespace
}  // namespace palpate
