// The exercise being edited, apart from the editor (engine/scoring/ExerciseDocument.h): its problems
// come from the engine's validators and its files, its points are checked on the drawn mesh when
// it is the exercise's (else on the mesh file), and its reach check runs on a worker thread,
// answers with the findings ExerciseReachCheck gives, and answers only the latest check asked for.
#include "engine/scoring/ExerciseDocument.h"

#include "engine/core/TissueMesh.h"
#include "engine/exercise/ExerciseGeometry.h"
#include "tests/scoring/ScoringTestRig.h"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <vector>

namespace palpate {
namespace {

const TouchReach kTouch{6.0, 1.0};

/// What the worker sends back, waited for on the test's thread.
struct Answers {
    std::mutex mutex;
    std::condition_variable arrived;
    std::vector<ReachCheckResult> results;

    ExerciseDocument::ReachReady sink() {
        return [this](ReachCheckResult r) {
            const std::lock_guard lock(mutex);
            results.push_back(std::move(r));
            arrived.notify_all();
        };
    }
    /// Waits (up to two minutes) for the answer to check `generation`.
    bool waitFor(std::uint64_t generation) {
        std::unique_lock lock(mutex);
        return arrived.wait_for(lock, std::chrono::minutes(2), [&] {
            for (const ReachCheckResult& r : results)
                if (r.generation == generation) return true;
            return false;
        });
    }
};

std::shared_ptr<const TissueMesh> meshOf(const std::string& path) {
    auto loaded = TissueMesh::load(path);
    EXPECT_TRUE(loaded.mesh) << loaded.error();
    return loaded.mesh ? std::make_shared<const TissueMesh>(std::move(*loaded.mesh)) : nullptr;
}

}  // namespace

TEST(ExerciseDocument, NamesMissingFilesAndInvalidValuesAndChecksPointsOnTheMeshFile) {
    ExerciseDocument doc(test::testResourceFinder(), kTouch);
    Exercise e = test::loadExampleExercise("press_targets");
    doc.setExercise(e);
    ExerciseProblems p = doc.examine();
    EXPECT_FALSE(p.any()) << (p.invalid.empty() ? p.placementError : p.invalid.front());
    // Not drawn: the points are checked on the mesh file, loaded by the document.
    ASSERT_NE(doc.checkMesh(), nullptr);
    ASSERT_NE(doc.geometry(), nullptr);
    EXPECT_EQ(doc.geometry()->targets().size(), e.pressTargets.targets.size());
    EXPECT_FALSE(doc.drawnMeshMatches());

    e.meshPath = "meshes/no_such_mesh.off";
    e.tissuePresetPath = "presets/tissues/no_such_tissue.json";
    e.pressTargets.targets[0].forceMaxN = 0.5 * e.pressTargets.targets[0].forceMinN;
    doc.setExercise(e);
    p = doc.examine();
    EXPECT_TRUE(p.meshNotFound);
    EXPECT_TRUE(p.presetNotFound);
    ASSERT_FALSE(p.invalid.empty());
    EXPECT_EQ(p.invalid.front().rfind("press_targets.targets[0].force_max_n", 0), 0u) << p.invalid.front();
    EXPECT_EQ(doc.geometry(), nullptr);
    EXPECT_EQ(doc.checkReach([](ReachCheckResult) { FAIL() << "nothing to check"; }), 0u);

    // A vertex beyond the mesh is a placement problem naming the target.
    e = test::loadExampleExercise("press_targets");
    e.pressTargets.targets[0].at.vertex = 10'000'000;
    doc.setExercise(e);
    p = doc.examine();
    EXPECT_NE(p.placementError.find("press_targets.targets[0]"), std::string::npos) << p.placementError;
}

TEST(ExerciseDocument, ThePointsAreCheckedOnTheDrawnMeshWhenItIsTheExercises) {
    ExerciseDocument doc(test::testResourceFinder(), kTouch);
    const Exercise e = test::loadExampleExercise("press_targets");
    doc.setExercise(e);
    const std::string meshFile = doc.meshFile();
    ASSERT_FALSE(meshFile.empty());
    const auto drawn = meshOf(meshFile);
    doc.setDrawnMesh(drawn, meshFile);
    EXPECT_TRUE(doc.drawnMeshMatches());
    EXPECT_FALSE(doc.examine().any());
    EXPECT_EQ(doc.checkMesh(), drawn);
    // The same file read in centimetres is another size: not the exercise's.
    Exercise inCm = e;
    inCm.meshUnit = MeshUnit{"cm", 10.0};
    doc.setExercise(inCm);
    EXPECT_FALSE(doc.drawnMeshMatches());
}

TEST(ExerciseDocument, TheReachCheckRunsOnItsWorkerAndAnswersAsTheEngineCheckDoes) {
    // The stomach wall cannot give the shipped targets' windows: a finding per target.
    Exercise e = test::loadExampleExercise("press_targets");
    e.tissuePresetPath = "presets/tissues/stomach_wall.json";
    ExerciseDocument doc(test::testResourceFinder(), kTouch);
    doc.setExercise(e);
    ASSERT_FALSE(doc.examine().any());
    Answers answers;
    const std::uint64_t first = doc.checkReach(answers.sink());
    ASSERT_NE(first, 0u);
    EXPECT_EQ(doc.latestCheck(), first);
    ASSERT_TRUE(answers.waitFor(first));

    ExerciseReachCheck direct(kTouch);
    const auto expected = direct.check(*doc.geometry(), doc.meshFile(), doc.presetFile(), *doc.checkMesh());
    ASSERT_FALSE(expected.empty());
    const std::lock_guard lock(answers.mutex);
    const ReachCheckResult& got = answers.results.back();
    ASSERT_EQ(got.findings.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(got.findings[i].kind, expected[i].kind);
        EXPECT_EQ(got.findings[i].item, expected[i].item);
        EXPECT_DOUBLE_EQ(got.findings[i].target.maxForceN, expected[i].target.maxForceN);
    }
    EXPECT_EQ(got.geometry, doc.geometry());
}

TEST(ExerciseDocument, OnlyTheLatestCheckAskedForIsCertainToAnswer) {
    Exercise e = test::loadExampleExercise("press_targets");
    ExerciseDocument doc(test::testResourceFinder(), kTouch);
    Answers answers;
    std::uint64_t last = 0;
    // Five edits in a row, each checked: the last one answers; one still waiting when a later
    // one is asked for is dropped; none answers twice.
    for (int i = 0; i < 5; ++i) {
        e.pressTargets.targets[0].forceMaxN += 0.01;
        doc.setExercise(e);
        ASSERT_FALSE(doc.examine().any());
        const std::uint64_t generation = doc.checkReach(answers.sink());
        EXPECT_GT(generation, last);
        last = generation;
    }
    ASSERT_TRUE(answers.waitFor(last));
    const std::lock_guard lock(answers.mutex);
    for (std::size_t i = 1; i < answers.results.size(); ++i)
        EXPECT_LT(answers.results[i - 1].generation, answers.results[i].generation);
    EXPECT_LE(answers.results.size(), 5u);
}

TEST(ExerciseDocument, GoingAwayWhileACheckRunsWaitsForItAndDoesNotHang) {
    Exercise e = test::loadExampleExercise("detect_lumps");
    Answers answers;
    {
        ExerciseDocument doc(test::testResourceFinder(), kTouch);
        doc.setExercise(e);
        ASSERT_FALSE(doc.examine().any());
        doc.checkReach(answers.sink());
    }  // the destructor joins the worker
    const std::lock_guard lock(answers.mutex);
    EXPECT_LE(answers.results.size(), 1u);
}

TEST(ExerciseDocument, TheSynchronousProbesShareTheWorkersProbe) {
    Exercise e = test::loadExampleExercise("press_targets");
    ExerciseDocument doc(test::testResourceFinder(), kTouch);
    doc.setExercise(e);
    ASSERT_FALSE(doc.examine().any());
    EXPECT_FALSE(doc.pressesOnDrawnMesh(0)) << "no mesh drawn";
    doc.setDrawnMesh(meshOf(doc.meshFile()), doc.meshFile());
    ASSERT_FALSE(doc.examine().any());
    Answers answers;
    doc.checkReach(answers.sink());  // runs while the probes below wait for the shared probe
    const auto presses = doc.pressesOnDrawnMesh(doc.geometry()->targets()[0].vertex);
    ASSERT_TRUE(presses);
    EXPECT_EQ(presses->forcesN.size(), kTouch.depthsMm().size());
    ExerciseReachCheck direct(kTouch);
    const TouchPresses* expected = direct.presses(doc.meshFile(), doc.presetFile(), *doc.checkMesh(),
                                                  doc.geometry()->targets()[0].vertex);
    ASSERT_NE(expected, nullptr);
    EXPECT_EQ(presses->forcesN, expected->forcesN);
    EXPECT_TRUE(doc.examineReach());
}

}  // namespace palpate
