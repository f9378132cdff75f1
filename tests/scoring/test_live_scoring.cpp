// Live == replay: a LiveScorer following the recording while the session runs (stepped, and on
// the real-time haptic thread) ends with the same report, bit for bit, as scoring the finished
// file. Also: the running score and guidance move during the session, a late mark makes it start
// over and still agree, and a LiveScorer refuses a recording of another mesh.
#include "engine/loop/HapticLoop.h"
#include "engine/record/RecordingReader.h"
#include "engine/scoring/LiveScorer.h"
#include "device/SimulatedDevice.h"
#include "tests/record/RecordTestRig.h"
#include "tests/scoring/ScoringTestRig.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <thread>

namespace palpate {
namespace {

bool same(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

void expectIdentical(const ScoreReport& live, const ScoreReport& replay) {
    EXPECT_TRUE(same(live.score, replay.score)) << live.score << " vs " << replay.score;
    ASSERT_EQ(live.metrics.size(), replay.metrics.size());
    for (std::size_t i = 0; i < live.metrics.size(); ++i) {
        const MetricResult &a = live.metrics[i], &b = replay.metrics[i];
        EXPECT_EQ(a.metric, b.metric);
        EXPECT_TRUE(same(a.value, b.value)) << metricName(a.metric) << ": " << a.value << " vs " << b.value;
        EXPECT_EQ(a.measured, b.measured);
        EXPECT_TRUE(same(a.subScore, b.subScore)) << metricName(a.metric);
        EXPECT_TRUE(same(a.contribution, b.contribution)) << metricName(a.metric);
    }
    ASSERT_EQ(live.targets.size(), replay.targets.size());
    for (std::size_t i = 0; i < live.targets.size(); ++i) {
        EXPECT_EQ(live.targets[i].achieved, replay.targets[i].achieved);
        EXPECT_TRUE(same(live.targets[i].achievedAtS, replay.targets[i].achievedAtS));
        EXPECT_TRUE(same(live.targets[i].errorMm, replay.targets[i].errorMm));
        EXPECT_TRUE(same(live.targets[i].inWindowS, replay.targets[i].inWindowS));
    }
    EXPECT_EQ(live.ticksScored, replay.ticksScored);
    EXPECT_EQ(live.ticksAfterEnd, replay.ticksAfterEnd);
    EXPECT_EQ(live.firstTick, replay.firstTick);
    EXPECT_EQ(live.lastTick, replay.lastTick);
    EXPECT_EQ(live.marks, replay.marks);
    EXPECT_EQ(live.guidance.completed, replay.guidance.completed);
    EXPECT_TRUE(same(live.guidance.exerciseTimeS, replay.guidance.exerciseTimeS));
    EXPECT_EQ(live.warnings, replay.warnings);
}

ScoreReport scoreFile(const std::string& path, const Exercise& exercise) {
    const RecordingReader reader = RecordingReader::open(path);
    std::string error;
    ReplayScorerDef options;
    options.findResource = test::testResourceFinder();
    const ScoreReport report = scoreRecording(reader, &exercise, error, options);
    EXPECT_EQ(error, "");
    return report;
}

LiveScorerDef liveDef(double holdBackS = 0.1) {
    LiveScorerDef def;
    def.holdBackS = holdBackS;
    def.options.findResource = test::testResourceFinder();
    return def;
}

class LiveEqualsReplay : public ::testing::TestWithParam<const char*> {};

TEST_P(LiveEqualsReplay, Stepped) {
    test::TempDir dir;
    const Exercise exercise = test::loadExampleExercise(GetParam());
    const auto script = test::loadTraineeScript(test::resourcesDir() + "/exercises/" + GetParam() + ".good.path");
    const std::string path = dir.file("live.palprec");
    LiveScorer live(path, exercise, liveDef());
    double lastTime = 0.0;
    int polls = 0, rising = 0;
    test::SessionRunDef def;
    def.afterFlush = [&](std::uint64_t) {
        live.poll();
        ++polls;
        ASSERT_EQ(live.error(), "");
        if (live.guidance().exerciseTimeS > lastTime) ++rising;
        lastTime = live.guidance().exerciseTimeS;
    };
    test::runScriptedSession(exercise, script, path, def);
    EXPECT_GT(rising, polls / 2);  // the running score follows the session
    const ScoreReport final = live.finish();
    EXPECT_EQ(live.error(), "");
    EXPECT_TRUE(final.guidance.completed);
    expectIdentical(final, scoreFile(path, exercise));
}

INSTANTIATE_TEST_SUITE_P(Examples, LiveEqualsReplay, ::testing::Values("press_targets", "find_lump", "trace"));

TEST(LiveScorer, GuidanceDuringAPressSession) {
    test::TempDir dir;
    const Exercise exercise = test::loadExampleExercise("press_targets");
    const auto script = test::loadTraineeScript(test::resourcesDir() + "/exercises/press_targets.good.path");
    const std::string path = dir.file("live.palprec");
    LiveScorer live(path, std::nullopt, liveDef());  // the exercise from the recording's note
    std::vector<int> targetsSeen;
    double maxProgress = 0.0;
    test::SessionRunDef def;
    def.flushEveryTicks = 100;
    def.afterFlush = [&](std::uint64_t) {
        live.poll();
        const ScoreGuidance& g = live.guidance();
        if (targetsSeen.empty() || targetsSeen.back() != g.targetIndex) targetsSeen.push_back(g.targetIndex);
        if (g.targetIndex == 0) maxProgress = std::max(maxProgress, g.holdProgress);
    };
    test::runScriptedSession(exercise, script, path, def);
    EXPECT_EQ(targetsSeen, (std::vector<int>{0, 1, 2, -1}));
    EXPECT_GT(maxProgress, 0.8);
    EXPECT_TRUE(live.exerciseOver());
    EXPECT_TRUE(live.recordingEnded() || live.finish().guidance.completed);
}

TEST(LiveScorer, ALateMarkStartsOverAndStillAgrees) {
    test::TempDir dir;
    const Exercise exercise = test::loadExampleExercise("find_lump");
    const auto script = test::loadTraineeScript(test::resourcesDir() + "/exercises/find_lump.good.path");
    const std::string path = dir.file("late.palprec");
    LiveScorer live(path, exercise, liveDef(0.0));  // no hold-back: the mark arrives after its tick is scored
    test::SessionRunDef def;
    def.flushEveryTicks = 50;
    def.marksAfterFlush = true;
    def.afterFlush = [&](std::uint64_t) { live.poll(); };
    test::runScriptedSession(exercise, script, path, def);
    const ScoreReport final = live.finish();
    EXPECT_GE(live.restarts(), 1);
    EXPECT_TRUE(final.guidance.marked);
    expectIdentical(final, scoreFile(path, exercise));
}

TEST(LiveScorer, RefusesARecordingOfAnotherMesh) {
    test::TempDir dir;
    const Exercise trace = test::loadExampleExercise("trace");  // on the stomach
    const auto script = test::loadTraineeScript(test::resourcesDir() + "/exercises/find_lump.good.path");
    const std::string path = dir.file("sphere.palprec");
    test::SessionRunDef def;
    def.seconds = 1.0;
    test::runScriptedSession(test::loadExampleExercise("find_lump"), script, path, def);  // on the sphere
    LiveScorer live(path, trace, liveDef());
    live.poll();
    EXPECT_NE(live.error().find("was recorded on"), std::string::npos) << live.error();
    EXPECT_NE(live.error().find("sphere_1442.off (1442 vertices"), std::string::npos) << live.error();
    EXPECT_NE(live.error().find("stomach_3970.off (3970 vertices"), std::string::npos) << live.error();
}

TEST(LiveScorerThreads, RealTimeSessionLiveEqualsReplay) {
    test::TempDir dir;
    const Exercise exercise = test::loadExampleExercise("press_targets");
    const auto script = test::loadTraineeScript(test::resourcesDir() + "/exercises/press_targets.good.path");
    std::vector<std::string> errors;
    auto assets = loadExerciseAssets(exercise, test::testResourceFinder(), errors);
    ASSERT_TRUE(assets) << errors.front();
    std::string error;
    auto scene = createExerciseScene(*assets, error);
    ASSERT_TRUE(scene) << error;
    auto device = std::make_unique<SimulatedDevice>(script.waypoints);
    ASSERT_TRUE(device->open());
    HapticLoopDef loopDef;
    loopDef.trySchedFifo = false;
    const RecordingHeader header =
        makeExerciseRecordingHeader(*assets, "sim:path:script", device->spec(), loopDef.safety, "", error);
    HapticLoop loop(loopDef, std::move(scene), std::move(device));
    const std::string path = dir.file("realtime.palprec");
    auto session = RecordingSession::start(loop, path, header, error);
    ASSERT_TRUE(session) << error;
    LiveScorer live(path, exercise, liveDef());
    error = loop.start();
    ASSERT_EQ(error, "");
    const auto start = std::chrono::steady_clock::now();
    bool marked = false;
    std::uint64_t polled = 0;
    while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(4500)) {
        std::this_thread::sleep_for(std::chrono::milliseconds(16));  // the GUI's display rate
        polled += live.poll();
        if (!marked && std::chrono::steady_clock::now() - start > std::chrono::milliseconds(1500)) {
            session->mark("a mark while running");
            marked = true;
        }
    }
    loop.stop();
    EXPECT_EQ(session->stop(), "");
    EXPECT_GT(polled, 1000u);  // it scored while the session ran
    const ScoreReport final = live.finish();
    EXPECT_EQ(live.error(), "");
    EXPECT_EQ(final.marks, 1u);
    EXPECT_GT(final.ticksScored, 2000u);
    expectIdentical(final, scoreFile(path, exercise));
    std::printf("[ figures  ] real-time 4.5 s: %llu ticks scored, %d restarts, score %.1f, target 1 %s\n",
                static_cast<unsigned long long>(final.ticksScored), live.restarts(), final.score,
                final.targets[0].achieved ? "achieved" : "not achieved");
}

}  // namespace
}  // namespace palpate
