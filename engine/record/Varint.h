#pragma once
// Variable-length integers for the recording's tick stream: LEB128 (7 bits per byte, low first,
// high bit = more) and zigzag (small negative numbers stay short). Most of a tick's fields are the
// difference between a value and its prediction, so they are near zero and take one byte.

#include <cstddef>
#include <cstdint>

namespace palpate {

/// The longest LEB128 encoding of a 64-bit value.
inline constexpr std::size_t kMaxVarintBytes = 10;

constexpr std::uint64_t zigzagEncode(std::int64_t v) {
    return (std::uint64_t(v) << 1) ^ std::uint64_t(v >> 63);
}
constexpr std::int64_t zigzagDecode(std::uint64_t u) {
    return std::int64_t(u >> 1) ^ -std::int64_t(u & 1u);
}

/// Writes `value` at `out` (room for kMaxVarintBytes); returns the bytes written.
inline std::size_t putVarint(std::uint8_t* out, std::uint64_t value) {
    std::size_t n = 0;
    while (value >= 0x80u) {
        out[n++] = std::uint8_t(value | 0x80u);
        value >>= 7;
    }
    out[n++] = std::uint8_t(value);
    return n;
}

/// Reads a varint from [*cursor, end). False (cursor unchanged) when it runs past the end or is
/// longer than 10 bytes or overflows 64 bits: garbage never reads out of bounds.
inline bool getVarint(const std::uint8_t** cursor, const std::uint8_t* end, std::uint64_t& value) {
    const std::uint8_t* p = *cursor;
    std::uint64_t result = 0;
    for (unsigned shift = 0; shift < 64; shift += 7) {
        if (p == end) return false;
        const std::uint8_t byte = *p++;
        if (shift == 63 && byte > 1u) return false;  // bits beyond 64
        result |= std::uint64_t(byte & 0x7Fu) << shift;
        if ((byte & 0x80u) == 0) {
            *cursor = p;
            value = result;
            return true;
        }
    }
    return false;
}

}  // namespace palpate
