// libFuzzer target for the recording reader: any bytes, no crash, no unbounded allocation, and the
// reader's own invariants hold. Built as `fuzz_reader` by the `fuzz` CMake preset (clang,
// -fsanitize=fuzzer,address,undefined); the same function runs over tests/record/corpus and a few
// thousand deterministic mutations in record_tests.
#include "engine/record/Crc32.h"
#include "engine/record/RecordingReader.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

// An invariant that fails is a bug the fuzzer found: say which, then crash so that it keeps the input.
#define check(condition)                                                                        \
    do {                                                                                        \
        if (!(condition)) {                                                                     \
            std::fprintf(stderr, "fuzz_reader: invariant failed: %s (line %d)\n", #condition, __LINE__); \
            std::abort();                                                                       \
        }                                                                                       \
    } while (0)

/// Rewrites every CRC that can be located (the header's, and each chunk's two) to match the bytes,
/// so that mutated payloads get past the CRCs and reach the decoders.
void fixRecordingCrcs(std::uint8_t* data, std::size_t size) {
    using namespace palpate;
    auto put32 = [](std::uint8_t* p, std::uint32_t v) {
        for (int i = 0; i < 4; ++i) p[i] = std::uint8_t(v >> (8 * i));
    };
    auto get32 = [](const std::uint8_t* p) {
        return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
    };
    if (size >= kPreambleBytes && std::memcmp(data, kRecordingMagic, 7) == 0) {
        const std::uint32_t length = get32(data + 8);
        if (length <= size - kPreambleBytes && size - kPreambleBytes - length >= 4)
            put32(data + kPreambleBytes + length, crc32(data + kPreambleBytes, length));
    }
    for (std::size_t at = findChunkMagic(data, size, 0); at < size; at = findChunkMagic(data, size, at + 1)) {
        if (size - at < kChunkHeaderBytes) break;
        std::uint8_t* chunk = data + at;
        put32(chunk + kChunkHeaderBytes - 4, crc32(chunk + 4, kChunkHeaderBytes - 8));
        const std::uint32_t length = get32(chunk + 8);
        if (length <= size - at - kChunkHeaderBytes && size - at - kChunkHeaderBytes - length >= 4)
            put32(chunk + kChunkHeaderBytes + length, crc32(chunk + kChunkHeaderBytes, length));
    }
}

#ifdef PALPATE_FUZZ_TARGET
extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t maxSize);

/// libFuzzer's own mutation, then, half of the time, CRCs made right again.
extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t maxSize,
                                               unsigned int seed) {
    size = LLVMFuzzerMutate(data, size, maxSize);
    if (seed % 2 == 0) fixRecordingCrcs(data, size);
    return size;
}
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace palpate;
    const RecordingReader reader = RecordingReader::fromBytes(std::vector<std::uint8_t>(data, data + size), "fuzz");
    const RecordingSummary& s = reader.summary();
    check(s.fileBytes == size);
    check(!s.intact || (s.headerOk && s.closedCleanly && reader.damage().empty()));
    check(s.chunks == reader.chunks().size());
    check(s.events == reader.events().size());

    // Chunks do not overlap each other or the damage, and lie inside the file.
    std::uint64_t covered = 0, ticks = 0;
    for (const ChunkInfo& c : reader.chunks()) {
        check(c.offset + c.bytes <= size);
        covered += c.bytes;
        if (c.type == ChunkType::Data) ticks += c.count;
    }
    for (const DamagedRegion& d : reader.damage()) {
        check(d.offset + d.bytes <= size);
        covered += d.bytes;
    }
    check(covered <= size);
    check(ticks == s.ticks);

    // Every chunk the scan accepted decodes again, to the same number of ticks.
    std::vector<RecordedTick> decoded;
    std::uint64_t again = 0;
    for (std::size_t i = 0; i < reader.chunks().size(); ++i) {
        check(reader.decodeChunk(i, decoded));
        if (reader.chunks()[i].type == ChunkType::Data) check(decoded.size() == reader.chunks()[i].count);
        again += decoded.size();
    }
    check(again == s.ticks);
    for (std::size_t i = 1; i < reader.events().size(); ++i) check(reader.events()[i - 1].tick <= reader.events()[i].tick);
    if (s.ticks > 0) {
        const auto first = reader.tickAt(s.firstTick);
        check(first.has_value() && first->tick == s.firstTick);
        check(reader.tickAt(s.lastTick).has_value());
    }
    return 0;
}
