// Replay: a stepped loop fed the recorded device input gives the recorded forces and touched
// vertices bit for bit, chunk hashes included; for stepped and real-time recordings, with
// parameter sets, pauses, device and scene switches; a difference is found at its tick.
#include "engine/core/MeshHash.h"
#include "engine/replay/RecordingPlayer.h"
#include "engine/record/RecordingReader.h"
#include "engine/record/RecordingSession.h"
#include "tests/record/RecordTestRig.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <thread>

using namespace palpate;
using namespace palpate::test;

namespace {

/// Steps a rig `ticks` times while recording to `path`, flushing now and then (stepped mode
/// outruns the writer thread).
void recordStepped(RecordRig& rig, const std::string& path, int ticks,
                   const std::function<void(int, RecordingSession&)>& during = {}) {
    std::string error;
    auto session = RecordingSession::start(*rig.loop, path, rig.header, error);
    ASSERT_TRUE(session) << error;
    for (int i = 0; i < ticks; ++i) {
        if (during) during(i, *session);
        rig.loop->stepOnce();
        if (i % 2000 == 1999) {
            ASSERT_EQ(session->flush(), "");
        }
    }
    ASSERT_EQ(session->stop(), "");
}

void expectExactReplay(const std::string& path, std::uint64_t ticks) {
    const RecordingReader reader = RecordingReader::open(path);
    ASSERT_TRUE(reader.summary().intact) << path;
    std::string error;
    const ReplayStatus s = replayRecording(reader, error);
    ASSERT_EQ(error, "");
    EXPECT_TRUE(s.ok()) << s.firstMismatch << " / " << s.stopReason;
    EXPECT_FALSE(s.mismatch) << s.firstMismatch;
    EXPECT_EQ(s.ticksReplayed, ticks);
    EXPECT_EQ(s.hashMismatches, 0u);
    std::uint64_t dataChunks = 0;
    for (const ChunkInfo& c : reader.chunks()) dataChunks += c.type == ChunkType::Data && c.count > 0;
    EXPECT_EQ(s.hashChecks, dataChunks);
    EXPECT_EQ(s.finalHash, reader.chunks().back().hash);
}

}  // namespace

TEST(Replay, SteppedRecordingReplaysBitExactly) {
    TempDir dir;
    RecordRig rig = makeRecordRig(SimTrajectory::Stroke);
    recordStepped(rig, dir.file("stroke.palprec"), 8000, [&](int i, RecordingSession& session) {
        if (i == 1500) {
            SlopeRingParams p;
            p.ringCount = 4;
            p.slopeMagnitudeMmPerN = {0.5, 0.3, 0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.001};
            ASSERT_EQ(rig.loop->setModelParams(slopeRingModelDef(p)), "");
        }
        if (i == 2500) rig.loop->pause();
        if (i == 2600) rig.loop->resume();
        if (i == 3000) session.mark("switching device");
        if (i == 3000) {
            auto device = aimedDevice(rig.loop->scene().mesh(), SimTrajectory::Sine);
            const DeviceSpec spec = device->spec();
            ASSERT_EQ(session.swapDevice(std::move(device), {"sim:sine", spec}), "");
        }
        if (i == 3050) rig.loop->collectRetired();
        if (i == 5000) {
            // A new scene: another mesh and other parameters, described for the replay.
            auto loaded = TissueMesh::load(smallSphereMeshPath());
            ASSERT_TRUE(loaded.mesh);
            TissuePreset preset;
            preset.model.slopeRing.springStiffnessNPerMm = 2.0;
            const RecordedScene description = describeScene(*loaded.mesh, smallSphereMeshPath(), preset);
            ASSERT_EQ(session.swapScene(HapticScene::create(std::move(*loaded.mesh), preset), description), "");
        }
    });
    rig.loop->collectRetired();
    expectExactReplay(dir.file("stroke.palprec"), 8000);

    const RecordingReader reader = RecordingReader::open(dir.file("stroke.palprec"));
    int scenes = 0, devices = 0;
    for (const auto& e : reader.events()) {
        if (e.kind == EventKind::SceneChanged) {
            ++scenes;
            ASSERT_TRUE(e.scene);
            EXPECT_EQ(e.scene->meshPath, smallSphereMeshPath());
            EXPECT_EQ(e.tick, 5001u);
        }
        if (e.kind == EventKind::DeviceChanged) {
            ++devices;
            ASSERT_TRUE(e.device);
            EXPECT_EQ(e.device->uri, "sim:sine");
        }
    }
    EXPECT_EQ(scenes, 1);
    EXPECT_EQ(devices, 1);
}

TEST(Replay, EveryMethodReplaysBitExactly) {
    TempDir dir;
    for (auto method : {SlopeRingMethod::Previous, SlopeRingMethod::Hybrid, SlopeRingMethod::Proposed}) {
        TissuePreset preset;
        preset.model.slopeRingMethod = method;
        RecordRig rig = makeRecordRig(SimTrajectory::Scan, preset);
        const std::string path = dir.file(std::string(methodName(method)) + ".palprec");
        recordStepped(rig, path, 2500);
        expectExactReplay(path, 2500);
    }
}

TEST(Replay, RecordingStartedMidSessionReplaysBitExactly) {
    // Attaching restarts the session state (tissue at rest, safety re-armed), so a recording
    // started in contact still replays from its header alone.
    TempDir dir;
    RecordRig rig = makeRecordRig(SimTrajectory::Stroke);
    for (int i = 0; i < 1800; ++i) rig.loop->stepOnce();  // deep in the stroke
    ASSERT_TRUE(rig.loop->newestSnapshot().contact);
    recordStepped(rig, dir.file("mid.palprec"), 3000);
    expectExactReplay(dir.file("mid.palprec"), 3000);
    const RecordingReader reader = RecordingReader::open(dir.file("mid.palprec"));
    EXPECT_EQ(reader.summary().firstTick, 1801u);
}

TEST(ReplayThreads, RealTimeRecordingReplaysBitExactly) {
    // The threaded loop's clock, overruns and device reads are all in the file: the stepped replay
    // of a real-time run gives its forces exactly.
    TempDir dir;
    RecordRig rig = makeRecordRig(SimTrajectory::Stroke);
    const std::string path = dir.file("realtime.palprec");
    std::string error;
    auto session = RecordingSession::start(*rig.loop, path, rig.header, error);
    ASSERT_TRUE(session) << error;
    ASSERT_EQ(rig.loop->start(), "");
    std::this_thread::sleep_for(std::chrono::milliseconds(700));
    SlopeRingParams p;
    p.contactStiffnessNPerMm = 0.6;
    ASSERT_EQ(rig.loop->setModelParams(slopeRingModelDef(p)), "");
    session->mark("stiffness changed");
    std::this_thread::sleep_for(std::chrono::milliseconds(1300));
    rig.loop->stop();
    ASSERT_EQ(session->stop(), "");
    const auto loopHash = rig.loop->report().determinismHash;
    const auto ticks = rig.loop->report().counters.ticks;
    EXPECT_EQ(session->stats().ticks, ticks);
    EXPECT_EQ(session->stats().hash, loopHash);
    expectExactReplay(path, ticks);
}

TEST(Replay, ADifferenceIsFoundAtItsTick) {
    // Same ticks, but a header that claims stiffer contact: the replay disagrees from the first
    // tick with force, and says which.
    TempDir dir;
    RecordRig rig = makeRecordRig(SimTrajectory::PressHold);
    const std::string path = dir.file("press.palprec");
    recordStepped(rig, path, 2500);
    const RecordingReader original = RecordingReader::open(path);
    std::uint64_t firstForceTick = 0;
    original.forEachTick([&](const RecordedTick& t) {
        if (t.forceN != glm::vec3(0.0f)) {
            firstForceTick = t.tick;
            return false;
        }
        return true;
    });
    ASSERT_GT(firstForceTick, 0u);

    RecordingHeader forged = original.header();
    forged.scene.params.contactStiffnessNPerMm *= 1.01;
    std::vector<std::uint8_t> bytes;
    const std::uint32_t forgedCrc = encodeRecordingHeader(forged, bytes);
    const auto file = readBytes(path);
    std::size_t headerBytes = 0;
    RecordingHeader ignored;
    std::string error;
    ASSERT_TRUE((error = decodeRecordingHeader(file.data(), file.size(), ignored, headerBytes)).empty());
    const std::size_t forgedHeaderBytes = bytes.size();
    bytes.insert(bytes.end(), file.begin() + std::ptrdiff_t(headerBytes), file.end());
    EXPECT_FALSE(RecordingReader::fromBytes(bytes, "forged").summary().intact);  // the chunks name the old header
    retagChunks(bytes, forgedHeaderBytes, forgedCrc);
    const RecordingReader reader = RecordingReader::fromBytes(bytes, "forged");
    ASSERT_TRUE(reader.summary().intact);  // retagged, the file is whole: only the replay can tell
    const ReplayStatus s = replayRecording(reader, error);
    EXPECT_TRUE(s.mismatch);
    EXPECT_FALSE(s.ok());
    EXPECT_GE(s.firstMismatchTick, firstForceTick - 1);
    EXPECT_LE(s.firstMismatchTick, firstForceTick + 200);  // force ramps in after contact
    EXPECT_NE(s.firstMismatch.find("tick " + std::to_string(s.firstMismatchTick)), std::string::npos);
    EXPECT_GT(s.hashMismatches, 0u);
}

TEST(Replay, RefusesADifferentMesh) {
    TempDir dir;
    RecordRig rig = makeRecordRig(SimTrajectory::PressHold);
    recordStepped(rig, dir.file("m.palprec"), 200);
    const RecordingReader reader = RecordingReader::open(dir.file("m.palprec"));
    std::string error;
    ReplayDef options;
    options.meshPath = smallSphereMeshPath();
    EXPECT_FALSE(RecordingPlayer::open(reader, error, options));
    EXPECT_NE(error.find("not the recorded mesh"), std::string::npos) << error;
    options.meshPath = dir.file("missing.off");
    error.clear();
    EXPECT_FALSE(RecordingPlayer::open(reader, error, options));
    EXPECT_NE(error.find("missing.off"), std::string::npos) << error;
}

TEST(Replay, PlayerSeeksAndStepsForATimeline) {
    TempDir dir;
    RecordRig rig = makeRecordRig(SimTrajectory::Stroke);
    recordStepped(rig, dir.file("p.palprec"), 4000);
    const RecordingReader reader = RecordingReader::open(dir.file("p.palprec"));
    std::string error;
    auto player = RecordingPlayer::open(reader, error);
    ASSERT_TRUE(player) << error;
    EXPECT_EQ(player->firstTick(), 1u);
    EXPECT_EQ(player->lastTick(), 4000u);
    EXPECT_EQ(player->recordedTick(), nullptr);
    EXPECT_EQ(player->step(10), 10u);
    EXPECT_EQ(player->currentTick(), 10u);
    ASSERT_TRUE(player->seek(2500));
    const HapticSnapshot& s = player->snapshot();
    const auto recorded = reader.tickAt(2500);
    ASSERT_TRUE(recorded);
    EXPECT_EQ(std::memcmp(&s.forceN, &recorded->forceN, sizeof(glm::vec3)), 0);
    EXPECT_EQ(s.touched, recorded->touched);
    EXPECT_EQ(player->positionsMm().size(), player->mesh().vertexCount());
    ASSERT_NE(s.touched, kNoVertex);
    const glm::vec3 touchedAt2500 = player->positionsMm()[s.touched];
    ASSERT_TRUE(player->seek(100));  // backwards: replays from the start
    EXPECT_EQ(player->currentTick(), 100u);
    ASSERT_TRUE(player->seek(2500));
    EXPECT_EQ(player->positionsMm()[player->snapshot().touched], touchedAt2500);
    EXPECT_FALSE(player->seek(4001));
    EXPECT_EQ(player->step(100000), 1500u);
    EXPECT_TRUE(player->atEnd());
    EXPECT_TRUE(player->status().ok()) << player->status().firstMismatch;
}
