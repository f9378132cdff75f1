#pragma once
// Reads a session recording, intact or not: the header, then chunk by chunk. A chunk whose CRC
// fails, that is truncated or that does not decode is reported (offset, length, reason, and the
// ticks it held when its header survived) and skipped; the reader resynchronises on the next chunk
// magic, so every intact chunk is recovered. Garbage never crashes it, and it never allocates more
// than the file's size plus small per-chunk records (lengths are capped; see RecordingFormat.h).
//
// For the GUI's timeline: chunks() (tick and time ranges), events() (with tick and loop time) and
// tickAt()/decodeChunk() for the ticks themselves, decoded on demand. Not thread-safe for writes;
// const members may be called from several threads.

#include "engine/loop/RecorderSink.h"
#include "engine/record/RecordingFormat.h"
#include "engine/stability/DivergenceKind.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

/// One intact chunk.
struct ChunkInfo {
    std::uint64_t offset = 0;  ///< where it starts in the file
    std::uint32_t bytes = 0;   ///< the whole chunk, header and CRCs included
    ChunkType type = ChunkType::Data;
    std::uint64_t firstTick = 0;
    std::uint32_t count = 0;   ///< Data: ticks; Gap: ticks dropped; End: ticks recorded in total
    std::uint64_t hash = 0;    ///< session determinism hash after the chunk's last tick
    std::uint32_t events = 0;
    double firstTimeS = 0.0, lastTimeS = 0.0;  ///< loop clock of its first and last tick (Data)
    bool hashChecked = false;  ///< the hash was recomputed from the ticks and matched
};

/// A stretch of the file that is not an intact chunk.
struct DamagedRegion {
    std::uint64_t offset = 0;
    std::uint64_t bytes = 0;
    std::string reason;
    bool ticksKnown = false;   ///< the chunk's header survived: firstTick and count say what was lost
    std::uint64_t firstTick = 0;
    std::uint32_t count = 0;
};

struct RecordingEvent {
    std::uint64_t tick = 0;
    double timeS = 0.0;           ///< loop clock at that tick
    EventKind kind = EventKind::Mark;
    std::string text;             ///< Mark, Exercise: the text; otherwise a short description
    SlopeRingParams params;       ///< ParamsApplied
    std::optional<ContactDef> contact;  ///< ParamsApplied (format 3): the tool and friction with them
    std::uint64_t sceneId = 0;    ///< SceneChanged
    std::optional<RecordedScene> scene;    ///< SceneChanged, when the recorder was told
    std::optional<RecordedDevice> device;  ///< DeviceChanged, when the recorder was told
    DeviceState deviceState = DeviceState::Disconnected;  ///< DeviceState
    std::uint64_t count = 0;      ///< CommandsLost
    DivergenceKind divergence = DivergenceKind::None;  ///< Divergence: what the guard saw
};

struct RecordingSummary {
    std::uint64_t fileBytes = 0;
    bool headerOk = false;
    std::uint64_t chunks = 0;        ///< intact chunks (all types)
    std::uint64_t ticks = 0;         ///< recovered ticks
    std::uint64_t firstTick = 0, lastTick = 0;
    double durationS = 0.0;          ///< loop time from the first recovered tick to the last (+ one period)
    std::uint64_t events = 0;
    std::uint64_t gaps = 0;          ///< gap chunks (ring overflow while recording)
    std::uint64_t droppedTicks = 0;  ///< ticks the gap chunks say were never recorded
    std::uint64_t damagedRegions = 0;
    std::uint64_t damagedBytes = 0;
    std::uint64_t lostTicks = 0;     ///< ticks missing between recovered chunks (damage, truncation)
    std::uint64_t hashMismatches = 0;  ///< chunks whose stored hash disagrees with their ticks
    bool closedCleanly = false;      ///< an end chunk is present
    bool intact = false;             ///< header ok, no damage, no mismatch, closed cleanly
    double bytesPerTick() const { return ticks > 0 ? double(fileBytes) / double(ticks) : 0.0; }
};

class RecordingReader {
public:
    /// Reads and scans a file. Problems with the file itself (missing, unreadable) are in
    /// fileError(); problems with its content in headerError() and damage().
    static RecordingReader open(const std::string& path);
    /// Scans bytes already in memory (tests, the fuzzer).
    static RecordingReader fromBytes(std::vector<std::uint8_t> bytes, const std::string& name = "<memory>");
    /// Opens a recording that is still being written (engine/scoring's LiveScorer follows the
    /// session's own file): a chunk or header cut short at the end is taken as not written yet
    /// rather than as damage, and refresh() reads what the writer appends.
    static RecordingReader openLive(const std::string& path);

    /// Live readers: reads the bytes appended since the last look and scans the chunks they
    /// complete. Chunks, damage and summary only grow; events stay ordered by tick (an event the
    /// writer placed in a later chunk than its tick is inserted where it belongs). Returns true
    /// when the file grew; false when it did not or the reader is not live (fileError() says if
    /// the file could not be read).
    bool refresh();
    /// Live readers: the writer is gone, so whatever is still cut short at the end is damage from
    /// now on (what open() would report). The reader is no longer live.
    void finishLive();
    bool live() const { return mLive; }
    /// Live readers: bytes at the end that do not make a whole chunk (or header) yet.
    std::uint64_t pendingBytes() const { return mBytes.size() - std::min<std::size_t>(mScan.offset, mBytes.size()); }

    const std::string& name() const { return mName; }
    const std::string& fileError() const { return mFileError; }
    bool headerOk() const { return mSummary.headerOk; }
    /// Names the field: "header.scene.meshPath: length ... runs past the end".
    const std::string& headerError() const { return mHeaderError; }
    const RecordingHeader& header() const { return mHeader; }
    double periodS() const { return 1.0 / (mSummary.headerOk ? mHeader.rateHz : 1000.0); }

    const RecordingSummary& summary() const { return mSummary; }
    const std::vector<ChunkInfo>& chunks() const { return mChunks; }
    const std::vector<DamagedRegion>& damage() const { return mDamage; }
    /// Every event, ordered by tick (events of one tick in recorded order).
    const std::vector<RecordingEvent>& events() const { return mEvents; }

    /// The ticks of chunk `index` (of chunks()); empty for gap and end chunks.
    bool decodeChunk(std::size_t index, std::vector<RecordedTick>& out) const;
    /// Calls `fn` for every recovered tick in file order (stops early when fn returns false).
    void forEachTick(const std::function<bool(const RecordedTick&)>& fn) const;
    /// Every recovered tick (about 80 bytes each in memory).
    std::vector<RecordedTick> ticks() const;
    /// The tick with this index, if it was recovered.
    std::optional<RecordedTick> tickAt(std::uint64_t tick) const;

private:
    /// Where the scan stands, so that a live reader can go on from there.
    struct ScanState {
        std::size_t offset = 0;           // the next chunk starts here
        bool headerPending = false;       // live: the header is not whole yet
        std::uint64_t expectedTick = 0;
        bool haveExpected = false;
        std::uint64_t runningHash = 0;
        bool hashKnown = false;
        bool sawEnd = false;
        std::uint64_t endTicks = 0;
        bool haveTime = false;
        double firstTimeS = 0.0, lastTimeS = 0.0;
        std::uint32_t vertexCount = 0;  // of the scene in force; 0 when not known
    };

    void scan();
    void scanChunks();
    void finishScan(std::vector<RecordingEvent>& newEvents);
    std::string scanData(const ChunkHeader& header, const std::uint8_t* payload, ChunkInfo& info,
                         std::vector<RecordingEvent>& events);
    /// "" when every tick of the chunk just scanned (mScratch) touches a vertex of the scene in force
    /// at that tick (the header's, then each SceneChanged event's from its tick on), else which tick
    /// does not. Moves the scene in force past the chunk.
    std::string checkTouched(const std::vector<RecordingEvent>& chunkEvents);
    void addDamage(std::uint64_t offset, std::uint64_t bytes, std::string reason, const ChunkHeader* header);

    std::string mName;
    std::vector<std::uint8_t> mBytes;
    std::string mFileError;
    std::string mHeaderError;
    RecordingHeader mHeader;
    RecordingSummary mSummary;
    std::vector<ChunkInfo> mChunks;
    std::vector<std::size_t> mTickChunks;  // data chunks with ticks, in tick order (for tickAt)
    std::vector<DamagedRegion> mDamage;
    std::vector<RecordingEvent> mEvents;
    std::vector<RecordedTick> mScratch;
    ScanState mScan;
    bool mLive = false;
};

}  // namespace palpate
