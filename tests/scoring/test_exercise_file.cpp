// Exercise files: the shipped examples read; save and load round-trip; every kind of mistake is an
// error naming the file and the key; the recording note carries an exercise.
#include "engine/exercise/ExerciseFile.h"
#include "engine/exercise/ExerciseGeometry.h"
#include "tests/record/RecordTestRig.h"
#include "tests/scoring/ScoringTestRig.h"
#include "tests/scoring/SyntheticTicks.h"
#include "engine/exercise/ExerciseKind.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>

namespace palpate {
namespace {

using Json = nlohmann::ordered_json;

Json pressJson() {
    return Json::parse(R"({
      "format": "palpate-exercise", "version": 1, "name": "p", "type": "press_targets",
      "mesh": "meshes/sphere_1442.off", "tissue_preset": "presets/default.json", "time_limit_s": 30,
      "press_targets": {"targets": [{"vertex": 3}, {"point_mm": [1, 2, 3], "hold_s": 0.5}]}
    })");
}

/// The errors of parsing `j`, joined.
std::string errorsOf(const Json& j) {
    const auto r = parseExercise(j.dump(), "ex.json");
    std::string all;
    for (const auto& e : r.errors) all += e + "\n";
    EXPECT_EQ(r.exercise.has_value(), r.errors.empty());
    return all;
}

void expectError(const Json& j, const std::string& key, const std::string& words = "") {
    const std::string errors = errorsOf(j);
    EXPECT_NE(errors.find("ex.json: " + key + ": " + words), std::string::npos)
        << "wanted an error on '" << key << "'" << (words.empty() ? "" : " saying '" + words + "'") << ", got:\n"
        << errors;
}

TEST(ExerciseFile, ShippedExamplesRead) {
    for (const char* name : {"press_targets", "find_lump", "trace"}) {
        const auto r = loadExercise(test::resourcesDir() + "/exercises/" + name + ".json");
        ASSERT_TRUE(r.exercise) << r.error();
        EXPECT_EQ(exerciseTypeName(r.exercise->type), name);
        std::vector<std::string> errors;
        const auto assets = loadExerciseAssets(*r.exercise, test::testResourceFinder(), errors);
        ASSERT_TRUE(assets) << errors.front();
        EXPECT_FALSE(assets->meshPath.empty());
    }
    const Exercise press = test::loadExampleExercise("press_targets");
    ASSERT_EQ(press.pressTargets.targets.size(), 3u);
    EXPECT_DOUBLE_EQ(press.pressTargets.targets[0].forceMinN, 1.0);  // the section's default
    EXPECT_DOUBLE_EQ(press.pressTargets.targets[2].forceMinN, 1.5);  // the target's own
}

TEST(ExerciseFile, SaveLoadRoundTrip) {
    test::TempDir dir;
    for (const char* name : {"press_targets", "find_lump", "trace"}) {
        Exercise e = test::loadExampleExercise(name);
        e.rubric[std::size_t(Metric::Completion)] = RubricItem{33.0, 0.9, 0.1};
        e.showLiveScore = false;
        const std::string path = dir.file(std::string(name) + ".json");
        ASSERT_EQ(saveExercise(e, path), "");
        EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
        const auto back = loadExercise(path);
        ASSERT_TRUE(back.exercise) << back.error();
        EXPECT_EQ(exerciseToJson(*back.exercise), exerciseToJson(e));
        EXPECT_DOUBLE_EQ(back.exercise->rubric[std::size_t(Metric::Completion)]->weight, 33.0);
        EXPECT_EQ(back.exercise->showLiveScore, std::optional<bool>(false));
        EXPECT_FALSE(showsLiveScore(*back.exercise));
    }
    // An invalid exercise is not saved, and an existing file stays as it was.
    Exercise bad = test::loadExampleExercise("trace");
    const std::string path = dir.file("trace.json");
    bad.trace.forceMaxN = 0.1;
    const std::string problem = saveExercise(bad, path);
    EXPECT_NE(problem.find("trace.force_max_n"), std::string::npos) << problem;
    EXPECT_TRUE(loadExercise(path).exercise);
}

// An exercise carries its words in other languages; a user of one reads them, with the exercise's
// own words for whatever the translation leaves out; the codes and entries are checked.
TEST(ExerciseFile, TranslationsRoundTripFallBackAndAreChecked) {
    Json j = pressJson();
    j["description"] = "Press them.";
    j["translations"] = Json::parse(R"({"de": {"name": "Drücken", "description": "Drücken Sie."},
                                        "ms": {"name": "Tekan"}})");
    const auto r = parseExercise(j.dump(), "ex.json");
    ASSERT_TRUE(r.exercise) << r.error();
    const Exercise& e = *r.exercise;
    EXPECT_EQ(exerciseTextIn(e, "de").name, "Drücken");
    EXPECT_EQ(exerciseTextIn(e, "de_AT").description, "Drücken Sie.");  // the region falls back to its language
    EXPECT_EQ(exerciseTextIn(e, "ms").name, "Tekan");
    EXPECT_EQ(exerciseTextIn(e, "ms").description, "Press them.");  // not translated: the exercise's own
    EXPECT_EQ(exerciseTextIn(e, "fr").name, "p");
    EXPECT_EQ(exerciseTextIn(e, "en").description, "Press them.");
    // Written back as read, and parsed to the same exercise.
    const auto back = parseExercise(exerciseToJson(e), "ex.json");
    ASSERT_TRUE(back.exercise) << back.error();
    EXPECT_EQ(exerciseToJson(*back.exercise), exerciseToJson(e));
    EXPECT_EQ(back.exercise->translations.at("ms").description, "");

    for (const char* code : {"de", "ms", "pt_BR", "fil"}) EXPECT_TRUE(isLanguageCode(code)) << code;
    for (const char* code : {"", "D", "DE", "de-AT", "de_at", "deutsch", "de_ATX", "d\x1b"})
        EXPECT_FALSE(isLanguageCode(code)) << code;

    Json bad = pressJson();
    bad["translations"] = "German";
    expectError(bad, "translations", "must be an object");
    bad["translations"] = Json::parse(R"({"Deutsch": {"name": "x"}})");
    expectError(bad, "translations", "a key of 7 bytes is not a language code");
    bad["translations"] = Json::parse(R"({"de": {"title": "x"}})");
    expectError(bad, "translations.de.title", "unknown key");
    bad["translations"] = Json::parse(R"({"de": {"name": 3}})");
    expectError(bad, "translations.de.name", "must be a string");
    bad["translations"] = Json::parse(R"({"de": {}})");
    expectError(bad, "translations.de", "gives neither a name nor a description");
}

// Every shipped exercise speaks German and Malay: a name and a description in each.
TEST(ExerciseFile, ShippedExercisesCarryGermanAndMalay) {
    int exercises = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::resourcesDir() + "/exercises")) {
        if (entry.path().extension() != ".json") continue;
        const auto r = loadExercise(entry.path().string());
        ASSERT_TRUE(r.exercise) << r.error();
        ++exercises;
        for (const char* code : {"de", "ms"}) {
            const ExerciseTextDef text = exerciseTextIn(*r.exercise, code);
            EXPECT_NE(text.name, r.exercise->name) << entry.path() << " in " << code;
            EXPECT_NE(text.description, r.exercise->description) << entry.path() << " in " << code;
        }
    }
    EXPECT_GE(exercises, 5);
}

TEST(ExerciseFile, ErrorsNameTheKey) {
    EXPECT_EQ(errorsOf(pressJson()), "");
    auto with = [](const std::function<void(Json&)>& change) {
        Json j = pressJson();
        change(j);
        return j;
    };
    expectError(with([](Json& j) { j["colour"] = "red"; }), "colour", "unknown key");
    expectError(with([](Json& j) { j["show_live_score"] = "yes"; }), "show_live_score", "must be true or false");
    expectError(with([](Json& j) { j["press_targets"]["targets"][1]["hold"] = 1; }), "press_targets.targets[1].hold",
                "unknown key");
    expectError(with([](Json& j) { j["format"] = "palpate-tissue-preset"; }), "format");
    expectError(with([](Json& j) { j["version"] = 2; }), "version", "version 2");
    expectError(with([](Json& j) { j.erase("name"); }), "name", "missing");
    expectError(with([](Json& j) { j.erase("mesh"); }), "mesh", "missing");
    expectError(with([](Json& j) { j["type"] = "poke"; }), "type", "unknown type 'poke'");
    expectError(with([](Json& j) { j["time_limit_s"] = "long"; }), "time_limit_s", "must be a number");
    expectError(with([](Json& j) { j["time_limit_s"] = 0; }), "time_limit_s", "0 is out of range");
    expectError(with([](Json& j) { j["damage"] = {{"displacement_limit_mm", -1}}; }), "damage.displacement_limit_mm");
    expectError(with([](Json& j) { j["force"] = {{"excessive_n", 0.5}}; }), "press_targets.targets[0].force_min_n",
                "1 N is not below force.excessive_n");
    expectError(with([](Json& j) { j["press_targets"]["targets"][0]["force_max_n"] = 0.5; }),
                "press_targets.targets[0].force_max_n", "0.5 must be greater than force_min_n 1");
    expectError(with([](Json& j) { j["press_targets"]["targets"][0]["tolerance_mm"] = 0; }),
                "press_targets.targets[0].tolerance_mm");
    expectError(with([](Json& j) { j["press_targets"]["targets"][0]["point_mm"] = {1, 2, 3}; }),
                "press_targets.targets[0]", "give vertex or point_mm, not both");
    expectError(with([](Json& j) { j["press_targets"]["targets"][0].erase("vertex"); }), "press_targets.targets[0]",
                "needs vertex or point_mm");
    expectError(with([](Json& j) { j["press_targets"]["targets"][0]["vertex"] = -3; }),
                "press_targets.targets[0].vertex");
    expectError(with([](Json& j) { j["press_targets"]["targets"][1]["point_mm"] = {1, 2}; }),
                "press_targets.targets[1].point_mm", "must be an array of three numbers");
    expectError(with([](Json& j) { j["press_targets"]["targets"] = Json::array(); }), "press_targets.targets",
                "needs at least one target");
    expectError(with([](Json& j) { j["trace"] = {{"path", Json::array()}}; }), "trace", "given, but type is press_targets");
    expectError(with([](Json& j) { j.erase("press_targets"); }), "press_targets", "missing");
    expectError(with([](Json& j) { j["rubric"] = {{"speed", {{"weight", 1}}}}; }), "rubric.speed", "unknown metric");
    expectError(with([](Json& j) { j["rubric"] = {{"lump_error_mm", {{"weight", 1}}}}; }), "rubric.lump_error_mm",
                "is not measured by press_targets");
    expectError(with([](Json& j) { j["rubric"] = {{"time_s", {{"full", 5}, {"zero", 5}}}}; }), "rubric.time_s.zero",
                "equals full");
    expectError(with([](Json& j) { j["rubric"] = {{"time_s", {{"weight", -1}}}}; }), "rubric.time_s.weight");
    expectError(with([](Json& j) { j["rubric"] = {{"time_s", {{"wieght", 1}}}}; }), "rubric.time_s.wieght", "unknown key");
    {
        Json j = pressJson();
        for (const char* m : {"completion", "time_s", "target_error_mm", "hold_in_window_fraction",
                              "excessive_force_events", "excessive_force_fraction", "damage_time_s", "economy"})
            j["rubric"][m] = {{"weight", 0}};
        expectError(j, "rubric", "every weight is 0");
    }
    // Find the lump and trace sections.
    Json lump = pressJson();
    lump["type"] = "find_lump";
    lump.erase("press_targets");
    lump["find_lump"] = {{"inclusion", {{"centre", {{"vertex", 1}}}, {"radius_mm", 5}, {"stiffness_factor", 1.5}}}};
    expectError(lump, "find_lump.inclusion.stiffness_factor", "1.5 is out of range (0, 1]");
    lump["find_lump"]["inclusion"].erase("radius_mm");
    expectError(lump, "find_lump.inclusion.radius_mm", "missing");
    Json trace = pressJson();
    trace["type"] = "trace";
    trace.erase("press_targets");
    trace["trace"] = {{"path", Json::array({Json{{"vertex", 1}}})}, {"force_min_n", 0.5}, {"force_max_n", 1.0}};
    expectError(trace, "trace.path", "needs at least 2 points");
    // Not JSON at all, and a missing file.
    const auto broken = parseExercise("{\"format\": ", "ex.json");
    ASSERT_FALSE(broken.errors.empty());
    EXPECT_NE(broken.error().find("ex.json: not valid JSON"), std::string::npos);
    EXPECT_NE(loadExercise("/nonexistent/x.json").error().find("no such file"), std::string::npos);
}

TEST(ExerciseFile, VertexNotOnTheMeshNamesTheKey) {
    Exercise e = test::gridExercise(ExerciseType::Trace);
    e.trace.path.resize(3);
    e.trace.path[0].vertex = 0;
    e.trace.path[1].vertex = 4;
    e.trace.path[2].vertex = 25;  // the grid has 25 vertices
    std::string error;
    EXPECT_EQ(ExerciseGeometry::build(e, test::gridMesh(), error), nullptr);
    EXPECT_EQ(error, "trace.path[2]: vertex 25 is not a vertex of grid (25 vertices)");
}

TEST(ExerciseFile, PathsResolveBesideTheFileThenUnderResources) {
    test::TempDir dir;
    Exercise e = test::loadExampleExercise("find_lump");
    e.sourcePath = dir.file("mine.json");
    EXPECT_EQ(resolveExercisePath(e, e.meshPath), "");
    EXPECT_EQ(resolveExercisePath(e, e.meshPath, test::testResourceFinder()),
              test::resourcesDir() + "/meshes/sphere_1442.off");
    std::filesystem::create_directories(dir.path() / "meshes");
    std::filesystem::copy_file(test::resourcesDir() + "/meshes/sphere_1442.off", dir.file("meshes/sphere_1442.off"));
    EXPECT_EQ(resolveExercisePath(e, e.meshPath, test::testResourceFinder()), dir.file("meshes/sphere_1442.off"));
    std::vector<std::string> errors;
    e.tissuePresetPath = "presets/none.json";
    EXPECT_FALSE(loadExerciseAssets(e, test::testResourceFinder(), errors));
    ASSERT_FALSE(errors.empty());
    EXPECT_NE(errors.front().find("mine.json: tissue_preset: presets/none.json was found neither"), std::string::npos)
        << errors.front();
}

TEST(ExerciseFile, RecordingNoteCarriesTheExercise) {
    const Exercise e = test::loadExampleExercise("trace");
    std::string error;
    const std::string note = exerciseRecordingNote(e, "trainee: A. Student", error);
    ASSERT_EQ(error, "");
    EXPECT_EQ(note.rfind("trainee: A. Student\npalpate-exercise: {", 0), 0u);
    std::vector<std::string> errors;
    const auto back = exerciseFromRecordingNote(note, errors);
    ASSERT_TRUE(back);
    EXPECT_TRUE(errors.empty());
    EXPECT_EQ(exerciseToJson(*back), exerciseToJson(e));
    EXPECT_FALSE(exerciseFromRecordingNote("just a note about palpate-exercise: x", errors));
    EXPECT_TRUE(errors.empty());
    EXPECT_FALSE(exerciseFromRecordingNote("palpate-exercise: {\"format\": 1}", errors));
    EXPECT_FALSE(errors.empty());
    // Too large for a note (RecordingFormat.h).
    Exercise huge = e;
    huge.description.assign(kMaxNoteBytes, 'x');
    EXPECT_EQ(exerciseRecordingNote(huge, "", error), "");
    EXPECT_NE(error.find("too large"), std::string::npos);
}

}  // namespace
}  // namespace palpate

namespace palpate {
namespace {

// "needs" (docs/lod.md): optional; round-trips; absurd values are errors naming the key.
TEST(ExerciseFile, NeedsAreOptionalRoundTripAndNamedWhenBad) {
    const auto plain = parseExercise(pressJson().dump(), "ex.json");
    ASSERT_TRUE(plain.exercise) << plain.error();
    EXPECT_FALSE(plain.exercise->needs);
    EXPECT_EQ(exerciseToJson(*plain.exercise).find("needs"), std::string::npos);

    Json j = pressJson();
    j["needs"] = {{"max_error", 0.08}, {"budget_us", 150}};
    const auto read = parseExercise(j.dump(), "ex.json");
    ASSERT_TRUE(read.exercise) << read.error();
    ASSERT_TRUE(read.exercise->needs);
    EXPECT_EQ(read.exercise->needs->maxErrorFraction, 0.08);
    EXPECT_EQ(read.exercise->needs->budgetUs, 150.0);
    const auto again = parseExercise(exerciseToJson(*read.exercise), "ex.json");
    ASSERT_TRUE(again.exercise) << again.error();
    ASSERT_TRUE(again.exercise->needs);
    EXPECT_EQ(exerciseToJson(*again.exercise), exerciseToJson(*read.exercise));

    auto with = [&](const Json& needs) {
        Json k = pressJson();
        k["needs"] = needs;
        return k;
    };
    expectError(with({{"max_error", -1}, {"budget_us", 100}}), "needs.max_error", "must be above 0");
    expectError(with({{"max_error", 0}, {"budget_us", 100}}), "needs.max_error", "must be above 0");
    expectError(with({{"max_error", 0.1}, {"budget_us", 0}}), "needs.budget_us", "must be above 0");
    expectError(with({{"max_error", 50}, {"budget_us", 100}}), "needs.max_error", "50 is absurd");
    expectError(with({{"max_error", 0.1}}), "needs.budget_us", "missing");
    expectError(with({{"max_error", 0.1}, {"budget_us", "fast"}}), "needs.budget_us", "must be a number");
    expectError(with({{"max_error", 0.1}, {"budget_us", 100}, {"level", 2}}), "needs.level", "unknown key");
    expectError(with(Json::array({0.1, 100})), "needs", "must be an object");

    // An exercise with an absurd target is not saved.
    test::TempDir dir;
    Exercise bad = *read.exercise;
    bad.needs->budgetUs = -3;
    const std::string problem = saveExercise(bad, dir.file("bad.json"));
    EXPECT_NE(problem.find("needs.budget_us"), std::string::npos) << problem;
    EXPECT_FALSE(std::filesystem::exists(dir.file("bad.json")));
}

}  // namespace
}  // namespace palpate
