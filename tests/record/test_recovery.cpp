// Damaged recordings: a truncated file gives back every chunk before the cut, a flipped byte is
// caught by a CRC and costs only its chunk, and a recorder killed with SIGKILL leaves a file whose
// recovered part ends at most 100 ms before the kill.
#include "engine/replay/RecordingPlayer.h"
#include "engine/record/RecordingReader.h"
#include "engine/record/RecordingSession.h"
#include "tests/record/RecordTestRig.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <random>
#include <thread>

using namespace palpate;
using namespace palpate::test;

namespace {

/// A stepped recording of 3000 ticks (120 data chunks) with a few events.
const std::vector<std::uint8_t>& sampleRecording() {
    static const std::vector<std::uint8_t> bytes = [] {
        TempDir dir;
        RecordRig rig = makeRecordRig(SimTrajectory::Stroke);
        std::string error;
        auto session = RecordingSession::start(*rig.loop, dir.file("s.palprec"), rig.header, error);
        if (!session) throw std::runtime_error(error);
        for (int i = 0; i < 3000; ++i) {
            if (i % 500 == 0) session->mark("mark " + std::to_string(i));
            rig.loop->stepOnce();
        }
        session->stop();
        return readBytes(dir.file("s.palprec"));
    }();
    return bytes;
}

}  // namespace

TEST(Recovery, TruncatedFileRecoversEveryIntactChunk) {
    const auto& full = sampleRecording();
    const RecordingReader whole = RecordingReader::fromBytes(full);
    ASSERT_TRUE(whole.summary().intact);
    const auto& chunks = whole.chunks();
    ASSERT_GT(chunks.size(), 100u);

    std::vector<std::size_t> cuts;
    std::mt19937 rng(5);
    for (int i = 0; i < 40; ++i) cuts.push_back(rng() % full.size());
    for (std::size_t k = 0; k < chunks.size(); k += 17) {
        cuts.push_back(chunks[k].offset);                    // exactly at a boundary
        cuts.push_back(chunks[k].offset + 1);                // one byte of the next chunk
        cuts.push_back(chunks[k].offset + chunks[k].bytes - 1);  // one byte short
    }
    cuts.push_back(5);  // inside the header
    for (std::size_t cut : cuts) {
        const RecordingReader r =
            RecordingReader::fromBytes(std::vector<std::uint8_t>(full.begin(), full.begin() + std::ptrdiff_t(cut)));
        std::size_t intact = 0;
        std::uint64_t ticks = 0;
        for (const ChunkInfo& c : chunks)
            if (c.offset + c.bytes <= cut && c.offset >= chunks.front().offset) {
                ++intact;
                if (c.type == ChunkType::Data) ticks += c.count;
            }
        if (cut < chunks.front().offset) {
            EXPECT_FALSE(r.headerOk());
            EXPECT_EQ(r.summary().chunks, 0u);
            continue;
        }
        EXPECT_EQ(r.summary().chunks, intact) << "cut at " << cut;
        EXPECT_EQ(r.summary().ticks, ticks) << "cut at " << cut;
        EXPECT_FALSE(r.summary().intact);
        EXPECT_FALSE(r.summary().closedCleanly);
        const bool onBoundary = std::any_of(chunks.begin(), chunks.end(), [&](const ChunkInfo& c) {
            return c.offset == cut;
        });
        EXPECT_EQ(r.damage().size(), onBoundary ? 0u : 1u) << "cut at " << cut;
        // The recovered ticks replay exactly.
        if (cut == chunks[34].offset) {
            std::string error;
            const ReplayStatus s = replayRecording(r, error);
            EXPECT_EQ(error, "");
            EXPECT_FALSE(s.mismatch);
            EXPECT_EQ(s.ticksReplayed, ticks);
        }
    }
}

TEST(Recovery, FlippedByteIsFoundByTheCrcAndCostsOnlyItsChunk) {
    const auto& full = sampleRecording();
    const RecordingReader whole = RecordingReader::fromBytes(full);
    const auto& chunks = whole.chunks();
    const std::uint64_t totalTicks = whole.summary().ticks;
    std::mt19937 rng(9);
    for (int trial = 0; trial < 30; ++trial) {
        const std::size_t k = 1 + rng() % (chunks.size() - 2);
        const ChunkInfo& victim = chunks[k];
        auto bytes = full;
        const bool inHeader = trial % 3 == 0;
        const std::size_t at = victim.offset + (inHeader ? 4 + rng() % (kChunkHeaderBytes - 4)
                                                         : kChunkHeaderBytes + rng() % (victim.bytes - kChunkHeaderBytes));
        bytes[at] ^= std::uint8_t(1u << (rng() % 8));
        const RecordingReader r = RecordingReader::fromBytes(bytes);
        ASSERT_EQ(r.damage().size(), 1u) << "byte " << at;
        const DamagedRegion& d = r.damage().front();
        EXPECT_EQ(d.offset, victim.offset);
        EXPECT_EQ(d.bytes, victim.bytes);
        EXPECT_NE(d.reason.find("CRC"), std::string::npos) << d.reason;
        EXPECT_EQ(r.summary().chunks, chunks.size() - 1);
        EXPECT_FALSE(r.summary().intact);
        if (victim.type == ChunkType::Data) {
            EXPECT_EQ(r.summary().ticks, totalTicks - victim.count);
            EXPECT_EQ(r.summary().lostTicks, victim.count);
            if (!inHeader) {
                EXPECT_TRUE(d.ticksKnown);
                EXPECT_EQ(d.firstTick, victim.firstTick);
            }
        }
    }
    // The first chunk damaged: what follows cannot be replayed (its state depends on lost ticks).
    {
        auto first = full;
        first[chunks[0].offset + kChunkHeaderBytes + 3] ^= 0x01;
        const RecordingReader r = RecordingReader::fromBytes(first);
        EXPECT_EQ(r.summary().chunks, chunks.size() - 1);
        std::string error;
        EXPECT_FALSE(RecordingPlayer::open(r, error));
        EXPECT_NE(error.find("start of the recording is damaged"), std::string::npos) << error;
    }
    // The file header: named, and the chunks are still there.
    auto bytes = full;
    bytes[20] ^= 0x01;
    const RecordingReader r = RecordingReader::fromBytes(bytes);
    EXPECT_FALSE(r.headerOk());
    EXPECT_NE(r.headerError().find("header.crc"), std::string::npos) << r.headerError();
    EXPECT_EQ(r.summary().chunks, chunks.size());
    EXPECT_EQ(r.summary().ticks, totalTicks);
    std::string error;
    EXPECT_FALSE(RecordingPlayer::open(r, error));
    EXPECT_NE(error.find("header"), std::string::npos);
}

TEST(Recovery, GarbageAndSplicesNeverConfuseTheReader) {
    const auto& full = sampleRecording();
    const RecordingReader whole = RecordingReader::fromBytes(full);
    const auto& chunks = whole.chunks();
    // Garbage inserted between two chunks (with a fake magic in it) is one damaged region.
    auto bytes = full;
    std::vector<std::uint8_t> garbage(300, 0x5A);
    garbage[10] = 'P', garbage[11] = 'C', garbage[12] = 'H', garbage[13] = 'K';
    bytes.insert(bytes.begin() + std::ptrdiff_t(chunks[50].offset), garbage.begin(), garbage.end());
    RecordingReader r = RecordingReader::fromBytes(bytes);
    EXPECT_EQ(r.summary().chunks, chunks.size());
    EXPECT_EQ(r.summary().ticks, whole.summary().ticks);
    ASSERT_EQ(r.damage().size(), 1u);
    EXPECT_EQ(r.damage()[0].bytes, 300u);
    // A chunk cut out of the middle: its ticks are lost, and the replay stops there.
    bytes = full;
    bytes.erase(bytes.begin() + std::ptrdiff_t(chunks[60].offset),
                bytes.begin() + std::ptrdiff_t(chunks[60].offset + chunks[60].bytes));
    r = RecordingReader::fromBytes(bytes);
    EXPECT_TRUE(r.damage().empty());
    EXPECT_EQ(r.summary().lostTicks, chunks[60].count);
    EXPECT_FALSE(r.summary().intact);
    std::string error;
    const ReplayStatus s = replayRecording(r, error);
    EXPECT_FALSE(s.mismatch);
    EXPECT_FALSE(s.complete);
    EXPECT_NE(s.stopReason.find("missing"), std::string::npos) << s.stopReason;
    EXPECT_EQ(s.ticksReplayed, chunks[60].firstTick - 1);
    // Not a recording at all.
    for (const std::string& text : std::vector<std::string>{"", "P", "PALPREC", "hello world", std::string(1000, 'P')}) {
        r = RecordingReader::fromBytes(std::vector<std::uint8_t>(text.begin(), text.end()));
        EXPECT_FALSE(r.summary().intact);
        EXPECT_EQ(r.summary().ticks, 0u);
    }
}

// One recording's header in front of another's chunks is not a recording: each chunk names its
// header (format 6). And a forger who retags them still cannot pass ticks that touch vertices past
// the mesh the header (or a later scene) names.
TEST(Recovery, ChunksBehindAnotherRecordingsHeaderAreNamedNotRead) {
    const auto& full = sampleRecording();
    const RecordingReader whole = RecordingReader::fromBytes(full);
    ASSERT_TRUE(whole.summary().intact);
    std::size_t headerBytes = 0;
    RecordingHeader other;
    ASSERT_EQ(decodeRecordingHeader(full.data(), full.size(), other, headerBytes), "");
    other.note = "another session";
    std::vector<std::uint8_t> spliced;
    const std::uint32_t otherCrc = encodeRecordingHeader(other, spliced);
    const std::size_t otherHeaderBytes = spliced.size();
    spliced.insert(spliced.end(), full.begin() + std::ptrdiff_t(headerBytes), full.end());
    RecordingReader r = RecordingReader::fromBytes(spliced);
    EXPECT_TRUE(r.headerOk());
    EXPECT_FALSE(r.summary().intact);
    EXPECT_EQ(r.summary().ticks, 0u);
    ASSERT_FALSE(r.damage().empty());
    EXPECT_NE(r.damage()[0].reason.find("chunk of another recording"), std::string::npos) << r.damage()[0].reason;

    // Retagged, the same chunks behind a header whose mesh has 3 vertices: the touched vertices
    // are past it.
    bool touchesPastThree = false;
    whole.forEachTick([&](const RecordedTick& t) {
        touchesPastThree |= t.touched != kNoVertex && t.touched >= 3;
        return !touchesPastThree;
    });
    ASSERT_TRUE(touchesPastThree);
    other.scene.vertexCount = 3;
    std::vector<std::uint8_t> small;
    const std::uint32_t smallCrc = encodeRecordingHeader(other, small);
    const std::size_t smallHeaderBytes = small.size();
    small.insert(small.end(), full.begin() + std::ptrdiff_t(headerBytes), full.end());
    retagChunks(small, smallHeaderBytes, smallCrc);
    r = RecordingReader::fromBytes(small);
    EXPECT_FALSE(r.summary().intact);
    EXPECT_LT(r.summary().ticks, whole.summary().ticks);
    bool named = false;
    for (const auto& d : r.damage()) named |= d.reason.find("touches vertex") != std::string::npos;
    EXPECT_TRUE(named);
    // The genuine header retagged onto them again reads whole (the check is not of the tag alone).
    retagChunks(spliced, otherHeaderBytes, otherCrc);
    EXPECT_TRUE(RecordingReader::fromBytes(spliced).summary().intact);
}

TEST(RecoveryThreads, SigkillMidRecordingLosesAtMost100Ms) {
    // A child records a real-time session and publishes the loop's newest tick to shared memory
    // every millisecond; the parent kills it with SIGKILL mid-recording and reads the file.
    TempDir dir;
    const std::string path = dir.file("killed.palprec");
    (void)sphereMeshPath();  // written before the fork
    struct Shared {
        std::atomic<std::uint64_t> loopTick{0};
        std::atomic<int> recording{0};
    };
    void* memory = ::mmap(nullptr, sizeof(Shared), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    ASSERT_NE(memory, MAP_FAILED);
    auto* shared = new (memory) Shared;

    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        try {
            RecordRig rig = makeRecordRig(SimTrajectory::Sine);
            std::string error;
            auto session = RecordingSession::start(*rig.loop, path, rig.header, error);
            if (!session || !rig.loop->start().empty()) ::_exit(3);
            shared->recording.store(1);
            for (;;) {  // until killed
                shared->loopTick.store(rig.loop->newestSnapshot().tick);
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
            }
        } catch (...) {
            ::_exit(4);
        }
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (shared->loopTick.load() < 1500 && std::chrono::steady_clock::now() < deadline) {
        int status = 0;
        if (::waitpid(child, &status, WNOHANG) == child) FAIL() << "the child ended early, status " << status;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    const std::uint64_t killTick = shared->loopTick.load();
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
    ASSERT_GE(killTick, 1500u) << "the child's loop did not get going";

    const RecordingReader reader = RecordingReader::open(path);
    ASSERT_TRUE(reader.headerOk()) << reader.headerError();
    const RecordingSummary& s = reader.summary();
    EXPECT_FALSE(s.closedCleanly);
    EXPECT_EQ(s.firstTick, 1u);
    EXPECT_EQ(s.lostTicks, 0u);
    EXPECT_EQ(s.droppedTicks, 0u);
    EXPECT_LE(reader.damage().size(), 1u);  // at most the chunk being written
    const double shortS = (double(killTick) - double(s.lastTick)) * reader.periodS();
    std::cout << "[ figures  ] killed at loop tick " << killTick << "; recovered ticks 1.." << s.lastTick << " ("
              << s.durationS << " s, " << s.chunks << " chunks); short by " << shortS * 1000.0 << " ms\n";
    RecordProperty("killed_at_tick", std::to_string(killTick));
    RecordProperty("recovered_last_tick", std::to_string(s.lastTick));
    EXPECT_LE(shortS, 0.100);
    // What was recovered replays exactly.
    std::string error;
    const ReplayStatus replay = replayRecording(reader, error);
    EXPECT_EQ(error, "");
    EXPECT_FALSE(replay.mismatch) << replay.firstMismatch;
    EXPECT_EQ(replay.ticksReplayed, s.ticks);
    ::munmap(memory, sizeof(Shared));
}
