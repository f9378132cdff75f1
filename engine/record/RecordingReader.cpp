#include "engine/record/RecordingReader.h"

#include "base/io/InputFile.h"
#include "engine/record/TickCodec.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <new>

namespace palpate {

namespace {

/// Whether a file holds the recording's magic at its start or a chunk's anywhere, read in pieces
/// without holding the file: a large file that holds neither is not a recording, and is refused
/// before it is read into memory (a 2 GB file of zeros, say).
bool holdsRecordingMagic(int fd, std::uint64_t sizeBytes) {
    constexpr std::size_t kPieceBytes = 1u << 20;
    constexpr std::size_t kOverlap = sizeof(kChunkMagic) - 1;  // a magic split between two pieces
    std::vector<std::uint8_t> piece(kPieceBytes + kOverlap);
    std::size_t kept = 0;
    for (std::uint64_t at = 0; at < sizeBytes;) {
        // A hole reads as zeros, which hold no magic: skip to the next data (a sparse file is quick).
        const off_t data = ::lseek(fd, off_t(at), SEEK_DATA);
        if (data < 0 && errno == ENXIO) return false;  // only a hole from here on
        if (data > off_t(at)) {
            at = std::uint64_t(data);
            kept = 0;
        }
        const ssize_t n = ::pread(fd, piece.data() + kept, kPieceBytes, off_t(at));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return true;  // let the whole read report what went wrong
        const std::size_t have = kept + std::size_t(n);
        if (at == 0 && have >= sizeof(kRecordingMagic) &&
            std::memcmp(piece.data(), kRecordingMagic, sizeof(kRecordingMagic)) == 0)
            return true;
        if (findChunkMagic(piece.data(), have, 0) < have) return true;
        kept = std::min(kOverlap, have);
        std::memmove(piece.data(), piece.data() + have - kept, kept);
        at += std::uint64_t(n);
    }
    return false;
}

/// Reads `path` into `bytes`, which holds what an earlier look read (a live reader reads only what
/// was appended). Through the bounded reader (base/io/InputFile.h): a FIFO, a device (/dev/zero)
/// or a directory is a message naming the path, never a hang, runaway memory or std::bad_alloc.
std::string readRecordingFile(const std::string& path, std::vector<std::uint8_t>& bytes) {
    std::string error;
    const std::optional<InputFd> file = openInputFile(path, kRecordingFile, error);
    if (!file) return error;
    if (file->sizeBytes() < bytes.size()) return path + ": the file shrank while it was being read live";
    const std::size_t old = bytes.size();
    constexpr std::uint64_t kLargeBytes = std::uint64_t(64) << 20;
    if (old == 0 && file->sizeBytes() > kLargeBytes && !holdsRecordingMagic(file->fd(), file->sizeBytes()))
        return path + ": not a Palpate recording (no recording or chunk magic in its " +
               std::to_string(file->sizeBytes()) + " bytes)";
    try {
        bytes.resize(std::size_t(file->sizeBytes()));
    } catch (const std::bad_alloc&) {
        // The reader holds a recording in memory (docs/recording.md, "Format limits and refusals"):
        // a file within the format's limit can still be more than this process may allocate.
        bytes.resize(old);
        return path + ": " + std::to_string(file->sizeBytes()) +
               " bytes are more than this process can hold in memory to read the recording";
    }
    std::size_t done = old;
    while (done < bytes.size()) {
        const ssize_t n = ::pread(file->fd(), bytes.data() + done, bytes.size() - done, off_t(done));
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            error = path + ": cannot be read: " + std::strerror(errno);
            bytes.resize(old);
            return error;
        }
        if (n == 0) break;  // shorter than fstat said (cut meanwhile): keep what is there
        done += std::size_t(n);
    }
    bytes.resize(done);
    return "";
}

/// Decodes the ticks of a data chunk into `out`; `after` is where its events start.
bool decodeTicks(const ChunkHeader& h, const std::uint8_t* payload, std::vector<RecordedTick>& out,
                 const std::uint8_t** after) {
    out.clear();
    // Every tick takes at least 6 bytes (flags, clock, force, touched): a count beyond the payload
    // is garbage, and checking it first bounds the allocation by the chunk's size.
    if (h.count > h.payloadBytes / 6) return false;
    out.reserve(h.count);
    const std::uint8_t* cursor = payload;
    const std::uint8_t* end = payload + h.payloadBytes;
    TickDecoder decoder;
    for (std::uint32_t i = 0; i < h.count; ++i) {
        RecordedTick t;
        if (!decoder.decode(&cursor, end, h.firstTick + i, t)) return false;
        out.push_back(t);
    }
    *after = cursor;
    return true;
}

std::string describe(const RecordingEvent& e) {
    switch (e.kind) {
        case EventKind::ParamsApplied:
            return "parameters applied (" + std::to_string(e.params.ringCount) + " rings, m1 " +
                   std::to_string(e.params.slopeMagnitudeMmPerN[0]) + " mm/N, contact " +
                   std::to_string(e.params.contactStiffnessNPerMm) + " N/mm, springs " +
                   std::to_string(e.params.springStiffnessNPerMm) + " N/mm)";
        case EventKind::SceneChanged:
            if (!e.scene) return "scene (not described)";
            return "scene " + e.scene->meshPath +
                   (e.scene->meshUnit.isMillimetres() ? std::string() : " (in " + e.scene->meshUnit.description() + ")");
        case EventKind::DeviceChanged: return e.device ? "device " + e.device->uri : "device (not described)";
        case EventKind::DeviceState: return std::string("device ") + deviceStateName(e.deviceState);
        case EventKind::Paused: return "paused";
        case EventKind::Resumed: return "resumed";
        case EventKind::CommandsLost: return std::to_string(e.count) + " applied commands lost";
        case EventKind::Mark:
        case EventKind::Exercise: return e.text;
        case EventKind::Divergence:
            return std::string(divergenceKindName(e.divergence)) + ": " + divergenceAdvice(e.divergence);
    }
    return {};
}

/// Parses a data chunk's event section. Unknown kinds are skipped (later format revisions).
std::string parseEvents(const std::uint8_t* cursor, const std::uint8_t* end, std::uint64_t firstTick,
                        std::vector<RecordingEvent>& out, std::uint32_t& count) {
    std::string why;
    ByteReader r(cursor, std::size_t(end - cursor), "event.");
    const std::uint64_t n = r.varint("count");
    if (r.ok() && n > r.remaining() / 3) r.fail("count", std::to_string(n) + " events cannot fit in the chunk");
    for (std::uint64_t i = 0; r.ok() && i < n; ++i) {
        RecordingEvent e;
        const std::uint64_t kind = r.varint("kind");
        e.tick = firstTick + std::uint64_t(r.svarint("tick"));
        const std::uint64_t length = r.varint("length");
        if (!r.ok()) break;
        if (length > r.remaining()) {
            r.fail("length", "runs past the end of the chunk");
            break;
        }
        ByteReader p(r.cursor(), std::size_t(length), std::string("event.") + eventKindName(EventKind(kind)) + ".");
        bool known = true;
        switch (kind) {
            case std::uint8_t(EventKind::ParamsApplied):
                e.params = decodeParams(p, "params");
                e.contact = decodeContact(p, "contact");
                decodeStiffening(p, "params", e.params);
                break;
            case std::uint8_t(EventKind::SceneChanged):
                e.sceneId = p.u64("sceneId");
                if (p.u8("described") != 0) {
                    e.scene = decodeScene(p, "scene");
                    if (const auto contact = decodeContact(p, "scene.contact")) e.scene->contact = *contact;
                    if (const auto unit = decodeMeshUnit(p, "scene.meshUnit")) e.scene->meshUnit = *unit;
                    decodeStiffening(p, "scene.params", e.scene->params);
                }
                break;
            case std::uint8_t(EventKind::DeviceChanged):
                if (p.u8("described") != 0) e.device = decodeDevice(p, "device");
                break;
            case std::uint8_t(EventKind::DeviceState): {
                const std::uint8_t state = p.u8("state");
                if (p.ok() && state > std::uint8_t(DeviceState::Fault)) p.fail("state", "unknown device state");
                e.deviceState = p.ok() ? DeviceState(state) : DeviceState::Disconnected;
                break;
            }
            case std::uint8_t(EventKind::Paused):
            case std::uint8_t(EventKind::Resumed): break;
            case std::uint8_t(EventKind::Mark):
            case std::uint8_t(EventKind::Exercise):
                if (length > kMaxEventTextBytes) p.fail("text", "longer than the limit");
                else e.text.assign(reinterpret_cast<const char*>(r.cursor()), std::size_t(length));
                break;
            case std::uint8_t(EventKind::CommandsLost): e.count = p.varint("count"); break;
            case std::uint8_t(EventKind::Divergence): {
                const std::uint8_t kind = p.u8("kind");
                if (p.ok() && (kind == 0 || kind > std::uint8_t(DivergenceKind::Inversion)))
                    p.fail("kind", "unknown divergence kind " + std::to_string(kind));
                e.divergence = p.ok() ? DivergenceKind(kind) : DivergenceKind::None;
                break;
            }
            default: known = false;
        }
        if (!p.ok()) {
            why = p.error();
            return why;
        }
        r.skip("payload", length);
        if (!known) continue;
        e.kind = EventKind(kind);
        if (e.kind != EventKind::Mark && e.kind != EventKind::Exercise) e.text = describe(e);
        out.push_back(std::move(e));
        ++count;
    }
    if (!r.ok()) {
        why = r.error();
        return why;
    }
    return {};
}

}  // namespace

RecordingReader RecordingReader::open(const std::string& path) {
    RecordingReader reader;
    reader.mName = path;
    reader.mFileError = readRecordingFile(path, reader.mBytes);
    if (!reader.mFileError.empty()) {
        reader.mBytes.clear();
        return reader;
    }
    reader.scan();
    return reader;
}

RecordingReader RecordingReader::fromBytes(std::vector<std::uint8_t> bytes, const std::string& name) {
    RecordingReader reader;
    reader.mName = name;
    reader.mBytes = std::move(bytes);
    reader.scan();
    return reader;
}

void RecordingReader::addDamage(std::uint64_t offset, std::uint64_t bytes, std::string reason,
                                const ChunkHeader* header) {
    if (bytes == 0) return;
    mSummary.damagedBytes += bytes;
    // Resynchronising through garbage can stop at false magics: one damaged stretch, one region.
    if (!mDamage.empty() && mDamage.back().offset + mDamage.back().bytes == offset && !header &&
        !mDamage.back().ticksKnown) {
        mDamage.back().bytes += bytes;
        return;
    }
    DamagedRegion d;
    d.offset = offset;
    d.bytes = bytes;
    d.reason = std::move(reason);
    if (header && header->type == ChunkType::Data) {
        d.ticksKnown = true;
        d.firstTick = header->firstTick;
        d.count = header->count;
        d.reason += " (ticks " + std::to_string(header->firstTick) + ".." +
                    std::to_string(header->firstTick + header->count) + ")";
    }
    mDamage.push_back(std::move(d));
}

std::string RecordingReader::scanData(const ChunkHeader& h, const std::uint8_t* payload, ChunkInfo& info,
                                      std::vector<RecordingEvent>& events) {
    std::string why;
    const std::uint8_t* after = nullptr;
    if (!decodeTicks(h, payload, mScratch, &after)) {
        why = "chunk ticks do not decode";
        return why;
    }
    const std::size_t firstEvent = events.size();
    std::uint32_t count = 0;
    if (!(why = parseEvents(after, payload + h.payloadBytes, h.firstTick, events, count)).empty()) {
        events.resize(firstEvent);
        return why;
    }
    info.events = count;
    if (!mScratch.empty()) {
        info.firstTimeS = mScratch.front().nowS;
        info.lastTimeS = mScratch.back().nowS;
    }
    // Event times: the clock of their tick when it is in this chunk, else extrapolated.
    for (std::size_t i = firstEvent; i < events.size(); ++i) {
        RecordingEvent& e = events[i];
        if (!mScratch.empty() && e.tick >= h.firstTick && e.tick - h.firstTick < mScratch.size()) {
            e.timeS = mScratch[std::size_t(e.tick - h.firstTick)].nowS;
        } else if (!mScratch.empty()) {
            e.timeS = info.firstTimeS + (double(e.tick) - double(h.firstTick)) * periodS();
        } else if (!mChunks.empty()) {
            const ChunkInfo& last = mChunks.back();
            const double lastTick = double(last.firstTick) + double(last.count) - 1.0;
            e.timeS = last.lastTimeS + (double(e.tick) - lastTick) * periodS();
        } else {
            e.timeS = double(e.tick) * periodS();
        }
    }
    return {};
}

std::string RecordingReader::checkTouched(const std::vector<RecordingEvent>& chunkEvents) {
    std::vector<const RecordingEvent*> scenes;
    for (const RecordingEvent& e : chunkEvents)
        if (e.kind == EventKind::SceneChanged) scenes.push_back(&e);
    std::stable_sort(scenes.begin(), scenes.end(),
                     [](const RecordingEvent* a, const RecordingEvent* b) { return a->tick < b->tick; });
    std::uint32_t count = mScan.vertexCount, before = count;
    std::uint64_t switchTick = 0;
    bool switched = false;
    std::size_t next = 0;
    const auto advance = [&](std::uint64_t tick) {
        for (; next < scenes.size() && scenes[next]->tick <= tick; ++next) {
            before = count;
            count = scenes[next]->scene ? scenes[next]->scene->vertexCount : 0;  // unknown scene: no check
            switchTick = scenes[next]->tick;
            switched = true;
        }
    };
    for (const RecordedTick& t : mScratch) {
        advance(t.tick);
        if (t.touched == kNoVertex || count == 0) continue;
        // The tick at a scene's switch may still be the old scene's: either count holds there.
        const std::uint32_t limit = switched && t.tick == switchTick ? std::max(before, count) : count;
        if (before == 0 && switched && t.tick == switchTick) continue;
        if (t.touched >= limit)
            return "chunk's tick " + std::to_string(t.tick) + " touches vertex " + std::to_string(t.touched) +
                   ", past the scene's " + std::to_string(limit) + " vertices (a chunk of another recording's mesh)";
    }
    advance(~std::uint64_t(0));
    mScan.vertexCount = count;
    return {};
}

namespace {

std::string hexTag(std::uint32_t tag) {
    char text[16];
    std::snprintf(text, sizeof text, "%06x", unsigned(tag));
    return text;
}

/// Live: the header is not whole yet (the file ends inside it, and what is there agrees so far).
bool headerCutShort(const std::vector<std::uint8_t>& bytes) {
    const std::size_t size = bytes.size();
    if (std::memcmp(bytes.data(), kRecordingMagic, std::min(size, sizeof(kRecordingMagic))) != 0) return false;
    if (size < kPreambleBytes) return true;
    const std::uint32_t length = std::uint32_t(bytes[8]) | std::uint32_t(bytes[9]) << 8 |
                                 std::uint32_t(bytes[10]) << 16 | std::uint32_t(bytes[11]) << 24;
    return length <= kMaxHeaderBytes && size < kPreambleBytes + std::size_t(length) + 4;
}

}  // namespace

RecordingReader RecordingReader::openLive(const std::string& path) {
    RecordingReader reader;
    reader.mName = path;
    reader.mLive = true;
    reader.refresh();
    return reader;
}

bool RecordingReader::refresh() {
    if (!mLive) return false;
    const std::size_t old = mBytes.size();
    mFileError = readRecordingFile(mName, mBytes);
    if (!mFileError.empty() || mBytes.size() == old) return false;
    if (old == 0 || mScan.headerPending) {
        scan();  // nothing was scanned yet
    } else {
        std::vector<RecordingEvent> events;
        std::swap(events, mEvents);  // the old ones; scanChunks appends the new ones to mEvents
        scanChunks();
        finishScan(events);
    }
    return true;
}

void RecordingReader::finishLive() {
    if (!mLive) return;
    mLive = false;
    if (mScan.headerPending) {
        scan();
        return;
    }
    std::vector<RecordingEvent> events;
    std::swap(events, mEvents);
    scanChunks();
    finishScan(events);
}

void RecordingReader::scan() {
    const std::uint8_t* data = mBytes.data();
    const std::size_t size = mBytes.size();
    mSummary = RecordingSummary{};
    mSummary.fileBytes = size;
    mChunks.clear();
    mTickChunks.clear();
    mDamage.clear();
    mEvents.clear();
    mHeaderError.clear();
    mScan = ScanState{};
    mScan.runningHash = kHashSeed;

    std::size_t headerBytes = 0;
    if ((mHeaderError = decodeRecordingHeader(data, size, mHeader, headerBytes)).empty()) {
        mSummary.headerOk = true;
        mScan.offset = headerBytes;
    } else if (mLive && headerCutShort(mBytes)) {
        mHeader = RecordingHeader{};
        mScan.headerPending = true;  // refresh() tries again when more has been written
        mScan.offset = 0;
        return;
    } else {
        mHeader = RecordingHeader{};
        mScan.offset = findChunkMagic(data, size, 0);
        addDamage(0, mScan.offset, mHeaderError, nullptr);
    }
    mScan.hashKnown = mSummary.headerOk;  // the session hash starts from the seed at the first chunk
    mScan.vertexCount = mSummary.headerOk ? mHeader.scene.vertexCount : 0;

    std::vector<RecordingEvent> none;
    scanChunks();  // appends to mEvents
    finishScan(none);
}

void RecordingReader::scanChunks() {
    const std::uint8_t* data = mBytes.data();
    const std::size_t size = mBytes.size();
    ScanState& st = mScan;
    std::vector<RecordingEvent>& events = mEvents;  // the new ones (the caller moved the old ones out)

    while (st.offset < size) {
        const std::size_t offset = st.offset;
        ChunkHeader h;
        const std::uint8_t* payload = nullptr;
        const ChunkStatus status = parseChunk(data, size, offset, h, payload);
        if (status != ChunkStatus::Ok) {
            // Live: a chunk cut short at the end is being written; it is read when it is whole.
            if (mLive && (status == ChunkStatus::Truncated || status == ChunkStatus::TruncatedPayload)) break;
            const bool headerValid = status == ChunkStatus::TruncatedPayload || status == ChunkStatus::BadPayloadCrc;
            std::size_t next = size;
            if (status == ChunkStatus::BadPayloadCrc) {
                // A flipped byte: the next chunk is where the length says, if it is intact there.
                const std::size_t end = offset + kChunkOverheadBytes + h.payloadBytes;
                ChunkHeader probe;
                const std::uint8_t* probePayload = nullptr;
                if (end < size && parseChunk(data, size, end, probe, probePayload) == ChunkStatus::Ok) next = end;
                else next = findChunkMagic(data, size, offset + 1);
            } else if (status != ChunkStatus::TruncatedPayload) {
                next = findChunkMagic(data, size, offset + 1);
            }
            addDamage(offset, next - offset, chunkStatusText(status), headerValid ? &h : nullptr);
            st.hashKnown = false;
            st.offset = next;
            continue;
        }
        const std::size_t chunkBytes = kChunkOverheadBytes + h.payloadBytes;
        st.offset = offset + chunkBytes;
        if (st.sawEnd) {
            addDamage(offset, chunkBytes, "chunk after the end chunk", nullptr);
            continue;
        }
        // (format 6) Every chunk names its header: one behind another recording's header was spliced in.
        if (mSummary.headerOk && mHeader.formatVersion >= kHeaderTagFormatVersion &&
            h.headerTag != chunkHeaderTag(mHeader.bodyCrc)) {
            addDamage(offset, chunkBytes,
                      "chunk of another recording (its header tag " + hexTag(h.headerTag) + ", this header's " +
                          hexTag(chunkHeaderTag(mHeader.bodyCrc)) + ")",
                      nullptr);
            st.hashKnown = false;
            continue;
        }
        ChunkInfo info;
        info.offset = offset;
        info.bytes = std::uint32_t(chunkBytes);
        info.type = h.type;
        info.firstTick = h.firstTick;
        info.count = h.count;
        info.hash = h.hash;

        // Ticks only move forward: a data chunk with ticks, or a gap, that starts before the end
        // of what came before is not part of this recording (spliced or forged).
        if ((h.type == ChunkType::Data && h.count > 0) || h.type == ChunkType::Gap) {
            if (st.haveExpected && h.firstTick < st.expectedTick) {
                addDamage(offset, chunkBytes,
                          "chunk out of order (ticks " + std::to_string(h.firstTick) + " after " +
                              std::to_string(st.expectedTick) + ")",
                          nullptr);
                continue;
            }
        }
        if (h.type == ChunkType::Data) {
            std::string why;
            std::vector<RecordingEvent> chunkEvents;
            if (!(why = scanData(h, payload, info, chunkEvents)).empty()) {
                addDamage(offset, chunkBytes, "chunk does not decode: " + why, &h);
                st.hashKnown = false;
                continue;
            }
            if (!(why = checkTouched(chunkEvents)).empty()) {
                addDamage(offset, chunkBytes, why, &h);
                st.hashKnown = false;
                continue;
            }
            if (h.count > 0) {
                if (st.haveExpected && h.firstTick > st.expectedTick) {
                    mSummary.lostTicks += h.firstTick - st.expectedTick;
                    st.hashKnown = false;
                }
                if (st.hashKnown) {
                    std::uint64_t hash = st.runningHash;
                    for (const RecordedTick& t : mScratch) hashTick(hash, t.forceN, t.touched);
                    info.hashChecked = hash == h.hash;
                    if (!info.hashChecked) ++mSummary.hashMismatches;
                }
                mTickChunks.push_back(mChunks.size());
                if (mSummary.ticks == 0) mSummary.firstTick = h.firstTick;
                mSummary.lastTick = h.firstTick + h.count - 1;
                mSummary.ticks += h.count;
                st.expectedTick = h.firstTick + h.count;
                st.haveExpected = true;
                st.runningHash = h.hash;
                st.hashKnown = true;
                if (!st.haveTime) st.firstTimeS = info.firstTimeS;
                st.lastTimeS = info.lastTimeS;
                st.haveTime = true;
            }
            for (auto& e : chunkEvents) events.push_back(std::move(e));
        } else if (h.type == ChunkType::Gap) {
            if (st.haveExpected && h.firstTick > st.expectedTick) {
                mSummary.lostTicks += h.firstTick - st.expectedTick;
                st.hashKnown = false;
            }
            ++mSummary.gaps;
            mSummary.droppedTicks += h.count;
            st.expectedTick = h.firstTick + h.count;
            st.haveExpected = true;
            if (st.hashKnown && h.hash != st.runningHash) ++mSummary.hashMismatches;
            st.runningHash = h.hash;
            st.hashKnown = true;
        } else {  // End
            st.sawEnd = true;
            st.endTicks = h.count;
            if (st.hashKnown && h.hash != st.runningHash) ++mSummary.hashMismatches;
        }
        mChunks.push_back(info);
    }
    mScratch = {};
}

void RecordingReader::finishScan(std::vector<RecordingEvent>& events) {
    // `events`: those read before (already ordered), then mEvents: the new ones in file order. A
    // stable sort of the two keeps file order among events of one tick, as a single scan would.
    if (!mEvents.empty()) {
        const std::size_t before = events.size();
        for (auto& e : mEvents) events.push_back(std::move(e));
        auto byTick = [](const RecordingEvent& a, const RecordingEvent& b) { return a.tick < b.tick; };
        std::stable_sort(events.begin() + std::ptrdiff_t(before), events.end(), byTick);
        std::inplace_merge(events.begin(), events.begin() + std::ptrdiff_t(before), events.end(), byTick);
    }
    mEvents = std::move(events);

    mSummary.fileBytes = mBytes.size();
    mSummary.chunks = mChunks.size();
    mSummary.events = mEvents.size();
    mSummary.damagedRegions = mDamage.size();
    mSummary.closedCleanly = mScan.sawEnd;
    // The end chunk knows how many ticks were written: any not recovered were lost.
    if (mScan.sawEnd && mScan.endTicks > mSummary.ticks + mSummary.lostTicks && mScan.endTicks != 0xFFFFFFFFu)
        mSummary.lostTicks = mScan.endTicks - mSummary.ticks;
    mSummary.durationS = mScan.haveTime ? mScan.lastTimeS - mScan.firstTimeS + periodS() : 0.0;
    mSummary.intact = mSummary.headerOk && mDamage.empty() && mSummary.hashMismatches == 0 && mScan.sawEnd &&
                      mSummary.lostTicks == 0;
}

bool RecordingReader::decodeChunk(std::size_t index, std::vector<RecordedTick>& out) const {
    out.clear();
    if (index >= mChunks.size()) return false;
    const ChunkInfo& c = mChunks[index];
    if (c.type != ChunkType::Data) return true;
    ChunkHeader h;
    const std::uint8_t* payload = nullptr;
    if (parseChunk(mBytes.data(), mBytes.size(), c.offset, h, payload) != ChunkStatus::Ok) return false;
    const std::uint8_t* after = nullptr;
    return decodeTicks(h, payload, out, &after);
}

void RecordingReader::forEachTick(const std::function<bool(const RecordedTick&)>& fn) const {
    std::vector<RecordedTick> ticks;
    for (std::size_t i = 0; i < mChunks.size(); ++i) {
        if (mChunks[i].type != ChunkType::Data || mChunks[i].count == 0) continue;
        if (!decodeChunk(i, ticks)) continue;
        for (const RecordedTick& t : ticks)
            if (!fn(t)) return;
    }
}

std::vector<RecordedTick> RecordingReader::ticks() const {
    std::vector<RecordedTick> all;
    all.reserve(std::size_t(mSummary.ticks));
    forEachTick([&](const RecordedTick& t) {
        all.push_back(t);
        return true;
    });
    return all;
}

std::optional<RecordedTick> RecordingReader::tickAt(std::uint64_t tick) const {
    // Chunks with ticks are in tick order (the scan rejects chunks out of order).
    auto it = std::upper_bound(mTickChunks.begin(), mTickChunks.end(), tick,
                               [this](std::uint64_t t, std::size_t i) { return t < mChunks[i].firstTick; });
    if (it == mTickChunks.begin()) return std::nullopt;
    const std::size_t index = *(it - 1);
    const ChunkInfo& c = mChunks[index];
    if (tick - c.firstTick >= c.count) return std::nullopt;
    std::vector<RecordedTick> ticks;
    if (!decodeChunk(index, ticks) || ticks.size() != c.count) return std::nullopt;
    return ticks[std::size_t(tick - c.firstTick)];
}

}  // namespace palpate
