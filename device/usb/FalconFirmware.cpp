#include "device/usb/FalconFirmware.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace palpate {
namespace {

constexpr int kControlTimeoutMs = 1000;
constexpr int kBulkTimeoutMs = 1000;
// Modem control values: (mask << 8) | level, for DTR (mask 1) and RTS (mask 2).
constexpr std::uint16_t kDtrHigh = 0x0101, kDtrLow = 0x0100, kRtsLow = 0x0200;

int control(UsbTransport& usb, std::uint8_t request, std::uint16_t value) {
    return usb.controlOut(kFtdiRequestTypeOut, request, value, 0, kControlTimeoutMs);
}

std::string step(int result, const char* what) {
    std::string error;
    if (result == 0) return {};
    error = std::string("Falcon firmware upload: ") + what + " failed (" + usbErrorText(result) + ")";
    return error;
}

}  // namespace

std::string readFalconFirmwareFile(const std::string& path, std::vector<std::uint8_t>& bytes) {
    std::string error;
    namespace fs = std::filesystem;
    bytes.clear();
    const std::string head = "Falcon firmware file '" + path + "': ";
    if (path.empty()) {
        error = "Falcon firmware file not given: name Novint's firmware with falcon:INDEX?firmware=PATH or the "
                "PALPATE_FALCON_FIRMWARE environment variable (docs/devices.md; we cannot ship it)";
        return error;
    }
    std::error_code ec;
    if (!fs::exists(path, ec)) {
        error = head + "does not exist";
        return error;
    }
    if (fs::is_directory(path, ec)) {
        error = head + "is a directory";
        return error;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = head + "cannot be read (" + std::strerror(errno) + ")";
        return error;
    }
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (bytes.empty()) {
        error = head + "is empty";
        return error;
    }
    if (bytes.size() > (1u << 20)) {
        error = head + "is " + std::to_string(bytes.size()) + " bytes, too large for Falcon firmware";
        bytes.clear();
        return error;
    }
    return {};
}

int setFalconNormalMode(UsbTransport& usb) {
    for (const auto& [request, value] : std::array<std::pair<std::uint8_t, std::uint16_t>, 4>{
             {{kFtdiSetLatencyTimer, 1}, {kFtdiSetBaudRate, 0x0002}, {kFtdiReset, kFtdiPurgeRx}, {kFtdiReset, kFtdiPurgeTx}}}) {
        const int r = control(usb, request, value);
        if (r != 0) return r;
    }
    return 0;
}

std::string uploadFalconFirmware(UsbTransport& usb, const std::vector<std::uint8_t>& firmware) {
    std::string error;
    error.clear();
    if (firmware.empty()) {
        error = "Falcon firmware upload: the firmware is empty";
        return error;
    }
    // 1. The boot loader listens at 9600 baud, 8N1, no flow control; DTR low-high resets it.
    if (!(error = step(control(usb, kFtdiReset, kFtdiPurgeRx), "purging the receive buffer")).empty()) return error;
    if (!(error = step(control(usb, kFtdiReset, kFtdiPurgeTx), "purging the send buffer")).empty()) return error;
    if (!(error = step(control(usb, kFtdiSetLatencyTimer, 16), "setting the latency timer")).empty()) return error;
    if (!(error = step(control(usb, kFtdiSetBaudRate, 0x4138), "setting 9600 baud")).empty()) return error;
    if (!(error = step(control(usb, kFtdiSetData, 8), "setting 8N1")).empty()) return error;
    if (!(error = step(control(usb, kFtdiSetFlowCtrl, 0), "disabling flow control")).empty()) return error;
    if (!(error = step(control(usb, kFtdiModemCtrl, kRtsLow), "setting RTS low")).empty()) return error;
    if (!(error = step(control(usb, kFtdiModemCtrl, kDtrLow), "setting DTR low")).empty()) return error;
    if (!(error = step(control(usb, kFtdiModemCtrl, kDtrHigh), "setting DTR high")).empty()) return error;

    // 2. Handshake: "\n C \r" until the loader answers "\n D , \r" (after the FTDI's 2 status bytes;
    //    some hosts see a leading 0x00 first).
    const std::uint8_t hello[3] = {0x0a, 0x43, 0x0d};
    const std::uint8_t answer[4] = {0x0a, 0x44, 0x2c, 0x0d};
    std::array<std::uint8_t, 512> buffer{};
    bool greeted = false;
    int lastError = 0;
    for (int attempt = 0; attempt < 100 && !greeted; ++attempt) {
        int sent = 0, got = 0;
        lastError = usb.bulkWrite(kFalconEndpointOut, hello, 3, sent, kBulkTimeoutMs);
        if (lastError == kUsbErrorNoDevice) break;
        if (lastError != 0) continue;
        lastError = usb.bulkRead(kFalconEndpointIn, buffer.data(), int(buffer.size()), got, kBulkTimeoutMs);
        if (lastError == kUsbErrorNoDevice) break;
        if (got == 6 && std::memcmp(buffer.data() + 2, answer, 4) == 0) greeted = true;
        if (got == 7 && buffer[2] == 0x00 && std::memcmp(buffer.data() + 3, answer, 4) == 0) greeted = true;
    }
    if (!greeted) {
        error = "Falcon firmware upload: the boot loader did not answer the handshake" +
                (lastError ? " (" + usbErrorText(lastError) + ")" : std::string(" (wrong answer)")) +
                "; power-cycle the Falcon and try again";
        return error;
    }

    // 3. 140 kbaud (divisor 0x15), then 'A' must come back.
    if (!(error = step(control(usb, kFtdiModemCtrl, kDtrLow), "setting DTR low")).empty()) return error;
    if (!(error = step(control(usb, kFtdiSetBaudRate, 0x0015), "setting the upload baud rate")).empty()) return error;
    {
        const std::uint8_t a = 0x41;
        int sent = 0, got = 0;
        if (!(error = step(usb.bulkWrite(kFalconEndpointOut, &a, 1, sent, kBulkTimeoutMs), "sending the start byte"))
                 .empty())
            return error;
        if (!(error = step(usb.bulkRead(kFalconEndpointIn, buffer.data(), 3, got, kBulkTimeoutMs),
                           "reading the start echo"))
                 .empty())
            return error;
        if (got != 3 || buffer[2] != 0x41) {
            error = "Falcon firmware upload: the boot loader did not echo the start byte";
            return error;
        }
    }

    // 4. The file in 62-byte chunks (62 + 2 status bytes = one 64-byte USB packet); every byte is
    //    echoed and compared, so a corrupted upload is caught here, not by a misbehaving motor.
    constexpr std::size_t kChunk = 62;
    std::array<std::uint8_t, 64> echo{};
    for (std::size_t offset = 0; offset < firmware.size(); offset += kChunk) {
        const std::size_t n = std::min(kChunk, firmware.size() - offset);
        int sent = 0;
        const int w = usb.bulkWrite(kFalconEndpointOut, firmware.data() + offset, int(n), sent, kBulkTimeoutMs);
        if (w != 0) {
            error = "Falcon firmware upload: writing bytes " + std::to_string(offset) + ".. failed (" + usbErrorText(w) + ")";
            return error;
        }
        std::size_t checked = 0;
        int emptyReads = 0;
        while (checked < n) {
            int got = 0;
            const int r = usb.bulkRead(kFalconEndpointIn, echo.data(), int(n - checked + 2), got, kBulkTimeoutMs);
            if (r != 0) {
                error = "Falcon firmware upload: reading the echo of byte " + std::to_string(offset + checked) +
                        " failed (" + usbErrorText(r) + ")";
                return error;
            }
            if (got < 2) {
                error = "Falcon firmware upload: short read (" + std::to_string(got) + " bytes) at byte " +
                        std::to_string(offset + checked);
                return error;
            }
            const std::size_t payload = std::size_t(got - 2);
            if (payload == 0) {
                // Status bytes only: the loader has not echoed yet. Bounded, so a dead one ends.
                if (++emptyReads > 100) {
                    error = "Falcon firmware upload: no echo of byte " + std::to_string(offset + checked);
                    return error;
                }
                continue;
            }
            if (payload > n - checked ||
                std::memcmp(echo.data() + 2, firmware.data() + offset + checked, payload) != 0) {
                error = "Falcon firmware upload: the echo of bytes " + std::to_string(offset + checked) +
                        ".. does not match (wrong file or a bad cable)";
                return error;
            }
            checked += payload;
        }
    }
    return step(setFalconNormalMode(usb), "switching to normal mode");
}

}  // namespace palpate
