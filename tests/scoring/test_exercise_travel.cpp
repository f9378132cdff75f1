// Copying an exercise's mesh or preset into its folder (engine/exercise/ExerciseTravel.h): under its
// own name, reused when the same bytes are there, a new name when a different file holds it, never
// overwriting; errors name the file. Exercise bundles (engine/exercise/ExerciseBundle.h): a shipped
// exercise bundled and imported elsewhere opens on its own files alone; a bundle that is not one is
// refused naming the key, writing nothing; base64 round trips.
#include "engine/exercise/ExerciseTravel.h"

#include "base/io/Base64.h"
#include "engine/exercise/ExerciseBundle.h"
#include "engine/exercise/ExerciseFile.h"
#include "engine/scoring/ExerciseSession.h"
#include "tests/record/RecordTestRig.h"
#include "tests/scoring/ScoringTestRig.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

namespace palpate {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct ExerciseTravel : ::testing::Test {
    fs::path root;
    void SetUp() override {
        root = fs::temp_directory_path() /
               ("palpate-travel-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root);
        fs::create_directories(root / "mine");
        fs::create_directories(root / "class");
    }
    void TearDown() override { fs::remove_all(root); }
};

TEST_F(ExerciseTravel, AFileIsCopiedUnderItsNameAndReusedWhenTheSameBytesAreThere) {
    write(root / "mine" / "organ.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    std::string error;
    auto name = copyIntoFolder((root / "mine" / "organ.off").string(), (root / "class").string(), error);
    ASSERT_TRUE(name) << error;
    EXPECT_EQ(*name, "organ.off");
    EXPECT_EQ(read(root / "class" / "organ.off"), read(root / "mine" / "organ.off"));
    // Again: the copy is there already, nothing new.
    name = copyIntoFolder((root / "mine" / "organ.off").string(), (root / "class").string(), error);
    ASSERT_TRUE(name) << error;
    EXPECT_EQ(*name, "organ.off");
    EXPECT_EQ(std::distance(fs::directory_iterator(root / "class"), fs::directory_iterator()), 1);
    // A file in the folder itself is its own copy.
    name = copyIntoFolder((root / "class" / "organ.off").string(), (root / "class").string(), error);
    ASSERT_TRUE(name) << error;
    EXPECT_EQ(*name, "organ.off");
}

TEST_F(ExerciseTravel, ADifferentFileOfTheSameNameIsNeverOverwritten) {
    write(root / "class" / "organ.off", "someone else's organ");
    write(root / "class" / "organ-2.off", "and another");
    write(root / "mine" / "organ.off", "mine");
    std::string error;
    const auto name = copyIntoFolder((root / "mine" / "organ.off").string(), (root / "class").string(), error);
    ASSERT_TRUE(name) << error;
    EXPECT_EQ(*name, "organ-3.off");
    EXPECT_EQ(read(root / "class" / "organ.off"), "someone else's organ");
    EXPECT_EQ(read(root / "class" / "organ-2.off"), "and another");
    EXPECT_EQ(read(root / "class" / "organ-3.off"), "mine");
}

TEST_F(ExerciseTravel, WhatCannotBeCopiedIsNamed) {
    std::string error;
    EXPECT_FALSE(copyIntoFolder((root / "mine" / "missing.off").string(), (root / "class").string(), error));
    EXPECT_NE(error.find("missing.off"), std::string::npos) << error;
    EXPECT_FALSE(copyIntoFolder((root / "mine").string(), (root / "class").string(), error));  // a folder
    EXPECT_NE(error.find("mine"), std::string::npos) << error;
    write(root / "mine" / "organ.off", "mine");
    error.clear();
    EXPECT_FALSE(copyIntoFolder((root / "mine" / "organ.off").string(), (root / "nowhere").string(), error));
    EXPECT_NE(error.find("organ.off"), std::string::npos) << error;
    EXPECT_FALSE(fs::exists(root / "nowhere"));
}

std::size_t filesIn(const fs::path& folder) {
    return std::size_t(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

TEST(Base64, RoundTripsEveryLengthAndRefusesWhatIsNotCanonical) {
    std::string bytes;
    for (int n = 0; n < 300; ++n) {
        const std::string text = encodeBase64(bytes);
        EXPECT_EQ(text.size(), (bytes.size() + 2) / 3 * 4);
        ASSERT_EQ(decodeBase64(text), bytes) << n;
        bytes += char(n * 37 + 11);
    }
    EXPECT_EQ(encodeBase64("Man"), "TWFu");
    EXPECT_EQ(encodeBase64("Ma"), "TWE=");
    EXPECT_EQ(encodeBase64("M"), "TQ==");
    for (const char* bad : {"TWF", "TW=u", "T===", "TWE", "TWF=TWFu", "TWF\n", "TWE!", "TWF=", "TR=="})
        EXPECT_FALSE(decodeBase64(bad)) << bad;  // "TWF=" and "TR==" set pad bits
}

TEST_F(ExerciseTravel, AShippedExerciseBundledOpensElsewhereOnItsOwnFiles) {
    const std::string exercise = test::resourcesDir() + "/exercises/detect_lumps.json";
    const std::string bundle = (root / "mine" / "detect.palpex").string();
    ASSERT_EQ(writeExerciseBundle(exercise, bundle, test::testResourceFinder()), "");
    std::string error;
    const auto imported = importExerciseBundle(bundle, (root / "class").string(), error);
    ASSERT_TRUE(imported) << error;
    EXPECT_EQ(imported->exercisePath, (root / "class" / "detect_lumps.json").string());
    for (const char* name : {"detect_lumps.json", "sphere_8664.off", "muscle.json", "detect_lumps.good.path",
                             "detect_lumps.bad.path", "detect_lumps.light.path"})
        EXPECT_TRUE(fs::exists(root / "class" / name)) << name;
    EXPECT_EQ(read(root / "class" / "sphere_8664.off"), read(test::resourcesDir() + "/meshes/sphere_8664.off"));
    EXPECT_EQ(read(root / "class" / "detect_lumps.good.path"),
              read(test::resourcesDir() + "/exercises/detect_lumps.good.path"));
    // Without resources/ at all: the exercise finds its mesh and preset beside it and is the same.
    const auto loaded = loadExercise(imported->exercisePath);
    ASSERT_TRUE(loaded.exercise) << loaded.error();
    EXPECT_EQ(loaded.exercise->meshPath, "sphere_8664.off");
    std::vector<std::string> errors;
    const auto assets = loadExerciseAssets(*loaded.exercise, ResourceFinder{}, errors);
    ASSERT_TRUE(assets) << (errors.empty() ? "" : errors.front());
    EXPECT_EQ(assets->geometry->lumps().size(), 3u);
    Exercise original = test::loadExampleExercise("detect_lumps");
    original.meshPath = loaded.exercise->meshPath;
    original.tissuePresetPath = loaded.exercise->tissuePresetPath;
    EXPECT_EQ(exerciseToJson(*loaded.exercise), exerciseToJson(original));

    // Imported again: nothing new. Into a folder where another sphere_8664.off lives: renamed, kept.
    const std::size_t before = filesIn(root / "class");
    ASSERT_TRUE(importExerciseBundle(bundle, (root / "class").string(), error)) << error;
    EXPECT_EQ(filesIn(root / "class"), before);
    fs::create_directories(root / "other");
    write(root / "other" / "sphere_8664.off", "someone else's");
    const auto second = importExerciseBundle(bundle, (root / "other").string(), error);
    ASSERT_TRUE(second) << error;
    EXPECT_EQ(read(root / "other" / "sphere_8664.off"), "someone else's");
    EXPECT_EQ(loadExercise(second->exercisePath).exercise->meshPath, "sphere_8664-2.off");

    // The bundle is never written over one of its inputs.
    EXPECT_NE(
        writeExerciseBundle(imported->exercisePath, (root / "class" / "sphere_8664.off").string(), {}).find("mesh"),
        std::string::npos);
    EXPECT_EQ(read(root / "class" / "sphere_8664.off"), read(test::resourcesDir() + "/meshes/sphere_8664.off"));
}

TEST_F(ExerciseTravel, ABundleThatIsNotOneIsRefusedNamingTheKeyAndWritesNothing) {
    const std::string exercise = test::resourcesDir() + "/exercises/find_lump.json";
    const std::string good = (root / "mine" / "find.palpex").string();
    ASSERT_EQ(writeExerciseBundle(exercise, good, test::testResourceFinder()), "");
    const nlohmann::ordered_json j = nlohmann::ordered_json::parse(read(good));
    struct Case {
        const char* what;
        std::function<void(nlohmann::ordered_json&)> change;
        const char* key;
    };
    const std::vector<Case> cases{
        {"another format", [](auto& b) { b["format"] = "palpate-exercise"; }, "format"},
        {"a newer version", [](auto& b) { b["version"] = 99; }, "version"},
        {"a name that leaves the folder", [](auto& b) { b["files"][0]["name"] = "../escape.off"; }, "files[0].name"},
        {"an absolute name", [](auto& b) { b["files"][0]["name"] = "/tmp/x.off"; }, "files[0].name"},
        {"bad base64", [](auto& b) { b["files"][0]["base64"] = "not base64!"; }, "files[0].base64"},
        {"an unknown role", [](auto& b) { b["files"][0]["role"] = "script"; }, "files[0].role"},
        {"an unknown key", [](auto& b) { b["extra"] = 1; }, "extra"},
        {"no mesh", [](auto& b) { b["files"].erase(0); }, "files"},
        {"a name twice", [](auto& b) { b["files"][1]["name"] = b["files"][0]["name"]; }, "files[1].name"},
        {"the exercise on another mesh", [](auto& b) { b["exercise"]["mesh"] = "other.off"; }, "exercise.mesh"},
        {"a broken exercise", [](auto& b) { b["exercise"]["time_limit_s"] = -1; }, "time_limit_s"},
        {"an exercise file name with a folder", [](auto& b) { b["exercise_file"] = "a/b.json"; }, "exercise_file"},
    };
    for (const Case& c : cases) {
        nlohmann::ordered_json b = j;
        c.change(b);
        const std::string path = (root / "mine" / "bad.palpex").string();
        write(path, b.dump());
        std::string error;
        EXPECT_FALSE(importExerciseBundle(path, (root / "class").string(), error)) << c.what;
        EXPECT_NE(error.find(path), std::string::npos) << c.what << ": " << error;
        EXPECT_NE(error.find(c.key), std::string::npos) << c.what << ": " << error;
        EXPECT_EQ(filesIn(root / "class"), 0u) << c.what;
    }
    std::string error;
    EXPECT_FALSE(importExerciseBundle(good, (root / "nowhere").string(), error));
    EXPECT_NE(error.find("nowhere"), std::string::npos) << error;
    write(root / "mine" / "text.palpex", "not json at all");
    EXPECT_FALSE(importExerciseBundle((root / "mine" / "text.palpex").string(), (root / "class").string(), error));
    EXPECT_NE(error.find("text.palpex"), std::string::npos) << error;
}

TEST_F(ExerciseTravel, TheCommandLineBundlesAndImports) {
    const std::string exercise = test::resourcesDir() + "/exercises/trace.json";
    const std::string bundle = (root / "mine" / "trace.palpex").string();
    auto r = test::runCli("exercise bundle " + test::shellQuote(exercise) + " --out " + test::shellQuote(bundle));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = test::runCli("exercise import " + test::shellQuote(bundle) + " --into " +
                     test::shellQuote((root / "class").string()));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("trace.json"), std::string::npos) << r.output;
    EXPECT_TRUE(loadExercise((root / "class" / "trace.json").string()).exercise);
    // Usage: no --out is a usage error; the bundle over its own exercise a failure; --help answers.
    EXPECT_EQ(test::runCli("exercise bundle " + test::shellQuote(exercise)).exitCode, 2);
    r = test::runCli("exercise bundle " + test::shellQuote((root / "class" / "trace.json").string()) + " --out " +
                     test::shellQuote((root / "class" / "trace.json").string()));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_TRUE(loadExercise((root / "class" / "trace.json").string()).exercise) << "the input is intact";
    EXPECT_EQ(test::runCli("exercise import --help").exitCode, 0);
}

}  // namespace
}  // namespace palpate
