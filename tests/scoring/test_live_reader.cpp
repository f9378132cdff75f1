// Reading a recording while it is written (RecordingReader::openLive, refresh, finishLive) and a
// player that follows it (RecordingPlayer::refresh): at every stage what was read is a prefix of
// the whole, an incomplete tail is not damage, and at the end everything equals open().
#include "engine/replay/RecordingPlayer.h"
#include "engine/record/RecordingReader.h"
#include "engine/record/RecordingSession.h"
#include "tests/record/RecordTestRig.h"

#include <gtest/gtest.h>

#include <fstream>
#include <random>

namespace palpate {
namespace {

/// A stepped 3 s stroke session with marks, one of them after its tick's chunk was written (so it
/// lands in a later chunk than its tick).
std::string recordSession(test::TempDir& dir) {
    auto rig = test::makeRecordRig(SimTrajectory::Stroke);
    std::string error;
    const std::string path = dir.file("session.palprec");
    auto session = RecordingSession::start(*rig.loop, path, rig.header, error);
    if (!session) throw std::runtime_error(error);
    for (int i = 1; i <= 3000; ++i) {
        rig.loop->stepOnce();
        if (i == 700) session->mark("before the flush");
        if (i % 100 == 0) session->flush();
        if (i == 1500) session->mark("late: its tick is already in the file");
    }
    session->stop();
    return path;
}

void append(const std::string& path, const std::vector<std::uint8_t>& bytes, std::size_t from, std::size_t to) {
    std::ofstream out(path, std::ios::binary | std::ios::app);
    out.write(reinterpret_cast<const char*>(bytes.data() + from), std::streamsize(to - from));
}

void expectSame(const RecordingReader& a, const RecordingReader& b) {
    ASSERT_EQ(a.chunks().size(), b.chunks().size());
    for (std::size_t i = 0; i < a.chunks().size(); ++i) {
        EXPECT_EQ(a.chunks()[i].offset, b.chunks()[i].offset);
        EXPECT_EQ(a.chunks()[i].firstTick, b.chunks()[i].firstTick);
        EXPECT_EQ(a.chunks()[i].count, b.chunks()[i].count);
        EXPECT_EQ(a.chunks()[i].hashChecked, b.chunks()[i].hashChecked);
        EXPECT_EQ(a.chunks()[i].firstTimeS, b.chunks()[i].firstTimeS);
    }
    ASSERT_EQ(a.events().size(), b.events().size());
    for (std::size_t i = 0; i < a.events().size(); ++i) {
        EXPECT_EQ(a.events()[i].tick, b.events()[i].tick);
        EXPECT_EQ(a.events()[i].kind, b.events()[i].kind);
        EXPECT_EQ(a.events()[i].text, b.events()[i].text);
        EXPECT_EQ(a.events()[i].timeS, b.events()[i].timeS);
    }
    ASSERT_EQ(a.damage().size(), b.damage().size());
    for (std::size_t i = 0; i < a.damage().size(); ++i) {
        EXPECT_EQ(a.damage()[i].offset, b.damage()[i].offset);
        EXPECT_EQ(a.damage()[i].bytes, b.damage()[i].bytes);
        EXPECT_EQ(a.damage()[i].reason, b.damage()[i].reason);
    }
    const RecordingSummary &s = a.summary(), &t = b.summary();
    EXPECT_EQ(s.fileBytes, t.fileBytes);
    EXPECT_EQ(s.headerOk, t.headerOk);
    EXPECT_EQ(s.ticks, t.ticks);
    EXPECT_EQ(s.firstTick, t.firstTick);
    EXPECT_EQ(s.lastTick, t.lastTick);
    EXPECT_EQ(s.durationS, t.durationS);
    EXPECT_EQ(s.events, t.events);
    EXPECT_EQ(s.lostTicks, t.lostTicks);
    EXPECT_EQ(s.hashMismatches, t.hashMismatches);
    EXPECT_EQ(s.closedCleanly, t.closedCleanly);
    EXPECT_EQ(s.intact, t.intact);
}

TEST(LiveReader, GrowingFileReadsAsAPrefixAndEndsEqualToOpen) {
    test::TempDir dir;
    const std::string whole = recordSession(dir);
    const auto bytes = test::readBytes(whole);
    const RecordingReader reference = RecordingReader::open(whole);
    ASSERT_TRUE(reference.summary().intact);
    // The late mark sits in a later chunk than its tick; events are still ordered by tick.
    std::uint64_t lateTick = 0;
    for (const auto& e : reference.events())
        if (e.kind == EventKind::Mark && e.text.rfind("late", 0) == 0) lateTick = e.tick;
    EXPECT_EQ(lateTick, 1500u);

    std::mt19937 random(7);
    const std::string live = dir.file("live.palprec");
    test::writeBytes(live, {});
    RecordingReader reader = RecordingReader::openLive(live);
    EXPECT_TRUE(reader.live());
    EXPECT_FALSE(reader.headerOk());
    std::unique_ptr<RecordingPlayer> player;
    std::size_t written = 0;
    int steps = 0;
    while (written < bytes.size()) {
        // Pieces that cut the header and chunks anywhere.
        const std::size_t next = std::min(bytes.size(), written + 1 + std::size_t(random() % 700));
        append(live, bytes, written, next);
        written = next;
        EXPECT_TRUE(reader.refresh());
        EXPECT_TRUE(reader.damage().empty()) << "at " << written << ": " << reader.damage().front().reason;
        ASSERT_LE(reader.chunks().size(), reference.chunks().size());
        for (std::size_t i = 0; i < reader.chunks().size(); ++i)
            ASSERT_EQ(reader.chunks()[i].offset, reference.chunks()[i].offset);
        if (!reader.chunks().empty()) {
            EXPECT_EQ(reader.pendingBytes(), written - (reader.chunks().back().offset + reader.chunks().back().bytes));
        }
        // A player follows from the first ticks on.
        if (!player && reader.summary().ticks > 0) {
            std::string error;
            player = RecordingPlayer::open(reader, error);
            ASSERT_TRUE(player) << error;
        } else if (player) {
            player->refresh();
        }
        if (player) player->step(~std::uint64_t(0));
        ++steps;
    }
    EXPECT_GT(steps, 50);
    EXPECT_FALSE(reader.refresh());  // nothing new
    reader.finishLive();
    EXPECT_FALSE(reader.live());
    expectSame(reader, reference);
    ASSERT_TRUE(player);
    player->refresh();
    player->step(~std::uint64_t(0));
    EXPECT_TRUE(player->status().ok()) << player->status().firstMismatch << player->status().stopReason;
    std::string error;
    const ReplayStatus full = replayRecording(reference, error);
    EXPECT_EQ(player->status().finalHash, full.finalHash);
    EXPECT_EQ(player->status().ticksReplayed, full.ticksReplayed);
}

TEST(LiveReader, ATailCutShortIsPendingLiveAndDamageOnceFinished) {
    test::TempDir dir;
    const std::string whole = recordSession(dir);
    auto bytes = test::readBytes(whole);
    const RecordingReader reference = RecordingReader::open(whole);
    // Cut inside the tenth chunk's payload (a crash mid-write).
    const ChunkInfo& c = reference.chunks()[10];
    bytes.resize(c.offset + c.bytes / 2);
    const std::string cut = dir.file("cut.palprec");
    test::writeBytes(cut, bytes);
    RecordingReader live = RecordingReader::openLive(cut);
    EXPECT_TRUE(live.damage().empty());
    EXPECT_EQ(live.chunks().size(), 10u);
    EXPECT_EQ(live.pendingBytes(), c.bytes / 2);
    live.finishLive();
    expectSame(live, RecordingReader::open(cut));
    EXPECT_EQ(live.damage().size(), 1u);
}

TEST(LiveReader, NotLiveReadersDoNotRefresh) {
    test::TempDir dir;
    RecordingReader r = RecordingReader::open(recordSession(dir));
    EXPECT_FALSE(r.live());
    EXPECT_FALSE(r.refresh());
    const RecordingReader missing = RecordingReader::openLive(dir.file("none.palprec"));
    EXPECT_FALSE(missing.fileError().empty());
}

}  // namespace
}  // namespace palpate
