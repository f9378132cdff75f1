// Detect lumps: lumps under the surface in the slope-ring model (a deeper lump is felt only when
// pressed deeper, by the closed form of the exact solve), the exercise file, the lumps placed on
// the mesh, and scripted trainees on the shipped exercises scored end to end, each with what it
// must get worked out by hand from the script (tests/scoring/make_example_scripts.py).
#include "engine/exercise/ExerciseFile.h"
#include "engine/exercise/ExerciseGeometry.h"
#include "engine/models/slopering/CoherentSlopeRing.h"
#include "engine/record/RecordingReader.h"
#include "engine/scene/HapticScene.h"
#include "engine/scene/TissuePreset.h"
#include "engine/scoring/ReplayScorer.h"
#include "tests/record/RecordTestRig.h"
#include "tests/scoring/ScoringTestRig.h"
#include "tests/support/AllocationCounter.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>

namespace palpate {
namespace {

const TissueMesh& sphere() {
    static const TissueMesh mesh = *TissueMesh::load(test::resourcesDir() + "/meshes/sphere_8664.off").mesh;
    return mesh;
}

TissuePreset muscle() {
    const auto p = loadTissuePreset(test::resourcesDir() + "/presets/tissues/muscle.json");
    if (!p.preset) throw std::runtime_error(p.error());
    return *p.preset;
}

/// A detect-lumps exercise with one lump above +x of the sphere.
Exercise oneLump(double depthMm, double contrast = 4.0, double radiusMm = 6.0) {
    Exercise e = test::loadExampleExercise("detect_lumps");
    LumpDef lump;
    lump.at.pointMm = glm::vec3(50.0f, 0.0f, 0.0f);
    lump.depthMm = depthMm;
    lump.contrast = contrast;
    lump.radiusMm = radiusMm;
    e.detectLumps.lumps = {lump};
    return e;
}

struct Pressed {
    double forceN = 0.0;     ///< rendered, magnitude
    double contactN = 0.0;   ///< the slope model's F
    double sinkMm = 0.0;     ///< how far the touched vertex moved
};

/// The lump's vertex pressed by a point tool `depthMm` below its rest position, held until the
/// force settles; without `exercise`, plain tissue.
Pressed press(double depthMm, const Exercise* exercise, double forceRelaxation = 0.0, int ticks = 5) {
    TissuePreset p = muscle();
    p.model.slopeRing.forceRelaxation = forceRelaxation;
    auto scene = HapticScene::create(sphere(), slopeRingModelDef(p.model.slopeRing), p.octree);
    auto* deformer = dynamic_cast<CoherentSlopeRing*>(&scene->model());
    EXPECT_NE(deformer, nullptr);
    if (exercise) {
        std::string error;
        const auto geometry = ExerciseGeometry::build(*exercise, sphere(), error);
        EXPECT_EQ(error, "");
        EXPECT_EQ(applyExercisePhysics(*geometry, *scene), "");
    }
    SurfacePoint at;
    at.pointMm = glm::vec3(50.0f, 0.0f, 0.0f);
    const VertexId v = ExerciseGeometry::snap(at, sphere());
    const glm::vec3 rest = sphere().restPositionsMm()[v], n = sphere().restNormals()[v];
    TickResult r;
    for (int tick = 0; tick < ticks; ++tick) r = deformer->step(rest - float(depthMm) * n, 0.001);
    EXPECT_EQ(r.touched, v);
    return {glm::length(glm::dvec3(r.forceN)), deformer->contactForceN(), glm::length(deformer->positionsMm()[v] - rest)};
}

/// The closed form (docs/scoring.md, "Lumps under the surface"): F = max(k_c d / (1 + g),
/// k_c (d - (1 - c) z) / (1 + g c)), g = k_c |m1|, c = 1 / contrast.
double closedFormF(double d, double z, double contrast) {
    const SlopeRingParams p = muscle().model.slopeRing;
    const double m1 = p.slopeMagnitudeMmPerN[0], kc = p.contactStiffnessNPerMm, g = kc * m1, c = 1.0 / contrast;
    return std::max(kc * d / (1.0 + g), kc * (d - (1.0 - c) * z) / (1.0 + g * c));
}

TEST(LumpsUnderTheSurface, ForceFollowsTheClosedForm) {
    const SlopeRingParams p = muscle().model.slopeRing;
    const double m1 = p.slopeMagnitudeMmPerN[0], ks = p.springStiffnessNPerMm;
    for (const double z : {2.0, 5.0, 8.0})
        for (const double d : {4.0, 10.0, 16.0}) {
            const Exercise e = oneLump(z);
            const Pressed r = press(d, &e);
            const double f = closedFormF(d, z, 4.0);
            EXPECT_NEAR(r.contactN, f, 1e-4 * f) << "lump " << z << " mm deep, pressed " << d << " mm";
            EXPECT_NEAR(r.forceN, ks * m1 * f, 1e-4 * ks * m1 * f) << z << " " << d;
            // The surface sinks |m1| F until it reaches the lump, then c |m1| per newton beyond.
            const double sink = std::min(m1 * f, 0.25 * m1 * f + 0.75 * z);
            EXPECT_NEAR(r.sinkMm, sink, 2e-3) << z << " " << d;
        }
}

TEST(LumpsUnderTheSurface, ADeeperLumpFeelsWeakerUnlessPressedDeeper) {
    const Exercise shallow = oneLump(2.0), middle = oneLump(5.0), deep = oneLump(8.0);
    // At 10 mm: each deeper lump renders less, all more than the tissue around them.
    const double tissue10 = press(10.0, nullptr).forceN;
    const double f2 = press(10.0, &shallow).forceN, f5 = press(10.0, &middle).forceN, f8 = press(10.0, &deep).forceN;
    EXPECT_GT(f2, f5);
    EXPECT_GT(f5, f8);
    EXPECT_GT(f8, tissue10);
    // Pressed 6 mm the surface sinks 6 |m1| / (1 + |m1|) = 5.2 mm: short of the 8 mm lump, which is
    // then not there at all for the hand.
    EXPECT_EQ(press(6.0, &deep).forceN, press(6.0, nullptr).forceN);
    EXPECT_GT(press(6.0, &shallow).forceN, 1.5 * press(6.0, nullptr).forceN);
    // Pressed deeper, the deep lump stands out as the shallow one did.
    EXPECT_LT(f8 / tissue10, 1.25);
    EXPECT_GT(press(16.0, &deep).forceN / press(16.0, nullptr).forceN, 1.5);
}

TEST(LumpsUnderTheSurface, RelaxedUpdateSettlesOnTheSameForce) {
    const Exercise e = oneLump(5.0);
    const Pressed relaxed = press(12.0, &e, 0.05, 2000);
    const double f = closedFormF(12.0, 5.0, 4.0);
    EXPECT_NEAR(relaxed.contactN, f, 1e-3 * f);
}

TEST(LumpsUnderTheSurface, ALumpAtTheSurfaceIsTheUniformInclusionBitForBit) {
    TissuePreset p = muscle();
    auto a = HapticScene::create(sphere(), slopeRingModelDef(p.model.slopeRing), p.octree);
    auto b = HapticScene::create(sphere(), slopeRingModelDef(p.model.slopeRing), p.octree);
    auto* da = dynamic_cast<CoherentSlopeRing*>(&a->model());
    auto* db = dynamic_cast<CoherentSlopeRing*>(&b->model());
    std::vector<float> factors(sphere().vertexCount(), 1.0f);
    for (std::size_t v = 0; v < factors.size(); v += 3) factors[v] = 0.3f;
    da->setCompliance(factors);
    db->setLumps(factors, std::vector<float>(factors.size(), 0.0f));
    const glm::vec3 rest = sphere().restPositionsMm()[0], n = sphere().restNormals()[0];
    for (int tick = 0; tick < 2000; ++tick) {
        const glm::vec3 tool = rest - (8.0f * std::sin(0.003f * float(tick))) * n + glm::vec3(0.0f, 0.004f * float(tick), 0.0f);
        const TickResult ra = da->step(tool, 0.001), rb = db->step(tool, 0.001);
        ASSERT_EQ(std::memcmp(&ra.forceN, &rb.forceN, sizeof(glm::vec3)), 0) << "tick " << tick;
    }
}

TEST(LumpsUnderTheSurface, DepthsAreValidatedAndTheTickAllocatesNothing) {
    TissuePreset p = muscle();
    auto scene = HapticScene::create(sphere(), slopeRingModelDef(p.model.slopeRing), p.octree);
    auto* d = dynamic_cast<CoherentSlopeRing*>(&scene->model());
    const std::size_t n = sphere().vertexCount();
    EXPECT_THROW(d->setLumps(std::vector<float>(n, 0.5f), std::vector<float>(n - 1, 1.0f)), std::invalid_argument);
    std::vector<float> depths(n, 1.0f);
    depths[5] = -1.0f;
    EXPECT_THROW(d->setLumps(std::vector<float>(n, 0.5f), depths), std::invalid_argument);
    depths[5] = std::nanf("");
    EXPECT_THROW(d->setLumps(std::vector<float>(n, 0.5f), depths), std::invalid_argument);

    std::string error;
    const auto geometry = ExerciseGeometry::build(test::loadExampleExercise("detect_lumps"), sphere(), error);
    ASSERT_EQ(applyExercisePhysics(*geometry, *scene), "");
    const glm::vec3 rest = sphere().restPositionsMm()[geometry->lumps()[0].vertex];
    const glm::vec3 normal = sphere().restNormals()[geometry->lumps()[0].vertex];
    auto tool = [&](int tick) {
        return rest - (6.0f + 6.0f * std::sin(0.01f * float(tick))) * normal + glm::vec3(0.0f, 0.01f * float(tick), 0.0f);
    };
    for (int tick = 0; tick < 200; ++tick) d->step(tool(tick), 0.001);
    test::AllocationCounter counter;
    for (int tick = 200; tick < 3000; ++tick) d->step(tool(tick), 0.001);
    EXPECT_EQ(counter.count(), 0u);
}

TEST(DetectLumpsGeometry, EachVertexMeetsTheLumpStraightBelowIt) {
    std::string error;
    const Exercise e = oneLump(3.0, 4.0, 6.0);
    const auto g = ExerciseGeometry::build(e, sphere(), error);
    ASSERT_TRUE(g) << error;
    ASSERT_EQ(g->lumps().size(), 1u);
    const ResolvedLump& lump = g->lumps()[0];
    EXPECT_EQ(g->lumpOfVertex()[lump.vertex], 0);
    EXPECT_NEAR(g->engageDepthMm()[lump.vertex], 3.0, 1e-4);
    EXPECT_FLOAT_EQ(g->compliance()[lump.vertex], 0.25f);
    EXPECT_NEAR(glm::length(lump.centreMm - lump.surfaceMm), 9.0, 1e-4);
    // Off the axis by r, the sphere of radius R is met deeper: about z + R - sqrt(R^2 - r^2) on a
    // flat surface; the 50 mm sphere's own curve brings it up by r^2 / (2 * 50) and tilts the ray.
    const auto& rest = sphere().restPositionsMm();
    std::size_t inside = 0;
    for (VertexId v = 0; v < sphere().vertexCount(); ++v) {
        const double r = glm::length(glm::dvec3(rest[v]) - glm::dvec3(lump.surfaceMm));
        if (r > 9.0) {
            EXPECT_EQ(g->lumpOfVertex()[v], -1) << "vertex " << v << " " << r << " mm away";
            EXPECT_FLOAT_EQ(g->compliance()[v], 1.0f);
        } else if (r < 3.0) {
            ++inside;
            EXPECT_EQ(g->lumpOfVertex()[v], 0);
            EXPECT_NEAR(g->engageDepthMm()[v], 3.0 + 6.0 - std::sqrt(36.0 - r * r), 0.4) << r;
        }
    }
    EXPECT_GT(inside, 2u);
    EXPECT_EQ(g->inclusionVertexCount(), lump.footprintVertices);
}

TEST(DetectLumpsFile, ReadsWritesAndNamesEveryBadKey) {
    const Exercise e = test::loadExampleExercise("detect_lumps");
    ASSERT_EQ(e.type, ExerciseType::DetectLumps);
    ASSERT_EQ(e.detectLumps.lumps.size(), 3u);
    EXPECT_EQ(e.detectLumps.lumps[2].depthMm, 8.0);
    EXPECT_EQ(e.coverage.minForceN, 0.4);  // read from the file (the default is 1 N)
    Exercise withStaircase = e;
    withStaircase.detectLumps.staircase = StaircaseDef{StaircaseDef::Parameter::DepthMm, 4.0, 1.0, 1.0, 10.0, 2, 1};
    const auto again = parseExercise(exerciseToJson(withStaircase), "again");
    ASSERT_TRUE(again.exercise) << again.error();
    EXPECT_EQ(exerciseToJson(*again.exercise), exerciseToJson(withStaircase));
    EXPECT_EQ(again.exercise->detectLumps.staircase->parameter, StaircaseDef::Parameter::DepthMm);

    const auto none = test::loadExampleExercise("no_lump");
    EXPECT_TRUE(none.detectLumps.lumps.empty());
    // No lump: nothing to find, so sensitivity and localisation carry no weight.
    const Rubric rubric = effectiveRubric(none);
    EXPECT_EQ(rubric[std::size_t(Metric::Sensitivity)].weight, 0.0);
    EXPECT_EQ(rubric[std::size_t(Metric::LocalisationMm)].weight, 0.0);
    EXPECT_GT(rubric[std::size_t(Metric::FalseAlarms)].weight, 0.0);

    auto errorsOf = [&](const std::string& from, const std::string& to) {
        std::string text = exerciseToJson(withStaircase);
        const auto at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
        return parseExercise(text, "x.json").error();
    };
    EXPECT_NE(errorsOf("\"contrast\": 4.0", "\"contrast\": 0.5").find("detect_lumps.lumps[0].contrast: 0.5 is out of range"),
              std::string::npos);
    EXPECT_NE(errorsOf("\"depth_mm\": 8.0", "\"depth_mm\": -1").find("detect_lumps.lumps[2].depth_mm"), std::string::npos);
    EXPECT_NE(errorsOf("\"parameter\": \"depth_mm\"", "\"parameter\": \"size\"").find("detect_lumps.staircase.parameter"),
              std::string::npos);
    EXPECT_NE(errorsOf("\"easiest\": 1.0", "\"easiest\": 12.0").find("detect_lumps.staircase.easiest"), std::string::npos);
    EXPECT_NE(errorsOf("\"radius_mm\": 6.0", "\"radius_mm\": 6.0, \"colour\": 1").find("colour"), std::string::npos);
    EXPECT_NE(errorsOf("\"lumps\": [", "\"lumpz\": [").find("lumpz"), std::string::npos);
    EXPECT_NE(parseExercise("{\"format\": \"palpate-exercise\", \"version\": 1, \"name\": \"n\", \"type\": \"detect_lumps\", "
                            "\"mesh\": \"m.off\", \"tissue_preset\": \"t.json\", \"time_limit_s\": 10, \"detect_lumps\": {}}",
                            "x.json")
                  .error()
                  .find("detect_lumps.lumps: missing"),
              std::string::npos);
    Exercise press = test::loadExampleExercise("press_targets");
    std::string text = exerciseToJson(press);
    text.insert(text.rfind('}'), ", \"coverage\": {\"min_force_n\": 1.0}");
    EXPECT_NE(parseExercise(text, "p.json").error().find("coverage: given, but type is press_targets"), std::string::npos);
}

/// A shipped exercise done by the scripted trainee `quality`, recorded (stepped) and scored from the file.
ScoreReport scoreScripted(const std::string& name, const std::string& quality, test::TempDir& dir,
                          std::string* recordingOut = nullptr) {
    const Exercise exercise = test::loadExampleExercise(name);
    const auto script = test::loadTraineeScript(test::resourcesDir() + "/exercises/" + name + "." + quality + ".path");
    const std::string recording = dir.file(name + "." + quality + ".palprec");
    test::runScriptedSession(exercise, script, recording);
    if (recordingOut) *recordingOut = recording;
    const RecordingReader reader = RecordingReader::open(recording);
    std::string error;
    ReplayScorerDef options;
    options.findResource = test::testResourceFinder();
    const ScoreReport report = scoreRecording(reader, &exercise, error, options);
    EXPECT_EQ(error, "");
    // The replay rebuilds the lumps from the recording's note: it must match what was felt.
    for (const std::string& w : report.warnings) ADD_FAILURE() << name << "." << quality << ": warning: " << w;
    std::printf("[ figures  ] %s, %s trainee: score %.1f\n%s", name.c_str(), quality.c_str(), report.score,
                scoreReportToText(report).c_str());
    return report;
}

bool hasFeedback(const ScoreReport& r, const std::string& key) {
    for (const PalpationFeedback& f : r.palpation->feedback)
        if (f.key == key) return true;
    return false;
}

TEST(ScriptedExaminers, TheThoroughOneFindsEveryLumpAndNothingElse) {
    test::TempDir dir;
    const ScoreReport r = scoreScripted("detect_lumps", "good", dir);
    ASSERT_TRUE(r.palpation && r.palpation->detection);
    const DetectionResult& d = *r.palpation->detection;
    // Three marks, each pressed on one of the three lumps.
    EXPECT_EQ(d.hits, 3u);
    EXPECT_EQ(d.misses, 0u);
    EXPECT_EQ(d.falseAlarms, 0u);
    EXPECT_EQ(d.sensitivity, 1.0);
    EXPECT_EQ(d.positivePredictive, 1.0);
    // Each finding is the contact point over the lump's vertex, which the script aims at within
    // the mesh's vertex spacing (about 2.7 mm).
    for (double mm : d.localisationMm) EXPECT_LT(mm, 2.0);
    // Rows 8 mm apart, each covering 5 mm either side at 0.7 N (above the 0.4 N coverage force).
    EXPECT_GT(r.palpation->coverageFraction, 0.9);
    // Search at 0.7 N of tissue (more over the shallow lumps); palpation pressed to 2.8 N.
    const ForceByPhase& phases = r.palpation->forceByPhase;
    ASSERT_TRUE(phases.search && phases.palpation);
    EXPECT_NEAR(phases.search->p50N, 0.7, 0.1);
    EXPECT_GT(phases.palpation->p90N, 2.5);
    EXPECT_GT(*phases.palpationOverSearch, 1.15);
    EXPECT_FALSE(hasFeedback(r, "pressed_too_lightly"));
    EXPECT_FALSE(hasFeedback(r, "false_alarms"));
    EXPECT_TRUE(r.guidance.completed);
    EXPECT_GT(r.score, 80.0);
}

TEST(ScriptedExaminers, TheLightPresserMissesTheDeepLumpAndIsToldWhy) {
    test::TempDir dir;
    const ScoreReport r = scoreScripted("detect_lumps", "light", dir);
    ASSERT_TRUE(r.palpation && r.palpation->detection);
    const DetectionResult& d = *r.palpation->detection;
    EXPECT_EQ(d.hits, 2u);
    EXPECT_EQ(d.misses, 1u);
    EXPECT_EQ(d.falseAlarms, 0u);
    EXPECT_EQ(d.findingOfLump[2], -1) << "the 8 mm lump";
    EXPECT_NEAR(*d.sensitivity, 2.0 / 3.0, 1e-12);
    EXPECT_EQ(d.positivePredictive, 1.0);
    EXPECT_TRUE(hasFeedback(r, "pressed_too_lightly"));
    // The force that reaches the 8 mm lump: 8 mm of sink at k_s |m1| / |m1| = k_s N per mm.
    ASSERT_TRUE(r.palpation->deepestLumpReachForceN);
    EXPECT_NEAR(*r.palpation->deepestLumpReachForceN, 8.0 * muscle().model.slopeRing.springStiffnessNPerMm, 0.15);
    const ScoreReport good = scoreScripted("detect_lumps", "good", dir);
    EXPECT_LT(r.score, good.score - 10.0);
}

TEST(ScriptedExaminers, PokingWithoutSearchingCoversLittleAndCallsLumpsThatAreNotThere) {
    test::TempDir dir;
    const ScoreReport r = scoreScripted("detect_lumps", "bad", dir);
    const DetectionResult& d = *r.palpation->detection;
    EXPECT_EQ(d.hits, 0u);
    EXPECT_EQ(d.misses, 3u);
    EXPECT_EQ(d.falseAlarms, 2u);
    EXPECT_EQ(d.positivePredictive, 0.0);
    // Three presses of a 5 mm radius: a few hundred mm^2 of the sphere's 31 416.
    EXPECT_LT(r.palpation->coverageFraction, 0.05);
    EXPECT_TRUE(hasFeedback(r, "low_coverage"));
    EXPECT_TRUE(hasFeedback(r, "false_alarms"));
    EXPECT_LT(r.score, 40.0);
}

TEST(ScriptedExaminers, FindTheLumpReportsCoverageWithoutJudgingIt) {
    test::TempDir dir;
    const ScoreReport r = scoreScripted("find_lump", "good", dir);
    ASSERT_TRUE(r.palpation);
    EXPECT_FALSE(r.palpation->detection) << "one lump, one mark: no detection matching";
    EXPECT_GT(r.palpation->coverageFraction, 0.0);
    EXPECT_LT(r.palpation->coverageFraction, 0.6);  // four presses: far from the whole sphere
    EXPECT_FALSE(hasFeedback(r, "low_coverage")) << "it may go straight to the lump";
    EXPECT_EQ(r.find(Metric::CoverageFraction)->weight, 0.0);
}

TEST(ScriptedExaminers, HealthyTissueRewardsRestraint) {
    test::TempDir dir;
    const ScoreReport good = scoreScripted("no_lump", "good", dir);
    const ScoreReport bad = scoreScripted("no_lump", "bad", dir);
    const DetectionResult& g = *good.palpation->detection;
    EXPECT_EQ(g.falseAlarms, 0u);
    EXPECT_FALSE(g.sensitivity) << "no lump: no sensitivity";
    EXPECT_FALSE(g.positivePredictive) << "nothing marked: no predictive value";
    EXPECT_GT(good.score, 80.0);
    const DetectionResult& b = *bad.palpation->detection;
    EXPECT_EQ(b.falseAlarms, 2u);
    EXPECT_EQ(b.positivePredictive, 0.0);
    // Two false alarms of the rubric's zero at three: two thirds of the false-alarm line, which
    // without lumps carries its own 20 and the 35 + 10 of finding and localising, out of 100:
    // 65 * (2 / 3) = 43 points fewer.
    EXPECT_NEAR(good.score - bad.score, 100.0 * 65.0 * (2.0 / 3.0) / 100.0, 2.0);
    // Nothing hides here, so nobody is told to press in on a spot that feels different.
    EXPECT_FALSE(hasFeedback(good, "light_palpation"));
    EXPECT_FALSE(hasFeedback(bad, "light_palpation"));
}

/// A shipped exercise done by a scripted trainee made from its good path, scored from the recording.
ScoreReport scoreScript(const std::string& name, const test::TraineeScript& script, const std::string& who,
                        test::TempDir& dir) {
    const Exercise exercise = test::loadExampleExercise(name);
    const std::string recording = dir.file(name + "." + who + ".palprec");
    test::runScriptedSession(exercise, script, recording);
    std::string error;
    ReplayScorerDef options;
    options.findResource = test::testResourceFinder();
    const ScoreReport r = scoreRecording(RecordingReader::open(recording), &exercise, error, options);
    EXPECT_EQ(error, "") << who;
    std::printf("[ figures  ] %s, %s: score %.1f, work done %.0f %%, examined %.0f %%\n", name.c_str(), who.c_str(),
                r.score, 100.0 * r.workDone, r.palpation ? 100.0 * r.palpation->coverageFraction : 0.0);
    return r;
}

/// The good path cut at `fraction` of its duration and finished there (its marks before the cut kept).
test::TraineeScript cutShort(test::TraineeScript script, double fraction) {
    const double cutS = fraction * script.durationS();
    std::erase_if(script.waypoints, [&](const Waypoint& w) { return w.timeS > cutS; });
    std::erase_if(script.marksS, [&](double t) { return t > cutS; });
    script.doneS = cutS;
    return script;
}

/// Scripted trainees from doing nothing to a thorough examination, and one who marks everywhere:
/// the scores come out in the order an instructor would put them (docs/scoring.md, "The rubric").
void expectScoresOrderedAsAnInstructorWould(const std::string& name) {
    test::TempDir dir;
    const auto good = test::loadTraineeScript(test::resourcesDir() + "/exercises/" + name + ".good.path");
    test::TraineeScript nothing = good;
    nothing.waypoints.resize(1);  // above the tissue, never touching it
    nothing.marksS.clear();
    nothing.doneS = 2.0;          // Start, then Finish
    test::TraineeScript marksEverywhere = good;
    marksEverywhere.marksS.clear();
    for (double t = 5.0; t < good.doneS; t += 4.0) marksEverywhere.marksS.push_back(t);

    const ScoreReport none = scoreScript(name, nothing, "nothing", dir);
    const ScoreReport side = scoreScript(name, cutShort(good, 0.25), "a quarter of the sweep", dir);
    const ScoreReport half = scoreScript(name, cutShort(good, 0.55), "half of the sweep", dir);
    const ScoreReport thorough = scoreScript(name, good, "thorough", dir);
    const ScoreReport marker = scoreScript(name, marksEverywhere, "marks everywhere", dir);

    EXPECT_LE(none.score, 5.0) << "touching nothing earns nothing";
    EXPECT_DOUBLE_EQ(none.workDone, 0.0);
    EXPECT_LT(none.score, side.score);
    EXPECT_LT(side.score, half.score);
    EXPECT_LT(half.score, thorough.score);
    EXPECT_LT(side.score, 50.0) << "a quarter of the surface is not half the marks";
    EXPECT_GT(thorough.score, 90.0);
    EXPECT_LT(marker.score, thorough.score - 20.0) << "marking everywhere is not an examination";
}

TEST(ScriptedExaminers, HealthyTissueScoresTheExaminationNotTheAbsenceOfMistakes) {
    expectScoresOrderedAsAnInstructorWould("no_lump");
}

TEST(ScriptedExaminers, DetectingLumpsScoresTheExaminationNotTheAbsenceOfMistakes) {
    expectScoresOrderedAsAnInstructorWould("detect_lumps");
}

TEST(ScriptedExaminers, AnExaminationNotFinishedIsScoredOnWhatWasExamined) {
    test::TempDir dir;
    const Exercise exercise = test::loadExampleExercise("detect_lumps");
    auto script = test::loadTraineeScript(test::resourcesDir() + "/exercises/detect_lumps.good.path");
    script.doneS = -1.0;  // never finished: the session ends with the script
    const std::string recording = dir.file("unfinished.palprec");
    test::runScriptedSession(exercise, script, recording);
    std::string error;
    ReplayScorerDef options;
    options.findResource = test::testResourceFinder();
    const ScoreReport r = scoreRecording(RecordingReader::open(recording), &exercise, error, options);
    ASSERT_EQ(error, "");
    EXPECT_FALSE(r.guidance.completed);
    ASSERT_NE(r.find(Metric::Completion), nullptr);
    EXPECT_DOUBLE_EQ(r.find(Metric::Completion)->value, r.palpation->coverageFraction);
    EXPECT_EQ(r.palpation->detection->hits, 3u);
    // Every line as the finished examination's but time (5 of 100: graded only when finished).
    EXPECT_GT(r.score, 90.0);
    EXPECT_LT(r.score, 96.0);
}

TEST(ScriptedExaminers, TheScoreSoFarIsTheReportsScoreWithoutItsDetail) {
    test::TempDir dir;
    std::string recording;
    scoreScripted("detect_lumps", "light", dir, &recording);
    const RecordingReader reader = RecordingReader::open(recording);
    const Exercise exercise = test::loadExampleExercise("detect_lumps");
    std::string error;
    ReplayScorerDef options;
    options.findResource = test::testResourceFinder();
    auto scorer = ReplayScorer::open(reader, &exercise, error, options);
    ASSERT_TRUE(scorer) << error;
    for (std::uint64_t tick : {1000u, 40000u, 75000u, 90000u}) {
        scorer->advanceTo(tick);
        const ScoreReport full = scorer->scorer().report();
        EXPECT_EQ(scorer->scorer().scoreSoFar(), full.score) << "tick " << tick;
        EXPECT_FALSE(full.palpation->peakForceN.empty());
    }
}

TEST(ScriptedExaminers, ScoreJsonCarriesDetectionCoverageAndForceByPhase) {
    test::TempDir dir;
    std::string recording;
    scoreScripted("detect_lumps", "light", dir, &recording);
    const auto result = test::runCli("score --recording " + test::shellQuote(recording) + " --json");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const auto j = nlohmann::json::parse(result.output.substr(result.output.find('{')));
    EXPECT_EQ(j["detection"]["hits"], 2);
    EXPECT_EQ(j["detection"]["misses"], 1);
    EXPECT_EQ(j["metrics"]["false_alarms"], 0);
    EXPECT_NEAR(j["metrics"]["sensitivity"].get<double>(), 2.0 / 3.0, 1e-9);
    EXPECT_EQ(j["metrics"]["positive_predictive_value"], 1.0);
    EXPECT_LT(j["metrics"]["localisation_mm"].get<double>(), 2.0);
    EXPECT_GT(j["metrics"]["coverage_fraction"].get<double>(), 0.9);
    // Each metric is said once: the detection and coverage sections do not repeat them.
    for (const char* repeated : {"sensitivity", "ppv", "false_alarms", "localisation_mm"})
        EXPECT_FALSE(j["detection"].contains(repeated)) << repeated;
    EXPECT_FALSE(j.contains("coverage_pct"));
    EXPECT_TRUE(j["force_by_phase"]["search"]["p50_n"].is_number());
    EXPECT_TRUE(j["force_by_phase"]["palpation"]["p90_n"].is_number());
    EXPECT_EQ(j["feedback"][0]["key"], "pressed_too_lightly");
}

}  // namespace
}  // namespace palpate
