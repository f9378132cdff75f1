// palpate-cli lod, run as a separate process on small meshes with --quick: levels are made and
// cached; plan prints the documented JSON and chooses the coarsest level with the fewest rings for
// a lax target; an impossible target exits 1 naming the closest; bad input exits with a message
// naming the problem; needs come from an exercise file.
#include "tests/engine/TestMeshes.h"
#include "tests/lod/LodTestMeshes.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace palpate {
namespace {

using Json = nlohmann::json;
using test::shellQuote;

class LodCli : public ::testing::Test {
protected:
    void SetUp() override {
        cli = test::cliPath();
        if (cli.empty()) GTEST_SKIP() << "built without PALPATE_CLI_PATH";
        meshPath = dir.file("sphere 1442.obj");  // a space in the path, on purpose
        ASSERT_EQ(test::generated(GeneratedShape::Sphere, 1442).save(meshPath), "");
    }
    /// stdout only (stderr to a file), for JSON.
    test::CommandResult runJson(const std::string& args) const {
        // runCommand appends 2>&1; inside the braces stderr has already gone to the file.
        return test::runCommand("{ " + shellQuote(cli) + " " + args + " 2>" + shellQuote(dir.file("stderr.txt")) + "; }");
    }
    test::CommandResult run(const std::string& args) const { return test::runCommand(shellQuote(cli) + " " + args); }
    std::string stderrText() const { return test::readFile(dir.file("stderr.txt")); }

    test::TempDir dir;
    std::string cli;
    std::string meshPath;
};

TEST_F(LodCli, LevelsAreMadeCheckedAndCached) {
    const auto first = runJson("lod levels --json --min-vertices 150 --mesh " + shellQuote(meshPath));
    ASSERT_EQ(first.exitCode, 0) << first.output << stderrText();
    const Json j = Json::parse(first.output);
    EXPECT_FALSE(j["from_cache"].get<bool>());
    ASSERT_GE(j["levels"].size(), 3u);
    EXPECT_EQ(j["levels"][0]["vertices"], 1442);
    for (const Json& level : j["levels"]) {
        EXPECT_TRUE(level["closed"].get<bool>());
        EXPECT_TRUE(level["manifold"].get<bool>());
        EXPECT_EQ(level["problem"], "");
    }
    EXPECT_TRUE(std::filesystem::exists(meshPath + ".levels/levels.json"));
    const auto second = runJson("lod levels --json --min-vertices 150 --mesh " + shellQuote(meshPath));
    ASSERT_EQ(second.exitCode, 0) << second.output;
    EXPECT_TRUE(Json::parse(second.output)["from_cache"].get<bool>());
    // The table form says the same.
    const auto text = run("lod levels --min-vertices 150 --mesh " + shellQuote(meshPath));
    EXPECT_EQ(text.exitCode, 0) << text.output;
    EXPECT_NE(text.output.find("closed, manifold"), std::string::npos) << text.output;
}

TEST_F(LodCli, PlanPrintsTheDocumentedJsonAndChoosesTheCheapest) {
    // A lax target: everything qualifies, so the coarsest level with 1 ring is the choice.
    const auto r = runJson("lod plan --quick --json --error 1.0 --budget-us 100000 --mesh " + shellQuote(meshPath));
    ASSERT_EQ(r.exitCode, 0) << r.output << stderrText();
    const Json j = Json::parse(r.output);
    ASSERT_TRUE(j["feasible"].get<bool>());
    const Json& chosen = j["chosen"];
    for (const char* key : {"vertices", "rings", "model", "error", "tick_us"}) EXPECT_TRUE(chosen.contains(key)) << key;
    ASSERT_GE(j["candidates"].size(), 6u);
    std::size_t fewestVertices = SIZE_MAX;
    for (const Json& c : j["candidates"]) {
        for (const char* key : {"vertices", "rings", "model", "error", "tick_us"}) EXPECT_TRUE(c.contains(key)) << key;
        fewestVertices = std::min(fewestVertices, c["vertices"].get<std::size_t>());
    }
    EXPECT_EQ(chosen["vertices"].get<std::size_t>(), fewestVertices);
    EXPECT_EQ(chosen["rings"], 1);
    EXPECT_EQ(chosen["model"], "coherent");
    EXPECT_NE(j["reason"].get<std::string>().find("coarsest"), std::string::npos);
    // Linear or stiffening tissue: within a 100 % target the linear model is enough.
    const Json& stiff = j["stiffening"];
    for (const char* key : {"law", "nonlinear", "knots", "feasible", "linear_error", "nonlinear_error", "depths", "reason"})
        EXPECT_TRUE(stiff.contains(key)) << key;
    EXPECT_FALSE(stiff["nonlinear"].get<bool>());
    EXPECT_TRUE(stiff["feasible"].get<bool>());
    EXPECT_EQ(stiff["depths"][0]["what"], "the plan's press");
    EXPECT_NE(stiff["reason"].get<std::string>().find("Linear tissue"), std::string::npos);

    // A target between the candidates' errors: the choice meets it, and no candidate that also
    // meets both is coarser or as coarse with fewer rings.
    std::vector<double> errors;
    for (const Json& c : j["candidates"]) errors.push_back(c["error"].get<double>());
    std::sort(errors.begin(), errors.end());
    const double target = errors[errors.size() / 2];
    const auto mid = runJson("lod plan --quick --json --budget-us 100000 --error " + std::to_string(target) +
                             " --mesh " + shellQuote(meshPath));
    ASSERT_EQ(mid.exitCode, 0) << mid.output << stderrText();
    const Json m = Json::parse(mid.output);
    const Json& pick = m["chosen"];
    EXPECT_LE(pick["error"].get<double>(), std::stod(std::to_string(target)) + 1e-12);
    for (const Json& c : m["candidates"]) {
        if (!c["meets_error"].get<bool>() || !c["meets_budget"].get<bool>()) continue;
        EXPECT_FALSE(c["vertices"] < pick["vertices"] || (c["vertices"] == pick["vertices"] && c["rings"] < pick["rings"]));
    }
}

TEST_F(LodCli, AnImpossibleTargetExitsOneAndNamesTheClosest) {
    const auto r = runJson("lod plan --quick --json --error 1e-6 --budget-us 100000 --mesh " + shellQuote(meshPath));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    const Json j = Json::parse(r.output);
    EXPECT_FALSE(j["feasible"].get<bool>());
    EXPECT_TRUE(j["chosen"].is_null());
    ASSERT_TRUE(j["closest"].is_object());
    EXPECT_NE(stderrText().find("nothing fits"), std::string::npos) << stderrText();
    const auto text = run("lod plan --quick --error 1e-6 --budget-us 100000 --mesh " + shellQuote(meshPath));
    EXPECT_EQ(text.exitCode, 1);
    EXPECT_NE(text.output.find("Closest: level"), std::string::npos) << text.output;
}

TEST_F(LodCli, BadInputIsNamed) {
    struct Case {
        std::string args;
        int exitCode;
        std::string words;
    };
    const std::string mesh = " --mesh " + shellQuote(meshPath);
    const std::string broken = dir.write("bowtie.off", test::toOff(test::bowtieTetrahedra()));
    for (const Case& c : std::vector<Case>{
             {"lod plan --quick --error -0.1 --budget-us 100" + mesh, 2, "--error: must be above 0"},
             {"lod plan --quick --error 0.1 --budget-us 0" + mesh, 2, "--budget-us: must be above 0"},
             {"lod plan --quick --error lots --budget-us 10" + mesh, 2, "--error: 'lots' is not a number"},
             {"lod plan --quick --error 0.1" + mesh, 2, "--budget-us"},
             {"lod plan --quick --error 0.1 --budget-us 10 --rings 0" + mesh, 2, "--rings"},
             {"lod plan --quick --error 0.1 --budget-us 10 --mesh /no/such.obj", 1, "/no/such.obj: no such file"},
             {"lod plan --quick --error 0.1 --budget-us 10 --mesh " + shellQuote(broken), 1, "non-manifold"},
             {"lod levels --mesh " + shellQuote(broken), 1, "non-manifold"},
             {"lod levels", 2, "--mesh FILE is required"},
             {"lod levels --ratio 2" + mesh, 2, "vertex ratio"},
             {"lod frobnicate", 2, "unknown subcommand"},
         }) {
        const auto r = run(c.args);
        EXPECT_EQ(r.exitCode, c.exitCode) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.words), std::string::npos) << c.args << "\n" << r.output;
    }
}

TEST_F(LodCli, ACorruptCacheIsRegenerated) {
    ASSERT_EQ(run("lod levels --min-vertices 150 --mesh " + shellQuote(meshPath)).exitCode, 0);
    { std::ofstream(meshPath + ".levels/levels.json") << "{\"format\": \"palpate-mesh-levels\", \"version\": "; }
    const auto r = run("lod levels --min-vertices 150 --mesh " + shellQuote(meshPath));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("corrupt"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("closed, manifold"), std::string::npos) << r.output;
}

TEST_F(LodCli, NeedsComeFromTheExercise) {
    const std::string exercise = dir.write("ex.json", R"({
      "format": "palpate-exercise", "version": 1, "name": "e", "type": "press_targets",
      "mesh": "sphere 1442.obj", "tissue_preset": "presets/default.json", "time_limit_s": 30,
      "press_targets": {"targets": [{"vertex": 3}]},
      "needs": {"max_error": 1.0, "budget_us": 100000}
    })");
    const auto r = runJson("lod plan --quick --json --exercise " + shellQuote(exercise));
    ASSERT_EQ(r.exitCode, 0) << r.output << stderrText();
    const Json j = Json::parse(r.output);
    EXPECT_EQ(j["needs"]["max_error"], 1.0);
    EXPECT_EQ(j["needs"]["budget_us"], 100000.0);
    EXPECT_EQ(j["needs"]["source"], exercise);
    EXPECT_TRUE(j["feasible"].get<bool>());
    // The command line overrides one of them.
    const auto strict = runJson("lod plan --quick --json --error 1e-6 --exercise " + shellQuote(exercise));
    EXPECT_EQ(strict.exitCode, 1) << strict.output;
    EXPECT_EQ(Json::parse(strict.output)["needs"]["max_error"], 1e-6);
}

TEST_F(LodCli, StiffeningTissueIsChosenWhereTheLinearForceMissesTheTarget) {
    // A tissue that stiffens (b = 5) pressed to 1 N: at that depth the linear force misses a 5 %
    // target, so the knots are chosen, and they meet it.
    const std::string exercise = dir.write("deep.json", R"({
      "format": "palpate-exercise", "version": 1, "name": "e", "type": "press_targets",
      "mesh": "sphere 1442.obj", "tissue_preset": "presets/default.json", "time_limit_s": 30,
      "press_targets": {"targets": [{"vertex": 3, "force_min_n": 0.5, "force_max_n": 1.0}]}
    })");
    const auto r = runJson("lod plan --quick --json --error 0.5 --budget-us 100000 --stiffening-exponent 5 --exercise " +
                           shellQuote(exercise));
    ASSERT_EQ(r.exitCode, 0) << r.output << stderrText();
    const Json lax = Json::parse(r.output)["stiffening"];
    const double linearError = lax["linear_error"].get<double>();
    EXPECT_GT(linearError, 0.05);
    EXPECT_LT(lax["nonlinear_error"].get<double>(), std::min(0.05, linearError / 3.0));
    EXPECT_NE(lax["depths"][0]["what"].get<std::string>().find("press target 1"), std::string::npos);
    EXPECT_EQ(lax["nonlinear"].get<bool>(), linearError > 0.5);

    const auto strict = runJson("lod plan --quick --json --error 0.05 --budget-us 100000 --stiffening-exponent 5 --exercise " +
                                shellQuote(exercise));
    const Json s = Json::parse(strict.output)["stiffening"];
    EXPECT_TRUE(s["nonlinear"].get<bool>());
    EXPECT_TRUE(s["feasible"].get<bool>());
    EXPECT_GT(s["knots"].get<int>(), 0);
    EXPECT_NE(s["reason"].get<std::string>().find("Stiffening tissue"), std::string::npos) << s["reason"];
    // Neo-Hookean tissue at the same depth stiffens less than b = 5 does.
    const auto neo = runJson("lod plan --quick --json --error 0.5 --budget-us 100000 --exercise " + shellQuote(exercise));
    EXPECT_LT(Json::parse(neo.output)["stiffening"]["linear_error"].get<double>(), linearError);
}

}  // namespace
}  // namespace palpate
