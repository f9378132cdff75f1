// Novint Falcon backend: packets both ways on byte fixtures written from libnifalcon's documented
// layout (docs/devices.md), the FTDI framing, the kinematics (Stamper; checked by round trips and
// by virtual work, not by our own numbers), firmware upload against a fake boot loader, and the
// device: no force before homing, unplug -> Disconnected at once -> reconnect and home again,
// NO_DEVICE / timeouts / missing firmware / permission errors.

#include "device/usb/FakeUsbBackend.h"
#include "device/usb/FalconDevice.h"
#include "device/usb/FalconFirmware.h"
#include "device/usb/FalconKinematics.h"
#include "device/usb/FalconProtocol.h"
#include "device/usb/HotplugTracker.h"
#include "tests/device/DeviceTestSupport.h"
#include "tests/device/FakeFalcon.h"
#include "tests/support/AllocationCounter.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace palpate {
namespace {

using test::FakeFalcon;
using test::waitUntil;

bool contains(const std::string& haystack, const std::string& needle) { return haystack.find(needle) != std::string::npos; }
constexpr double kPi = 3.14159265358979323846;

TEST(FalconProtocol, CommandBytesFollowTheDocumentedLayout) {
    FalconCommand c;
    c.motor = {1, -1, 0x1234};
    c.leds = kFalconLedGreen;
    c.homingMode = true;
    const std::array<std::uint8_t, 16> expected = {'<',  0x42, 0x41, 0x41, 0x41, 0x50, 0x50, 0x50,
                                                   0x50, 0x45, 0x44, 0x43, 0x42, 0x44, 0x41, '>'};
    EXPECT_EQ(encodeFalconCommand(c), expected);
    const std::array<std::uint8_t, 16> idle = {'<',  0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41,
                                               0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, '>'};
    EXPECT_EQ(encodeFalconCommand(FalconCommand{}), idle);
}

TEST(FalconProtocol, ReportBytesDecodeToEncodersHomingAndButtons) {
    // encoders -2, 16, 32767; homed motors 1 and 3 (0b101); buttons 0b0011
    const std::uint8_t packet[16] = {'<',  0x4f, 0x50, 0x50, 0x50, 0x41, 0x42, 0x41,
                                     0x41, 0x50, 0x50, 0x50, 0x48, 0x94, 0x41, '>'};
    FalconReport r;
    ASSERT_TRUE(decodeFalconReport(packet, 16, r));
    EXPECT_EQ(r.encoder, (std::array<std::int16_t, 3>{-2, 16, 32767}));
    EXPECT_EQ(r.homedMask, 5);
    EXPECT_FALSE(r.allHomed());
    EXPECT_EQ(r.buttons, 3);
}

TEST(FalconProtocol, MalformedReportsAreRejected) {
    std::uint8_t packet[16] = {'<', 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, '>'};
    FalconReport r;
    EXPECT_TRUE(decodeFalconReport(packet, 16, r));
    EXPECT_FALSE(decodeFalconReport(packet, 15, r));  // short
    packet[15] = 'x';
    EXPECT_FALSE(decodeFalconReport(packet, 16, r));  // bad end
    packet[15] = '>';
    packet[3] = 0x10;  // below 'A': cannot come from the nibble encoding
    EXPECT_FALSE(decodeFalconReport(packet, 16, r));
    EXPECT_FALSE(decodeFalconReport(nullptr, 16, r));
}

TEST(FalconProtocol, FtdiStatusBytesAreStrippedPer64BytePacket) {
    std::vector<std::uint8_t> transfer(70);
    for (std::size_t i = 0; i < transfer.size(); ++i) transfer[i] = std::uint8_t(i);
    std::vector<std::uint8_t> payload(70);
    // 64-byte packet: bytes 2..63 (62), then 6 more bytes: 66..69 (4).
    ASSERT_EQ(stripFtdiStatus(transfer.data(), transfer.size(), payload.data()), 66u);
    EXPECT_EQ(payload[0], 2);
    EXPECT_EQ(payload[61], 63);
    EXPECT_EQ(payload[62], 66);
    EXPECT_EQ(stripFtdiStatus(transfer.data(), 2, payload.data()), 0u);  // status only
    EXPECT_EQ(stripFtdiStatus(transfer.data(), 1, payload.data()), 0u);
}

TEST(FalconProtocol, ParserFindsReportsSplitAcrossTransfersAndSkipsNoise) {
    FalconCommand c;
    c.motor = {100, -200, 300};  // reuse the command encoding's framing as a report body
    auto packet = encodeFalconCommand(c);
    packet[13] = 0x41 + 0x70;  // all homed
    std::vector<std::uint8_t> stream = {0x00, 'x', '>'};  // noise first
    stream.insert(stream.end(), packet.begin(), packet.begin() + 5);
    FalconReportParser parser;
    FalconReport r;
    EXPECT_EQ(parser.push(stream.data(), stream.size(), r), 0);
    EXPECT_EQ(parser.push(packet.data() + 5, 11, r), 1);
    EXPECT_EQ(r.encoder, (std::array<std::int16_t, 3>{100, -200, 300}));
    EXPECT_TRUE(r.allHomed());
    // A cut frame followed by a whole one: the cut one is counted as malformed, the whole one parsed.
    std::vector<std::uint8_t> cut(packet.begin(), packet.begin() + 7);
    cut.insert(cut.end(), packet.begin(), packet.end());
    EXPECT_EQ(parser.push(cut.data(), cut.size(), r), 1);
    EXPECT_EQ(parser.malformed(), 1u);
}

TEST(FalconKinematics, EncoderZeroIsTheDocumentedOffsetAngle) {
    EXPECT_NEAR(falconEncoderToThetaRad(0), 35.0 * kPi / 180.0, 1e-12);
    // One count: the arc of 1/1280 of the 14.25 mm shaft, as an angle of the 110 mm pulley.
    const double perCountDeg = 14.25 / 1280.0 / 110.0 * 360.0;
    EXPECT_NEAR(falconEncoderToThetaRad(1000) - falconEncoderToThetaRad(0), 1000 * perCountDeg * kPi / 180.0, 1e-12);
}

TEST(FalconKinematics, ForwardUndoesInverseOverTheWorkspace) {
    int checked = 0;
    for (double x = -40; x <= 40; x += 20)
        for (double y = -40; y <= 40; y += 20)
            for (double z = 80; z <= 160; z += 20) {
                const glm::dvec3 p(x, y, z);
                glm::dvec3 theta;
                ASSERT_TRUE(falconInverseKinematics(p, theta)) << x << " " << y << " " << z;
                glm::dvec3 back;
                ASSERT_TRUE(falconForwardKinematics(theta, glm::dvec3(0, 0, 110), back)) << x << " " << y << " " << z;
                EXPECT_NEAR(glm::length(back - p), 0.0, 1e-4) << x << " " << y << " " << z;
                ++checked;
            }
    EXPECT_EQ(checked, 125);
    glm::dvec3 theta;
    EXPECT_FALSE(falconInverseKinematics(glm::dvec3(0, 0, 1000), theta));  // out of reach
}

TEST(FalconKinematics, TorquesDoTheSameWorkAsTheForce) {
    // Virtual work: for a small motion dx, tau . dtheta = F . dx. Independent of how J was built.
    const glm::dvec3 p(10, -5, 115), forceN(1.0, -2.0, 3.0);
    glm::dvec3 torqueNm;
    ASSERT_TRUE(falconTorquesNm(p, forceN, torqueNm));
    for (const glm::dvec3 dx : {glm::dvec3(0.01, 0, 0), glm::dvec3(0, 0.01, 0), glm::dvec3(0, 0, 0.01)}) {
        glm::dvec3 t0, t1;
        ASSERT_TRUE(falconInverseKinematics(p - dx * 0.5, t0));
        ASSERT_TRUE(falconInverseKinematics(p + dx * 0.5, t1));
        const double workTorque = glm::dot(torqueNm, t1 - t0);        // N*m * rad
        const double workForce = glm::dot(forceN, dx) / 1000.0;        // N * m
        EXPECT_NEAR(workTorque, workForce, 1e-9);
    }
}

TEST(FalconKinematics, MotorCommandsScaleTogetherToKeepTheDirection) {
    const glm::dvec3 p(0, 0, 110);
    const auto small = falconMotorCommands(p, glm::dvec3(0, 0, 1));
    const auto huge = falconMotorCommands(p, glm::dvec3(0, 0, 1000));
    int largest = 0;
    for (int i = 0; i < 3; ++i) largest = std::max(largest, std::abs(int(huge[i])));
    EXPECT_EQ(largest, 32000);
    for (int i = 0; i < 3; ++i) {
        ASSERT_NE(small[i], 0);
        // Same ratios between motors (within rounding).
        EXPECT_NEAR(double(huge[i]) / huge[0], double(small[i]) / small[0], 0.01);
    }
    // libnifalcon's convention: command = -10000 * torque.
    glm::dvec3 torque;
    ASSERT_TRUE(falconTorquesNm(p, glm::dvec3(0, 0, 1), torque));
    EXPECT_EQ(small[0], std::int16_t(std::lround(-10000.0 * torque.x)));
    EXPECT_EQ(falconMotorCommands(glm::dvec3(0, 0, 1000), glm::dvec3(0, 0, 1)), (std::array<std::int16_t, 3>{0, 0, 0}));
}

// --- firmware upload -------------------------------------------------------------------------

UsbDeviceInfo falconInfo(std::uint8_t address = 7) {
    UsbDeviceInfo info;
    info.busNumber = 1;
    info.deviceAddress = address;
    info.vendorId = kFalconVendorId;
    info.productId = kFalconProductId;
    return info;
}

std::vector<std::uint8_t> fakeFirmware(std::size_t n) {
    std::vector<std::uint8_t> fw(n);
    for (std::size_t i = 0; i < n; ++i) fw[i] = std::uint8_t(i * 7 + 3);
    return fw;
}

TEST(FalconFirmware, UploadFollowsTheBootLoaderSequence) {
    FakeUsbBackend backend;
    auto usbDevice = backend.add(falconInfo());
    FakeFalcon falcon(usbDevice);
    std::string error;
    auto usb = backend.open(falconInfo(), error);
    ASSERT_TRUE(usb) << error;
    const auto fw = fakeFirmware(200);  // 4 chunks: 62 + 62 + 62 + 14
    ASSERT_TRUE((error = uploadFalconFirmware(*usb, fw)).empty()) << error;
    EXPECT_EQ(falcon.uploadedBytes(), 200u);
    EXPECT_TRUE(falcon.firmwareRunning());
    // The FTDI set-up as documented: 9600 baud (0x4138), 8N1, DTR low-high, 140 kbaud (0x15),
    // then normal mode: latency 1, baud divisor 2.
    const auto controls = usbDevice->controls();
    auto has = [&](std::uint8_t request, std::uint16_t value) {
        for (const auto& c : controls)
            if (c.requestType == 0x40 && c.request == request && c.value == value) return true;
        return false;
    };
    EXPECT_TRUE(has(3, 0x4138));
    EXPECT_TRUE(has(4, 8));
    EXPECT_TRUE(has(1, 0x0101));
    EXPECT_TRUE(has(3, 0x0015));
    EXPECT_TRUE(has(9, 1));
    EXPECT_TRUE(has(3, 0x0002));
    // Chunks of at most 62 bytes, in order.
    const auto writes = usbDevice->bulkWrites();
    std::vector<std::uint8_t> sent;
    for (const auto& w : writes)
        if (w.size() > 1 && !(w.size() == 3 && w[0] == 0x0a)) {
            EXPECT_LE(w.size(), 62u);
            sent.insert(sent.end(), w.begin(), w.end());
        }
    EXPECT_EQ(sent, fw);
}

TEST(FalconFirmware, ABadEchoTimeoutsAndUnplugAreClearErrors) {
    {
        FakeUsbBackend backend;
        auto usbDevice = backend.add(falconInfo());
        FakeFalcon falcon(usbDevice);
        falcon.corruptEchoAt = 70;
        std::string error;
        auto usb = backend.open(falconInfo(), error);
        EXPECT_FALSE((error = uploadFalconFirmware(*usb, fakeFirmware(200))).empty());
        EXPECT_TRUE(contains(error, "echo of bytes 62.. does not match")) << error;
    }
    {
        FakeUsbBackend backend;
        auto usbDevice = backend.add(falconInfo());  // nothing answers: every read times out
        std::string error;
        auto usb = backend.open(falconInfo(), error);
        EXPECT_FALSE((error = uploadFalconFirmware(*usb, fakeFirmware(10))).empty());
        EXPECT_TRUE(contains(error, "did not answer the handshake")) << error;
        EXPECT_TRUE(contains(error, "LIBUSB_ERROR_TIMEOUT")) << error;
    }
    {
        FakeUsbBackend backend;
        auto usbDevice = backend.add(falconInfo());
        FakeFalcon falcon(usbDevice);
        std::string error;
        auto usb = backend.open(falconInfo(), error);
        ASSERT_TRUE(usb) << error;
        usbDevice->unplug();  // pulled out mid-upload: every transfer now fails with NO_DEVICE
        EXPECT_FALSE((error = uploadFalconFirmware(*usb, fakeFirmware(10))).empty());
        EXPECT_TRUE(contains(error, "LIBUSB_ERROR_NO_DEVICE")) << error;
    }
    {
        std::vector<std::uint8_t> bytes;
        std::string error;
        EXPECT_FALSE((error = readFalconFirmwareFile("/no/such/falcon.bin", bytes)).empty());
        EXPECT_TRUE(contains(error, "Falcon firmware file '/no/such/falcon.bin': does not exist")) << error;
        EXPECT_FALSE((error = readFalconFirmwareFile("", bytes)).empty());
        EXPECT_TRUE(contains(error, "PALPATE_FALCON_FIRMWARE")) << error;
        EXPECT_FALSE((error = readFalconFirmwareFile("/", bytes)).empty());
        EXPECT_TRUE(contains(error, "is a directory")) << error;
    }
}

// --- the device -------------------------------------------------------------------------------

std::array<std::int16_t, 3> encodersAt(const glm::dvec3& falconMm) {
    glm::dvec3 theta;
    EXPECT_TRUE(falconInverseKinematics(falconMm, theta));
    const double perCountRad = 14.25 / 1280.0 / 110.0 * 2.0 * kPi;
    std::array<std::int16_t, 3> out{};
    for (int i = 0; i < 3; ++i) out[i] = std::int16_t(std::lround((theta[i] - 35.0 * kPi / 180.0) / perCountRad));
    return out;
}

std::string writeFirmwareFile(const std::vector<std::uint8_t>& fw) {
    const std::string path = ::testing::TempDir() + "palpate_fake_falcon_firmware.bin";
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(fw.data()), std::streamsize(fw.size()));
    return path;
}

FalconReport decodeCommandAsReport(const std::array<std::uint8_t, 16>& cmd) {
    FalconReport r;  // same nibble layout: decode the motors with the report decoder's arithmetic
    for (int m = 0; m < 3; ++m) {
        std::uint16_t v = 0;
        for (int k = 0; k < 4; ++k) v = std::uint16_t(v | ((cmd[1 + 4 * m + k] - 0x41) & 0xf) << (4 * k));
        r.encoder[m] = std::int16_t(v);
    }
    return r;
}

TEST(FalconDevice, UploadsFirmwareHomesThenRendersForceAndNeverBefore) {
    auto backend = std::make_shared<FakeUsbBackend>();
    auto usbDevice = backend->add(falconInfo());
    FakeFalcon falcon(usbDevice);
    falcon.homingCommandsNeeded = 50;
    const auto e = encodersAt(glm::dvec3(0, 0, 120));
    falcon.setEncoders(e[0], e[1], e[2]);
    FalconDeviceDef def;
    def.firmwarePath = writeFirmwareFile(fakeFirmware(300));
    FalconDevice device(backend, def);
    ASSERT_TRUE(device.open()) << device.lastError();
    EXPECT_EQ(device.firmwareUploads(), 1u);
    EXPECT_EQ(falcon.uploadedBytes(), 300u);
    // Homing: NeedsCalibration, and the loop's writes are not rendered.
    device.writeForce(glm::vec3(0, 0, 3));
    ASSERT_TRUE(waitUntil([&] { return device.state() == DeviceState::Ready; })) << device.lastError();
    // Homing commands carry zero motors (and so did the firmware probe before them).
    const auto commandsAtReady = falcon.commands();
    std::size_t homingCommands = 0;
    for (const auto& cmd : commandsAtReady) {
        EXPECT_EQ(decodeCommandAsReport(cmd).encoder, (std::array<std::int16_t, 3>{0, 0, 0}));
        if ((cmd[13] - 0x41) & 1) ++homingCommands;
    }
    EXPECT_GE(homingCommands, 50u);

    DeviceSample sample;
    device.setTimeS(2.0);
    ASSERT_TRUE(waitUntil([&] { return device.read(sample); }));
    EXPECT_NEAR(sample.positionMm.x, 0.0f, 0.1f);
    EXPECT_NEAR(sample.positionMm.z, 10.0f, 0.1f);  // 120 mm in the Falcon frame, centre at 110
    EXPECT_LE(sample.timeS, 2.0);

    // Now a force is rendered: non-zero motor commands in the direction the kinematics give.
    device.writeForce(glm::vec3(0, 0, 2));
    const auto expected = falconMotorCommands(glm::dvec3(0, 0, 120), glm::dvec3(0, 0, 2));
    ASSERT_TRUE(waitUntil([&] {
        const auto m = device.lastMotorCommand();
        return std::abs(m[0] - expected[0]) <= 40 && m[0] != 0;
    }));
    // No command with force went out before the firmware had seen 50 homing commands.
    std::size_t homingSeen = 0;
    for (const auto& cmd : falcon.commands()) {
        if ((cmd[13] - 0x41) & 1) ++homingSeen;
        if (decodeCommandAsReport(cmd).encoder != std::array<std::int16_t, 3>{0, 0, 0}) {
            EXPECT_GE(homingSeen, 50u);
        }
    }
    device.emergencyStop();
    EXPECT_EQ(device.state(), DeviceState::Fault);
    ASSERT_TRUE(waitUntil([&] { return device.lastMotorCommand() == std::array<std::int16_t, 3>{0, 0, 0}; }));
    device.close();
}

TEST(FalconDevice, UnplugGivesDisconnectedAtOnceAndReplugHomesAgain) {
    auto backend = std::make_shared<FakeUsbBackend>();
    auto first = backend->add(falconInfo(7));
    FakeFalcon falcon(first, /*firmwareRunning=*/true);
    falcon.homingCommandsNeeded = 1;
    const auto e = encodersAt(glm::dvec3(0, 0, 110));
    falcon.setEncoders(e[0], e[1], e[2]);
    FalconDeviceDef def;
    def.reconnectPeriodMs = 1;
    FalconDevice device(backend, def);
    ASSERT_TRUE(device.open()) << device.lastError();
    EXPECT_EQ(device.firmwareUploads(), 0u);  // already running: no file needed
    ASSERT_TRUE(waitUntil([&] { return device.state() == DeviceState::Ready; }));

    backend->remove(falconInfo(7));  // hotplug Left fires synchronously here
    EXPECT_EQ(device.state(), DeviceState::Disconnected);  // at once, before any transfer fails
    DeviceSample sample;
    EXPECT_FALSE(device.read(sample));
    ASSERT_TRUE(waitUntil([&] { return device.losses() == 1u; }));
    EXPECT_TRUE(contains(device.lastLossReason(), "Falcon 0 at /dev/bus/usb/001/007: unplugged")) << device.lastLossReason();
    EXPECT_TRUE(contains(device.lastLossReason(), "force is off")) << device.lastLossReason();

    // A duplicate removal and a removal of a device never seen change nothing.
    backend->fire(UsbHotplugEvent::Left, falconInfo(7));
    backend->fire(UsbHotplugEvent::Left, falconInfo(99));

    auto second = backend->add(falconInfo(8));  // back, at a new address, power-cycled
    FakeFalcon falcon2(second, /*firmwareRunning=*/true);
    falcon2.homingCommandsNeeded = 20;
    falcon2.setEncoders(e[0], e[1], e[2]);
    backend->fire(UsbHotplugEvent::Arrived, falconInfo(8));  // a duplicate arrival is harmless
    ASSERT_TRUE(waitUntil([&] { return device.reconnects() == 1u; })) << device.lastError();
    ASSERT_TRUE(waitUntil([&] { return device.state() == DeviceState::Ready; })) << device.lastError();
    // It homed again before Ready: the new unit saw the homing bit at least 20 times.
    std::size_t homing = 0;
    for (const auto& cmd : falcon2.commands()) homing += ((cmd[13] - 0x41) & 1) ? 1u : 0u;
    EXPECT_GE(homing, 20u);
    device.close();
}

TEST(FalconDevice, NoDeviceFromATransferAndLongSilenceAreLosses) {
    auto backend = std::make_shared<FakeUsbBackend>();
    auto usbDevice = backend->add(falconInfo());
    FakeFalcon falcon(usbDevice, true);
    falcon.homingCommandsNeeded = 1;
    FalconDeviceDef def;
    def.reconnectPeriodMs = 1;
    def.maxConsecutiveTimeouts = 5;
    FalconDevice device(backend, def);
    ASSERT_TRUE(device.open()) << device.lastError();
    ASSERT_TRUE(waitUntil([&] { return device.state() == DeviceState::Ready; }));
    usbDevice->failNextRead(kUsbErrorNoDevice);  // libusb says NO_DEVICE, no hotplug event
    ASSERT_TRUE(waitUntil([&] { return device.losses() == 1u; }));
    EXPECT_TRUE(contains(device.lastLossReason(), "LIBUSB_ERROR_NO_DEVICE")) << device.lastLossReason();
    // Still present, so it reconnects and homes again.
    ASSERT_TRUE(waitUntil([&] { return device.reconnects() >= 1u && device.state() == DeviceState::Ready; }));

    // Now the firmware stops answering (every read times out).
    usbDevice->setResponder([](std::uint8_t, const std::uint8_t*, int) { return std::vector<std::uint8_t>{}; });
    ASSERT_TRUE(waitUntil([&] { return device.losses() == 2u; }));
    EXPECT_TRUE(contains(device.lastLossReason(), "no answer for 6 exchanges")) << device.lastLossReason();
    EXPECT_TRUE(contains(device.lastLossReason(), "LIBUSB_ERROR_TIMEOUT")) << device.lastLossReason();
    ASSERT_TRUE(waitUntil([&] { return contains(device.lastError(), "reconnecting: "); })) << device.lastError();
    EXPECT_TRUE(contains(device.lastError(), "no answer for")) << device.lastError();  // the cause stays in view
    EXPECT_NE(device.state(), DeviceState::Ready);
    device.close();
}

TEST(FalconDevice, OpenErrorsNameTheFalconAndTheProblem) {
    auto backend = std::make_shared<FakeUsbBackend>();
    {
        FalconDevice device(backend, FalconDeviceDef{});
        EXPECT_FALSE(device.open());
        EXPECT_TRUE(contains(device.lastError(), "Falcon 0: not found (0 Falcons connected")) << device.lastError();
    }
    auto usbDevice = backend->add(falconInfo());
    FakeFalcon falcon(usbDevice);  // boot loader only: firmware needed
    {
        FalconDevice device(backend, FalconDeviceDef{});
        EXPECT_FALSE(device.open());
        EXPECT_TRUE(contains(device.lastError(), "firmware is not running and no firmware file was given")) << device.lastError();
        EXPECT_TRUE(contains(device.lastError(), "falcon:0?firmware=PATH")) << device.lastError();
    }
    {
        FalconDeviceDef def;
        def.firmwarePath = "/no/such/firmware.bin";
        FalconDevice device(backend, def);
        EXPECT_FALSE(device.open());
        EXPECT_TRUE(contains(device.lastError(), "'/no/such/firmware.bin': does not exist")) << device.lastError();
    }
    {
        FalconDeviceDef def;
        def.index = 1;
        FalconDevice device(backend, def);
        EXPECT_FALSE(device.open());
        EXPECT_TRUE(contains(device.lastError(), "Falcon 1: not found (1 Falcon connected")) << device.lastError();
    }
    usbDevice->denyOpen(true);
    {
        FalconDevice device(backend, FalconDeviceDef{});
        EXPECT_FALSE(device.open());
        EXPECT_TRUE(contains(device.lastError(), "permission denied on /dev/bus/usb/001/007 (0403:cb48)")) << device.lastError();
        EXPECT_TRUE(contains(device.lastError(), "70-palpate-falcon.rules")) << device.lastError();
    }
    FalconDevice noUsb(nullptr, FalconDeviceDef{});
    EXPECT_FALSE(noUsb.open());
    EXPECT_TRUE(contains(noUsb.lastError(), "no USB support")) << noUsb.lastError();
}

TEST(HotplugTracker, ArrivalTwiceAndRemovalWithoutArrivalAreIdempotent) {
    HotplugTracker tracker;
    EXPECT_TRUE(tracker.arrived(falconInfo(3)));
    EXPECT_FALSE(tracker.arrived(falconInfo(3)));  // libusb's scan and udev both announce it
    EXPECT_EQ(tracker.count(), 1u);
    EXPECT_FALSE(tracker.left(falconInfo(4)));  // never arrived
    EXPECT_TRUE(tracker.left(falconInfo(3)));
    EXPECT_FALSE(tracker.left(falconInfo(3)));  // already gone
    EXPECT_EQ(tracker.count(), 0u);
    EXPECT_EQ(tracker.ignoredEvents(), 3u);
    EXPECT_TRUE(tracker.arrived(falconInfo(3)));  // and it may come back
}

TEST(FalconDevice, HapticThreadCallsDoNotAllocate) {
    auto backend = std::make_shared<FakeUsbBackend>();
    auto usbDevice = backend->add(falconInfo());
    FakeFalcon falcon(usbDevice, true);
    falcon.homingCommandsNeeded = 1;
    const auto e = encodersAt(glm::dvec3(0, 0, 110));
    falcon.setEncoders(e[0], e[1], e[2]);
    FalconDevice device(backend, FalconDeviceDef{});
    ASSERT_TRUE(device.open()) << device.lastError();
    ASSERT_TRUE(waitUntil([&] { return device.state() == DeviceState::Ready; }));
    DeviceSample sample;
    ASSERT_TRUE(waitUntil([&] { return device.read(sample); }));
    // What the tick calls, on this (test) thread: setTimeS, read, writeForce, state.
    const test::AllocationCounter counter;
    for (int i = 0; i < 1000; ++i) {
        device.setTimeS(i * 0.001);
        device.read(sample);
        device.writeForce(glm::vec3(0.0f, 0.0f, 0.5f));
        (void)device.state();
    }
    EXPECT_EQ(counter.count(), 0u);
    device.close();
}

}  // namespace
}  // namespace palpate
