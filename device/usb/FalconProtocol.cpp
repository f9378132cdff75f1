#include "device/usb/FalconProtocol.h"

#include <cstring>

namespace palpate {
namespace {

constexpr std::uint8_t kNibbleBase = 0x41;  // 'A': every payload byte is a nibble + 'A'

bool nibbleOf(std::uint8_t byte, std::uint8_t& nibble) {
    if (byte < kNibbleBase || byte > kNibbleBase + 0x7f) return false;
    nibble = std::uint8_t(byte - kNibbleBase);
    return true;
}

}  // namespace

std::array<std::uint8_t, kFalconPacketBytes> encodeFalconCommand(const FalconCommand& command) {
    std::array<std::uint8_t, kFalconPacketBytes> out{};
    out[0] = '<';
    for (int m = 0; m < 3; ++m) {
        const auto v = std::uint16_t(command.motor[m]);
        for (int k = 0; k < 4; ++k) out[1 + 4 * m + k] = std::uint8_t(kNibbleBase + ((v >> (4 * k)) & 0xf));
    }
    out[13] = std::uint8_t(kNibbleBase + ((command.leds & 0x0e) | (command.homingMode ? 0x01 : 0x00)));
    out[14] = kNibbleBase;
    out[15] = '>';
    return out;
}

bool decodeFalconReport(const std::uint8_t* packet, std::size_t length, FalconReport& out) {
    if (packet == nullptr || length < kFalconPacketBytes || packet[0] != '<' || packet[15] != '>') return false;
    FalconReport r;
    for (int m = 0; m < 3; ++m) {
        std::uint16_t v = 0;
        for (int k = 0; k < 4; ++k) {
            std::uint8_t nibble = 0;
            if (!nibbleOf(packet[1 + 4 * m + k], nibble)) return false;
            // Only the low nibble carries data; libnifalcon masks it the same way.
            v = std::uint16_t(v | ((nibble & 0xf) << (4 * k)));
        }
        r.encoder[m] = std::int16_t(v);
    }
    std::uint8_t status = 0;
    if (!nibbleOf(packet[13], status)) return false;
    r.homedMask = std::uint8_t((status >> 4) & 0x7);
    r.buttons = std::uint8_t(status & 0x0f);
    out = r;
    return true;
}

std::size_t stripFtdiStatus(const std::uint8_t* transfer, std::size_t length, std::uint8_t* payload) {
    std::size_t n = 0;
    for (std::size_t start = 0; start < length; start += 64) {
        const std::size_t end = start + 64 < length ? start + 64 : length;
        if (end - start <= 2) continue;  // status bytes only
        std::memcpy(payload + n, transfer + start + 2, end - start - 2);
        n += end - start - 2;
    }
    return n;
}

int FalconReportParser::push(const std::uint8_t* data, std::size_t length, FalconReport& latest) {
    int complete = 0;
    for (std::size_t i = 0; i < length; ++i) {
        const std::uint8_t b = data[i];
        if (mFill == 0) {
            if (b == '<') mPacket[mFill++] = b;  // skip noise up to the next frame start
            continue;
        }
        if (b == '<' && mFill < kFalconPacketBytes - 1) {
            // A new frame started inside this one: the partial frame was cut; start again here.
            ++mMalformed;
            mFill = 0;
            mPacket[mFill++] = b;
            continue;
        }
        mPacket[mFill++] = b;
        if (mFill == kFalconPacketBytes) {
            FalconReport r;
            if (decodeFalconReport(mPacket.data(), mFill, r)) {
                latest = r;
                ++complete;
            } else {
                ++mMalformed;
            }
            mFill = 0;
        }
    }
    return complete;
}

}  // namespace palpate
