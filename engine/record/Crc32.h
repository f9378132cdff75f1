#pragma once
// CRC-32/ISO-HDLC (the zlib/PNG/Ethernet CRC: reflected polynomial 0xEDB88320, initial value and
// final XOR 0xFFFFFFFF), table driven. Every chunk of a recording carries one, so that a reader can
// tell an intact chunk from a damaged one without a zlib dependency.

#include <cstddef>
#include <cstdint>

namespace palpate {

/// CRC of `size` bytes. Check value: crc32("123456789", 9) == 0xCBF43926.
std::uint32_t crc32(const void* data, std::size_t size);

/// Continues a CRC over more bytes: crc32Update(crc32(a), b) == crc32(a followed by b).
std::uint32_t crc32Update(std::uint32_t crc, const void* data, std::size_t size);

}  // namespace palpate
