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

TEST(StabilityCli, EveryNewMapRunsQuicklyFromTheCli) {
    for (const char* name : {"radius-of-influence", "volumetric-rings", "mass-spring-local"}) {
        const CliRun r = run(std::string("stability --model ") + name + " --quick --json");
        ASSERT_EQ(r.status, 0) << name;
        const auto json = nlohmann::json::parse(r.out);
        EXPECT_EQ(json["model"], name);
        EXPECT_EQ(json["cells"].size(), 36u) << name;
        EXPECT_LT(json["relative_gap"].get<double>(), 0.05) << name;
    }
}

TEST(StabilityCli, PassivityIsInTheJsonAndTheCsvOfTheMapsThatHaveIt) {
    const std::string csv = ::testing::TempDir() + "stability_passivity.csv";
    const CliRun r = run("stability --model slope-ring-passivity --quick --json --csv " + csv);
    ASSERT_EQ(r.status, 0);
    const auto json = nlohmann::json::parse(r.out);
    ASSERT_TRUE(json["passivity"].is_object());
    EXPECT_NE(json["passivity"]["formula"].get<std::string>().find("K_eq"), std::string::npos);
    int passive = 0, not_passive = 0;
    for (const auto& cell : json["cells"]) {
        ASSERT_TRUE(cell.contains("passivity_ratio"));
        (cell["passive"].get<bool>() ? passive : not_passive) += 1;
        // Passivity is sufficient: a passive cell is a bounded one.
        if (cell["passive"].get<bool>()) {
            EXPECT_TRUE(cell["bounded"].get<bool>()) << cell.dump();
        }
    }
    EXPECT_GT(passive, 0);
    EXPECT_GT(not_passive, 0);
    EXPECT_LT(json["relative_gap"].get<double>(), 0.08);
    std::ifstream in(csv);
    std::string header;
    std::getline(in, header);
    EXPECT_NE(header.find(",passivity_ratio"), std::string::npos) << header;
    // A map without passivity says so.
    const CliRun plain = run("stability --model mass-spring-implicit --quick --json");
    ASSERT_EQ(plain.status, 0);
    EXPECT_TRUE(nlohmann::json::parse(plain.out)["passivity"].is_null());
}

// The models bench (docs/models.md): bench models --csv writes one row per model and size (here a small sphere).
TEST(BenchModelsCli, CsvHasOneRowPerModelAndSize) {
    const std::string csv = ::testing::TempDir() + "bench_models.csv";
    const CliRun r = run("bench models --sizes 242 --models radius-of-influence,ffd --repeats 1 --budget-s 2 --csv " + csv);
    ASSERT_EQ(r.status, 0);
    std::ifstream in(csv);
    std::string header, line;
    std::getline(in, header);
    EXPECT_EQ(header, "model,vertices,tick_us,displacement_error,force_error,repeats,note,reason");
    int rows = 0;
    while (std::getline(in, line)) {
        ++rows;
        EXPECT_TRUE(line.rfind("radius-of-influence,242,", 0) == 0 || line.rfind("ffd,242,", 0) == 0) << line;
        EXPECT_NE(line.find(",1,\""), std::string::npos) << line;  // repeats, then the quoted note
    }
    EXPECT_EQ(rows, 2);
}
