// JSON safety of presets and exercises: a number beyond a double (1e400) and a key given twice are
// errors naming the file and the key path, also in the preset an exercise names; no exception of
// the JSON library leaves a loader; a writer refuses what its reader would refuse; the documented
// exercise limits (1000 targets, 10 000 path points) fit in an exercise file.
#include "engine/exercise/ExerciseFile.h"
#include "base/io/FileLimits.h"
#include "base/io/JsonReader.h"
#include "engine/scene/TissuePreset.h"
#include "engine/scoring/ExerciseSession.h"
#include "tests/io/IoTestDir.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using namespace palpate;
using palpate::test::contains;
using palpate::test::IoTestDir;

namespace {

std::string shipped(const std::string& relative) {
    std::ifstream in(std::string(PALPATE_SOURCE_DIR) + "/resources/" + relative, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

std::string defaultPreset() { return shipped("presets/default.json"); }
std::string pressExercise() { return shipped("exercises/press_targets.json"); }

std::string firstError(const std::vector<std::string>& errors) { return errors.empty() ? "(none)" : errors.front(); }

}  // namespace

TEST(JsonSafety, APresetNumberBeyondADoubleNamesTheKey) {
    const auto r = parseTissuePreset(replaced(defaultPreset(), "\"damping_ratio\": 1.0", "\"damping_ratio\": 1e400"),
                                     "my.json");
    EXPECT_FALSE(r.preset);
    EXPECT_EQ(firstError(r.errors),
              "my.json: slope_ring.damping_ratio: 1e400 is too large for a double (at most about 1.8e308)");
    const auto list = parseTissuePreset(replaced(defaultPreset(), "[0.6, 0.35, 0.15]", "[0.6, -1e999, 0.15]"),
                                        "my.json");
    EXPECT_EQ(firstError(list.errors),
              "my.json: slope_ring.slopes_mm_per_n[1]: -1e999 is too large for a double (at most about 1.8e308)");
    const auto top = parseTissuePreset(
        replaced(defaultPreset(), "\"haptic_rate_hz\": 1000.0", "\"haptic_rate_hz\": 2e308"), "my.json");
    EXPECT_EQ(firstError(top.errors),
              "my.json: haptic_rate_hz: 2e308 is too large for a double (at most about 1.8e308)");
}

TEST(JsonSafety, APresetKeyGivenTwiceIsAnError) {
    const auto r = parseTissuePreset(replaced(defaultPreset(), "\"damping_ratio\": 1.0",
                                              "\"damping_ratio\": 1.0, \"damping_ratio\": 2.0"),
                                     "my.json");
    EXPECT_FALSE(r.preset);
    EXPECT_EQ(firstError(r.errors), "my.json: slope_ring.damping_ratio: appears twice");
    const auto top = parseTissuePreset(
        replaced(defaultPreset(), "\"name\": \"default\",", "\"name\": \"a\", \"name\": \"b\","), "my.json");
    EXPECT_EQ(firstError(top.errors), "my.json: name: appears twice");
}

TEST(JsonSafety, AnExerciseNumberBeyondADoubleAndAKeyGivenTwiceNameTheKey) {
    const auto big = parseExercise(
        replaced(pressExercise(), "{\"vertex\": 3537}", "{\"vertex\": 3537, \"hold_s\": 1e400}"), "ex.json");
    EXPECT_FALSE(big.exercise);
    EXPECT_EQ(firstError(big.errors),
              "ex.json: press_targets.targets[1].hold_s: 1e400 is too large for a double (at most about 1.8e308)");
    const auto twice = parseExercise(
        replaced(pressExercise(), "{\"vertex\": 3537}", "{\"vertex\": 3537, \"vertex\": 1}"), "ex.json");
    EXPECT_FALSE(twice.exercise);
    EXPECT_EQ(firstError(twice.errors), "ex.json: press_targets.targets[1].vertex: appears twice");
}

TEST(JsonSafety, ThePresetAnExerciseNamesIsCheckedTheSameWay) {
    IoTestDir dir;
    const std::string preset = dir.write("bad.json", replaced(defaultPreset(), "\"damping_ratio\": 1.0",
                                                              "\"damping_ratio\": 1e400"));
    const std::string exercisePath = dir.write(
        "ex.json",
        replaced(replaced(pressExercise(), "presets/tissues/skin.json", "bad.json"), "meshes/stomach_3970.off",
                 std::string(PALPATE_SOURCE_DIR) + "/resources/meshes/stomach_3970.off"));
    const auto exercise = loadExercise(exercisePath);
    ASSERT_TRUE(exercise.exercise) << exercise.error();
    std::vector<std::string> errors;
    EXPECT_FALSE(loadExerciseAssets(*exercise.exercise, {}, errors));
    EXPECT_EQ(firstError(errors),
              exercisePath + ": tissue_preset: " + preset +
                  ": slope_ring.damping_ratio: 1e400 is too large for a double (at most about 1.8e308)");
}

TEST(JsonSafety, NestingBeyondTheLimitIsRefusedNotRecursedInto) {
    std::vector<std::string> errors;
    JsonReader r(errors, "deep.json");
    EXPECT_FALSE(r.parse(std::string(100000, '[') + std::string(100000, ']')));
    EXPECT_TRUE(contains(firstError(errors), "deep.json: ")) << firstError(errors);
    EXPECT_TRUE(contains(firstError(errors), "nested more than 64 levels deep")) << firstError(errors);
    errors.clear();
    EXPECT_TRUE(r.parse(std::string(60, '[') + std::string(60, ']')));
    EXPECT_TRUE(errors.empty());
}

TEST(JsonSafety, AWriterRefusesWhatItsReaderWouldRefuse) {
    IoTestDir dir;
    TissuePreset preset;
    preset.description = std::string(kPresetFile.maxBytes, 'd');
    const std::string presetPath = dir.file("p.json");
    const std::string problem = saveTissuePreset(preset, presetPath);
    EXPECT_TRUE(contains(problem, presetPath + ": not saved: the preset would be ")) << problem;
    EXPECT_TRUE(contains(problem, "more than the 1 MiB a preset file may hold")) << problem;
    // The reader refuses the same text from a file or a recording's copy.
    EXPECT_FALSE(parseTissuePreset(tissuePresetToJson(preset), "copy").preset);

    auto exercise = parseExercise(pressExercise(), "ex.json");
    ASSERT_TRUE(exercise.exercise) << exercise.error();
    exercise.exercise->description = std::string(kExerciseFile.maxBytes, 'd');
    const std::string exercisePath = dir.file("e.json");
    const std::string refused = saveExercise(*exercise.exercise, exercisePath);
    EXPECT_TRUE(contains(refused, exercisePath + ": not saved: the exercise would be ")) << refused;
    EXPECT_TRUE(contains(refused, "more than the 4 MiB an exercise file may hold")) << refused;
    EXPECT_TRUE(dir.names().empty());
}

TEST(JsonSafety, TheDocumentedExerciseLimitsFitInAnExerciseFile) {
    IoTestDir dir;
    auto loaded = parseExercise(pressExercise(), dir.file("ex.json"));
    ASSERT_TRUE(loaded.exercise) << loaded.error();
    // The longest numbers each field can hold: every target a point with denormal-length coordinates.
    Exercise press = *loaded.exercise;
    press.description = "x";
    press.pressTargets.targets.assign(std::size_t(kMaxPressTargets), PressTarget{});
    for (PressTarget& t : press.pressTargets.targets) {
        t.at.vertex.reset();
        t.at.pointMm = glm::vec3(-1.17549421e-38f, -1.17549421e-38f, -1.17549421e-38f);
        t.forceMinN = 4.9406564584124654e-324;
        t.forceMaxN = 2.2250738585072014e-308;
        t.holdS = 2.2250738585072009e-308;
        t.toleranceMm = 2.2250738585072004e-308;
    }
    press.excessiveForceN = 999.99999999999989;
    const std::string pressPath = dir.file("press.json");
    ASSERT_EQ(saveExercise(press, pressPath), "");
    const auto pressBack = loadExercise(pressPath);
    ASSERT_TRUE(pressBack.exercise) << pressBack.error();
    EXPECT_EQ(pressBack.exercise->pressTargets.targets.size(), std::size_t(kMaxPressTargets));

    const auto traceLoaded = parseExercise(shipped("exercises/trace.json"), dir.file("t.json"));
    ASSERT_TRUE(traceLoaded.exercise) << traceLoaded.error();
    Exercise trace = *traceLoaded.exercise;
    trace.trace.path.assign(std::size_t(kMaxTracePathPoints), SurfacePoint{});
    for (std::size_t i = 0; i < trace.trace.path.size(); ++i)
        trace.trace.path[i].pointMm = glm::vec3(-1.17549421e-38f, -1.0000001e-38f * float(i % 7 + 1), -999999.94f);
    const std::string tracePath = dir.file("trace.json");
    ASSERT_EQ(saveExercise(trace, tracePath), "");
    const auto traceBack = loadExercise(tracePath);
    ASSERT_TRUE(traceBack.exercise) << traceBack.error();
    EXPECT_EQ(traceBack.exercise->trace.path.size(), std::size_t(kMaxTracePathPoints));
    // The margin docs/conventions.md states: the largest is well inside the limit.
    const auto largest = std::max(std::filesystem::file_size(pressPath), std::filesystem::file_size(tracePath));
    RecordProperty("largest_exercise_bytes", std::to_string(largest));
    EXPECT_LT(largest, kExerciseFile.maxBytes / 2);

    // One more than the limit is refused by the reader, naming the list.
    press.pressTargets.targets.push_back(press.pressTargets.targets.front());
    const auto over = parseExercise(exerciseToJson(press), "over.json");
    EXPECT_FALSE(over.exercise);
    EXPECT_EQ(firstError(over.errors), "over.json: press_targets.targets: has more than 1000 targets");
}
