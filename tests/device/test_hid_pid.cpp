// HID PID joysticks (experimental): the report descriptor parser (positions, sizes, usages,
// collections; malformed input named by byte offset; random and mutated bytes never crash), the
// PID reports built from a parsed descriptor compared with bytes derived by hand from it, the
// sysfs descriptor read, and the device on a fake backend: effect set-up, finite duration, and
// Stop All + Disable Actuators on close.

#include "device/hid/FakeHidBackend.h"
#include "device/hid/HidPidCodec.h"
#include "device/hid/HidPidDevice.h"
#include "device/hid/HidReportDescriptor.h"
#include "tests/device/DeviceTestSupport.h"
#include "tests/device/PidDescriptorFixture.h"
#include "tests/support/AllocationCounter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>

namespace palpate {
namespace {

using test::pidJoystickDescriptor;
using test::waitUntil;

bool contains(const std::string& haystack, const std::string& needle) { return haystack.find(needle) != std::string::npos; }

TEST(HidReportDescriptor, FieldsOfTheJoystickDescriptor) {
    const auto& bytes = pidJoystickDescriptor();
    HidReportDescriptor d;
    std::string error;
    ASSERT_TRUE((error = parseHidReportDescriptor(bytes.data(), bytes.size(), d)).empty()) << error;
    EXPECT_TRUE(d.numberedReports);
    ASSERT_EQ(d.applications.size(), 1u);
    EXPECT_EQ(d.applications[0], hidUsage(0x01, 0x04));
    // Input report 1: X, Y (16 bits each), then 8 one-bit buttons: 5 bytes.
    EXPECT_EQ(d.reportBytes(HidReportType::Input, 1), 5u);
    const HidField* xy = d.find(HidReportType::Input, hidUsage(0x01, 0x04), hidUsage(0x01, 0x30));
    ASSERT_NE(xy, nullptr);
    EXPECT_EQ(xy->bitOffset, 0u);
    EXPECT_EQ(xy->bitSize, 16u);
    EXPECT_EQ(xy->count, 2u);
    EXPECT_EQ(xy->logicalMax, 1023);
    const HidField* buttons = d.find(HidReportType::Input, hidUsage(0x01, 0x04), hidUsage(0x09, 8));
    ASSERT_NE(buttons, nullptr);
    EXPECT_EQ(buttons->bitOffset, 32u);
    EXPECT_EQ(buttons->usages.size(), 8u);  // the usage range expanded
    // Set Effect: 17 data bytes; Direction elements carry 4-byte (page-qualified) usages.
    EXPECT_EQ(d.reportBytes(HidReportType::Output, 0x11), 17u);
    const HidField* direction = d.find(HidReportType::Output, pid::kDirection, hidUsage(0x0a, 1));
    ASSERT_NE(direction, nullptr);
    EXPECT_EQ(direction->bitOffset, 104u);
    EXPECT_EQ(direction->logicalMax, 36000);
    const HidField* magnitude = d.find(HidReportType::Output, pid::kSetConstantForceReport, pid::kMagnitude);
    ASSERT_NE(magnitude, nullptr);
    EXPECT_EQ(magnitude->logicalMin, -10000);  // signed 16-bit logical minimum
    EXPECT_EQ(magnitude->logicalMax, 10000);
    EXPECT_EQ(d.reportBytes(HidReportType::Feature, 0x05), 3u);
    EXPECT_TRUE(descriptorHasPid(d));
}

TEST(HidPidCodec, ReportsMatchTheBytesDerivedFromTheDescriptor) {
    const auto& bytes = pidJoystickDescriptor();
    HidPidLayout layout;
    std::string error;
    ASSERT_TRUE((error = resolveHidPidLayout(bytes.data(), bytes.size(), layout)).empty()) << error;
    // Set Effect: index 1, type Constant (1st of 3 -> 1), duration 100 ms, repeat/sample/delay 0,
    // gain 255, no trigger (0), axes X+Y and direction enable (bits 0..2 = 0x07), direction 90
    // degrees = 9000 of 36000 (0x2328), second direction 0.
    EXPECT_EQ(buildPidSetEffect(layout, 1, 100, 90.0),
              (std::vector<std::uint8_t>{0x11, 0x01, 0x01, 0x64, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xff, 0x00,
                                         0x07, 0x28, 0x23, 0x00, 0x00}));
    // Constant force: half of +-10000 = 5000 (0x1388), -5000 = 0xec78; beyond +-1 clamps.
    EXPECT_EQ(buildPidSetConstantForce(layout, 1, 0.5), (std::vector<std::uint8_t>{0x15, 0x01, 0x88, 0x13}));
    EXPECT_EQ(buildPidSetConstantForce(layout, 1, -0.5), (std::vector<std::uint8_t>{0x15, 0x01, 0x78, 0xec}));
    EXPECT_EQ(buildPidSetConstantForce(layout, 1, 7.0), (std::vector<std::uint8_t>{0x15, 0x01, 0x10, 0x27}));
    // Effect Operation: Start = 1, Stop = 3; loop count 1.
    EXPECT_EQ(buildPidEffectOperation(layout, 1, true), (std::vector<std::uint8_t>{0x1a, 0x01, 0x01, 0x01}));
    EXPECT_EQ(buildPidEffectOperation(layout, 1, false), (std::vector<std::uint8_t>{0x1a, 0x01, 0x03, 0x01}));
    // Device Control: Enable 1, Disable 2, Stop All 3, Reset 4.
    EXPECT_EQ(buildPidDeviceControl(layout, HidPidControl::EnableActuators), (std::vector<std::uint8_t>{0x1c, 0x01}));
    EXPECT_EQ(buildPidDeviceControl(layout, HidPidControl::DisableActuators), (std::vector<std::uint8_t>{0x1c, 0x02}));
    EXPECT_EQ(buildPidDeviceControl(layout, HidPidControl::StopAllEffects), (std::vector<std::uint8_t>{0x1c, 0x03}));
    EXPECT_EQ(buildPidDeviceControl(layout, HidPidControl::DeviceReset), (std::vector<std::uint8_t>{0x1c, 0x04}));
    EXPECT_EQ(buildPidCreateNewEffect(layout), (std::vector<std::uint8_t>{0x05, 0x01, 0x00, 0x00}));
}

TEST(HidPidCodec, ANonPidDescriptorIsRefusedByName) {
    // A plain mouse: no PID reports.
    const std::vector<std::uint8_t> mouse = {0x05, 0x01, 0x09, 0x02, 0xA1, 0x01, 0x09, 0x30, 0x15, 0x81, 0x25,
                                             0x7F, 0x75, 0x08, 0x95, 0x01, 0x81, 0x06, 0xC0};
    HidPidLayout layout;
    std::string error;
    EXPECT_FALSE((error = resolveHidPidLayout(mouse.data(), mouse.size(), layout)).empty());
    EXPECT_TRUE(contains(error, "not a HID PID device")) << error;
    EXPECT_TRUE(contains(error, "Set Effect / Effect Block Index")) << error;
}

TEST(HidReportDescriptor, MalformedDescriptorsNameTheByte) {
    struct Case {
        std::vector<std::uint8_t> bytes;
        const char* mention;
    };
    const Case cases[] = {
        {{}, "empty"},
        {{0x05}, "byte 0: item data runs past the end"},
        {{0x05, 0x01, 0xC0}, "byte 2: End Collection without Collection"},
        {{0xA1, 0x01}, "collection(s) not closed"},
        {{0xB4}, "byte 0: Pop without Push"},
        {{0x85, 0x00}, "report ID 0 outside 1..255"},
        {{0x75, 0x40, 0x95, 0x01, 0x81, 0x02}, "report size above 32 bits"},
        {{0x75, 0x08, 0x96, 0x01, 0x10, 0x81, 0x02}, "report count above 4096"},
        {{0x29, 0x05}, "Usage Maximum without Usage Minimum"},
        {{0x19, 0x00, 0x2A, 0xFF, 0xFF}, "usage range of more than 1024"},
        {{0xFE, 0x10, 0x00}, "long item data runs past the end"},
        {{0x0C}, "reserved item type"},
    };
    for (const Case& c : cases) {
        HidReportDescriptor d;
        std::string error;
        EXPECT_FALSE((error = parseHidReportDescriptor(c.bytes.data(), c.bytes.size(), d)).empty())
            << c.mention << " " << error;
        EXPECT_TRUE(contains(error, c.mention)) << error;
        EXPECT_TRUE(d.fields.empty());
    }
}

TEST(HidReportDescriptor, RandomAndMutatedBytesNeverCrash) {
    // Fuzz-style: the parser and the PID resolver see hostile bytes; they must return (true or
    // false with a message), never crash, hang or read out of bounds (ASan build checks the last).
    std::mt19937 rng(12345);
    std::uniform_int_distribution<int> byte(0, 255);
    int rejected = 0;
    for (int round = 0; round < 3000; ++round) {
        std::vector<std::uint8_t> bytes;
        if (round % 2 == 0) {
            bytes.resize(std::size_t(1 + rng() % 200));
            for (auto& b : bytes) b = std::uint8_t(byte(rng));
        } else {
            bytes = pidJoystickDescriptor();
            const int mutations = 1 + int(rng() % 8);
            for (int m = 0; m < mutations; ++m) {
                switch (rng() % 3) {
                    case 0: bytes[rng() % bytes.size()] = std::uint8_t(byte(rng)); break;
                    case 1: bytes.erase(bytes.begin() + long(rng() % bytes.size())); break;
                    case 2: bytes.insert(bytes.begin() + long(rng() % bytes.size()), std::uint8_t(byte(rng))); break;
                }
                if (bytes.empty()) bytes.push_back(0);
            }
        }
        HidReportDescriptor d;
        std::string error;
        if (!(error = parseHidReportDescriptor(bytes.data(), bytes.size(), d)).empty()) {
            ++rejected;
            EXPECT_FALSE(error.empty());
            continue;
        }
        HidPidLayout layout;
        if ((error = resolveHidPidLayout(bytes.data(), bytes.size(), layout)).empty()) {
            // Whatever was resolved must build reports within their declared size.
            for (const auto& r : {buildPidSetEffect(layout, 1, 100, 45.0), buildPidSetConstantForce(layout, 1, 0.3),
                                  buildPidEffectOperation(layout, 1, true),
                                  buildPidDeviceControl(layout, HidPidControl::StopAllEffects)})
                EXPECT_LE(r.size(), 4097u);
        }
    }
    EXPECT_GT(rejected, 100);  // the fuzzer does reach the error paths
}

TEST(HidReportDescriptor, SetAndGetFieldRoundTripSignedValues) {
    HidField f;
    f.bitOffset = 3;
    f.bitSize = 12;
    f.count = 2;
    f.logicalMin = -2048;
    f.logicalMax = 2047;
    std::vector<std::uint8_t> report(5, 0);
    ASSERT_TRUE(hidSetField(report, 1, f, 1, -5));
    std::int64_t v = 0;
    ASSERT_TRUE(hidGetField(report.data(), report.size(), 1, f, 1, v));
    EXPECT_EQ(v, -5);
    EXPECT_FALSE(hidSetField(report, 1, f, 2, 0));   // element out of range
    EXPECT_FALSE(hidSetField(report, 3, f, 1, 0));   // would run past the end
}

TEST(HidSysfs, ReadsTheDescriptorOfAHidrawNode) {
    namespace fs = std::filesystem;
    const fs::path root = fs::path(::testing::TempDir()) / "palpate_sysfs";
    fs::create_directories(root / "class/hidraw/hidraw3/device");
    const auto& bytes = pidJoystickDescriptor();
    std::ofstream(root / "class/hidraw/hidraw3/device/report_descriptor", std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    std::vector<std::uint8_t> out;
    std::string error;
    ASSERT_TRUE((error = readHidrawReportDescriptor("/dev/hidraw3", out, root.string())).empty()) << error;
    EXPECT_EQ(out, bytes);
    EXPECT_FALSE((error = readHidrawReportDescriptor("/dev/hidraw4", out, root.string())).empty());
    EXPECT_TRUE(contains(error, "HID device '/dev/hidraw4': cannot read its report descriptor")) << error;
    EXPECT_FALSE((error = readHidrawReportDescriptor("/dev/input/event3", out, root.string())).empty());
    EXPECT_TRUE(contains(error, "not a hidraw node")) << error;
    fs::remove_all(root);
}

HidDeviceInfo joystickInfo() {
    HidDeviceInfo info;
    info.path = "/fake/hidraw5";
    info.vendorId = 0x1234;
    info.productId = 0x5678;
    info.product = "FFB stick";
    info.usagePage = 1;
    info.usage = 4;
    return info;
}

TEST(HidPidDevice, SetsUpOneFiniteEffectAndStopsEverythingOnClose) {
    auto backend = std::make_shared<FakeHidBackend>();
    auto stick = backend->add(joystickInfo());
    stick->setReportDescriptor(pidJoystickDescriptor());
    HidPidDevice device(backend, HidSelector{});
    ASSERT_TRUE(device.open()) << device.lastError();
    EXPECT_EQ(device.state(), DeviceState::Ready);
    ASSERT_TRUE(waitUntil([&] { return stick->writes().size() >= 7; }));
    const auto writes = stick->writes();
    // Reset, actuators on, the effect with a finite (100 ms) duration, zero force, start.
    EXPECT_EQ(writes[0], (std::vector<std::uint8_t>{0x1c, 0x04}));
    EXPECT_EQ(writes[1], (std::vector<std::uint8_t>{0x1c, 0x01}));
    EXPECT_EQ(writes[2][0], 0x11);
    EXPECT_EQ(writes[2][3], 0x64);  // duration 100 ms, never "infinite" (0xffff)
    EXPECT_EQ(writes[3], (std::vector<std::uint8_t>{0x15, 0x01, 0x00, 0x00}));
    EXPECT_EQ(writes[4], (std::vector<std::uint8_t>{0x1a, 0x01, 0x01, 0x01}));
    ASSERT_EQ(stick->featureReports().size(), 1u);  // Create New Effect
    EXPECT_EQ(stick->featureReports()[0][0], 0x05);

    // A force along +x: direction 90 degrees, magnitude |F| / maxForceN of the range.
    device.writeForce(glm::vec3(device.spec().maxForceN * 0.5f, 0, 0));
    ASSERT_TRUE(waitUntil([&] {
        for (const auto& w : stick->writes())
            if (w == std::vector<std::uint8_t>{0x15, 0x01, 0x88, 0x13}) return true;
        return false;
    }));
    {
        const test::AllocationCounter counter;  // the tick's calls
        DeviceSample s;
        for (int i = 0; i < 1000; ++i) {
            device.setTimeS(i * 0.001);
            device.read(s);
            device.writeForce(glm::vec3(device.spec().maxForceN * 0.5f, 0, 0));
        }
        EXPECT_EQ(counter.count(), 0u);
    }
    // The stick's input: X at 1023 (right), Y centre.
    stick->pushReport({0x01, 0xff, 0x03, 0x00, 0x02, 0x00});
    DeviceSample sample;
    ASSERT_TRUE(waitUntil([&] { return device.read(sample) && sample.positionMm.x > 39.0f; }));

    device.close();
    const auto last = stick->writes();
    ASSERT_GE(last.size(), 2u);
    EXPECT_EQ(last[last.size() - 2], (std::vector<std::uint8_t>{0x1c, 0x03}));  // Stop All Effects
    EXPECT_EQ(last.back(), (std::vector<std::uint8_t>{0x1c, 0x02}));           // Disable Actuators
}

TEST(HidPidDevice, ErrorsNameTheDeviceAndTheProblem) {
    auto backend = std::make_shared<FakeHidBackend>();
    HidPidDevice none(backend, HidSelector{});
    EXPECT_FALSE(none.open());
    EXPECT_TRUE(contains(none.lastError(), "HID PID joystick: not found")) << none.lastError();

    auto stick = backend->add(joystickInfo());
    stick->setReportDescriptor({0x05, 0x01, 0xA1, 0x01});  // malformed: collection never closed
    HidPidDevice bad(backend, HidSelector{});
    EXPECT_FALSE(bad.open());
    EXPECT_TRUE(contains(bad.lastError(), "1234:5678")) << bad.lastError();
    EXPECT_TRUE(contains(bad.lastError(), "not closed")) << bad.lastError();

    stick->setReportDescriptor(pidJoystickDescriptor());
    stick->failWrites(true);
    HidPidDevice failing(backend, HidSelector{});
    EXPECT_FALSE(failing.open());
    EXPECT_TRUE(contains(failing.lastError(), "uploading the effect failed")) << failing.lastError();

    stick->failWrites(false);
    HidPidDevice device(backend, HidSelector{});
    ASSERT_TRUE(device.open()) << device.lastError();
    stick->unplug();  // -1 from hidapi
    ASSERT_TRUE(waitUntil([&] { return device.state() == DeviceState::Disconnected; }));
    EXPECT_TRUE(contains(device.lastError(), "/fake/hidraw5")) << device.lastError();
    DeviceSample sample;
    EXPECT_FALSE(device.read(sample));
}

}  // namespace
}  // namespace palpate
