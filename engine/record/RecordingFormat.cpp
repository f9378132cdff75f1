#include "engine/record/RecordingFormat.h"

#include "engine/record/Crc32.h"
#include "engine/core/HapticRate.h"

#include <cmath>
#include <cstring>

#ifndef PALPATE_ENGINE_VERSION
#define PALPATE_ENGINE_VERSION "unknown"
#endif

namespace palpate {

namespace {

std::uint32_t readU32(const std::uint8_t* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}

std::uint64_t readU64(const std::uint8_t* p) { return std::uint64_t(readU32(p)) | std::uint64_t(readU32(p + 4)) << 32; }

}  // namespace

std::string RecordingHeader::recordingEngineVersion() { return PALPATE_ENGINE_VERSION; }

const char* chunkTypeName(ChunkType type) {
    switch (type) {
        case ChunkType::Data: return "data";
        case ChunkType::Gap: return "gap";
        case ChunkType::End: return "end";
    }
    return "unknown";
}

const char* eventKindName(EventKind kind) {
    switch (kind) {
        case EventKind::ParamsApplied: return "params";
        case EventKind::SceneChanged: return "scene";
        case EventKind::DeviceChanged: return "device";
        case EventKind::DeviceState: return "device-state";
        case EventKind::Paused: return "paused";
        case EventKind::Resumed: return "resumed";
        case EventKind::Mark: return "mark";
        case EventKind::Exercise: return "exercise";
        case EventKind::CommandsLost: return "commands-lost";
        case EventKind::Divergence: return "divergence";
    }
    return "unknown";
}

const char* chunkStatusText(ChunkStatus status) {
    switch (status) {
        case ChunkStatus::Ok: return "ok";
        case ChunkStatus::NoMagic: return "no chunk magic";
        case ChunkStatus::Truncated: return "truncated chunk header";
        case ChunkStatus::TruncatedPayload: return "truncated chunk";
        case ChunkStatus::BadHeaderCrc: return "chunk header CRC mismatch";
        case ChunkStatus::BadField: return "chunk header field out of range";
        case ChunkStatus::BadPayloadCrc: return "chunk payload CRC mismatch";
    }
    return "unknown";
}

// --- parameters, scene, device ---

// The parameters in their table's order (base/params/FieldTable.h), every stored list entry
// included: whole numbers as i32, the rest as f64 (docs/recording.md has the layout).
bool isStiffeningField(const char* key) { return std::string(key).rfind("stiffening", 0) == 0; }

namespace {

/// The fields of the table that are (`stiffening`) or are not the stiffening knots, in table order.
void encodeFields(ByteWriter& w, const SlopeRingParams& p, bool stiffening) {
    for (const FieldDef<SlopeRingParams>& f : slopeRingFields())
        for (int i = 0; i < f.capacity && isStiffeningField(f.spec.key) == stiffening; ++i) {
            if (f.type == FieldType::Whole) w.i32(int(f.get(p, i)));
            else w.f64(f.get(p, i));
        }
}

void decodeFields(ByteReader& r, const std::string& field, SlopeRingParams& p, bool stiffening) {
    for (const FieldDef<SlopeRingParams>& f : slopeRingFields())
        for (int i = 0; i < f.capacity && isStiffeningField(f.spec.key) == stiffening; ++i) {
            const std::string name = field + "." + f.spec.key +
                                     (f.type == FieldType::RealList ? "[" + std::to_string(i) + "]" : "");
            if (f.type != FieldType::Whole) {
                f.set(p, i, r.f64(name));
                continue;
            }
            // A count sizes what follows: refused here when out of range, not at validation.
            const int v = r.i32(name);
            if (r.ok() && !inRange(f, v))
                r.fail(name,
                       std::to_string(v) + " is outside " + formatNumber(f.spec.lo) + ".." + formatNumber(f.spec.hi));
            f.set(p, i, v);
        }
}

}  // namespace

void encodeParams(ByteWriter& w, const SlopeRingParams& p) { encodeFields(w, p, false); }

SlopeRingParams decodeParams(ByteReader& r, const std::string& field) {
    SlopeRingParams p;
    decodeFields(r, field, p, false);
    return p;
}

void encodeStiffening(ByteWriter& w, const SlopeRingParams& p) { encodeFields(w, p, true); }

void decodeStiffening(ByteReader& r, const std::string& field, SlopeRingParams& p) {
    if (r.remaining() == 0) return;  // before format 5: no knots
    decodeFields(r, field, p, true);
}

void encodeContact(ByteWriter& w, const ContactDef& c) {
    w.f64(c.toolRadiusMm);
    w.f64(c.staticFriction);
    w.f64(c.dynamicFriction);
}

std::optional<ContactDef> decodeContact(ByteReader& r, const std::string& field) {
    if (r.remaining() < 3 * sizeof(double)) return std::nullopt;
    ContactDef c;
    c.toolRadiusMm = r.f64(field + ".toolRadiusMm");
    c.staticFriction = r.f64(field + ".staticFriction");
    c.dynamicFriction = r.f64(field + ".dynamicFriction");
    const Problems problems = validateContactDef(c);
    if (r.ok() && !problems.empty()) r.fail(field + "." + problems.front().field, problems.front().message);
    return c;
}

void encodeMeshUnit(ByteWriter& w, const MeshUnit& unit) {
    w.f64(unit.mmPerUnit);
    w.str(unit.name);
}

std::optional<MeshUnit> decodeMeshUnit(ByteReader& r, const std::string& field) {
    if (r.remaining() == 0) return std::nullopt;
    MeshUnit unit;
    unit.mmPerUnit = r.f64(field + ".mmPerUnit");
    unit.name = r.str(field + ".name", kMaxNameBytes);
    if (!r.ok()) return std::nullopt;
    // The units an exercise or --mesh-unit accepts (engine/core/MeshUnit.h).
    if (!(std::isfinite(unit.mmPerUnit) && unit.mmPerUnit >= kMinMmPerUnit && unit.mmPerUnit <= kMaxMmPerUnit)) {
        r.fail(field + ".mmPerUnit", formatNumber(unit.mmPerUnit) + " mm per file unit is outside " +
                                         formatNumber(kMinMmPerUnit) + ".." + formatNumber(kMaxMmPerUnit));
        return std::nullopt;
    }
    if (!unit.name.empty()) {
        std::string problem;
        const auto named = parseMeshUnit(unit.name, problem);
        if (!named || named->name != unit.name || named->mmPerUnit != unit.mmPerUnit) {
            r.fail(field + ".name", named ? "'" + unit.name + "' is not " + formatNumber(unit.mmPerUnit) + " mm" : problem);
            return std::nullopt;
        }
    }
    return unit;
}

void encodeScene(ByteWriter& w, const RecordedScene& s) {
    w.str(s.meshPath);
    w.u64(s.meshHash);
    w.u32(s.vertexCount);
    w.u32(s.triangleCount);
    w.u8(std::uint8_t(s.method));
    encodeParams(w, s.params);
    w.i32(s.octree.maxDepth);
    w.i32(s.octree.leafCapacity);
    w.str(s.presetJson);
}

RecordedScene decodeScene(ByteReader& r, const std::string& field) {
    RecordedScene s;
    s.meshPath = r.str(field + ".meshPath", kMaxPathBytes);
    s.meshHash = r.u64(field + ".meshHash");
    s.vertexCount = r.u32(field + ".vertexCount");
    s.triangleCount = r.u32(field + ".triangleCount");
    const std::uint8_t method = r.u8(field + ".method");
    if (r.ok() && method > std::uint8_t(SlopeRingMethod::Coherent))
        r.fail(field + ".method", "unknown model " + std::to_string(method));
    s.method = r.ok() ? SlopeRingMethod(method) : SlopeRingMethod::Coherent;
    s.params = decodeParams(r, field + ".params");
    s.octree.maxDepth = r.i32(field + ".octree.maxDepth");
    s.octree.leafCapacity = r.i32(field + ".octree.leafCapacity");
    s.presetJson = r.str(field + ".presetJson", kMaxPresetJsonBytes);
    return s;
}

void encodeDevice(ByteWriter& w, const RecordedDevice& d) {
    w.str(d.uri);
    w.str(d.spec.name);
    w.f64(d.spec.maxForceN);
    w.f64(d.spec.maxStiffnessNPerMm);
    w.f64(d.spec.maxDampingNsPerMm);
    w.f64(d.spec.workspaceRadiusMm);
    w.u8(d.spec.actuated ? 1 : 0);
    w.i32(d.spec.buttonCount);
}

RecordedDevice decodeDevice(ByteReader& r, const std::string& field) {
    RecordedDevice d;
    d.uri = r.str(field + ".uri", kMaxPathBytes);
    d.spec.name = r.str(field + ".spec.name", kMaxNameBytes);
    d.spec.maxForceN = r.f64(field + ".spec.maxForceN");
    d.spec.maxStiffnessNPerMm = r.f64(field + ".spec.maxStiffnessNPerMm");
    d.spec.maxDampingNsPerMm = r.f64(field + ".spec.maxDampingNsPerMm");
    d.spec.workspaceRadiusMm = r.f64(field + ".spec.workspaceRadiusMm");
    d.spec.actuated = r.u8(field + ".spec.actuated") != 0;
    d.spec.buttonCount = r.i32(field + ".spec.buttonCount");
    return d;
}

// --- header ---

namespace {

std::string tooLong(const std::string& field, std::size_t bytes, std::size_t limit, const std::string& what) {
    return "header." + field + ": " + what + " is " + std::to_string(bytes) + " bytes; a recording holds at most " +
           std::to_string(limit);
}

}  // namespace

Problems validateRecordingHeader(const RecordingHeader& h) {
    // The same limits decodeRecordingHeader, decodeScene and decodeDevice read with.
    const struct {
        const char* field;
        const std::string& text;
        std::size_t limit;
        const char* what;
    } texts[] = {
        {"engineVersion", h.engineVersion, kMaxNameBytes, "the engine version"},
        {"scene.meshPath", h.scene.meshPath, kMaxPathBytes, "the mesh path"},
        {"scene.presetJson", h.scene.presetJson, kMaxPresetJsonBytes, "the tissue preset (as JSON)"},
        {"device.uri", h.device.uri, kMaxPathBytes, "the device URI"},
        {"device.spec.name", h.device.spec.name, kMaxNameBytes, "the device name"},
        {"note", h.note, kMaxNoteBytes, "the note"},
    };
    for (const auto& t : texts)
        if (t.text.size() > t.limit) return oneProblem(t.field, tooLong(t.field, t.text.size(), t.limit, t.what));
    std::vector<std::uint8_t> bytes;
    encodeRecordingHeader(h, bytes);
    if (bytes.size() - kPreambleBytes - 4 > kMaxHeaderBytes)
        return oneProblem("length",
                          tooLong("length", bytes.size() - kPreambleBytes - 4, kMaxHeaderBytes, "the header"));
    return {};
}

std::uint32_t encodeRecordingHeader(const RecordingHeader& h, std::vector<std::uint8_t>& out) {
    std::vector<std::uint8_t> body;
    ByteWriter b(body);
    b.str(h.engineVersion);
    b.u64(std::uint64_t(h.startUnixUs));
    b.f64(h.rateHz);
    encodeScene(b, h.scene);
    encodeDevice(b, h.device);
    b.f64(h.safety.holdOffThresholdFraction);
    b.f64(h.safety.rampTimeS);
    b.i32(h.safety.staleSampleMaxTicks);
    b.f64(h.safety.staleSampleTimeoutS);
    b.f64(h.safety.maxSampleAgeS);
    b.u8(h.safety.rearmAfterStale ? 1 : 0);
    b.str(h.note);
    encodeContact(b, h.scene.contact);  // format 3
    encodeMeshUnit(b, h.scene.meshUnit);  // format 4
    encodeStiffening(b, h.scene.params);  // format 5

    ByteWriter w(out);
    w.bytes(kRecordingMagic, sizeof(kRecordingMagic));
    w.u8(kRecordingFormatVersion);
    w.u32(std::uint32_t(body.size()));
    w.bytes(body.data(), body.size());
    const std::uint32_t crc = crc32(body.data(), body.size());
    w.u32(crc);
    return crc;
}

std::string decodeRecordingHeader(const std::uint8_t* data, std::size_t size, RecordingHeader& header,
                                  std::size_t& headerBytes) {
    std::string error;
    if (size < sizeof(kRecordingMagic) || std::memcmp(data, kRecordingMagic, sizeof(kRecordingMagic)) != 0) {
        error = "header.magic: not a Palpate recording (expected \"PALPREC\")";
        return error;
    }
    if (size < kPreambleBytes) {
        error = "header.length: truncated (file ends after " + std::to_string(size) + " bytes)";
        return error;
    }
    const std::uint8_t version = data[7];
    if (version < kOldestRecordingFormatVersion || version > kRecordingFormatVersion) {
        error = "header.formatVersion: " + std::to_string(version) + " is not supported (this build reads " +
                std::to_string(kOldestRecordingFormatVersion) + " to " + std::to_string(kRecordingFormatVersion) + ")";
        return error;
    }
    const std::uint32_t length = readU32(data + 8);
    if (length > kMaxHeaderBytes) {
        error = "header.length: " + std::to_string(length) + " bytes exceeds the limit of " +
                std::to_string(kMaxHeaderBytes);
        return error;
    }
    if (size - kPreambleBytes < std::size_t(length) + 4) {
        error = "header.length: " + std::to_string(length) + " bytes run past the end of the file";
        return error;
    }
    const std::uint8_t* body = data + kPreambleBytes;
    if (crc32(body, length) != readU32(body + length)) {
        error = "header.crc: CRC mismatch (the header is damaged)";
        return error;
    }
    ByteReader r(body, length, "header.");
    RecordingHeader h;
    h.engineVersion = r.str("engineVersion", kMaxNameBytes);
    h.startUnixUs = std::int64_t(r.u64("startUnixUs"));
    h.rateHz = r.f64("rateHz");
    if (r.ok() && !hapticRateInRange(h.rateHz))
        r.fail("rateHz", std::to_string(h.rateHz) + " Hz is outside 10..10000");
    h.scene = decodeScene(r, "scene");
    h.device = decodeDevice(r, "device");
    h.safety.holdOffThresholdFraction = r.f64("safety.holdOffThresholdFraction");
    h.safety.rampTimeS = r.f64("safety.rampTimeS");
    h.safety.staleSampleMaxTicks = r.i32("safety.staleSampleMaxTicks");
    h.safety.staleSampleTimeoutS = r.f64("safety.staleSampleTimeoutS");
    h.safety.maxSampleAgeS = r.f64("safety.maxSampleAgeS");
    h.safety.rearmAfterStale = r.u8("safety.rearmAfterStale") != 0;
    h.note = r.str("note", kMaxNoteBytes);
    // Format 3 appends the contact (older files end here: a point tool without friction).
    if (const auto contact = decodeContact(r, "scene.contact")) h.scene.contact = *contact;
    // Format 4 appends the mesh's unit (older files: mm).
    if (const auto unit = decodeMeshUnit(r, "scene.meshUnit")) h.scene.meshUnit = *unit;
    // Format 5 appends the stiffening knots (older files: linear tissue).
    decodeStiffening(r, "scene.params", h.scene.params);
    // Bytes after the known fields are allowed: later minor revisions append fields.
    if (!r.ok()) {
        error = r.error();
        return error;
    }
    // 1 and 2 share every layout; 2 adds an event kind; 3 appends the contact; 4 the mesh's unit
    h.formatVersion = version;
    h.bodyCrc = readU32(body + length);
    header = std::move(h);
    headerBytes = kPreambleBytes + length + 4;
    return {};
}

// --- chunks ---

void encodeChunk(const ChunkHeader& h, const std::uint8_t* payload, std::size_t payloadBytes,
                 std::vector<std::uint8_t>& out) {
    const std::size_t start = out.size();
    ByteWriter w(out);
    w.bytes(kChunkMagic, sizeof(kChunkMagic));
    w.u8(std::uint8_t(h.type));
    w.u8(std::uint8_t(h.headerTag & 0xFFu));
    w.u16(std::uint16_t((h.headerTag >> 8) & 0xFFFFu));
    w.u32(std::uint32_t(payloadBytes));
    w.u64(h.firstTick);
    w.u32(h.count);
    w.u64(h.hash);
    w.u32(crc32(out.data() + start + 4, kChunkHeaderBytes - 8));
    if (payloadBytes > 0) w.bytes(payload, payloadBytes);
    w.u32(crc32(payload, payloadBytes));
}

ChunkStatus parseChunk(const std::uint8_t* data, std::size_t size, std::size_t offset, ChunkHeader& header,
                       const std::uint8_t*& payload) {
    if (offset > size || size - offset < sizeof(kChunkMagic)) return ChunkStatus::Truncated;
    const std::uint8_t* p = data + offset;
    if (std::memcmp(p, kChunkMagic, sizeof(kChunkMagic)) != 0) return ChunkStatus::NoMagic;
    if (size - offset < kChunkHeaderBytes) return ChunkStatus::Truncated;
    if (crc32(p + 4, kChunkHeaderBytes - 8) != readU32(p + kChunkHeaderBytes - 4)) return ChunkStatus::BadHeaderCrc;
    ChunkHeader h;
    const std::uint8_t type = p[4];
    if (type < std::uint8_t(ChunkType::Data) || type > std::uint8_t(ChunkType::End)) return ChunkStatus::BadField;
    h.type = ChunkType(type);
    h.payloadBytes = readU32(p + 8);
    h.firstTick = readU64(p + 12);
    h.count = readU32(p + 20);
    h.hash = readU64(p + 24);
    h.headerTag = std::uint32_t(p[5]) | std::uint32_t(p[6]) << 8 | std::uint32_t(p[7]) << 16;
    if (h.payloadBytes > kMaxChunkPayloadBytes) return ChunkStatus::BadField;
    if (h.firstTick > ~std::uint64_t(0) - h.count) return ChunkStatus::BadField;  // tick range wraps
    // From here the header is trustworthy (its CRC matched): the caller may use it to say which
    // ticks a damaged chunk held and where the next chunk starts.
    header = h;
    if (size - offset - kChunkHeaderBytes < std::size_t(h.payloadBytes) + 4) return ChunkStatus::TruncatedPayload;
    const std::uint8_t* body = p + kChunkHeaderBytes;
    if (crc32(body, h.payloadBytes) != readU32(body + h.payloadBytes)) return ChunkStatus::BadPayloadCrc;
    payload = body;
    return ChunkStatus::Ok;
}

std::size_t findChunkMagic(const std::uint8_t* data, std::size_t size, std::size_t from) {
    if (size < sizeof(kChunkMagic)) return size;
    for (std::size_t i = from; i + sizeof(kChunkMagic) <= size; ++i) {
        const void* hit = std::memchr(data + i, kChunkMagic[0], size - sizeof(kChunkMagic) + 1 - i);
        if (!hit) return size;
        i = std::size_t(static_cast<const std::uint8_t*>(hit) - data);
        if (std::memcmp(data + i, kChunkMagic, sizeof(kChunkMagic)) == 0) return i;
    }
    return size;
}

}  // namespace palpate
