// The recording's building blocks: CRC-32, varints, the header, chunks, the tick codec, mesh hash.
#include "engine/core/MeshGenerator.h"
#include "engine/record/ByteIo.h"
#include "engine/record/Crc32.h"
#include "engine/core/MeshHash.h"
#include "engine/record/RecordingFormat.h"
#include "engine/record/TickCodec.h"
#include "engine/record/Varint.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

using namespace palpate;

namespace {

RecordingHeader sampleHeader() {
    RecordingHeader h;
    h.startUnixUs = 1700000000123456;
    h.rateHz = 2000.0;
    h.scene.meshPath = "/data/meshes/stomach 3970.off";
    h.scene.meshHash = 0x0123456789abcdefull;
    h.scene.vertexCount = 3970;
    h.scene.triangleCount = 7936;
    h.scene.method = SlopeRingMethod::Proposed;
    h.scene.params.ringCount = 3;
    h.scene.params.contactStiffnessNPerMm = 0.8125;
    h.scene.octree.maxDepth = 7;
    h.scene.presetJson = "{\"name\": \"liver\"}";
    h.device.uri = "sim:path:/tmp/a:b.csv";
    h.device.spec.name = "Phantom";
    h.device.spec.maxForceN = 3.3;
    h.device.spec.buttonCount = 2;
    h.device.spec.actuated = true;
    h.safety.rampTimeS = 0.25;
    h.safety.staleSampleMaxTicks = 7;
    h.note = "trainee 12, exercise 'palpate the nodule'";
    return h;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool sameBits(const glm::vec3& a, const glm::vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST(RecordFormat, Crc32MatchesTheStandardCheckValue) {
    EXPECT_EQ(crc32("123456789", 9), 0xCBF43926u);
    EXPECT_EQ(crc32("", 0), 0u);
    EXPECT_EQ(crc32Update(crc32("1234", 4), "56789", 5), 0xCBF43926u);
    EXPECT_EQ(crc32("The quick brown fox jumps over the lazy dog", 43), 0x414FA339u);
}

TEST(RecordFormat, VarintsRoundTripAndRejectMalformedInput) {
    const std::uint64_t values[] = {0, 1, 127, 128, 300, 16383, 16384, 0xFFFFFFFFull, 1ull << 63,
                                    std::numeric_limits<std::uint64_t>::max()};
    for (std::uint64_t v : values) {
        std::uint8_t buffer[kMaxVarintBytes];
        const std::size_t n = putVarint(buffer, v);
        const std::uint8_t* cursor = buffer;
        std::uint64_t back = 0;
        ASSERT_TRUE(getVarint(&cursor, buffer + n, back));
        EXPECT_EQ(back, v);
        EXPECT_EQ(cursor, buffer + n);
        // Cut short: never reads past the end.
        if (n > 1) {
            cursor = buffer;
            EXPECT_FALSE(getVarint(&cursor, buffer + n - 1, back));
            EXPECT_EQ(cursor, buffer);
        }
    }
    const std::uint8_t tooLong[11] = {0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x01};
    const std::uint8_t* cursor = tooLong;
    std::uint64_t v = 0;
    EXPECT_FALSE(getVarint(&cursor, tooLong + 11, v));
    const std::uint8_t overflow[10] = {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x02};
    cursor = overflow;
    EXPECT_FALSE(getVarint(&cursor, overflow + 10, v));
    for (std::int64_t s : {std::int64_t(0), std::int64_t(-1), std::int64_t(1), std::int64_t(-64), std::int64_t(63),
                           std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max()})
        EXPECT_EQ(zigzagDecode(zigzagEncode(s)), s);
    EXPECT_EQ(zigzagEncode(-1), 1u);
    EXPECT_EQ(zigzagEncode(1), 2u);
}

TEST(RecordFormat, StiffeningKnotsRoundTripAndOlderHeadersHaveNone) {
    RecordingHeader h = sampleHeader();
    h.scene.params.stiffeningKnots = 2;
    h.scene.params.stiffeningForceN[0] = 0.4;
    h.scene.params.stiffeningCompliance[0] = 0.5;
    h.scene.params.stiffeningForceN[1] = 1.25;
    h.scene.params.stiffeningCompliance[1] = 0.2;
    std::vector<std::uint8_t> bytes;
    encodeRecordingHeader(h, bytes);
    RecordingHeader back;
    std::size_t headerBytes = 0;
    std::string error;
    ASSERT_TRUE((error = decodeRecordingHeader(bytes.data(), bytes.size(), back, headerBytes)).empty()) << error;
    EXPECT_EQ(back.scene.params.stiffeningKnots, 2);
    EXPECT_EQ(back.scene.params.stiffeningForceN[1], 1.25);
    EXPECT_EQ(back.scene.params.stiffeningCompliance[1], 0.2);
    // A count out of range is refused, naming the field.
    std::vector<std::uint8_t> tail;
    ByteWriter w(tail);
    encodeStiffening(w, h.scene.params);
    SlopeRingParams p;
    tail[0] = 9;
    ByteReader refused(tail.data(), tail.size(), "");
    decodeStiffening(refused, "scene.params", p);
    EXPECT_FALSE(refused.ok());
    EXPECT_NE(refused.error().find("stiffeningKnots"), std::string::npos) << refused.error();
    // Nothing left to read (a format-4 header): no knots, linear tissue.
    ByteReader empty(tail.data(), 0, "");
    SlopeRingParams linear;
    decodeStiffening(empty, "scene.params", linear);
    EXPECT_TRUE(empty.ok());
    EXPECT_EQ(linear.stiffeningKnots, 0);
}

TEST(RecordFormat, HeaderRoundTripsEveryField) {
    const RecordingHeader h = sampleHeader();
    std::vector<std::uint8_t> bytes;
    encodeRecordingHeader(h, bytes);
    ASSERT_EQ(std::memcmp(bytes.data(), "PALPREC", 7), 0);
    EXPECT_EQ(bytes[7], kRecordingFormatVersion);
    RecordingHeader back;
    std::size_t headerBytes = 0;
    std::string error;
    ASSERT_TRUE((error = decodeRecordingHeader(bytes.data(), bytes.size(), back, headerBytes)).empty()) << error;
    EXPECT_EQ(headerBytes, bytes.size());
    EXPECT_EQ(back.engineVersion, h.engineVersion);
    EXPECT_FALSE(back.engineVersion.empty());
    EXPECT_EQ(back.startUnixUs, h.startUnixUs);
    EXPECT_EQ(back.rateHz, h.rateHz);
    EXPECT_EQ(back.scene.meshPath, h.scene.meshPath);
    EXPECT_EQ(back.scene.meshHash, h.scene.meshHash);
    EXPECT_EQ(back.scene.vertexCount, h.scene.vertexCount);
    EXPECT_EQ(back.scene.triangleCount, h.scene.triangleCount);
    EXPECT_EQ(back.scene.method, h.scene.method);
    EXPECT_EQ(back.scene.params.ringCount, 3);
    EXPECT_EQ(back.scene.params.contactStiffnessNPerMm, 0.8125);
    EXPECT_EQ(back.scene.params.slopeMagnitudeMmPerN, h.scene.params.slopeMagnitudeMmPerN);
    EXPECT_EQ(back.scene.octree.maxDepth, 7);
    EXPECT_EQ(back.scene.presetJson, h.scene.presetJson);
    EXPECT_EQ(back.device.uri, h.device.uri);
    EXPECT_EQ(back.device.spec.name, "Phantom");
    EXPECT_EQ(back.device.spec.maxForceN, 3.3);
    EXPECT_EQ(back.device.spec.buttonCount, 2);
    EXPECT_TRUE(back.device.spec.actuated);
    EXPECT_EQ(back.safety.rampTimeS, 0.25);
    EXPECT_EQ(back.safety.staleSampleMaxTicks, 7);
    EXPECT_EQ(back.note, h.note);
}

TEST(RecordFormat, HeaderErrorsNameTheField) {
    std::vector<std::uint8_t> good;
    encodeRecordingHeader(sampleHeader(), good);
    auto decode = [](const std::vector<std::uint8_t>& bytes) {
        RecordingHeader h;
        std::size_t n = 0;
        std::string error;
        EXPECT_FALSE((error = decodeRecordingHeader(bytes.data(), bytes.size(), h, n)).empty());
        return error;
    };
    std::vector<std::uint8_t> bad = good;
    bad[0] = 'X';
    EXPECT_NE(decode(bad).find("header.magic"), std::string::npos);
    bad = good;
    bad[7] = 99;
    EXPECT_NE(decode(bad).find("header.formatVersion"), std::string::npos);
    bad = good;
    bad[11] = 0x7F;  // length ~2 GB
    EXPECT_NE(decode(bad).find("header.length"), std::string::npos);
    EXPECT_NE(decode({good.begin(), good.begin() + 40}).find("header.length"), std::string::npos);
    bad = good;
    bad[30] ^= 0x10;
    EXPECT_NE(decode(bad).find("header.crc"), std::string::npos);

    // A field that is wrong under a valid CRC: the message names it.
    RecordingHeader slow = sampleHeader();
    slow.rateHz = 5.0;
    bad.clear();
    encodeRecordingHeader(slow, bad);
    EXPECT_NE(decode(bad).find("header.rateHz"), std::string::npos) << decode(bad);
    RecordingHeader rings = sampleHeader();
    rings.scene.params.ringCount = 42;
    bad.clear();
    encodeRecordingHeader(rings, bad);
    EXPECT_NE(decode(bad).find("header.scene.params.ringCount"), std::string::npos) << decode(bad);
    // A string whose length runs past the body (rebuilt with a matching CRC).
    std::vector<std::uint8_t> body;
    body.reserve(64);  // (GCC 12 warns a false -Wstringop-overflow on the growth path)
    ByteWriter w(body);
    w.str("0.1.0");
    w.u64(0);
    w.f64(1000.0);
    w.varint(1u << 30);  // scene.meshPath length
    std::vector<std::uint8_t> file(kRecordingMagic, kRecordingMagic + 7);
    ByteWriter f(file);
    f.u8(kRecordingFormatVersion);
    f.u32(std::uint32_t(body.size()));
    f.bytes(body.data(), body.size());
    f.u32(crc32(body.data(), body.size()));
    EXPECT_NE(decode(file).find("header.scene.meshPath"), std::string::npos) << decode(file);
}

TEST(RecordFormat, ChunksCarryTwoCrcsAndResyncFindsTheMagic) {
    std::vector<std::uint8_t> payload = {1, 2, 3, 4, 5, 'P', 'C', 'H', 'K', 9};
    ChunkHeader h;
    h.type = ChunkType::Data;
    h.firstTick = 123456789012ull;
    h.count = 7;
    h.hash = 0xfeedfacecafebeefull;
    std::vector<std::uint8_t> bytes = {0xAA, 0xBB};
    encodeChunk(h, payload.data(), payload.size(), bytes);
    ASSERT_EQ(bytes.size(), 2 + kChunkOverheadBytes + payload.size());
    ChunkHeader back;
    const std::uint8_t* p = nullptr;
    ASSERT_EQ(parseChunk(bytes.data(), bytes.size(), 2, back, p), ChunkStatus::Ok);
    EXPECT_EQ(back.firstTick, h.firstTick);
    EXPECT_EQ(back.count, 7u);
    EXPECT_EQ(back.hash, h.hash);
    EXPECT_EQ(back.payloadBytes, payload.size());
    EXPECT_EQ(std::memcmp(p, payload.data(), payload.size()), 0);
    EXPECT_EQ(parseChunk(bytes.data(), bytes.size(), 0, back, p), ChunkStatus::NoMagic);
    EXPECT_EQ(findChunkMagic(bytes.data(), bytes.size(), 0), 2u);
    EXPECT_EQ(findChunkMagic(bytes.data(), bytes.size(), 3), 2 + kChunkHeaderBytes + 5);  // the one in the payload
    EXPECT_EQ(findChunkMagic(bytes.data(), bytes.size(), 2 + kChunkHeaderBytes + 6), bytes.size());

    auto flipped = bytes;
    flipped[2 + 14] ^= 1;  // first tick
    EXPECT_EQ(parseChunk(flipped.data(), flipped.size(), 2, back, p), ChunkStatus::BadHeaderCrc);
    flipped = bytes;
    flipped[2 + kChunkHeaderBytes + 1] ^= 0x40;
    EXPECT_EQ(parseChunk(flipped.data(), flipped.size(), 2, back, p), ChunkStatus::BadPayloadCrc);
    EXPECT_EQ(back.count, 7u);  // the header survived and says what was lost
    EXPECT_EQ(parseChunk(bytes.data(), bytes.size() - 1, 2, back, p), ChunkStatus::TruncatedPayload);
    EXPECT_EQ(parseChunk(bytes.data(), 20, 2, back, p), ChunkStatus::Truncated);
}

TEST(RecordFormat, TickCodecIsLosslessOnEveryBitPattern) {
    std::mt19937_64 rng(11);
    std::vector<RecordedTick> ticks;
    const float specials[] = {0.0f, -0.0f, std::numeric_limits<float>::infinity(), -1e-38f, 1e38f,
                              std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::denorm_min()};
    for (int i = 0; i < 2000; ++i) {
        RecordedTick t;
        t.tick = 1000 + std::uint64_t(i);
        t.nowS = i % 97 == 0 ? double(rng()) : 0.001 * double(i + 1) + 1e-12 * double(rng() % 5);
        t.readOk = rng() % 7 != 0;
        t.sample.sequence = i % 50 == 0 ? rng() : std::uint64_t(i);
        t.sample.timeS = rng() % 3 == 0 ? t.nowS : t.nowS - 0.0003;
        t.sample.positionMm = glm::vec3(50.0f + 0.01f * float(i), std::sin(0.01f * float(i)), -0.0f);
        if (i % 13 == 0) t.sample.positionMm.y = specials[rng() % std::size(specials)];
        t.sample.buttons = (i / 100) % 3 == 0 ? 0u : std::uint32_t(rng());
        t.forceN = glm::vec3(0.1f * std::cos(0.02f * float(i)), 0.0f, 2.0f);
        if (i % 11 == 0) t.forceN.z = specials[rng() % std::size(specials)];
        t.touched = i % 17 == 0 ? kNoVertex : std::uint32_t(rng() % 5000);
        t.deviceState = DeviceState(rng() % 5);
        t.tickOverran = rng() % 5 == 0;
        t.paused = rng() % 9 == 0;
        t.contact = rng() % 2 == 0;
        ticks.push_back(t);
    }
    std::vector<std::uint8_t> bytes;
    TickEncoder encoder;
    for (const auto& t : ticks) encoder.encode(t, bytes);
    TickDecoder decoder;
    const std::uint8_t* cursor = bytes.data();
    for (std::size_t i = 0; i < ticks.size(); ++i) {
        const RecordedTick& want = ticks[i];
        RecordedTick got;
        ASSERT_TRUE(decoder.decode(&cursor, bytes.data() + bytes.size(), want.tick, got)) << i;
        EXPECT_EQ(got.tick, want.tick);
        EXPECT_TRUE(sameBits(got.nowS, want.nowS)) << i;
        EXPECT_EQ(got.readOk, want.readOk);
        if (want.readOk) {
            EXPECT_EQ(got.sample.sequence, want.sample.sequence) << i;
            EXPECT_TRUE(sameBits(got.sample.timeS, want.sample.timeS)) << i;
            EXPECT_TRUE(sameBits(got.sample.positionMm, want.sample.positionMm)) << i;
            EXPECT_EQ(got.sample.buttons, want.sample.buttons) << i;
        }
        EXPECT_TRUE(sameBits(got.forceN, want.forceN)) << i;
        EXPECT_EQ(got.touched, want.touched);
        EXPECT_EQ(got.deviceState, want.deviceState);
        EXPECT_EQ(got.tickOverran, want.tickOverran);
        EXPECT_EQ(got.paused, want.paused);
        EXPECT_EQ(got.contact, want.contact);
    }
    EXPECT_EQ(cursor, bytes.data() + bytes.size());
    // Truncated input fails instead of reading on.
    TickDecoder again;
    cursor = bytes.data();
    RecordedTick t;
    const std::uint8_t* end = bytes.data() + 5;
    bool failed = false;
    for (int i = 0; i < 10 && !failed; ++i) failed = !again.decode(&cursor, end, 0, t);
    EXPECT_TRUE(failed);
    EXPECT_LE(cursor, end);
}

TEST(RecordFormat, SessionHashStepIsTheLoopsFnv) {
    std::uint64_t h = kHashSeed;
    hashTick(h, glm::vec3(0.0f), kNoVertex);
    // FNV-1a over 12 zero bytes then ff ff ff ff, computed independently.
    std::uint64_t want = 1469598103934665603ull;
    const unsigned char bytes[16] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0xff, 0xff, 0xff, 0xff};
    for (unsigned char b : bytes) {
        want ^= b;
        want *= 1099511628211ull;
    }
    EXPECT_EQ(h, want);
}

TEST(RecordFormat, MeshHashSeesPositionsAndFaces) {
    auto a = generateMesh(GeneratedShape::Sphere, 200);
    auto b = generateMesh(GeneratedShape::Sphere, 200);
    auto c = generateMesh(GeneratedShape::Sphere, 202);
    auto d = generateMesh(GeneratedShape::Stomach, 200);
    ASSERT_TRUE(a.mesh && b.mesh && c.mesh && d.mesh);
    EXPECT_EQ(meshHash(*a.mesh), meshHash(*b.mesh));
    EXPECT_NE(meshHash(*a.mesh), meshHash(*c.mesh));
    EXPECT_NE(meshHash(*a.mesh), meshHash(*d.mesh));
    auto positions = a.mesh->restPositionsMm();
    positions[17].x = std::nextafter(positions[17].x, 1e9f);
    auto moved = TissueMesh::fromTriangles(positions, a.mesh->triangles(), "moved", false);
    ASSERT_TRUE(moved.mesh);
    EXPECT_NE(meshHash(*moved.mesh), meshHash(*a.mesh));
}
