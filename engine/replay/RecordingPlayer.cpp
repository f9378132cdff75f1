#include "engine/replay/RecordingPlayer.h"

#include "engine/scene/TissuePreset.h"
#include "engine/core/MeshHash.h"
#include "engine/exercise/RecordedExercise.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace palpate {

namespace {

std::string vecText(const glm::vec3& v) {
    std::ostringstream s;
    s.precision(9);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}

std::string touchedText(VertexId v) { return v == kNoVertex ? "none" : std::to_string(v); }

}  // namespace

RecordingPlayer::RecordingPlayer(const RecordingReader& reader, const ReplayDef& options)
    : mReader(reader), mOptions(options) {}

RecordingPlayer::~RecordingPlayer() = default;

std::unique_ptr<RecordingPlayer> RecordingPlayer::open(const RecordingReader& reader, std::string& error,
                                                       const ReplayDef& options) {
    if (!reader.fileError().empty()) {
        error = reader.fileError();
        return nullptr;
    }
    if (!reader.headerOk()) {
        error = reader.name() + ": cannot replay without the header: " + reader.headerError();
        return nullptr;
    }
    std::unique_ptr<RecordingPlayer> player(new RecordingPlayer(reader, options));
    if (!options.prepareScene && options.applyRecordedExercise)
        player->mOptions.prepareScene = recordedExercisePhysics(reader.header());
    if (!(error = player->findReplayableRange()).empty()) return nullptr;
    if (!(error = player->restart()).empty()) return nullptr;
    return player;
}

std::string RecordingPlayer::findReplayableRange() {
    std::string error;
    const RecordingReader& reader = mReader;
    mRangeChunks = reader.chunks().size();
    mRangeDamage = reader.damage().size();
    // The replayable stretch: from the first tick while chunks follow each other without damage,
    // gap or missing tick between them.
    const auto& chunks = reader.chunks();
    bool started = false;
    std::uint64_t expected = 0;
    std::string stopReason;
    for (std::size_t i = 0; i < chunks.size(); ++i) {
        const ChunkInfo& c = chunks[i];
        const bool contiguousBytes = i == 0 || chunks[i - 1].offset + chunks[i - 1].bytes == c.offset;
        if (started && !contiguousBytes) {
            stopReason = "damaged bytes at offset " + std::to_string(chunks[i - 1].offset + chunks[i - 1].bytes);
            break;
        }
        if (c.type == ChunkType::End) break;
        if (c.type == ChunkType::Gap) {
            const std::string gap = "gap of " + std::to_string(c.count) + " ticks at tick " +
                                    std::to_string(c.firstTick) + " (the ring overflowed while recording)";
            if (!started) {
                error = reader.name() + ": cannot replay: the recording begins with a " + gap;
                return error;
            }
            stopReason = gap;
            break;
        }
        if (c.count == 0) continue;
        if (!started && !reader.damage().empty() && reader.damage().front().offset < c.offset) {
            // The state at this chunk's first tick depends on ticks that are lost.
            error = reader.name() + ": cannot replay: the start of the recording is damaged (" +
                    reader.damage().front().reason + ")";
            return error;
        }
        if (started && c.firstTick != expected) {
            stopReason = "ticks " + std::to_string(expected) + ".." + std::to_string(c.firstTick) + " are missing";
            break;
        }
        if (!started) mFirstTick = c.firstTick;
        started = true;
        expected = c.firstTick + c.count;
        mLastReplayableTick = expected - 1;
    }
    if (!started) {
        error = reader.name() + ": no ticks to replay";
        return error;
    }
    mStatus.stopReason = stopReason;
    return {};
}

bool RecordingPlayer::refresh() {
    if (mReader.chunks().size() == mRangeChunks && mReader.damage().size() == mRangeDamage) return false;
    const std::uint64_t before = mLastReplayableTick;
    const std::string stopReason = mStatus.stopReason;
    std::string error;
    if (!(error = findReplayableRange()).empty()) {
        mStatus.stopReason = stopReason;
        return false;
    }
    if (mStopped) mStatus.stopReason = stopReason;  // the stop's own reason stays
    if (mLastReplayableTick == before) return false;
    if (!mStopped && (!mHaveCurrent || mCurrentTick < mLastReplayableTick)) {
        mEnded = false;
        mStatus.complete = false;
    }
    return true;
}

std::unique_ptr<HapticScene> RecordingPlayer::buildScene(const RecordedScene& scene, const std::string& pathOverride,
                                                         const std::optional<MeshUnit>& unitOverride,
                                                         std::string& error) {
    const std::string path = pathOverride.empty() ? scene.meshPath : pathOverride;
    // The file's coordinates scaled as the session scaled them (docs/meshes.md, "Units"): the
    // hash is of the mesh in mm, so another unit is another mesh.
    const MeshUnit unit = unitOverride.value_or(scene.meshUnit);
    const auto key = std::make_pair(path, unit.mmPerUnit);
    auto found = mMeshes.find(key);
    if (found == mMeshes.end()) {
        auto loaded = TissueMesh::load(path, unit);
        if (!loaded.mesh) {
            error = "cannot load the recorded mesh: " + loaded.error();
            return nullptr;
        }
        found = mMeshes.emplace(key, std::move(*loaded.mesh)).first;
    }
    const std::uint64_t hash = meshHash(found->second);
    if (mOptions.requireMeshHash && hash != scene.meshHash) {
        std::ostringstream s;
        s << path << (unit.isMillimetres() ? std::string() : " (in " + unit.description() + ")")
          << " is not the recorded mesh (hash " << std::hex << hash << ", recorded " << scene.meshHash << ")";
        error = s.str();
        return nullptr;
    }
    std::unique_ptr<HapticScene> built;
    try {
        // A registry model other than the slope-ring methods is named by the stored preset JSON
        // only; its binary slope-ring parameters, method and octree stay the exact ones.
        const PresetLoadResult stored = parseTissuePreset(scene.presetJson, "presetJson");
        ModelDef model;
        if (stored.preset && stored.preset->model.kind != ModelKind::SlopeRing) {
            TissuePreset preset = *stored.preset;
            preset.model.slopeRing = scene.params;
            preset.model.slopeRingMethod = scene.method;
            model = presetModelDef(preset);
        } else {
            model = slopeRingModelDef(scene.params, scene.method);
        }
        model.contact = scene.contact;
        built = HapticScene::create(found->second, model, scene.octree);
        mModel = model;
    } catch (const std::exception& e) {
        error = std::string("the recorded scene cannot be rebuilt: ") + e.what();
        return nullptr;
    }
    if (mOptions.prepareScene) {
        const std::string problem = mOptions.prepareScene(*built);
        if (!problem.empty()) {
            error = "the recorded scene cannot be prepared: " + problem;
            return nullptr;
        }
    }
    return built;
}

std::string RecordingPlayer::restart() {
    std::string error;
    const RecordingHeader& h = mReader.header();
    auto scene = buildScene(h.scene, mOptions.meshPath, mOptions.meshUnit, error);
    if (!scene) return error;
    HapticLoopDef def;
    def.rateHz = h.rateHz;
    def.trySchedFifo = false;
    def.safety = h.safety;
    try {
        mLoop = std::make_unique<HapticLoop>(def, std::move(scene), std::make_unique<ReplayDevice>(mFeed, h.device.spec));
    } catch (const std::exception& e) {
        error = std::string("the recorded loop cannot be rebuilt: ") + e.what();
        return error;
    }
    const std::string stopReason = mStatus.stopReason;  // a limit of the file, not of this run
    mStatus = ReplayStatus{};
    mStatus.stopReason = stopReason;
    mFeed.tick = nullptr;
    mCurrentTick = mFirstTick - 1;
    mHaveCurrent = false;
    mEnded = false;
    mStopped = false;
    mPaused = false;
    mChunk = 0;
    mChunkTicks.clear();
    mChunkPos = 0;
    mNextEvent = 0;
    mEventsSeen = mReader.events().size();
    mEventsApplied = false;
    mEventsThroughTick = 0;
    return {};
}

void RecordingPlayer::stop(const std::string& reason) {
    mEnded = true;
    mStopped = true;
    mStatus.stopReason = reason;
    mStatus.complete = false;
}

bool RecordingPlayer::nextRecord(RecordedTick& out) {
    while (mChunkPos >= mChunkTicks.size()) {
        const auto& chunks = mReader.chunks();
        while (mChunk < chunks.size() && (chunks[mChunk].type != ChunkType::Data || chunks[mChunk].count == 0)) ++mChunk;
        if (mChunk >= chunks.size()) return false;
        mChunkOfTicks = mChunk;
        if (!mReader.decodeChunk(mChunk++, mChunkTicks)) return false;
        mChunkPos = 0;
    }
    out = mChunkTicks[mChunkPos++];
    return true;
}

bool RecordingPlayer::applyEvents(std::uint64_t tick) {
    const auto& events = mReader.events();
    if (events.size() != mEventsSeen) {
        // A live reader added events, possibly before the cursor (a mark the writer put in a later
        // chunk than its tick): go on after the last tick whose events were applied.
        mNextEvent = !mEventsApplied ? 0
                                     : std::size_t(std::upper_bound(events.begin(), events.end(), mEventsThroughTick,
                                                                    [](std::uint64_t t, const RecordingEvent& e) {
                                                                        return t < e.tick;
                                                                    }) -
                                                   events.begin());
        mEventsSeen = events.size();
    }
    mEventsApplied = true;
    mEventsThroughTick = tick;
    for (; mNextEvent < events.size() && events[mNextEvent].tick <= tick; ++mNextEvent) {
        const RecordingEvent& e = events[mNextEvent];
        std::string error;
        switch (e.kind) {
            case EventKind::ParamsApplied:
                if (SlopeRingParams* params = slopeRingParamsOf(mModel)) {
                    *params = e.params;
                    if (e.contact) mModel.contact = *e.contact;
                    error = mLoop->setModelParams(mModel);
                } else {
                    error = "parameters applied to a model that takes no slope-ring parameters";
                }
                break;
            case EventKind::SceneChanged: {
                if (!e.scene) {
                    error = "a scene switch the recorder was not told about (use RecordingSession::swapScene)";
                    break;
                }
                auto scene = buildScene(*e.scene, "", std::nullopt, error);
                if (scene) error = mLoop->swapScene(std::move(scene));
                break;
            }
            case EventKind::DeviceChanged:
                error = mLoop->swapDevice(
                    std::make_unique<ReplayDevice>(mFeed, e.device ? e.device->spec : mReader.header().device.spec));
                break;
            case EventKind::Divergence:  // nothing to apply: the replayed tick's guard must fire by itself
                ++mStatus.divergencesRecorded;
                mExpectedDivergence = e.divergence;
                mExpectedDivergenceTick = e.tick;
                break;
            default: break;  // marks, states, pauses: nothing to re-apply (pause follows each tick's flag)
        }
        if (!error.empty()) {
            stop("tick " + std::to_string(e.tick) + ": " + error);
            return false;
        }
    }
    return true;
}

bool RecordingPlayer::stepOne() {
    if (mEnded) return false;
    if (mHaveCurrent && mCurrentTick >= mLastReplayableTick) {
        mEnded = true;
        mStatus.complete = mStatus.stopReason.empty();
        return false;
    }
    RecordedTick rec;
    if (!nextRecord(rec)) {
        stop("the recording's ticks end early");
        return false;
    }
    if (!applyEvents(rec.tick)) return false;
    if (rec.paused != mPaused) {
        if (rec.paused) mLoop->pause();
        else mLoop->resume();
        mPaused = rec.paused;
    }
    mCurrent = rec;
    mHaveCurrent = true;
    mFeed.tick = &mCurrent;
    mLoop->stepAt(rec.nowS, rec.tickOverran);
    mLoop->collectRetired();
    mCurrentTick = rec.tick;
    ++mStatus.ticksReplayed;

    const HapticSnapshot& s = mLoop->newestSnapshot();
    const bool forceSame = std::memcmp(&s.forceN, &rec.forceN, sizeof(glm::vec3)) == 0;
    const bool diverged = s.counters.divergences > 0 && s.counters.lastDivergenceTick == s.tick;
    if (diverged) ++mStatus.divergencesReplayed;
    const DivergenceKind replayedDivergence = diverged ? s.counters.lastDivergence : DivergenceKind::None;
    const DivergenceKind recordedDivergence =
        mExpectedDivergenceTick == rec.tick ? mExpectedDivergence : DivergenceKind::None;
    const bool divergenceSame = mReader.header().formatVersion < 2 || replayedDivergence == recordedDivergence;
    if (!divergenceSame || !forceSame || s.touched != rec.touched || s.contact != rec.contact) {
        ++mStatus.mismatches;
        if (!mStatus.mismatch) {
            mStatus.mismatch = true;
            mStatus.firstMismatchTick = rec.tick;
            mStatus.firstMismatch =
                !divergenceSame
                    ? "tick " + std::to_string(rec.tick) + ": divergence " + divergenceKindName(replayedDivergence) +
                          ", recorded " + divergenceKindName(recordedDivergence)
                    : "tick " + std::to_string(rec.tick) + ": force " + vecText(s.forceN) + " N, recorded " +
                          vecText(rec.forceN) + " N; touched " + touchedText(s.touched) + ", recorded " +
                          touchedText(rec.touched) + "; contact " + (s.contact ? "yes" : "no") + ", recorded " +
                          (rec.contact ? "yes" : "no");
        }
    }
    mStatus.finalHash = s.determinismHash;
    const ChunkInfo& chunk = mReader.chunks()[mChunkOfTicks];
    if (rec.tick == chunk.firstTick + chunk.count - 1) {
        ++mStatus.hashChecks;
        if (s.determinismHash != chunk.hash) ++mStatus.hashMismatches;
    }
    if (mCurrentTick >= mLastReplayableTick) {
        mEnded = true;
        mStatus.complete = mStatus.stopReason.empty();
    }
    return true;
}

std::uint64_t RecordingPlayer::step(std::uint64_t n) {
    std::uint64_t ran = 0;
    while (ran < n && stepOne()) ++ran;
    return ran;
}

bool RecordingPlayer::seek(std::uint64_t tick) {
    if (tick < mFirstTick || tick > mLastReplayableTick) return false;
    if (mHaveCurrent && tick < mCurrentTick) {
        std::string error;
        if (!(error = restart()).empty()) {
            stop(error);
            return false;
        }
    }
    while ((!mHaveCurrent || mCurrentTick < tick) && stepOne()) {
    }
    return mHaveCurrent && mCurrentTick == tick;
}

ReplayStatus replayRecording(const RecordingReader& reader, std::string& error, const ReplayDef& options) {
    auto player = RecordingPlayer::open(reader, error, options);
    if (!player) {
        ReplayStatus failed;
        failed.stopReason = error;
        return failed;
    }
    player->step(std::numeric_limits<std::uint64_t>::max());
    return player->status();
}

}  // namespace palpate
