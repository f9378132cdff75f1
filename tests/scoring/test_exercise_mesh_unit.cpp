// An exercise's "mesh_unit" (docs/scoring.md, docs/meshes.md "Units"): its mesh is read in that
// unit wherever it is loaded (the session, its recording, the replay and the score), so that an
// exercise on a mesh written in cm is the same exercise as on the mesh written in mm.
#include "engine/core/MeshHash.h"
#include "engine/exercise/ExerciseFile.h"
#include "engine/record/RecordingReader.h"
#include "engine/scoring/ReplayScorer.h"
#include "tests/record/RecordTestRig.h"
#include "tests/record/UnitMeshFiles.h"
#include "tests/scoring/ScoringTestRig.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace palpate {
namespace {

using Json = nlohmann::ordered_json;

struct UnitRun {
    ScoreReport report;
    RecordingHeader header;
    std::string error;
};

/// A session of `exercise` driven by the example's good script, recorded, then scored from the
/// file with the exercise as saved to and read back from a file (the reader's mesh_unit).
UnitRun runAndScore(const Exercise& exercise, const std::string& scriptName, test::TempDir& dir, const std::string& tag) {
    UnitRun run;
    const std::string exercisePath = dir.file(tag + ".json");
    EXPECT_EQ(saveExercise(exercise, exercisePath), "");
    const auto saved = loadExercise(exercisePath);
    EXPECT_TRUE(saved.exercise) << saved.error();
    if (!saved.exercise) return run;
    const auto script = test::loadTraineeScript(test::resourcesDir() + "/exercises/" + scriptName + ".good.path");
    const std::string recording = dir.file(tag + ".palprec");
    test::runScriptedSession(*saved.exercise, script, recording);
    const RecordingReader reader = RecordingReader::open(recording);
    run.header = reader.header();
    ReplayScorerDef options;
    options.findResource = test::testResourceFinder();
    run.report = scoreRecording(reader, &*saved.exercise, run.error, options);
    return run;
}

struct UnitCase {
    const char* exercise;
    const char* unit;
};

void PrintTo(const UnitCase& c, std::ostream* out) { *out << c.exercise << " in " << c.unit; }

class ExerciseMeshUnit : public ::testing::TestWithParam<UnitCase> {};

TEST_P(ExerciseMeshUnit, OnTheMeshWrittenInTheUnitScoresAsOnTheMeshInMm) {
    const UnitCase c = GetParam();
    std::string problem;
    const auto unit = parseMeshUnit(c.unit, problem);
    ASSERT_TRUE(unit) << problem;
    test::TempDir dir;
    Exercise mm = test::loadExampleExercise(c.exercise);
    const std::string shipped = resolveExercisePath(mm, mm.meshPath, test::testResourceFinder());
    const test::UnitMeshFiles files =
        test::writeUnitMeshFiles(shipped, unit->mmPerUnit, unit->name, dir.path().string(), "tissue");
    mm.meshPath = files.mmPath;
    Exercise inUnit = mm;  // the same targets, path, rubric: only the mesh file and its unit differ
    inUnit.meshPath = files.unitPath;
    inUnit.meshUnit = *unit;

    const UnitRun a = runAndScore(mm, c.exercise, dir, "mm");
    const UnitRun b = runAndScore(inUnit, c.exercise, dir, c.unit);
    ASSERT_EQ(a.error, "");
    ASSERT_EQ(b.error, "");
    // The recording says the unit, and its mesh is the same mesh (in mm) as the mm session's.
    EXPECT_TRUE(a.header.scene.meshUnit.isMillimetres());
    EXPECT_EQ(b.header.scene.meshUnit.name, unit->name);
    EXPECT_EQ(b.header.scene.meshUnit.mmPerUnit, unit->mmPerUnit);
    EXPECT_EQ(b.header.scene.meshHash, a.header.scene.meshHash);
    // The same score, metric by metric.
    EXPECT_TRUE(a.report.guidance.completed);
    EXPECT_GT(a.report.score, 80.0);
    EXPECT_EQ(b.report.score, a.report.score);
    ASSERT_EQ(b.report.metrics.size(), a.report.metrics.size());
    for (std::size_t i = 0; i < a.report.metrics.size(); ++i)
        EXPECT_EQ(b.report.metrics[i].value, a.report.metrics[i].value) << metricName(a.report.metrics[i].metric);
    EXPECT_TRUE(b.report.warnings.empty()) << b.report.warnings.front();

    // The recording scores on its own too (the exercise in its note carries the unit).
    const RecordingReader reader = RecordingReader::open(dir.file(std::string(c.unit) + ".palprec"));
    std::string error;
    ReplayScorerDef options;
    options.findResource = test::testResourceFinder();
    const ScoreReport alone = scoreRecording(reader, nullptr, error, options);
    EXPECT_EQ(error, "");
    EXPECT_EQ(alone.score, a.report.score);
}

INSTANTIATE_TEST_SUITE_P(Units, ExerciseMeshUnit,
                         ::testing::Values(UnitCase{"press_targets", "cm"}, UnitCase{"find_lump", "m"},
                                           UnitCase{"trace", "in"}),
                         [](const auto& info) { return std::string(info.param.exercise) + "_" + info.param.unit; });

TEST(ExerciseMeshUnitFile, TheMeshInTheWrongUnitIsAnotherMesh) {
    // The exercise in cm scored against a recording made on the mm file: the score is refused
    // rather than given on a mesh ten times the size.
    test::TempDir dir;
    Exercise mm = test::loadExampleExercise("press_targets");
    const std::string shipped = resolveExercisePath(mm, mm.meshPath, test::testResourceFinder());
    const auto files = test::writeUnitMeshFiles(shipped, 10.0, "cm", dir.path().string(), "tissue");
    mm.meshPath = files.mmPath;
    const UnitRun a = runAndScore(mm, "press_targets", dir, "mm");
    ASSERT_EQ(a.error, "");
    Exercise wrong = mm;
    wrong.meshUnit = MeshUnit{"cm", 10.0};  // the mm file read as cm
    const RecordingReader reader = RecordingReader::open(dir.file("mm.palprec"));
    std::string error;
    ReplayScorerDef options;
    options.findResource = test::testResourceFinder();
    scoreRecording(reader, &wrong, error, options);
    EXPECT_NE(error.find("a different mesh"), std::string::npos) << error;
}

TEST(ExerciseMeshUnitCliThreads, RunExerciseReadsItsMeshInItsUnit) {
    // `run --exercise`: the session's mesh is the exercise's in its unit (the targets' mesh), so
    // the scripted trainee scores as on the shipped exercise, and the recording scores alone.
    test::TempDir dir;
    Exercise e = test::loadExampleExercise("trace");
    const auto finder = test::testResourceFinder();
    const std::string shipped = resolveExercisePath(e, e.meshPath, finder);
    const auto files = test::writeUnitMeshFiles(shipped, 10.0, "cm", dir.path().string(), "tissue");
    e.meshPath = files.unitPath;
    e.tissuePresetPath = resolveExercisePath(e, e.tissuePresetPath, finder);
    e.meshUnit = MeshUnit{"cm", 10.0};
    const std::string exercisePath = dir.file("trace cm.json");
    ASSERT_EQ(saveExercise(e, exercisePath), "");
    const std::string script = test::resourcesDir() + "/exercises/trace.good.path";
    const std::string recording = dir.file("run.palprec");
    const auto r = test::runCli("run --exercise " + test::shellQuote(exercisePath) + " --device " +
                                test::shellQuote("sim:path:" + script) + " --record " + test::shellQuote(recording) +
                                " --no-fifo --json");  // stdout and stderr: a warning would break the JSON
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto j = Json::parse(r.output);
    EXPECT_EQ(j.value("mesh_unit", ""), "cm");
    ASSERT_TRUE(j.contains("score")) << r.output;
    EXPECT_TRUE(j["score"]["completed"].get<bool>());
    EXPECT_GT(j["score"]["score"].get<double>(), 80.0);
    const auto again = test::runCli("score --recording " + test::shellQuote(recording) + " --json");
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_EQ(nlohmann::json::parse(again.output)["metrics"], nlohmann::json::parse(j["score"]["metrics"].dump()));
    // The exercise sets the unit; the option is refused beside it.
    const auto both = test::runCli("run --exercise " + test::shellQuote(exercisePath) + " --mesh-unit cm");
    EXPECT_EQ(both.exitCode, 2) << both.output;
    EXPECT_NE(both.output.find("--mesh-unit"), std::string::npos) << both.output;
    // Without its unit, a sphere written in cm is implausibly small: the warning names the
    // exercise's key.
    Exercise noUnit = test::loadExampleExercise("find_lump");
    const auto sphere = test::writeUnitMeshFiles(resolveExercisePath(noUnit, noUnit.meshPath, finder), 10.0, "cm",
                                                 dir.path().string(), "sphere");
    noUnit.meshPath = sphere.unitPath;
    noUnit.tissuePresetPath = resolveExercisePath(noUnit, noUnit.tissuePresetPath, finder);
    const std::string noUnitPath = dir.file("lump no unit.json");
    ASSERT_EQ(saveExercise(noUnit, noUnitPath), "");
    const auto warned = test::runCli("run --exercise " + test::shellQuote(noUnitPath) + " --seconds 0.2 --no-fifo");
    EXPECT_NE(warned.output.find("set \"mesh_unit\": \"cm\" in " + noUnitPath), std::string::npos) << warned.output;
}

Json pressJson() {
    return Json::parse(R"({
      "format": "palpate-exercise", "version": 1, "name": "p", "type": "press_targets",
      "mesh": "meshes/sphere_1442.off", "tissue_preset": "presets/default.json", "time_limit_s": 30,
      "press_targets": {"targets": [{"vertex": 3}]}
    })");
}

TEST(ExerciseMeshUnitFile, ReadWrittenOnlyWhenNotMmAndRoundTrips) {
    // Absent: mm, and not written back (a file from before units reads and writes the same).
    const auto plain = parseExercise(pressJson().dump(), "ex.json");
    ASSERT_TRUE(plain.exercise) << plain.error();
    EXPECT_TRUE(plain.exercise->meshUnit.isMillimetres());
    EXPECT_EQ(exerciseToJson(*plain.exercise).find("mesh_unit"), std::string::npos);
    // A saved mm exercise, read and saved again, is the same bytes, without the key.
    test::TempDir dir;
    for (const char* name : {"press_targets", "find_lump", "trace"}) {
        const std::string first = dir.file(std::string(name) + ".json"), second = dir.file(std::string(name) + "2.json");
        ASSERT_EQ(saveExercise(test::loadExampleExercise(name), first), "");
        const auto read = loadExercise(first);
        ASSERT_TRUE(read.exercise) << read.error();
        ASSERT_EQ(saveExercise(*read.exercise, second), "");
        EXPECT_EQ(test::readBytes(second), test::readBytes(first)) << name;
        const auto bytes = test::readBytes(first);
        EXPECT_EQ(std::string(bytes.begin(), bytes.end()).find("mesh_unit"), std::string::npos) << name;
    }

    struct Case {
        Json given;
        const char* name;
        double mmPerUnit;
        Json written;
    };
    const Case cases[] = {{"cm", "cm", 10.0, "cm"},     {"M", "m", 1000.0, "m"},   {"in", "in", 25.4, "in"},
                          {"mm", "mm", 1.0, nullptr},   {2.5, "", 2.5, 2.5},       {10, "cm", 10.0, "cm"},
                          {"0.001", "", 0.001, 0.001}};
    for (const Case& c : cases) {
        Json j = pressJson();
        j["mesh_unit"] = c.given;
        const auto read = parseExercise(j.dump(), "ex.json");
        ASSERT_TRUE(read.exercise) << c.given.dump() << ": " << read.error();
        EXPECT_EQ(read.exercise->meshUnit.name, c.name) << c.given.dump();
        EXPECT_EQ(read.exercise->meshUnit.mmPerUnit, c.mmPerUnit) << c.given.dump();
        const Json out = Json::parse(exerciseToJson(*read.exercise));
        if (c.written.is_null()) EXPECT_FALSE(out.contains("mesh_unit")) << c.given.dump();
        else EXPECT_EQ(out.value("mesh_unit", Json()), c.written) << c.given.dump();
        const auto again = parseExercise(out.dump(), "ex.json");
        ASSERT_TRUE(again.exercise) << again.error();
        EXPECT_EQ(again.exercise->meshUnit.mmPerUnit, c.mmPerUnit);
    }
}

TEST(ExerciseMeshUnitFile, BadValuesAreErrorsNamingTheKey) {
    for (const Json& bad : {Json("furlong"), Json(-1), Json(0), Json(1e9), Json(""), Json(true), Json::array({10}),
                            Json("10 cm"), Json("-2")}) {
        Json j = pressJson();
        j["mesh_unit"] = bad;
        const auto r = parseExercise(j.dump(), "ex.json");
        EXPECT_FALSE(r.exercise) << bad.dump();
        ASSERT_FALSE(r.errors.empty()) << bad.dump();
        EXPECT_EQ(r.errors.front().rfind("ex.json: mesh_unit: ", 0), 0u) << bad.dump() << ": " << r.errors.front();
    }
    // Nor is an exercise saved with one.
    test::TempDir dir;
    Exercise e = *parseExercise(pressJson().dump(), "ex.json").exercise;
    e.meshUnit = MeshUnit{"", 0.0};
    const std::string problem = saveExercise(e, dir.file("bad.json"));
    EXPECT_NE(problem.find("mesh_unit"), std::string::npos) << problem;
}

}  // namespace
}  // namespace palpate
