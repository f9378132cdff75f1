#pragma once
// The session recorder's writer: a RecorderSink that the haptic tick feeds wait-free (a fixed ring
// of ticks and a small ring of applied commands), and a writer thread that drains both every
// drainPeriodS, delta-codes the ticks into one chunk per drain and appends it with one write(2).
// Data handed to the kernel survives a kill -9, so a crash loses at most one drain period (plus the
// chunk being written). If the ring overflows, the tick is dropped, never waited for, and the file
// gets a gap chunk with the count. Events from the controller (marks, exercise events, scene and
// device descriptions) take a mutex the haptic thread never touches.
//
// Threads: onTick/onCommand on the haptic thread only; every other member on controller threads
// (mark, exerciseEvent, describe*, stats and flush are safe from any thread; close from one).
// Usually driven through RecordingSession, which also attaches it to a HapticLoop.

#include "base/params/Problem.h"

#include "engine/loop/RecorderSink.h"
#include "engine/record/RecordingFormat.h"
#include "base/concurrency/SpscRing.h"
#include "engine/record/TickCodec.h"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace palpate {

struct RecordingWriterDef {
    /// Ticks the ring holds: how long the writer may stall before ticks are dropped (8 s at 1 kHz).
    std::size_t ringCapacityTicks = 8192;
    /// Applied commands (parameter sets, scene and device switches) the second ring holds.
    std::size_t commandCapacity = 256;
    /// The writer drains and appends a chunk this often: the most a crash loses.
    double drainPeriodS = 0.025;
    /// fdatasync at most this often (and on close); a kill -9 needs none, a power cut does.
    double syncPeriodS = 1.0;
    /// Ticks per chunk when a drain holds many (stepped runs); 0: one drain period at the rate.
    std::size_t ticksPerChunk = 0;
    /// A file already at the path is replaced, once the new recording has started (its header
    /// written to a file beside it, then renamed over the old one). False: such a path is refused,
    /// so that a recording is never lost to a new one nobody asked to replace it.
    bool replaceExisting = false;
};

/// "" when usable, else a message naming the field.
Problems validateRecordingWriterDef(const RecordingWriterDef& def);

/// Figures of a recording so far (any thread).
struct RecordingStats {
    std::uint64_t ticks = 0;         ///< ticks in whole chunks written to the file (what a reader finds)
    std::uint64_t droppedTicks = 0;  ///< ticks lost to a full ring (each run is a gap chunk)
    std::uint64_t gaps = 0;
    std::uint64_t events = 0;
    std::uint64_t chunks = 0;
    std::uint64_t bytes = 0;         ///< file size so far
    std::uint64_t lostCommands = 0;  ///< applied commands lost to a full command ring
    std::uint64_t firstTick = 0, lastTick = 0;
    double elapsedS = 0.0;           ///< loop time the written ticks cover
    std::uint64_t hash = 0;          ///< session determinism hash after the last written tick
    std::string error;               ///< the first write error ("" while all is well)
    double bytesPerTick() const { return ticks > 0 ? double(bytes) / double(ticks) : 0.0; }
};

class RecordingWriter final : public RecorderSink {
public:
    /// Creates the file, locks it against a second writer, writes the header and starts the writer
    /// thread. Null with `error` naming the path on failure: an existing file (unless
    /// def.replaceExisting), one another process is writing, a path that is not a regular file, a
    /// header the reader would refuse (validateRecordingHeader), no thread. A failed start leaves
    /// no file behind and the file it would have replaced untouched.
    static std::unique_ptr<RecordingWriter> create(const std::string& path, const RecordingHeader& header,
                                                   std::string& error, const RecordingWriterDef& def = {});
    ~RecordingWriter() override;
    RecordingWriter(const RecordingWriter&) = delete;
    RecordingWriter& operator=(const RecordingWriter&) = delete;

    /// Blocks until everything the loop handed over so far is in the file (page cache). Stepped
    /// runs call it now and then so the ring never fills; readers of a live file call it first.
    std::string flush();
    /// Writes what is left, a final gap chunk if ticks were dropped last, the end chunk; syncs and
    /// closes. Call once no loop feeds this sink any more (HapticLoop::detachRecorder, or the loop
    /// stopped or destroyed). Idempotent; returns "" or the first write error.
    std::string close();

    /// A user's mark at the loop's current tick.
    void mark(const std::string& text);
    /// An exercise event (free text, e.g. JSON) at the loop's current tick.
    void exerciseEvent(const std::string& text);
    /// Tells the recorder what a scene about to be switched in is (HapticScene::id()), so that the
    /// scene-change event can be replayed. Call before HapticLoop::swapScene.
    void describeScene(std::uint64_t sceneId, const RecordedScene& scene);
    /// The same for a device about to be switched in (key: the HapticDevice's address).
    void describeDevice(const void* device, const RecordedDevice& description);

    RecordingStats stats() const;
    const std::string& path() const { return mPath; }
    const RecordingHeader& header() const { return mHeader; }

    // RecorderSink: haptic thread, wait-free.
    void onTick(const RecordedTick& tick) noexcept override;
    void onCommand(const RecordedCommand& command) noexcept override;

private:
    struct Item {
        RecordedTick tick;
        std::uint32_t droppedBefore;  ///< ticks the ring had no room for just before this one
    };
    struct PendingEvent {
        EventKind kind;
        std::uint64_t tick;
        std::string text;
    };

    RecordingWriter(std::string path, const RecordingHeader& header, const RecordingWriterDef& def, int fd);
    void threadMain();
    void drain(bool final);
    void emitTicks(std::size_t begin, std::size_t end);
    void emitChunk(const ChunkHeader& header, const std::vector<std::uint8_t>& payload);
    void waitForHeader();
    void appendEventsUpTo(std::uint64_t lastTick, std::uint64_t firstTick);
    void addEvent(EventKind kind, std::uint64_t tick, std::uint64_t firstTick, const std::uint8_t* payload,
                  std::size_t bytes);
    void writeOut();
    void controllerEvent(EventKind kind, const std::string& text);

    const std::string mPath;
    const RecordingHeader mHeader;
    const RecordingWriterDef mDef;
    const double mPeriodS;
    const std::size_t mTicksPerChunk;
    int mFd = -1;

    // Haptic thread -> writer.
    SpscRing<Item> mTicks;
    SpscRing<RecordedCommand> mCommands;
    std::atomic<std::uint32_t> mPendingDrops{0};  // producer-owned; read by close() after detach
    std::atomic<std::uint64_t> mDroppedTotal{0};
    std::atomic<std::uint64_t> mLostCommands{0};
    std::atomic<std::uint64_t> mCurrentTick{0};

    // Controller -> writer (the haptic thread never takes this mutex).
    mutable std::mutex mMutex;
    std::condition_variable mWake, mFlushed;
    bool mStop = false;
    std::uint64_t mFlushRequested = 0, mFlushDone = 0;
    std::vector<PendingEvent> mControllerEvents;
    std::map<std::uint64_t, RecordedScene> mSceneDescriptions;
    std::map<const void*, RecordedDevice> mDeviceDescriptions;
    RecordingStats mStats;  // published copy, under mMutex
    bool mClosed = false;

    // Writer thread state (buffers reused: a drain without events allocates nothing).
    std::vector<Item> mDrained;
    std::vector<RecordedCommand> mPendingCommands;
    std::vector<PendingEvent> mEventsTaken;
    std::vector<std::uint8_t> mPayload, mEventBytes, mOut, mScratch;
    std::uint32_t mEventCount = 0;
    TickEncoder mEncoder;
    RecordingStats mWorking;  // the writer's running figures (what was encoded)
    /// The figures after each chunk in mOut, so that a failed write reports what did reach the file.
    struct Encoded {
        std::size_t endBytes;  // where the chunk ends in mOut
        RecordingStats figures;
    };
    std::vector<Encoded> mEncoded;
    RecordingStats mWritten;      // the figures of the whole chunks in the file
    bool mHeaderWritten = false;  // under mMutex: the thread waits for it
    std::uint32_t mHeaderTag = 0;  // set before the thread starts: every chunk carries it
    std::uint64_t mLostCommandsReported = 0;
    bool mHaveLastTick = false;
    RecordedTick mLastTick;
    double mFirstNowS = 0.0;
    double mLastSyncS = 0.0;

    std::thread mThread;
};

}  // namespace palpate
