// palpate-cli stability as a user runs it: --list, --model with --json and --csv, and bad usage.
#include "engine/stability/StabilityModels.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

namespace {

struct CliRun {
    int status = -1;
    std::string out;
};

CliRun run(const std::string& arguments) {
    CliRun r;
    const std::string command = std::string(PALPATE_CLI_PATH) + " " + arguments + " 2>/dev/null";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buffer{};
    while (std::fgets(buffer.data(), int(buffer.size()), pipe)) r.out += buffer.data();
    const int status = pclose(pipe);
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

}  // namespace

TEST(StabilityCli, ListNamesEveryMapOnePerLine) {
    const CliRun r = run("stability --list");
    ASSERT_EQ(r.status, 0);
    std::string expected;
    for (const auto& name : palpate::stabilityModelNames()) expected += name + "\n";
    EXPECT_EQ(r.out, expected);
}

TEST(StabilityCli, JsonAndCsvOfAQuickMap) {
    const std::string csv = ::testing::TempDir() + "stability_map.csv";
    const CliRun r = run("stability --model slope-ring-relaxation --quick --json --csv " + csv);
    ASSERT_EQ(r.status, 0);
    const auto json = nlohmann::json::parse(r.out);
    EXPECT_EQ(json["model"], "slope-ring-relaxation");
    for (const char* key : {"derived_boundary", "measured_boundary", "relative_gap", "cells"}) EXPECT_TRUE(json.contains(key)) << key;
    EXPECT_EQ(json["cells"].size(), 36u);
    EXPECT_LT(json["relative_gap"].get<double>(), 0.05);
    std::ifstream in(csv);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str().rfind("kind,", 0), 0u);
    EXPECT_NE(text.str().find("boundary,"), std::string::npos);
}

TEST(StabilityCli, UnknownModelAndMissingChoiceAreUsageErrors) {
    EXPECT_EQ(run("stability --model nope").status, 2);
    EXPECT_EQ(run("stability").status, 2);
}
