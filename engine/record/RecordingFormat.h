#pragma once
// The session recording file (docs/recording.md has the byte-by-byte layout):
//
//   preamble  "PALPREC" + format version (u8), header length (u32), header body, CRC-32 of the body
//   chunks    "PCHK", type, header tag, payload length, first tick, count, hash, CRC-32 of those
//             fields, payload, CRC-32 of the payload
//
// Append-only: a chunk is written whole with one write(2), so a crash loses at most the chunk being
// filled. Every chunk decodes on its own (its delta coding restarts), so a damaged chunk costs only
// itself: the reader resynchronises on the next chunk magic.

#include "base/params/Problem.h"

#include "device/HapticDevice.h"
#include "device/SafetyFilter.h"
#include "engine/core/MeshUnit.h"
#include "engine/core/Octree.h"
#include "engine/models/slopering/SlopeRingMethod.h"
#include "engine/models/ContactDef.h"
#include "engine/models/slopering/SlopeRingParams.h"
#include "base/io/FileLimits.h"
#include "engine/record/ByteIo.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

inline constexpr char kRecordingMagic[7] = {'P', 'A', 'L', 'P', 'R', 'E', 'C'};
/// 2: adds the Divergence event (kind 10). Version 1 files read unchanged (they have none).
/// 3: appends the contact to the header, scene and parameter events. 4: appends the mesh's unit
/// to the header and scene events (older files: mm). 5: appends the slope-ring parameters'
/// stiffening knots to the header and the scene and parameter events (older files: linear tissue).
/// 6: every chunk carries its header's tag (the low 24 bits of the header body's CRC, in bytes
/// that were zero), so that chunks spliced behind another recording's header are told apart.
inline constexpr std::uint8_t kRecordingFormatVersion = 6;
/// The first version whose chunks carry their header's tag.
inline constexpr std::uint8_t kHeaderTagFormatVersion = 6;
inline constexpr std::uint8_t kOldestRecordingFormatVersion = 1;
inline constexpr std::uint8_t kChunkMagic[4] = {'P', 'C', 'H', 'K'};
/// Magic (7) + version (1) + header length (4).
inline constexpr std::size_t kPreambleBytes = 12;
/// Magic, type, header tag (3 bytes), payload length, first tick, count, hash, header CRC.
inline constexpr std::size_t kChunkHeaderBytes = 36;
/// Chunk header + payload CRC: what a chunk costs besides its payload.
inline constexpr std::size_t kChunkOverheadBytes = kChunkHeaderBytes + 4;

// The format's limits, stated once: the reader refuses anything larger (so that garbage never
// makes it allocate or loop without bound) and the writer refuses to write it (validateRecordingHeader,
// the event texts), so that every file the recorder writes reads back. They are sized from the
// input files a session embeds (base/io/FileLimits.h), so that every preset that loads and the
// documented exercise limits (docs/scoring.md: 1000 targets, 10 000 path points) fit.
inline constexpr std::size_t kMaxPathBytes = 4096;
inline constexpr std::size_t kMaxNameBytes = 256;
/// The tissue preset as JSON (its description included): whatever a preset file may hold.
inline constexpr std::size_t kMaxPresetJsonBytes = std::size_t(kPresetFile.maxBytes);
/// A mark's or an exercise event's text.
inline constexpr std::size_t kMaxEventTextBytes = 64 * 1024;
/// The header's note: a person's text (up to 1 MiB) and, for an exercise session, the whole
/// exercise as JSON (an exercise file's limit).
inline constexpr std::size_t kMaxNoteBytes = std::size_t(kExerciseFile.maxBytes + kMiB);
/// The header body: its texts at their limits plus the fixed fields, with room to spare.
inline constexpr std::uint32_t kMaxHeaderBytes =
    std::uint32_t(kMaxPresetJsonBytes + kMaxNoteBytes + 4 * kMaxPathBytes + 4 * kMaxNameBytes + 64 * 1024);
inline constexpr std::uint32_t kMaxChunkPayloadBytes = 64u << 20;
/// A whole recording (the reader holds it in memory): about 70 hours at 1 kHz.
inline constexpr std::uint64_t kMaxRecordingBytes = std::uint64_t(4) << 30;
inline constexpr InputKind kRecordingFile{"a Palpate recording", kMaxRecordingBytes};

enum class ChunkType : std::uint8_t {
    Data = 1,  ///< `count` ticks from `firstTick` (delta coded), then the events of that stretch
    Gap = 2,   ///< the ring buffer overflowed: `count` ticks from `firstTick` were never recorded
    End = 3,   ///< written by a clean close: totals; a file without it did not close (crash, kill)
};
const char* chunkTypeName(ChunkType type);

enum class EventKind : std::uint8_t {
    ParamsApplied = 1,  ///< a whole parameter set, applied at the event's tick boundary
    SceneChanged = 2,   ///< a new scene (mesh, model, parameters) switched in
    DeviceChanged = 3,  ///< a new device switched in
    DeviceState = 4,    ///< the device's state changed (seen by the tick)
    Paused = 5,
    Resumed = 6,
    Mark = 7,           ///< a user's mark (text)
    Exercise = 8,       ///< an exercise event (text, e.g. JSON)
    CommandsLost = 9,   ///< the applied-command queue overflowed: replay cannot be exact
    Divergence = 10,    ///< (format 2) the divergence guard fired in that tick: 1 byte, the DivergenceKind
};
const char* eventKindName(EventKind kind);

/// The scene a session runs: enough to rebuild it for replay and to check it is the same mesh.
struct RecordedScene {
    std::string meshPath;
    /// (format 4) The unit of the mesh file's coordinates, which the replay loads it in; older
    /// files: mm (docs/meshes.md, "Units").
    MeshUnit meshUnit;
    std::uint64_t meshHash = 0;  ///< meshHash() of the loaded (renumbered, scaled to mm) mesh
    std::uint32_t vertexCount = 0;
    std::uint32_t triangleCount = 0;
    SlopeRingMethod method = SlopeRingMethod::Coherent;
    SlopeRingParams params;      ///< binary, exact: what replay uses
    ContactDef contact;          ///< (format 3) the tool and friction; older files: a point tool
    OctreeDef octree;
    std::string presetJson;      ///< the whole TissuePreset as JSON, for people and tools
};

struct RecordedDevice {
    std::string uri;
    DeviceSpec spec;
};

/// Everything a replay needs besides the ticks, and what a person wants to know about the session.
struct RecordingHeader {
    std::string engineVersion = recordingEngineVersion();
    std::int64_t startUnixUs = 0;  ///< wall clock at the start (µs since 1970)
    double rateHz = 1000.0;
    RecordedScene scene;
    RecordedDevice device;
    SafetyFilterDef safety;
    std::string note;              ///< free text: trainee, exercise, ...
    /// The file's format version (decode sets it; encode always writes kRecordingFormatVersion).
    std::uint8_t formatVersion = kRecordingFormatVersion;
    /// The CRC-32 of the header body as stored (decode sets it): its low 24 bits tag the chunks.
    std::uint32_t bodyCrc = 0;

    /// The engine's version (PALPATE version) as stored in new recordings.
    static std::string recordingEngineVersion();
};

/// "" when the writer may write `header` (every text within its limit, the body within
/// kMaxHeaderBytes), else the problem naming the field ("header.note: 100000 bytes, at most ...").
Problems validateRecordingHeader(const RecordingHeader& header);

/// Preamble, body and CRC, appended to `out`; returns the body's CRC.
std::uint32_t encodeRecordingHeader(const RecordingHeader& header, std::vector<std::uint8_t>& out);
/// The tag a chunk carries to say which header it belongs to (format 6).
inline std::uint32_t chunkHeaderTag(std::uint32_t headerBodyCrc) { return headerBodyCrc & 0xFFFFFFu; }
/// Parses the preamble and header from the start of `data`; sets `headerBytes` to where the first
/// chunk may start. On failure returns false and `error` names the field ("header.meshPath: ...").
std::string decodeRecordingHeader(const std::uint8_t* data, std::size_t size, RecordingHeader& header,
                                  std::size_t& headerBytes);

void encodeParams(ByteWriter& w, const SlopeRingParams& params);
SlopeRingParams decodeParams(ByteReader& r, const std::string& field);
/// (format 3) The tool and friction, appended after what older formats wrote: decodeContact reads
/// them when the bytes are there (nullopt when not; a failed read names `field`).
void encodeContact(ByteWriter& w, const ContactDef& contact);
std::optional<ContactDef> decodeContact(ByteReader& r, const std::string& field);
/// (format 4) The mesh's unit (mm per file unit, then its name), appended after the contact:
/// decodeMeshUnit reads it when the bytes are there (nullopt when not; a factor out of range or a
/// name that is not its factor's fails under `field`).
void encodeMeshUnit(ByteWriter& w, const MeshUnit& unit);
/// The stiffening knots (docs/method.md), appended by format 5: i32 count, then the two lists' stored
/// entries as f64. decodeStiffening reads them into `params` when the bytes are there.
void encodeStiffening(ByteWriter& w, const SlopeRingParams& params);
void decodeStiffening(ByteReader& r, const std::string& field, SlopeRingParams& params);
/// Whether `key` is one of the fields encodeStiffening writes (encodeParams leaves them out).
bool isStiffeningField(const char* key);
std::optional<MeshUnit> decodeMeshUnit(ByteReader& r, const std::string& field);
void encodeScene(ByteWriter& w, const RecordedScene& scene);
RecordedScene decodeScene(ByteReader& r, const std::string& field);
void encodeDevice(ByteWriter& w, const RecordedDevice& device);
RecordedDevice decodeDevice(ByteReader& r, const std::string& field);

/// The fixed fields of a chunk.
struct ChunkHeader {
    ChunkType type = ChunkType::Data;
    std::uint32_t payloadBytes = 0;
    std::uint64_t firstTick = 0;
    std::uint32_t count = 0;
    std::uint64_t hash = 0;  ///< session determinism hash after the chunk's last tick
    std::uint32_t headerTag = 0;  ///< (format 6) chunkHeaderTag of its recording's header; 0 before
};

/// Appends a whole chunk (header, payload, CRCs) to `out`.
void encodeChunk(const ChunkHeader& header, const std::uint8_t* payload, std::size_t payloadBytes,
                 std::vector<std::uint8_t>& out);

enum class ChunkStatus { Ok, NoMagic, Truncated, BadHeaderCrc, BadField, TruncatedPayload, BadPayloadCrc };
const char* chunkStatusText(ChunkStatus status);

/// Checks the chunk starting at `offset` (magic, CRCs, field ranges). On Ok, `header` and
/// `payload` describe it and the chunk ends at offset + kChunkOverheadBytes + payloadBytes. On
/// TruncatedPayload and BadPayloadCrc the header was intact and `header` is set (payload is not).
ChunkStatus parseChunk(const std::uint8_t* data, std::size_t size, std::size_t offset, ChunkHeader& header,
                       const std::uint8_t*& payload);

/// Offset of the next chunk magic at or after `from`, or `size` when there is none.
std::size_t findChunkMagic(const std::uint8_t* data, std::size_t size, std::size_t from);

}  // namespace palpate
