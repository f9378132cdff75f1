#pragma once
// Little-endian fields for the recording format: a writer that appends to a reused buffer, and a
// bounded reader that never reads past its span and remembers the first field it failed on, so
// that a damaged header is reported by name ("header.meshPath: ...").

#include "engine/record/Varint.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace palpate {

class ByteWriter {
public:
    explicit ByteWriter(std::vector<std::uint8_t>& out) : mOut(out) {}
    void u8(std::uint8_t v) { mOut.push_back(v); }
    void u16(std::uint16_t v) { fixed(v, 2); }
    void u32(std::uint32_t v) { fixed(v, 4); }
    void u64(std::uint64_t v) { fixed(v, 8); }
    void i32(std::int32_t v) { fixed(std::uint32_t(v), 4); }
    void f64(double v) {
        std::uint64_t bits;
        std::memcpy(&bits, &v, 8);
        fixed(bits, 8);
    }
    void varint(std::uint64_t v) {
        std::uint8_t buffer[kMaxVarintBytes];
        const std::size_t n = putVarint(buffer, v);
        mOut.insert(mOut.end(), buffer, buffer + n);
    }
    void svarint(std::int64_t v) { varint(zigzagEncode(v)); }
    /// Length (varint) then bytes.
    void str(std::string_view s) {
        varint(s.size());
        mOut.insert(mOut.end(), s.begin(), s.end());
    }
    void bytes(const void* data, std::size_t size) {
        const auto* p = static_cast<const std::uint8_t*>(data);
        mOut.insert(mOut.end(), p, p + size);
    }
    std::size_t size() const { return mOut.size(); }
    /// Overwrites 4 bytes at `offset` (a length or CRC known only later).
    void patchU32(std::size_t offset, std::uint32_t v) {
        for (int i = 0; i < 4; ++i) mOut[offset + std::size_t(i)] = std::uint8_t(v >> (8 * i));
    }

private:
    void fixed(std::uint64_t v, int bytes) {
        for (int i = 0; i < bytes; ++i) mOut.push_back(std::uint8_t(v >> (8 * i)));
    }
    std::vector<std::uint8_t>& mOut;
};

/// Reads fields in order; after the first failure every read fails and error() names that field.
class ByteReader {
public:
    ByteReader(const std::uint8_t* data, std::size_t size, std::string context = {})
        : mCursor(data), mEnd(data + size), mContext(std::move(context)) {}

    bool ok() const { return mError.empty(); }
    const std::string& error() const { return mError; }
    std::size_t remaining() const { return std::size_t(mEnd - mCursor); }
    const std::uint8_t* cursor() const { return mCursor; }
    /// Records a failure of the caller's own check (a value out of range) under `field`.
    void fail(std::string_view field, std::string_view why) {
        if (mError.empty()) mError = mContext + std::string(field) + ": " + std::string(why);
    }

    std::uint8_t u8(std::string_view field) { return std::uint8_t(fixed(field, 1)); }
    std::uint16_t u16(std::string_view field) { return std::uint16_t(fixed(field, 2)); }
    std::uint32_t u32(std::string_view field) { return std::uint32_t(fixed(field, 4)); }
    std::uint64_t u64(std::string_view field) { return fixed(field, 8); }
    std::int32_t i32(std::string_view field) { return std::int32_t(std::uint32_t(fixed(field, 4))); }
    double f64(std::string_view field) {
        const std::uint64_t bits = fixed(field, 8);
        double v;
        std::memcpy(&v, &bits, 8);
        return v;
    }
    std::uint64_t varint(std::string_view field) {
        std::uint64_t v = 0;
        if (!ok()) return 0;
        if (!getVarint(&mCursor, mEnd, v)) fail(field, "truncated or malformed varint");
        return ok() ? v : 0;
    }
    std::int64_t svarint(std::string_view field) { return zigzagDecode(varint(field)); }
    /// A length-prefixed string of at most maxBytes (and never more than what is left).
    std::string str(std::string_view field, std::size_t maxBytes) {
        const std::uint64_t n = varint(field);
        if (!ok()) return {};
        if (n > maxBytes) {
            fail(field, "length " + std::to_string(n) + " exceeds the limit of " + std::to_string(maxBytes) + " bytes");
            return {};
        }
        if (n > remaining()) {
            fail(field, "length " + std::to_string(n) + " runs past the end (" + std::to_string(remaining()) +
                            " bytes left)");
            return {};
        }
        std::string s(reinterpret_cast<const char*>(mCursor), std::size_t(n));
        mCursor += n;
        return s;
    }
    /// Skips n bytes (an event payload of an unknown kind).
    void skip(std::string_view field, std::uint64_t n) {
        if (!ok()) return;
        if (n > remaining()) {
            fail(field, "runs past the end");
            return;
        }
        mCursor += n;
    }

private:
    std::uint64_t fixed(std::string_view field, int bytes) {
        if (!ok()) return 0;
        if (remaining() < std::size_t(bytes)) {
            fail(field, "truncated");
            return 0;
        }
        std::uint64_t v = 0;
        for (int i = 0; i < bytes; ++i) v |= std::uint64_t(mCursor[i]) << (8 * i);
        mCursor += bytes;
        return v;
    }

    const std::uint8_t* mCursor;
    const std::uint8_t* mEnd;
    std::string mContext;
    std::string mError;
};

}  // namespace palpate
