#include "engine/record/TickCodec.h"

#include "engine/record/Varint.h"

#include <cstring>

namespace palpate {

namespace {

enum TickFlag : std::uint32_t {
    kReadOk = 1u << 0,
    kTimeIsNow = 1u << 1,  ///< the sample is stamped with the tick's clock (simulated devices)
    kContact = 1u << 2,
    kOverran = 1u << 3,
    kPaused = 1u << 4,
    kButtonsChanged = 1u << 5,
    kStateChanged = 1u << 6,
    kKnownFlags = (1u << 7) - 1,
};

std::uint64_t bits64(double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, 8);
    return b;
}
double fromBits64(std::uint64_t b) {
    double v;
    std::memcpy(&v, &b, 8);
    return v;
}
std::uint32_t bits32(float v) {
    std::uint32_t b;
    std::memcpy(&b, &v, 4);
    return b;
}
float fromBits32(std::uint32_t b) {
    float v;
    std::memcpy(&v, &b, 4);
    return v;
}

// Second-order prediction in wrapping unsigned arithmetic: within one binade the bit pattern is
// linear in the value, so a steadily moving value leaves a residual near zero.
std::uint64_t predict64(const std::uint64_t h[2], int n) { return n == 0 ? 0 : n == 1 ? h[0] : 2 * h[0] - h[1]; }
std::uint32_t predict32(std::uint32_t h0, std::uint32_t h1, int n) {
    return n == 0 ? 0u : n == 1 ? h0 : std::uint32_t(2u * h0 - h1);
}
void push64(std::uint64_t h[2], std::uint64_t v) {
    h[1] = h[0];
    h[0] = v;
}

void putV(std::vector<std::uint8_t>& out, std::uint64_t v) {
    std::uint8_t buffer[kMaxVarintBytes];
    const std::size_t n = putVarint(buffer, v);
    out.insert(out.end(), buffer, buffer + n);
}
void putResidual64(std::vector<std::uint8_t>& out, std::uint64_t actual, std::uint64_t predicted) {
    putV(out, zigzagEncode(std::int64_t(actual - predicted)));
}
void putResidual32(std::vector<std::uint8_t>& out, std::uint32_t actual, std::uint32_t predicted) {
    putV(out, zigzagEncode(std::int32_t(actual - predicted)));
}

void encodeVec3(std::vector<std::uint8_t>& out, std::uint32_t history[2][3], int n, const glm::vec3& v) {
    const std::uint32_t b[3] = {bits32(v.x), bits32(v.y), bits32(v.z)};
    for (int k = 0; k < 3; ++k) {
        putResidual32(out, b[k], predict32(history[0][k], history[1][k], n));
        history[1][k] = history[0][k];
        history[0][k] = b[k];
    }
}

bool decodeVec3(const std::uint8_t** cursor, const std::uint8_t* end, std::uint32_t history[2][3], int n,
                glm::vec3& v) {
    std::uint32_t b[3];
    for (int k = 0; k < 3; ++k) {
        std::uint64_t u;
        if (!getVarint(cursor, end, u)) return false;
        const std::int64_t residual = zigzagDecode(u);
        b[k] = std::uint32_t(predict32(history[0][k], history[1][k], n) + std::uint32_t(residual));
        history[1][k] = history[0][k];
        history[0][k] = b[k];
    }
    v = glm::vec3(fromBits32(b[0]), fromBits32(b[1]), fromBits32(b[2]));
    return true;
}

}  // namespace

void TickEncoder::encode(const RecordedTick& t, std::vector<std::uint8_t>& out) {
    const std::uint64_t nowBits = bits64(t.nowS);
    const std::uint64_t timeBits = bits64(t.sample.timeS);
    const auto state = std::uint8_t(t.deviceState);
    std::uint32_t flags = 0;
    if (t.readOk) flags |= kReadOk;
    if (t.readOk && timeBits == nowBits) flags |= kTimeIsNow;
    if (t.contact) flags |= kContact;
    if (t.tickOverran) flags |= kOverran;
    if (t.paused) flags |= kPaused;
    if (t.readOk && t.sample.buttons != mP.buttons) flags |= kButtonsChanged;
    if (state != mP.state) flags |= kStateChanged;
    putV(out, flags);
    if (flags & kStateChanged) {
        out.push_back(state);
        mP.state = state;
    }
    putResidual64(out, nowBits, predict64(mP.now, mP.ticks));
    push64(mP.now, nowBits);
    if (t.readOk) {
        putResidual64(out, t.sample.sequence, mP.sequence + 1);
        mP.sequence = t.sample.sequence;
        if (!(flags & kTimeIsNow)) {
            putResidual64(out, timeBits, predict64(mP.time, mP.times));
            push64(mP.time, timeBits);
            ++mP.times;
        }
        encodeVec3(out, mP.pos, mP.positions, t.sample.positionMm);
        ++mP.positions;
        if (flags & kButtonsChanged) {
            putV(out, t.sample.buttons);
            mP.buttons = t.sample.buttons;
        }
    }
    encodeVec3(out, mP.force, mP.ticks, t.forceN);
    putV(out, zigzagEncode(std::int64_t(t.touched) - std::int64_t(mP.touched)));
    mP.touched = t.touched;
    ++mP.ticks;
}

bool TickDecoder::decode(const std::uint8_t** cursor, const std::uint8_t* end, std::uint64_t tickIndex,
                         RecordedTick& t) {
    std::uint64_t u = 0;
    if (!getVarint(cursor, end, u) || (u & ~std::uint64_t(kKnownFlags)) != 0) return false;
    const auto flags = std::uint32_t(u);
    t = RecordedTick{};
    t.tick = tickIndex;
    t.readOk = flags & kReadOk;
    t.contact = flags & kContact;
    t.tickOverran = flags & kOverran;
    t.paused = flags & kPaused;
    if (!t.readOk && (flags & (kTimeIsNow | kButtonsChanged))) return false;
    if (flags & kStateChanged) {
        if (*cursor == end || **cursor > std::uint8_t(DeviceState::Fault)) return false;
        mP.state = *(*cursor)++;
    }
    t.deviceState = DeviceState(mP.state);
    if (!getVarint(cursor, end, u)) return false;
    const std::uint64_t nowBits = predict64(mP.now, mP.ticks) + std::uint64_t(zigzagDecode(u));
    push64(mP.now, nowBits);
    t.nowS = fromBits64(nowBits);
    if (t.readOk) {
        if (!getVarint(cursor, end, u)) return false;
        mP.sequence = mP.sequence + 1 + std::uint64_t(zigzagDecode(u));
        t.sample.sequence = mP.sequence;
        if (flags & kTimeIsNow) {
            t.sample.timeS = t.nowS;
        } else {
            if (!getVarint(cursor, end, u)) return false;
            const std::uint64_t timeBits = predict64(mP.time, mP.times) + std::uint64_t(zigzagDecode(u));
            push64(mP.time, timeBits);
            ++mP.times;
            t.sample.timeS = fromBits64(timeBits);
        }
        if (!decodeVec3(cursor, end, mP.pos, mP.positions, t.sample.positionMm)) return false;
        ++mP.positions;
        if (flags & kButtonsChanged) {
            if (!getVarint(cursor, end, u) || u > 0xFFFFFFFFu) return false;
            mP.buttons = std::uint32_t(u);
        }
        t.sample.buttons = mP.buttons;
    }
    if (!decodeVec3(cursor, end, mP.force, mP.ticks, t.forceN)) return false;
    if (!getVarint(cursor, end, u)) return false;
    const std::int64_t touched = std::int64_t(mP.touched) + zigzagDecode(u);
    if (touched < 0 || touched > std::int64_t(0xFFFFFFFFu)) return false;
    mP.touched = std::uint32_t(touched);
    t.touched = mP.touched;
    ++mP.ticks;
    return true;
}

void hashTick(std::uint64_t& hash, const glm::vec3& forceN, VertexId touched) {
    auto feed = [&hash](const void* data, std::size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) {
            hash ^= bytes[i];
            hash *= 1099511628211ull;
        }
    };
    feed(&forceN, sizeof(forceN));
    feed(&touched, sizeof(touched));
}

}  // namespace palpate
