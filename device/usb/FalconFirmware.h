#pragma once
// Puts Novint's firmware into a Falcon. The Falcon boots into a loader that talks through its FTDI
// bridge; the sequence below follows libnifalcon's FalconCommLibUSB::setFirmwareMode and
// FalconFirmware::loadFirmware (BSD; docs/devices.md): FTDI set-up at 9600 baud, a handshake
// ("\n C \r" answered by "\n D , \r"), 140 kbaud, an 'A' answered by 'A', then the file in
// 62-byte chunks that the loader echoes back, then normal mode (latency 1 ms, fast baud rate).
// The file is Novint's and not ours to ship: the user names it (docs/devices.md).

#include "device/usb/FalconProtocol.h"
#include "device/usb/UsbTransport.h"

#include <cstdint>
#include <string>
#include <vector>

namespace palpate {

/// FTDI vendor requests (libftdi's SIO_* constants).
enum FtdiRequest : std::uint8_t {
    kFtdiReset = 0,
    kFtdiModemCtrl = 1,
    kFtdiSetFlowCtrl = 2,
    kFtdiSetBaudRate = 3,
    kFtdiSetData = 4,
    kFtdiSetLatencyTimer = 9,
};
constexpr std::uint8_t kFtdiRequestTypeOut = 0x40;  ///< vendor, host-to-device
constexpr std::uint16_t kFtdiPurgeRx = 1;
constexpr std::uint16_t kFtdiPurgeTx = 2;

/// Reads a firmware file: "" or the problem naming the file (missing, unreadable,
/// empty or implausibly large: > 1 MiB).
std::string readFalconFirmwareFile(const std::string& path, std::vector<std::uint8_t>& bytes);

/// Boot-loader mode, upload and echo check, then normal mode: "" or the problem saying which step
/// failed and the USB error (timeouts, NO_DEVICE, an echo that does not match).
std::string uploadFalconFirmware(UsbTransport& usb, const std::vector<std::uint8_t>& firmware);

/// Normal mode (after an upload, or when the firmware already runs): latency 1 ms, fast baud rate,
/// buffers purged. 0 or the first failing UsbError.
int setFalconNormalMode(UsbTransport& usb);

}  // namespace palpate
