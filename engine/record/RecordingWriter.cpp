#include "engine/record/RecordingWriter.h"
#include "engine/core/HapticRate.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/types.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <new>
#include <sstream>
#include <system_error>

namespace palpate {

namespace {

double monotonicS() {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

/// write(2) until everything is written or a real error; returns the bytes written.
std::size_t writeAll(int fd, const std::uint8_t* data, std::size_t size, int& error) {
    std::size_t written = 0;
    while (written < size) {
        const ssize_t n = ::write(fd, data + written, size - written);
        if (n < 0) {
            if (errno == EINTR) continue;
            error = errno;
            return written;
        }
        written += std::size_t(n);
    }
    error = 0;
    return written;
}

/// The process holding a flock on the file `fd` is open on, from /proc/locks (0 when unknown).
long lockHolderPid(int fd) {
    struct stat st {};
    if (::fstat(fd, &st) != 0) return 0;
    std::ifstream locks("/proc/locks");
    std::string line;
    while (std::getline(locks, line)) {
        // "1: FLOCK  ADVISORY  WRITE 1234 08:01:56789 0 EOF"
        std::istringstream fields(line);
        std::string id, type, mode, access, device;
        long pid = 0;
        if (!(fields >> id >> type >> mode >> access >> pid >> device) || type != "FLOCK") continue;
        unsigned devMajor = 0, devMinor = 0;
        unsigned long long inode = 0;
        if (std::sscanf(device.c_str(), "%x:%x:%llu", &devMajor, &devMinor, &inode) != 3) continue;
        if (inode == st.st_ino && devMajor == major(st.st_dev) && devMinor == minor(st.st_dev)) return pid;
    }
    return 0;
}

std::string beingWritten(const std::string& path, int fd) {
    const long pid = lockHolderPid(fd);
    return path + ": is being written by another Palpate (" +
           (pid > 0 ? "process " + std::to_string(pid) : std::string("another process")) +
           "); a recording has one writer: choose another file";
}

/// A new file beside `path` as `tempPath`, locked, ready for the header; it takes the name `path`
/// (publishOutput) only once the header is on disk, so a kill -9 before that leaves `path` as it
/// was (absent, or the recording it replaces), never an empty file. -1 with `error` on failure
/// (nothing left behind).
int openOutput(const std::string& path, bool replace, std::string& tempPath, std::string& error) {
    struct stat st {};
    const bool exists = ::stat(path.c_str(), &st) == 0;
    if (exists && !S_ISREG(st.st_mode)) {
        error = path + ": is not a regular file; a recording is written to a regular file";
        return -1;
    }
    if (exists && !replace) {
        error = path + ": already exists; a recording replaces a file only when asked to";
        return -1;
    }
    if (exists) {
        // Refuse before anything is written: the old file may be a session still being recorded.
        const int old = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
        if (old >= 0) {
            const bool locked = ::flock(old, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK;
            if (locked) error = beingWritten(path, old);
            ::close(old);  // also releases the probe's own lock
            if (locked) return -1;
        }
    }
    tempPath = path + ".partial-" + std::to_string(::getpid());
    const std::string& target = tempPath;
    // O_TRUNC: one this process (pid) left behind when killed is its own to reuse.
    const int fd = ::open(target.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0) {
        error = target + ": cannot create the recording: " + std::strerror(errno);
        return -1;
    }
    // Held until close: a second recorder on this path is refused (see beingWritten).
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        error = errno == EWOULDBLOCK ? beingWritten(path, fd) : target + ": cannot lock: " + std::strerror(errno);
        ::close(fd);
        return -1;  // O_EXCL made it ours, but another process locked it at once: theirs now
    }
    return fd;
}

/// Gives the started recording (header on disk) its name: over the old file when replacing, else
/// only if nothing took the name meanwhile (link refuses an existing one). "" or the problem.
std::string publishOutput(const std::string& tempPath, const std::string& path, bool replacing) {
    if (replacing) {
        if (::rename(tempPath.c_str(), path.c_str()) != 0)
            return path + ": cannot replace it with the new recording: " + std::strerror(errno);
        return {};
    }
    if (::link(tempPath.c_str(), path.c_str()) != 0)
        return errno == EEXIST ? path + ": already exists; a recording replaces a file only when asked to"
                               : path + ": cannot create the recording: " + std::strerror(errno);
    ::unlink(tempPath.c_str());
    return {};
}

std::string writeErrorText(const std::string& path, int error, std::uint64_t ticksOnDisk) {
    if (error == EFBIG)
        return path + ": file size limit reached after " + std::to_string(ticksOnDisk) +
               " ticks; the recording stops there";
    return path + ": writing the recording failed after " + std::to_string(ticksOnDisk) +
           " ticks: " + std::strerror(error);
}

}  // namespace

Problems validateRecordingWriterDef(const RecordingWriterDef& def) {
    if (def.ringCapacityTicks < 2 || def.ringCapacityTicks > (1u << 24))
        return oneProblem("ringCapacityTicks", "RecordingWriterDef.ringCapacityTicks must be in 2..16777216");
    if (def.commandCapacity < 2 || def.commandCapacity > (1u << 16))
        return oneProblem("commandCapacity", "RecordingWriterDef.commandCapacity must be in 2..65536");
    if (!(def.drainPeriodS >= 0.001 && def.drainPeriodS <= 0.1))
        return oneProblem("drainPeriodS",
                          "RecordingWriterDef.drainPeriodS must be in 0.001..0.1 s (a crash loses at most one period)");
    if (!(def.syncPeriodS > 0.0) || !std::isfinite(def.syncPeriodS))
        return oneProblem("syncPeriodS", "RecordingWriterDef.syncPeriodS must be finite and > 0");
    if (def.ticksPerChunk > (1u << 20))
        return oneProblem("ticksPerChunk", "RecordingWriterDef.ticksPerChunk must be at most 1048576");
    return {};
}

std::unique_ptr<RecordingWriter> RecordingWriter::create(const std::string& path, const RecordingHeader& header,
                                                         std::string& error, const RecordingWriterDef& def) {
    if (const std::string problem = joinedMessages(validateRecordingWriterDef(def)); !problem.empty()) {
        error = problem;
        return nullptr;
    }
    if (!hapticRateInRange(header.rateHz)) {
        error = "recording header: rateHz " + std::to_string(header.rateHz) + " is outside 10..10000";
        return nullptr;
    }
    // What the reader would refuse is never written (RecordingFormat.h states the limits).
    if (const std::string problem = joinedMessages(validateRecordingHeader(header)); !problem.empty()) {
        error = path + ": not recorded: " + problem;
        return nullptr;
    }
    std::vector<std::uint8_t> bytes;
    const std::uint32_t headerCrc = encodeRecordingHeader(header, bytes);

    std::string tempPath;
    const bool replacing = ::access(path.c_str(), F_OK) == 0;
    const int fd = openOutput(path, def.replaceExisting, tempPath, error);
    if (fd < 0) return nullptr;
    const std::string& written = tempPath;
    auto abandon = [&](std::unique_ptr<RecordingWriter> writer, const std::string& why) {
        if (writer) {
            writer->close();  // joins the thread; the fd is closed there
        } else {
            ::close(fd);
        }
        ::unlink(written.c_str());
        error = why;
        return nullptr;
    };
    std::unique_ptr<RecordingWriter> writer;
    try {
        writer.reset(new RecordingWriter(path, header, def, fd));
    } catch (const std::bad_alloc&) {  // its chunk buffers, under a tight address-space limit
        return abandon(nullptr, path + ": cannot allocate the recording's buffers: out of memory");
    }
    writer->mHeaderTag = chunkHeaderTag(headerCrc);
    try {
        writer->mThread = std::thread([w = writer.get()] { w->threadMain(); });
    } catch (const std::system_error& e) {
        writer->mFd = -1;
        writer.reset();
        return abandon(nullptr, path + ": cannot start the recording's writer thread: " + e.what());
    }
    int why = 0;
    if (writeAll(fd, bytes.data(), bytes.size(), why) != bytes.size())
        return abandon(std::move(writer), path + ": cannot write the recording header: " + std::strerror(why));
    if (const std::string problem = publishOutput(tempPath, path, replacing); !problem.empty())
        return abandon(std::move(writer), problem);
    {
        std::lock_guard lock(writer->mMutex);
        writer->mWorking.bytes = bytes.size();
        writer->mWritten = writer->mWorking;
        writer->mStats = writer->mWritten;
        writer->mHeaderWritten = true;
    }
    writer->mWake.notify_all();
    return writer;
}

RecordingWriter::RecordingWriter(std::string path, const RecordingHeader& header, const RecordingWriterDef& def,
                                 int fd)
    : mPath(std::move(path)),
      mHeader(header),
      mDef(def),
      mPeriodS(1.0 / header.rateHz),
      mTicksPerChunk(def.ticksPerChunk > 0 ? def.ticksPerChunk
                                           : std::max<std::size_t>(1, std::size_t(std::lround(def.drainPeriodS * header.rateHz)))),
      mFd(fd),
      mTicks(def.ringCapacityTicks),
      mCommands(def.commandCapacity) {
    mDrained.reserve(mTicks.capacity());
    mPendingCommands.reserve(2 * mCommands.capacity());
    mPayload.reserve(64 * 1024);
    mEventBytes.reserve(4096);
    mOut.reserve(256 * 1024);
    mScratch.reserve(1024);
    mEncoded.reserve(64);
    mWorking.hash = kHashSeed;
    mWritten = mWorking;
    mLastSyncS = monotonicS();
}

RecordingWriter::~RecordingWriter() { close(); }

// --- haptic thread ---

void RecordingWriter::onTick(const RecordedTick& tick) noexcept {
    const std::uint32_t drops = mPendingDrops.load(std::memory_order_relaxed);
    if (mTicks.push(Item{tick, drops})) {
        if (drops != 0) mPendingDrops.store(0, std::memory_order_relaxed);
    } else {
        mPendingDrops.store(drops + 1, std::memory_order_relaxed);
        mDroppedTotal.fetch_add(1, std::memory_order_relaxed);
    }
    mCurrentTick.store(tick.tick, std::memory_order_relaxed);
}

void RecordingWriter::onCommand(const RecordedCommand& command) noexcept {
    if (!mCommands.push(command)) mLostCommands.fetch_add(1, std::memory_order_relaxed);
}

// --- controller threads ---

void RecordingWriter::controllerEvent(EventKind kind, const std::string& text) {
    std::lock_guard lock(mMutex);
    if (mClosed) return;
    mControllerEvents.push_back(
        {kind, mCurrentTick.load(std::memory_order_relaxed), text.substr(0, kMaxEventTextBytes)});
}

void RecordingWriter::mark(const std::string& text) { controllerEvent(EventKind::Mark, text); }
void RecordingWriter::exerciseEvent(const std::string& text) { controllerEvent(EventKind::Exercise, text); }

void RecordingWriter::describeScene(std::uint64_t sceneId, const RecordedScene& scene) {
    std::lock_guard lock(mMutex);
    mSceneDescriptions[sceneId] = scene;
}

void RecordingWriter::describeDevice(const void* device, const RecordedDevice& description) {
    std::lock_guard lock(mMutex);
    mDeviceDescriptions[device] = description;
}

RecordingStats RecordingWriter::stats() const {
    std::lock_guard lock(mMutex);
    RecordingStats s = mStats;
    s.droppedTicks = mDroppedTotal.load(std::memory_order_relaxed);
    s.lostCommands = mLostCommands.load(std::memory_order_relaxed);
    return s;
}

std::string RecordingWriter::flush() {
    std::unique_lock lock(mMutex);
    if (mClosed) return mStats.error;
    const std::uint64_t target = ++mFlushRequested;
    mWake.notify_all();
    mFlushed.wait(lock, [&] { return mFlushDone >= target || mClosed; });
    return mStats.error;
}

std::string RecordingWriter::close() {
    {
        std::lock_guard lock(mMutex);
        if (mClosed) return mStats.error;
        mClosed = true;
        mStop = true;
    }
    mWake.notify_all();
    if (mThread.joinable()) mThread.join();
    mFlushed.notify_all();
    std::string error = mWritten.error;
    if (mFd >= 0) {
        if (::fsync(mFd) != 0 && error.empty()) error = mPath + ": fsync failed: " + std::strerror(errno);
        if (::close(mFd) != 0 && error.empty()) error = mPath + ": close failed: " + std::strerror(errno);
        mFd = -1;
    }
    std::lock_guard lock(mMutex);
    mWritten.error = error;
    mStats = mWritten;
    return error;
}

// --- writer thread ---

void RecordingWriter::threadMain() {
    std::unique_lock lock(mMutex);
    // Started before the header is written (so that a thread that cannot start costs no file).
    mWake.wait(lock, [&] { return mHeaderWritten || mStop; });
    if (!mHeaderWritten) return;  // abandoned: nothing of ours is in the file
    for (;;) {
        mWake.wait_for(lock, std::chrono::duration<double>(mDef.drainPeriodS),
                       [&] { return mStop || mFlushRequested != mFlushDone; });
        const bool stop = mStop;
        const std::uint64_t flushTarget = mFlushRequested;
        mEventsTaken.swap(mControllerEvents);  // both keep their capacity
        lock.unlock();
        drain(stop);
        lock.lock();
        mStats = mWritten;
        mFlushDone = flushTarget;
        mFlushed.notify_all();
        if (stop) return;
    }
}

void RecordingWriter::drain(bool final) {
    mDrained.clear();
    Item item;
    while (mTicks.pop(item)) mDrained.push_back(item);
    // Commands after ticks: a command is pushed before its tick, so every command of a drained
    // tick is visible now. Those of later ticks wait for their tick's chunk.
    RecordedCommand command;
    while (mCommands.pop(command)) mPendingCommands.push_back(command);

    std::size_t begin = 0;
    for (std::size_t i = 0; i < mDrained.size(); ++i) {
        const std::uint32_t dropped = mDrained[i].droppedBefore;
        if (dropped == 0) continue;
        emitTicks(begin, i);
        ChunkHeader gap;
        gap.type = ChunkType::Gap;
        gap.firstTick = mDrained[i].tick.tick - dropped;
        gap.count = dropped;
        gap.hash = mWorking.hash;
        mPayload.clear();
        ++mWorking.gaps;
        mWorking.droppedTicks += dropped;
        emitChunk(gap, mPayload);
        begin = i;
    }
    emitTicks(begin, mDrained.size());

    const std::uint64_t nextTick = mHaveLastTick ? mLastTick.tick + 1 : 0;
    if (final) {
        // Ticks dropped at the very end have no later tick to carry their count.
        if (const std::uint32_t dropped = mPendingDrops.exchange(0, std::memory_order_acq_rel); dropped > 0) {
            ChunkHeader gap;
            gap.type = ChunkType::Gap;
            gap.firstTick = mCurrentTick.load(std::memory_order_relaxed) + 1 - dropped;
            gap.count = dropped;
            gap.hash = mWorking.hash;
            mPayload.clear();
            ++mWorking.gaps;
            mWorking.droppedTicks += dropped;
            emitChunk(gap, mPayload);
        }
    }
    // Events no tick chunk took (controller events while the loop is stopped; at the end, also
    // commands of ticks that never came).
    const bool leftovers = !mEventsTaken.empty() || (final && !mPendingCommands.empty()) ||
                           mLostCommands.load(std::memory_order_relaxed) != mLostCommandsReported;
    if (leftovers) {
        mPayload.clear();
        mEventBytes.clear();
        mEventCount = 0;
        appendEventsUpTo(final ? ~std::uint64_t(0) : (nextTick == 0 ? 0 : nextTick - 1), nextTick);
        if (mEventCount > 0) {
            ByteWriter w(mPayload);
            w.varint(mEventCount);
            w.bytes(mEventBytes.data(), mEventBytes.size());
            ChunkHeader data;
            data.type = ChunkType::Data;
            data.firstTick = nextTick;
            data.count = 0;
            data.hash = mWorking.hash;
            emitChunk(data, mPayload);
        }
    }
    if (final) {
        mPayload.clear();
        ByteWriter w(mPayload);
        w.varint(mWorking.ticks);
        w.varint(mWorking.droppedTicks);
        w.varint(mWorking.events);
        w.varint(mLostCommands.load(std::memory_order_relaxed));
        w.varint(mWorking.chunks);
        ChunkHeader end;
        end.type = ChunkType::End;
        end.firstTick = nextTick;
        end.count = std::uint32_t(std::min<std::uint64_t>(mWorking.ticks, 0xFFFFFFFFu));
        end.hash = mWorking.hash;
        emitChunk(end, mPayload);
    }
    writeOut();
}

void RecordingWriter::emitTicks(std::size_t begin, std::size_t end) {
    while (begin < end) {
        // One chunk per drain period of loop time; a short remainder joins the last chunk.
        std::size_t take = end - begin;
        if (take >= 2 * mTicksPerChunk) take = mTicksPerChunk;
        const std::uint64_t firstTick = mDrained[begin].tick.tick;
        mPayload.clear();
        mEventBytes.clear();
        mEventCount = 0;
        mEncoder.reset();
        for (std::size_t i = begin; i < begin + take; ++i) {
            const RecordedTick& t = mDrained[i].tick;
            mEncoder.encode(t, mPayload);
            hashTick(mWorking.hash, t.forceN, t.touched);
            // Derived events for the timeline: device state and pause changes.
            if (!mHaveLastTick || t.deviceState != mLastTick.deviceState) {
                const auto state = std::uint8_t(t.deviceState);
                addEvent(EventKind::DeviceState, t.tick, firstTick, &state, 1);
            }
            if (mHaveLastTick ? t.paused != mLastTick.paused : t.paused)
                addEvent(t.paused ? EventKind::Paused : EventKind::Resumed, t.tick, firstTick, nullptr, 0);
            // The divergence guard fired in this tick (format 2): its kind.
            if (t.divergence != 0) addEvent(EventKind::Divergence, t.tick, firstTick, &t.divergence, 1);
            if (!mHaveLastTick) {
                mFirstNowS = t.nowS;
                mWorking.firstTick = t.tick;
            }
            mLastTick = t;
            mHaveLastTick = true;
        }
        const std::uint64_t lastTick = mDrained[begin + take - 1].tick.tick;
        appendEventsUpTo(lastTick, firstTick);
        ByteWriter w(mPayload);
        w.varint(mEventCount);
        w.bytes(mEventBytes.data(), mEventBytes.size());
        ChunkHeader data;
        data.type = ChunkType::Data;
        data.firstTick = firstTick;
        data.count = std::uint32_t(take);
        data.hash = mWorking.hash;
        mWorking.ticks += take;
        mWorking.lastTick = lastTick;
        mWorking.elapsedS = mLastTick.nowS - mFirstNowS + mPeriodS;
        emitChunk(data, mPayload);
        begin += take;
    }
}

void RecordingWriter::appendEventsUpTo(std::uint64_t lastTick, std::uint64_t firstTick) {
    // Applied commands of ticks up to lastTick, in the order the loop applied them.
    std::size_t kept = 0;
    bool needDescriptions = false;
    for (const RecordedCommand& c : mPendingCommands)
        if (c.tick <= lastTick && c.kind != RecordedCommand::Kind::Params) needDescriptions = true;
    std::unique_lock lock(mMutex, std::defer_lock);
    if (needDescriptions) lock.lock();
    for (const RecordedCommand& c : mPendingCommands) {
        if (c.tick > lastTick) {
            mPendingCommands[kept++] = c;
            continue;
        }
        mScratch.clear();
        ByteWriter w(mScratch);
        switch (c.kind) {
            case RecordedCommand::Kind::Params:
                encodeParams(w, c.params);
                encodeContact(w, c.contact);
                encodeStiffening(w, c.params);  // format 5
                addEvent(EventKind::ParamsApplied, c.tick, firstTick, mScratch.data(), mScratch.size());
                break;
            case RecordedCommand::Kind::Scene: {
                w.u64(c.sceneId);
                const auto found = mSceneDescriptions.find(c.sceneId);
                w.u8(found != mSceneDescriptions.end() ? 1 : 0);
                if (found != mSceneDescriptions.end()) {
                    encodeScene(w, found->second);
                    encodeContact(w, found->second.contact);
                    encodeMeshUnit(w, found->second.meshUnit);  // format 4
                    encodeStiffening(w, found->second.params);  // format 5
                }
                addEvent(EventKind::SceneChanged, c.tick, firstTick, mScratch.data(), mScratch.size());
                break;
            }
            case RecordedCommand::Kind::Device: {
                const auto found = mDeviceDescriptions.find(c.device);
                w.u8(found != mDeviceDescriptions.end() ? 1 : 0);
                if (found != mDeviceDescriptions.end()) encodeDevice(w, found->second);
                addEvent(EventKind::DeviceChanged, c.tick, firstTick, mScratch.data(), mScratch.size());
                break;
            }
        }
    }
    mPendingCommands.resize(kept);
    if (lock.owns_lock()) lock.unlock();

    const std::uint64_t lost = mLostCommands.load(std::memory_order_relaxed);
    if (lost != mLostCommandsReported) {
        mScratch.clear();
        ByteWriter w(mScratch);
        w.varint(lost - mLostCommandsReported);
        addEvent(EventKind::CommandsLost, mHaveLastTick ? mLastTick.tick : firstTick, firstTick, mScratch.data(),
                 mScratch.size());
        mLostCommandsReported = lost;
    }
    // Controller events (marks, exercise events) go into the first chunk written after they came.
    for (const PendingEvent& e : mEventsTaken)
        addEvent(e.kind, e.tick, firstTick, reinterpret_cast<const std::uint8_t*>(e.text.data()), e.text.size());
    mEventsTaken.clear();
}

void RecordingWriter::addEvent(EventKind kind, std::uint64_t tick, std::uint64_t firstTick, const std::uint8_t* payload,
                               std::size_t bytes) {
    ByteWriter w(mEventBytes);
    w.varint(std::uint8_t(kind));
    w.svarint(std::int64_t(tick - firstTick));
    w.varint(bytes);
    if (bytes > 0) w.bytes(payload, bytes);
    ++mEventCount;
    ++mWorking.events;
}

void RecordingWriter::emitChunk(const ChunkHeader& chunk, const std::vector<std::uint8_t>& payload) {
    ChunkHeader header = chunk;
    header.headerTag = mHeaderTag;
    encodeChunk(header, payload.data(), payload.size(), mOut);
    ++mWorking.chunks;
    mEncoded.push_back({mOut.size(), mWorking});
}

void RecordingWriter::writeOut() {
    if (mOut.empty()) return;
    if (mWritten.error.empty() && mWritten.bytes + mOut.size() > kMaxRecordingBytes) {
        // The reader refuses a larger file: the recording ends here, readable.
        mWritten.error = mPath + ": the recording reached the format's limit of " + std::to_string(kMaxRecordingBytes) +
                         " bytes after " + std::to_string(mWritten.ticks) + " ticks; it stops there";
    }
    if (mWritten.error.empty()) {
        int why = 0;
        const std::size_t written = writeAll(mFd, mOut.data(), mOut.size(), why);
        // The figures say what a reader will find: the whole chunks that reached the file.
        std::size_t whole = 0;
        const RecordingStats before = mWritten;
        for (const Encoded& e : mEncoded) {
            if (e.endBytes > written) break;
            whole = e.endBytes;
            mWritten = e.figures;
        }
        mWritten.bytes = before.bytes + whole;
        if (why != 0) {
            // A chunk cut short would read as damage: cut the file back to the last whole chunk
            // (shrinking works on a full disk and under a file-size limit). Later chunks are dropped.
            if (written != whole) (void)::ftruncate(mFd, off_t(mWritten.bytes));
            mWritten.error = writeErrorText(mPath, why, mWritten.ticks);
        }
    }
    mOut.clear();
    mEncoded.clear();
    const double nowS = monotonicS();
    if (nowS - mLastSyncS >= mDef.syncPeriodS) {
        ::fdatasync(mFd);
        mLastSyncS = nowS;
    }
}

}  // namespace palpate
