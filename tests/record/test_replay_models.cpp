// Replay of the registry models other than the slope-ring methods: the player rebuilds the scene
// from the recording's preset JSON (RecordingPlayer::buildScene), so a stepped recording of the
// radius-of-influence or mass-spring model replays bit for bit.
#include "engine/scene/HapticScene.h"
#include "engine/replay/RecordingPlayer.h"
#include "engine/record/RecordingReader.h"
#include "engine/record/RecordingSession.h"
#include "tests/record/RecordTestRig.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

using namespace palpate;
using namespace palpate::test;

namespace {

struct ModelRun {
    std::uint64_t contactTicks = 0;
    std::string modelName;
};

/// Records `ticks` stepped ticks of `modelName` on the rig's sphere under a press and stroke.
ModelRun recordModel(const std::string& modelName, const std::string& path, int ticks) {
    ModelRun run;
    TissuePreset preset;
    const auto def = modelDefForName(modelName);
    EXPECT_TRUE(def) << modelName;
    if (!def) return run;
    setPresetModel(preset, *def);
    auto loaded = TissueMesh::load(sphereMeshPath());
    EXPECT_TRUE(loaded.mesh) << loaded.error();
    if (!loaded.mesh) return run;
    auto device = aimedDevice(*loaded.mesh, SimTrajectory::Stroke, float(presetToolRadiusMm(preset)));
    HapticLoopDef loopDef;
    loopDef.rateHz = preset.hapticRateHz;
    loopDef.trySchedFifo = false;
    const RecordingHeader header =
        makeRecordingHeader(*loaded.mesh, sphereMeshPath(), preset, "sim:stroke", device->spec(), loopDef.safety);
    // On the heap: the loop's snapshot buffers are too large for the stack.
    auto loop = std::make_unique<HapticLoop>(loopDef, HapticScene::create(std::move(*loaded.mesh), preset),
                                             std::move(device));
    run.modelName = loop->scene().model().name();
    std::string error;
    auto session = RecordingSession::start(*loop, path, header, error);
    EXPECT_TRUE(session) << error;
    if (!session) return run;
    for (int i = 0; i < ticks; ++i) {
        loop->stepOnce();
        run.contactTicks += loop->newestSnapshot().contact;
    }
    EXPECT_EQ(session->stop(), "");
    return run;
}

void expectExactReplay(const std::string& path, std::uint64_t ticks) {
    const RecordingReader reader = RecordingReader::open(path);
    ASSERT_TRUE(reader.summary().intact) << path;
    std::string error;
    const ReplayStatus s = replayRecording(reader, error);
    ASSERT_EQ(error, "");
    EXPECT_TRUE(s.ok()) << s.firstMismatch << " / " << s.stopReason;
    EXPECT_FALSE(s.mismatch) << s.firstMismatch;
    EXPECT_EQ(s.mismatches, 0u);
    EXPECT_EQ(s.ticksReplayed, ticks);
    EXPECT_EQ(s.hashMismatches, 0u);
    EXPECT_EQ(s.finalHash, reader.chunks().back().hash);
}

}  // namespace

TEST(ReplayModels, RadiusOfInfluenceReplaysBitExactly) {
    TempDir dir;
    const std::string path = dir.file("roi.palprec");
    const ModelRun run = recordModel("radius-of-influence", path, 1500);
    EXPECT_EQ(run.modelName, "radius-of-influence");
    EXPECT_GT(run.contactTicks, 100u) << "the stroke must press the tissue";
    expectExactReplay(path, 1500);
}

TEST(ReplayModels, MassSpringLocalReplaysBitExactly) {
    TempDir dir;
    const std::string path = dir.file("msl.palprec");
    const ModelRun run = recordModel("mass-spring-local", path, 1500);
    EXPECT_EQ(run.modelName, "mass-spring-local");
    EXPECT_GT(run.contactTicks, 100u) << "the stroke must press the tissue";
    expectExactReplay(path, 1500);
}

TEST(ReplayModels, TheRecordingNamesTheModelInItsPresetJson) {
    TempDir dir;
    const std::string path = dir.file("roi.palprec");
    recordModel("radius-of-influence", path, 300);
    const RecordingReader reader = RecordingReader::open(path);
    const auto stored = parseTissuePreset(reader.header().scene.presetJson, "presetJson");
    ASSERT_TRUE(stored.preset) << stored.error();
    EXPECT_EQ(presetModelName(*stored.preset), "radius-of-influence");
}
