#include "device/hid/SpaceMouseCodec.h"

namespace palpate {
namespace {

std::int16_t le16(const std::uint8_t* p) { return std::int16_t(std::uint16_t(p[0]) | std::uint16_t(p[1]) << 8); }

}  // namespace

bool isSpaceMouseVidPid(std::uint16_t vendorId, std::uint16_t productId) {
    if (vendorId == k3DconnexionVendorId) return true;
    return vendorId == kLogitechVendorId && productId >= 0xc600 && productId <= 0xc6ff;
}

const char* spaceMouseReportName(SpaceMouseReport report) {
    switch (report) {
        case SpaceMouseReport::Translation: return "translation";
        case SpaceMouseReport::Rotation: return "rotation";
        case SpaceMouseReport::SixAxes: return "six axes";
        case SpaceMouseReport::Buttons: return "buttons";
        case SpaceMouseReport::Ignored: return "ignored";
        case SpaceMouseReport::ShortReport: return "short report";
        case SpaceMouseReport::Empty: return "empty";
    }
    return "unknown";
}

SpaceMouseReport decodeSpaceMouseReport(const std::uint8_t* data, std::size_t length, SpaceMouseRaw& state) {
    if (length == 0 || data == nullptr) return SpaceMouseReport::Empty;
    switch (data[0]) {
        case 1:
            // The length, not the vendor ID, tells the two layouts apart: a 13-byte report 1 carries
            // all six axes whatever the unit calls itself.
            if (length >= 13) {
                for (int i = 0; i < 3; ++i) state.translation[i] = le16(data + 1 + 2 * i);
                for (int i = 0; i < 3; ++i) state.rotation[i] = le16(data + 7 + 2 * i);
                return SpaceMouseReport::SixAxes;
            }
            if (length < 7) return SpaceMouseReport::ShortReport;
            for (int i = 0; i < 3; ++i) state.translation[i] = le16(data + 1 + 2 * i);
            return SpaceMouseReport::Translation;
        case 2:
            if (length < 7) return SpaceMouseReport::ShortReport;
            for (int i = 0; i < 3; ++i) state.rotation[i] = le16(data + 1 + 2 * i);
            return SpaceMouseReport::Rotation;
        case 3: {
            if (length < 2) return SpaceMouseReport::ShortReport;
            std::uint32_t buttons = 0;
            for (std::size_t i = 1; i < length && i <= 4; ++i) buttons |= std::uint32_t(data[i]) << (8 * (i - 1));
            state.buttons = buttons;
            return SpaceMouseReport::Buttons;
        }
        default: return SpaceMouseReport::Ignored;
    }
}

std::array<std::uint8_t, 2> encodeSpaceMouseLed(bool on) { return {4, std::uint8_t(on ? 1 : 0)}; }

}  // namespace palpate
