// Recording a haptic loop: round trip of every tick and event, the session hash, ring overflow
// (gap records), and the tick's real-time rules with a recorder attached.
#include "engine/record/RecordingReader.h"
#include "engine/record/RecordingSession.h"
#include "tests/record/RecordTestRig.h"
#include "tests/support/AllocationCounter.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <thread>

using namespace palpate;
using namespace palpate::test;

namespace {

/// Forwards to the writer and keeps a copy of everything the loop handed over (tests only).
class TeeSink final : public RecorderSink {
public:
    explicit TeeSink(RecorderSink& next) : mNext(next) { ticks.reserve(20000); }
    void onTick(const RecordedTick& t) noexcept override {
        ticks.push_back(t);
        mNext.onTick(t);
    }
    void onCommand(const RecordedCommand& c) noexcept override {
        commands.push_back(c);
        mNext.onCommand(c);
    }
    std::vector<RecordedTick> ticks;
    std::vector<RecordedCommand> commands;

private:
    RecorderSink& mNext;
};

bool sameTick(const RecordedTick& a, const RecordedTick& b) {
    return a.tick == b.tick && std::memcmp(&a.nowS, &b.nowS, 8) == 0 && a.readOk == b.readOk &&
           (!a.readOk || (a.sample.sequence == b.sample.sequence &&
                          std::memcmp(&a.sample.timeS, &b.sample.timeS, 8) == 0 &&
                          std::memcmp(&a.sample.positionMm, &b.sample.positionMm, 12) == 0 &&
                          a.sample.buttons == b.sample.buttons)) &&
           std::memcmp(&a.forceN, &b.forceN, 12) == 0 && a.touched == b.touched && a.deviceState == b.deviceState &&
           a.tickOverran == b.tickOverran && a.paused == b.paused && a.contact == b.contact;
}

}  // namespace

TEST(Recorder, RoundTripKeepsEveryTickAndEvent) {
    TempDir dir;
    RecordRig rig = makeRecordRig(SimTrajectory::Stroke);
    rig.header.note = "round trip";
    std::string error;
    auto writer = RecordingWriter::create(dir.file("round.palprec"), rig.header, error);
    ASSERT_TRUE(writer) << error;
    TeeSink tee(*writer);
    rig.loop->attachRecorder(&tee);

    SlopeRingParams softer;
    softer.springStiffnessNPerMm = 0.9;
    for (int i = 0; i < 3000; ++i) {
        if (i == 1000) {
            ASSERT_EQ(rig.loop->setModelParams(slopeRingModelDef(softer)), "");
        }
        if (i == 1500) writer->mark("halfway");
        if (i == 1600) writer->exerciseEvent(R"({"event":"nodule found"})");
        if (i == 2000) rig.loop->pause();
        if (i == 2100) rig.loop->resume();
        rig.loop->stepOnce();
        if (i % 1000 == 999) {
            ASSERT_EQ(writer->flush(), "");
        }
    }
    rig.loop->detachRecorder();
    ASSERT_EQ(writer->close(), "");
    const RecordingStats stats = writer->stats();

    const RecordingReader reader = RecordingReader::open(writer->path());
    ASSERT_EQ(reader.fileError(), "");
    ASSERT_TRUE(reader.headerOk()) << reader.headerError();
    const RecordingSummary& s = reader.summary();
    EXPECT_TRUE(s.intact);
    EXPECT_TRUE(s.closedCleanly);
    EXPECT_EQ(s.ticks, 3000u);
    EXPECT_EQ(s.firstTick, 1u);
    EXPECT_EQ(s.lastTick, 3000u);
    EXPECT_EQ(s.fileBytes, stats.bytes);
    EXPECT_EQ(stats.ticks, 3000u);
    EXPECT_EQ(stats.droppedTicks, 0u);
    EXPECT_NEAR(s.durationS, 3.0, 1e-9);
    EXPECT_EQ(reader.header().note, "round trip");
    EXPECT_EQ(reader.header().scene.meshHash, rig.header.scene.meshHash);

    // Every tick, bit for bit, as the loop handed it over.
    const auto ticks = reader.ticks();
    ASSERT_EQ(ticks.size(), tee.ticks.size());
    for (std::size_t i = 0; i < ticks.size(); ++i) ASSERT_TRUE(sameTick(ticks[i], tee.ticks[i])) << "tick " << i + 1;
    for (const ChunkInfo& c : reader.chunks())
        if (c.type == ChunkType::Data && c.count > 0) {
            EXPECT_TRUE(c.hashChecked) << c.firstTick;
        }

    // The session hash is the loop's: the recording started with the loop.
    EXPECT_EQ(stats.hash, rig.loop->report().determinismHash);
    EXPECT_EQ(reader.chunks().back().hash, rig.loop->report().determinismHash);

    // Events: the applied parameters at the tick the loop applied them, marks, pause, state.
    int params = 0, marks = 0, exercise = 0, paused = 0, resumed = 0, states = 0;
    for (const RecordingEvent& e : reader.events()) {
        switch (e.kind) {
            case EventKind::ParamsApplied:
                ++params;
                EXPECT_EQ(e.tick, 1001u);
                EXPECT_EQ(e.params.springStiffnessNPerMm, 0.9);
                EXPECT_NEAR(e.timeS, 1.001, 1e-9);
                break;
            case EventKind::Mark:
                ++marks;
                EXPECT_EQ(e.text, "halfway");
                EXPECT_EQ(e.tick, 1500u);
                break;
            case EventKind::Exercise: ++exercise; EXPECT_EQ(e.text, R"({"event":"nodule found"})"); break;
            case EventKind::Paused: ++paused; EXPECT_EQ(e.tick, 2001u); break;
            case EventKind::Resumed: ++resumed; EXPECT_EQ(e.tick, 2101u); break;
            case EventKind::DeviceState: ++states; EXPECT_EQ(e.deviceState, DeviceState::Ready); break;
            default: ADD_FAILURE() << "unexpected event " << eventKindName(e.kind);
        }
    }
    EXPECT_EQ(params, 1);
    EXPECT_EQ(marks, 1);
    EXPECT_EQ(exercise, 1);
    EXPECT_EQ(paused, 1);
    EXPECT_EQ(resumed, 1);
    EXPECT_EQ(states, 1);
    ASSERT_EQ(tee.commands.size(), 1u);
    EXPECT_EQ(tee.commands[0].tick, 1001u);

    // Random access for a timeline.
    const auto t = reader.tickAt(1234);
    ASSERT_TRUE(t);
    EXPECT_TRUE(sameTick(*t, tee.ticks[1233]));
    EXPECT_FALSE(reader.tickAt(3001));
    EXPECT_FALSE(reader.tickAt(0));
}

TEST(Recorder, FullRingDropsTicksAndTheFileSaysSo) {
    TempDir dir;
    RecordRig rig = makeRecordRig(SimTrajectory::Sine);
    RecordingWriterDef def;
    def.ringCapacityTicks = 64;
    def.drainPeriodS = 0.1;  // the writer sleeps while 1000 stepped ticks come in
    std::string error;
    auto session = RecordingSession::start(*rig.loop, dir.file("gap.palprec"), rig.header, error, def);
    ASSERT_TRUE(session) << error;
    for (int i = 0; i < 1000; ++i) rig.loop->stepOnce();
    ASSERT_EQ(session->flush(), "");
    for (int i = 0; i < 10; ++i) rig.loop->stepOnce();
    for (int i = 0; i < 500; ++i) rig.loop->stepOnce();  // dropped at the end: no later tick carries them
    ASSERT_EQ(session->stop(), "");
    const RecordingStats stats = session->stats();
    EXPECT_GT(stats.droppedTicks, 0u);
    EXPECT_EQ(stats.ticks + stats.droppedTicks, 1510u);

    const RecordingReader reader = RecordingReader::open(dir.file("gap.palprec"));
    const RecordingSummary& s = reader.summary();
    EXPECT_GE(s.gaps, 1u);
    EXPECT_EQ(s.droppedTicks, stats.droppedTicks);
    EXPECT_EQ(s.ticks, stats.ticks);
    EXPECT_EQ(s.lostTicks, 0u);   // dropped (said so), not lost
    EXPECT_TRUE(s.intact);        // the file is whole; it records the gap
    std::uint64_t covered = 0;
    for (const ChunkInfo& c : reader.chunks())
        if (c.type != ChunkType::End) covered += c.count;
    EXPECT_EQ(covered, 1510u);  // every tick is either recorded or inside a gap record
}

TEST(Recorder, SteppedTickWithRecorderDoesNotAllocate) {
    TempDir dir;
    for (auto method : {SlopeRingMethod::Coherent, SlopeRingMethod::Proposed}) {
        TissuePreset preset;
        preset.model.slopeRingMethod = method;
        RecordRig rig = makeRecordRig(SimTrajectory::Stroke, preset);
        std::string error;
        auto session = RecordingSession::start(*rig.loop,
                                               dir.file("alloc-" + std::string(methodName(method)) + ".palprec"),
                                               rig.header, error);
        ASSERT_TRUE(session) << error;
        const auto atAttach = threadAllocationCount();
        for (int i = 0; i < 50; ++i) rig.loop->stepOnce();  // the first picks the recorder up (and resets)
        EXPECT_EQ(threadAllocationCount() - atAttach, 0u) << methodName(method);
        SlopeRingParams p;
        p.contactStiffnessNPerMm = 0.7;
        ASSERT_EQ(rig.loop->setModelParams(slopeRingModelDef(p, method)), "");
        const auto before = threadAllocationCount();
        for (int i = 0; i < 5000; ++i) rig.loop->stepOnce();  // ring: 8192 ticks, no flush needed
        const auto after = threadAllocationCount();
        EXPECT_EQ(after - before, 0u) << methodName(method);
        ASSERT_EQ(session->stop(), "");
        EXPECT_EQ(session->stats().ticks, 5050u);
    }
}

TEST(RecorderThreads, RunningTickWithRecorderDoesNotAllocate) {
    // The haptic thread's own allocation count, read on that thread (the writer thread may
    // allocate for events; it is not real-time).
    class CountingSink final : public RecorderSink {
    public:
        explicit CountingSink(RecorderSink& next) : mNext(next) {}
        void onTick(const RecordedTick& t) noexcept override {
            mNext.onTick(t);
            allocations.store(threadAllocationCount(), std::memory_order_relaxed);
            ticks.fetch_add(1, std::memory_order_relaxed);
        }
        void onCommand(const RecordedCommand& c) noexcept override { mNext.onCommand(c); }
        std::atomic<std::uint64_t> allocations{0}, ticks{0};

    private:
        RecorderSink& mNext;
    };
    TempDir dir;
    RecordRig rig = makeRecordRig(SimTrajectory::Sine);
    std::string error;
    auto writer = RecordingWriter::create(dir.file("thread.palprec"), rig.header, error);
    ASSERT_TRUE(writer) << error;
    CountingSink counting(*writer);
    rig.loop->attachRecorder(&counting);
    ASSERT_EQ(rig.loop->start(), "");
    while (counting.ticks.load() < 100) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    const auto before = counting.allocations.load();
    const auto ticksBefore = counting.ticks.load();
    for (int i = 0; i < 20; ++i) {  // marks and stats from the controller meanwhile
        writer->mark("mark " + std::to_string(i));
        (void)writer->stats();
        std::this_thread::sleep_for(std::chrono::milliseconds(15));
    }
    const auto after = counting.allocations.load();
    rig.loop->detachRecorder();
    rig.loop->stop();
    ASSERT_EQ(writer->close(), "");
    EXPECT_GT(counting.ticks.load(), ticksBefore + 100);
    EXPECT_EQ(after - before, 0u);
    const RecordingReader reader = RecordingReader::open(writer->path());
    EXPECT_TRUE(reader.summary().intact);
    EXPECT_EQ(reader.summary().ticks, counting.ticks.load());
    std::size_t marks = 0;
    for (const auto& e : reader.events()) marks += e.kind == EventKind::Mark;
    EXPECT_EQ(marks, 20u);
}

TEST(RecorderThreads, StartAndStopWhileTheLoopRuns) {
    // Sessions come and go on a running loop; each file is whole and replay-consistent in itself.
    TempDir dir;
    RecordRig rig = makeRecordRig(SimTrajectory::Sine);
    ASSERT_EQ(rig.loop->start(), "");
    for (int round = 0; round < 5; ++round) {
        std::string error;
        const std::string path = dir.file("churn" + std::to_string(round) + ".palprec");
        auto session = RecordingSession::start(*rig.loop, path, rig.header, error);
        ASSERT_TRUE(session) << error;
        // Until the writer has some ticks (a loaded machine may take longer than a few ms): waiting
        // for a count, not for a time, so the check below never depends on the machine's speed.
        const std::uint64_t wantTicks = 21 + 10 * std::uint64_t(round);
        for (int waited = 0; waited < 10000 && session->stats().ticks < wantTicks; waited += 5) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            session->flush();
        }
        session->mark("round " + std::to_string(round));
        ASSERT_EQ(session->stop(), "");
        const RecordingReader reader = RecordingReader::open(path);
        EXPECT_TRUE(reader.summary().intact) << path;
        EXPECT_GT(reader.summary().ticks, 20u);
        EXPECT_EQ(reader.summary().ticks, session->stats().ticks);
    }
    rig.loop->stop();
}

TEST(Recorder, BadWriterDefinitionsAndPathsAreReported) {
    RecordRig rig = makeRecordRig(SimTrajectory::PressHold);
    std::string error;
    RecordingWriterDef def;
    def.drainPeriodS = 0.5;
    EXPECT_FALSE(RecordingWriter::create("/tmp/never.palprec", rig.header, error, def));
    EXPECT_NE(error.find("drainPeriodS"), std::string::npos) << error;
    error.clear();
    EXPECT_FALSE(RecordingSession::start(*rig.loop, "/nonexistent-dir/x.palprec", rig.header, error));
    EXPECT_NE(error.find("/nonexistent-dir/x.palprec"), std::string::npos) << error;
    RecordingHeader wrongRate = rig.header;
    wrongRate.rateHz = 500.0;
    error.clear();
    EXPECT_FALSE(RecordingSession::start(*rig.loop, "/tmp/never.palprec", wrongRate, error));
    EXPECT_NE(error.find("rateHz"), std::string::npos) << error;
}

TEST(Recorder, SizeGoalOf40BytesPerTickHolds) {
    // A minute of loop time in stepped mode (chunks of one drain period, as in real time).
    TempDir dir;
    for (auto trajectory : {SimTrajectory::Stroke, SimTrajectory::Sine}) {
        RecordRig rig = makeRecordRig(trajectory);
        const std::string path = dir.file("size-" + std::to_string(int(trajectory)) + ".palprec");
        std::string error;
        auto session = RecordingSession::start(*rig.loop, path, rig.header, error);
        ASSERT_TRUE(session) << error;
        for (int i = 0; i < 60000; ++i) {
            rig.loop->stepOnce();
            if (i % 4000 == 3999) {
                ASSERT_EQ(session->flush(), "");
            }
        }
        ASSERT_EQ(session->stop(), "");
        const RecordingStats s = session->stats();
        EXPECT_EQ(s.ticks, 60000u);
        EXPECT_LE(s.bytesPerTick(), 40.0) << simTrajectoryName(trajectory);
        std::cout << "[ figures  ] sim:" << simTrajectoryName(trajectory) << ", 60 s stepped: " << s.bytes
                  << " bytes, " << s.bytesPerTick() << " bytes/tick, " << s.chunks << " chunks\n";
    }
}

// A scripted device's script starts with the recording: the first recorded sample is where the
// script begins however long the loop ran before, so a scripted run's score does not depend on how
// soon the recording attached (docs/haptic-loop.md).
TEST(Recorder, AScriptedDeviceStartsItsScriptWithTheRecording) {
    TempDir dir;
    RecordRig rig = makeRecordRig(SimTrajectory::Stroke);
    for (int i = 0; i < 2500; ++i) rig.loop->stepOnce();  // 2.5 s into the stroke: pressing
    const glm::vec3 startMm = rig.device->positionAtMm(0.0);
    std::string error;
    auto writer = RecordingWriter::create(dir.file("late.palprec"), rig.header, error);
    ASSERT_TRUE(writer) << error;
    TeeSink tee(*writer);
    rig.loop->attachRecorder(&tee);
    for (int i = 0; i < 1200; ++i) rig.loop->stepOnce();
    rig.loop->detachRecorder();
    ASSERT_EQ(writer->close(), "");
    ASSERT_FALSE(tee.ticks.empty());
    ASSERT_TRUE(tee.ticks.front().readOk);
    EXPECT_EQ(tee.ticks.front().sample.positionMm, startMm);
    // and the script goes on from there on the recording's clock
    const RecordedTick& later = tee.ticks[1000];
    EXPECT_EQ(later.sample.positionMm, rig.device->positionAtMm(later.nowS - tee.ticks.front().nowS));
}
