#pragma once
// The Novint Falcon's wire protocol, as documented by libnifalcon (Kyle Machulis et al., BSD;
// docs/devices.md cites the files), implemented here without any I/O:
//  * the FTDI FT232 bridge prefixes every 64-byte bulk IN packet with 2 modem-status bytes;
//  * with Novint's firmware running, the host sends 16-byte commands and the Falcon answers each
//    with one 16-byte report, both framed '<' ... '>', each payload byte being a nibble + 0x41:
//      command: '<', 3 motors x 4 nibbles (int16, least significant nibble first), then
//               byte 13 = LED bits | homing-mode bit (0x01), byte 14 = 0, '>'
//      report:  '<', 3 encoders x 4 nibbles (int16, same order), then
//               byte 13: bits 4..6 = homed flags of motors 1..3, bits 0..3 = grip buttons, '>'
//  * before that, the firmware is uploaded in a boot-loader mode (FalconFirmwareLoader).

#include <array>
#include <cstddef>
#include <cstdint>

namespace palpate {

constexpr std::uint16_t kFalconVendorId = 0x0403;   ///< FTDI
constexpr std::uint16_t kFalconProductId = 0xcb48;  ///< Novint Falcon
constexpr std::uint8_t kFalconEndpointOut = 0x02;
constexpr std::uint8_t kFalconEndpointIn = 0x81;
constexpr std::size_t kFalconPacketBytes = 16;

/// LED bits of the command's byte 13 (libnifalcon FalconFirmware: GREEN 0x2, BLUE 0x4, RED 0x8).
enum FalconLed : std::uint8_t { kFalconLedGreen = 0x02, kFalconLedBlue = 0x04, kFalconLedRed = 0x08 };

struct FalconCommand {
    std::array<std::int16_t, 3> motor{};  ///< motor commands (libnifalcon's units; see FalconKinematics)
    std::uint8_t leds = 0;                ///< FalconLed bits
    bool homingMode = false;              ///< ask the firmware to home the encoders
};

struct FalconReport {
    std::array<std::int16_t, 3> encoder{};  ///< encoder counts of motors 1..3
    std::uint8_t homedMask = 0;             ///< bit i: motor i+1 homed
    std::uint8_t buttons = 0;               ///< grip buttons (4-button grip: bits 0..3)
    bool allHomed() const { return (homedMask & 7u) == 7u; }
};

/// The 16 bytes of a command.
std::array<std::uint8_t, kFalconPacketBytes> encodeFalconCommand(const FalconCommand& command);

/// Decodes one 16-byte report; false if the framing or a payload byte is invalid.
bool decodeFalconReport(const std::uint8_t* packet, std::size_t length, FalconReport& out);

/// Copies the payload of a bulk IN transfer without the FTDI's 2 status bytes per 64-byte packet.
/// Returns the payload byte count (<= length). A transfer shorter than 2 bytes has no payload.
std::size_t stripFtdiStatus(const std::uint8_t* transfer, std::size_t length, std::uint8_t* payload);

/// Finds reports in a byte stream that may split them across transfers or carry noise. Holds at
/// most one partial packet; no allocation.
class FalconReportParser {
public:
    /// Feeds bytes; returns how many complete, valid reports they finished; `latest` gets the last.
    int push(const std::uint8_t* data, std::size_t length, FalconReport& latest);
    /// Frames dropped as malformed since construction.
    std::uint64_t malformed() const { return mMalformed; }
    void reset() { mFill = 0; }

private:
    std::array<std::uint8_t, kFalconPacketBytes> mPacket{};
    std::size_t mFill = 0;
    std::uint64_t mMalformed = 0;
};

}  // namespace palpate
