#pragma once
// 3Dconnexion SpaceMouse input reports (hidraw, numbered reports), decoded without any I/O.
// Layouts (docs/devices.md cites the sources: libndofdev, spacenavd, the 3Dconnexion reports
// recorded by the open-source community):
//   older units (VID 0x046d):  report 1 = Tx,Ty,Tz   report 2 = Rx,Ry,Rz   (7 bytes each)
//   newer units (VID 0x256f):  report 1 = Tx,Ty,Tz,Rx,Ry,Rz                 (13 bytes)
//   both:                      report 3 = buttons, one bit each, little-endian, bytes 1..
// Axes are int16 little-endian, about +-350 at full deflection. HID axes: +x right, +y toward the
// user, +z down (pressing the cap). Output report 4 switches the LED (byte 1: 0 off, 1 on).

#include <array>
#include <cstddef>
#include <cstdint>

namespace palpate {

constexpr std::uint16_t kLogitechVendorId = 0x046d;     ///< older 3Dconnexion units
constexpr std::uint16_t k3DconnexionVendorId = 0x256f;  ///< newer units
constexpr std::uint16_t kHidUsagePageGenericDesktop = 0x01;
constexpr std::uint16_t kHidUsageMultiAxisController = 0x08;

/// Whether a VID:PID is a 3Dconnexion 6-DoF device (0x256f: all; 0x046d: the 0xc6xx range that
/// 3Dconnexion used while part of Logitech, e.g. c626 SpaceNavigator, c62b SpaceMouse Pro).
bool isSpaceMouseVidPid(std::uint16_t vendorId, std::uint16_t productId);

/// The device's latest raw readings, as the reports left them.
struct SpaceMouseRaw {
    std::array<std::int16_t, 3> translation{};  ///< Tx, Ty, Tz (counts)
    std::array<std::int16_t, 3> rotation{};     ///< Rx, Ry, Rz (counts)
    std::uint32_t buttons = 0;                  ///< bit i = button i (first 32)
};

enum class SpaceMouseReport {
    Translation,   ///< report 1, 7 bytes
    Rotation,      ///< report 2
    SixAxes,       ///< report 1, 13 bytes
    Buttons,       ///< report 3
    Ignored,       ///< another report ID (battery, vendor): state untouched
    ShortReport,   ///< a known report ID with too few bytes: state untouched
    Empty,         ///< zero bytes
};

const char* spaceMouseReportName(SpaceMouseReport report);

/// Applies one input report to `state`. Never reads beyond `length`.
SpaceMouseReport decodeSpaceMouseReport(const std::uint8_t* data, std::size_t length, SpaceMouseRaw& state);

/// The LED output report: {4, on ? 1 : 0}.
std::array<std::uint8_t, 2> encodeSpaceMouseLed(bool on);

}  // namespace palpate
