#pragma once
// A Novint Falcon as the USB wire sees it, for tests: the boot loader (handshake, 'A', echoed
// upload) and, once a firmware has been uploaded and normal mode set, the firmware's answer to
// every 16-byte command: a 16-byte report after the FTDI's 2 status bytes. Homing completes after
// `homingCommandsNeeded` commands with the homing bit. Written from the protocol as libnifalcon
// documents it, independently of our encoder (reports are assembled byte by byte here).

#include "device/usb/FakeUsbBackend.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace palpate::test {

class FakeFalcon {
public:
    explicit FakeFalcon(std::shared_ptr<FakeUsbDevice> device, bool firmwareRunning = false)
        : mDevice(std::move(device)), mFirmwareRunning(firmwareRunning) {
        mDevice->setControlHandler([this](const UsbControlRecord& r) { return onControl(r); });
        mDevice->setResponder([this](std::uint8_t, const std::uint8_t* d, int n) { return onWrite(d, n); });
    }

    void setEncoders(std::int16_t a, std::int16_t b, std::int16_t c) {
        std::lock_guard lock(mMutex);
        mEncoders = {a, b, c};
    }
    void setButtons(std::uint8_t buttons) {
        std::lock_guard lock(mMutex);
        mButtons = buttons;
    }
    int homingCommandsNeeded = 5;
    /// Echo upload bytes wrongly from this offset (-1: never).
    long corruptEchoAt = -1;

    bool firmwareRunning() const {
        std::lock_guard lock(mMutex);
        return mFirmwareRunning;
    }
    std::size_t uploadedBytes() const {
        std::lock_guard lock(mMutex);
        return mUploaded;
    }
    /// Every 16-byte command the firmware received, raw.
    std::vector<std::array<std::uint8_t, 16>> commands() const {
        std::lock_guard lock(mMutex);
        return mCommands;
    }
    std::size_t commandCount() const {
        std::lock_guard lock(mMutex);
        return mCommandCount;
    }

private:
    enum class Mode { Boot, Handshaken, Uploading, Normal };

    int onControl(const UsbControlRecord& r) {
        std::lock_guard lock(mMutex);
        if (r.requestType == 0x40 && r.request == 3) {  // baud rate
            if (r.value == 0x0015 && mMode == Mode::Handshaken) mMode = Mode::Uploading;
            if (r.value == 0x0002) {
                // Normal mode: the firmware runs if one was uploaded (or was already running).
                if (mUploaded > 0) mFirmwareRunning = true;
                mMode = Mode::Normal;
            }
        }
        return 0;
    }

    std::vector<std::uint8_t> onWrite(const std::uint8_t* d, int n) {
        std::lock_guard lock(mMutex);
        if (mFirmwareRunning && mMode == Mode::Normal) {
            if (n != 16 || d[0] != '<' || d[15] != '>') return {};
            std::array<std::uint8_t, 16> cmd{};
            std::copy(d, d + 16, cmd.begin());
            if (mCommands.size() < 100000) mCommands.push_back(cmd);
            ++mCommandCount;
            if ((cmd[13] - 0x41) & 0x01) ++mHomingCommands;
            if (mHomingCommands >= homingCommandsNeeded) mHomed = 7;
            // The report: '<', 12 nibble bytes (least significant nibble first) + 0x41, status, '>'.
            std::vector<std::uint8_t> out = {0x31, 0x60, '<'};
            for (int m = 0; m < 3; ++m) {
                const auto v = std::uint16_t(mEncoders[m]);
                for (int k = 0; k < 4; ++k) out.push_back(std::uint8_t(((v >> (4 * k)) & 0xf) + 0x41));
            }
            out.push_back(std::uint8_t(((mHomed << 4) | mButtons) + 0x41));
            out.push_back(0x41);
            out.push_back('>');
            return out;
        }
        if (mMode == Mode::Boot || mMode == Mode::Normal) {
            if (n == 3 && d[0] == 0x0a && d[1] == 0x43 && d[2] == 0x0d) {
                mMode = Mode::Handshaken;
                return {0x31, 0x60, 0x0a, 0x44, 0x2c, 0x0d};  // the "Linux case": 6 bytes
            }
            return {};  // no firmware: a command gets no answer
        }
        if (mMode == Mode::Uploading) {
            if (!mGotStart) {
                if (n == 1 && d[0] == 0x41) {
                    mGotStart = true;
                    return {0x31, 0x60, 0x41};
                }
                return {};
            }
            std::vector<std::uint8_t> out = {0x31, 0x60};
            for (int i = 0; i < n; ++i) {
                std::uint8_t b = d[i];
                if (corruptEchoAt >= 0 && long(mUploaded) + i >= corruptEchoAt) b ^= 0xff;
                out.push_back(b);
            }
            mUploaded += std::size_t(n);
            return out;
        }
        return {};
    }

    std::shared_ptr<FakeUsbDevice> mDevice;
    mutable std::mutex mMutex;
    Mode mMode = Mode::Boot;
    bool mFirmwareRunning;
    bool mGotStart = false;
    std::size_t mUploaded = 0;
    std::array<std::int16_t, 3> mEncoders{0, 0, 0};
    std::uint8_t mButtons = 0;
    int mHomingCommands = 0;
    int mHomed = 0;
    std::vector<std::array<std::uint8_t, 16>> mCommands;
    std::size_t mCommandCount = 0;
};

}  // namespace palpate::test
