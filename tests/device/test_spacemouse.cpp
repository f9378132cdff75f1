// SpaceMouse backend: the report codec on byte fixtures written from the documented layouts
// (libndofdev / spacenavd, docs/devices.md), rate and position control, and the device with its
// I/O thread on a fake hidapi backend: interface selection (usage page 1 / usage 8), a recorded
// capture replayed, -1 from hidapi (unplug) -> Disconnected -> reconnect, permission denied.

#include "device/hid/FakeHidBackend.h"
#include "device/hid/HidCapture.h"
#include "device/hid/SpaceMouseCodec.h"
#include "device/hid/SpaceMouseControl.h"
#include "device/hid/SpaceMouseDevice.h"
#include "tests/device/DeviceTestSupport.h"
#include "tests/support/AllocationCounter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

namespace palpate {
namespace {

using test::waitUntil;

bool contains(const std::string& haystack, const std::string& needle) { return haystack.find(needle) != std::string::npos; }

TEST(SpaceMouseCodec, OlderUnitsSendTranslationAndRotationInReports1And2) {
    SpaceMouseRaw raw;
    // Tx = 10 (0a 00), Ty = -10 (f6 ff), Tz = 350 (5e 01)
    const std::uint8_t r1[] = {0x01, 0x0a, 0x00, 0xf6, 0xff, 0x5e, 0x01};
    EXPECT_EQ(decodeSpaceMouseReport(r1, sizeof r1, raw), SpaceMouseReport::Translation);
    EXPECT_EQ(raw.translation[0], 10);
    EXPECT_EQ(raw.translation[1], -10);
    EXPECT_EQ(raw.translation[2], 350);
    EXPECT_EQ(raw.rotation[0], 0);
    // Rx = -350 (a2 fe), Ry = 1, Rz = -1
    const std::uint8_t r2[] = {0x02, 0xa2, 0xfe, 0x01, 0x00, 0xff, 0xff};
    EXPECT_EQ(decodeSpaceMouseReport(r2, sizeof r2, raw), SpaceMouseReport::Rotation);
    EXPECT_EQ(raw.rotation[0], -350);
    EXPECT_EQ(raw.rotation[1], 1);
    EXPECT_EQ(raw.rotation[2], -1);
    EXPECT_EQ(raw.translation[2], 350);  // untouched by report 2
}

TEST(SpaceMouseCodec, NewerUnitsSendAllSixAxesInReport1) {
    SpaceMouseRaw raw;
    const std::uint8_t r1[] = {0x01, 0x01, 0x00, 0x02, 0x00, 0x03, 0x00, 0xfc, 0xff, 0xfb, 0xff, 0x5e, 0x01};
    EXPECT_EQ(decodeSpaceMouseReport(r1, sizeof r1, raw), SpaceMouseReport::SixAxes);
    EXPECT_EQ(raw.translation, (std::array<std::int16_t, 3>{1, 2, 3}));
    EXPECT_EQ(raw.rotation, (std::array<std::int16_t, 3>{-4, -5, 350}));
}

TEST(SpaceMouseCodec, ButtonsAreBitsLittleEndian) {
    SpaceMouseRaw raw;
    const std::uint8_t r3[] = {0x03, 0x02, 0x01};  // button 1 and button 8
    EXPECT_EQ(decodeSpaceMouseReport(r3, sizeof r3, raw), SpaceMouseReport::Buttons);
    EXPECT_EQ(raw.buttons, 0x0102u);
    const std::uint8_t up[] = {0x03, 0x00};
    decodeSpaceMouseReport(up, sizeof up, raw);
    EXPECT_EQ(raw.buttons, 0u);
}

TEST(SpaceMouseCodec, ShortEmptyAndUnknownReportsLeaveTheStateAlone) {
    SpaceMouseRaw raw;
    raw.translation = {7, 8, 9};
    raw.buttons = 5;
    const std::uint8_t short1[] = {0x01, 0x0a, 0x00, 0xf6};
    EXPECT_EQ(decodeSpaceMouseReport(short1, sizeof short1, raw), SpaceMouseReport::ShortReport);
    const std::uint8_t short2[] = {0x02, 0x0a};
    EXPECT_EQ(decodeSpaceMouseReport(short2, sizeof short2, raw), SpaceMouseReport::ShortReport);
    const std::uint8_t short3[] = {0x03};
    EXPECT_EQ(decodeSpaceMouseReport(short3, sizeof short3, raw), SpaceMouseReport::ShortReport);
    EXPECT_EQ(decodeSpaceMouseReport(short1, 0, raw), SpaceMouseReport::Empty);
    EXPECT_EQ(decodeSpaceMouseReport(nullptr, 7, raw), SpaceMouseReport::Empty);
    const std::uint8_t battery[] = {0x17, 0x64};
    EXPECT_EQ(decodeSpaceMouseReport(battery, sizeof battery, raw), SpaceMouseReport::Ignored);
    EXPECT_EQ(raw.translation, (std::array<std::int16_t, 3>{7, 8, 9}));
    EXPECT_EQ(raw.buttons, 5u);
}

TEST(SpaceMouseCodec, LedReportAndVendorIds) {
    EXPECT_EQ(encodeSpaceMouseLed(true), (std::array<std::uint8_t, 2>{4, 1}));
    EXPECT_EQ(encodeSpaceMouseLed(false), (std::array<std::uint8_t, 2>{4, 0}));
    EXPECT_TRUE(isSpaceMouseVidPid(0x046d, 0xc626));  // SpaceNavigator
    EXPECT_TRUE(isSpaceMouseVidPid(0x256f, 0xc635));  // SpaceMouse Compact
    EXPECT_FALSE(isSpaceMouseVidPid(0x046d, 0xc077));  // a Logitech mouse
    EXPECT_FALSE(isSpaceMouseVidPid(0x0403, 0xcb48));
}

TEST(SpaceMouseControl, DeadbandAndFullScaleAndSceneAxes) {
    SpaceMouseControlDef def;
    SpaceMouseRaw raw;
    raw.translation = {std::int16_t(def.deadbandCounts), 350, -700};
    const glm::vec3 d = spaceMouseDeflection(raw, def);
    EXPECT_EQ(d.x, 0.0f);   // inside the deadband
    EXPECT_EQ(d.y, -1.0f);  // +Ty (toward the user) is -y in the scene
    EXPECT_EQ(d.z, 1.0f);   // -Tz (pulling the cap up) is +z, clamped at full scale
    raw.translation = {std::int16_t(def.deadbandCounts + 1), 0, 0};
    EXPECT_GT(spaceMouseDeflection(raw, def).x, 0.0f);
    EXPECT_LT(spaceMouseDeflection(raw, def).x, 0.01f);  // continuous at the deadband edge
}

TEST(SpaceMouseControl, RateModeIntegratesAndStaysWhereLetGo) {
    SpaceMouseControlDef def;
    def.mode = SpaceMouseMode::Rate;
    SpaceMouseControl control(def);
    SpaceMouseRaw press;
    press.translation = {0, 0, 350};  // pressing the cap fully down: into the tissue at rateMmPerS
    for (int i = 0; i < 100; ++i) control.update(press, 0.001);
    EXPECT_NEAR(control.positionMm().z, def.homeMm.z - def.rateMmPerS * 0.1, 1e-3);
    const glm::vec3 held = control.positionMm();
    control.update(SpaceMouseRaw{}, 0.5);  // released: stays
    EXPECT_EQ(control.positionMm(), held);
    // A huge gap does not fling the tool: at most 50 ms of motion.
    control.update(press, 10.0);
    EXPECT_NEAR(control.positionMm().z, held.z - def.rateMmPerS * 0.05, 1e-3);
    // Never leaves the workspace sphere around home.
    for (int i = 0; i < 10000; ++i) control.update(press, 0.05);
    EXPECT_LE(std::fabs(control.positionMm().z - def.homeMm.z), def.workspaceRadiusMm + 1e-3);
    // Non-finite or negative time steps do not move it.
    const glm::vec3 before = control.positionMm();
    control.update(press, -1.0);
    control.update(press, std::nan(""));
    EXPECT_EQ(control.positionMm(), before);
}

TEST(SpaceMouseControl, PositionModeFollowsTheCapAndSpringsBack) {
    SpaceMouseControlDef def;
    def.mode = SpaceMouseMode::Position;
    SpaceMouseControl control(def);
    SpaceMouseRaw raw;
    raw.translation = {350, 0, 0};
    EXPECT_NEAR(control.update(raw, 0.001).x, def.homeMm.x + def.positionRangeMm, 1e-4);
    EXPECT_EQ(control.update(SpaceMouseRaw{}, 0.001), def.homeMm);
}

TEST(SpaceMouseControl, InvalidDefinitionsAreRejectedByName) {
    SpaceMouseControlDef def;
    def.deadbandCounts = 400;
    EXPECT_TRUE(hasProblem(validateSpaceMouseControlDef(def), "deadbandCounts"))
        << joinedMessages(validateSpaceMouseControlDef(def));
    def = {};
    def.rateMmPerS = std::nan("");
    EXPECT_TRUE(hasProblem(validateSpaceMouseControlDef(def), "rateMmPerS"))
        << joinedMessages(validateSpaceMouseControlDef(def));
    EXPECT_THROW(SpaceMouseControl{def}, std::invalid_argument);
}

HidDeviceInfo navigatorInfo(const std::string& path, std::uint16_t usagePage, std::uint16_t usage) {
    HidDeviceInfo info;
    info.path = path;
    info.vendorId = 0x046d;
    info.productId = 0xc626;
    info.product = "SpaceNavigator";
    info.usagePage = usagePage;
    info.usage = usage;
    return info;
}

TEST(SpaceMouseDevice, OpensTheMultiAxisInterfaceAndSwitchesTheLedOn) {
    auto backend = std::make_shared<FakeHidBackend>();
    auto keyboardLike = backend->add(navigatorInfo("/fake/hidraw0", 0x0c, 0x01));  // consumer control collection
    auto sixDof = backend->add(navigatorInfo("/fake/hidraw1", 1, 8));
    SpaceMouseDevice device(backend, HidSelector{});
    ASSERT_TRUE(device.open()) << device.lastError();
    EXPECT_EQ(device.state(), DeviceState::Ready);
    EXPECT_EQ(device.devicePath(), "/fake/hidraw1");
    ASSERT_FALSE(sixDof->writes().empty());
    EXPECT_EQ(sixDof->writes().front(), (std::vector<std::uint8_t>{4, 1}));
    EXPECT_TRUE(keyboardLike->writes().empty());
    EXPECT_FALSE(device.spec().actuated);
    device.close();
    EXPECT_EQ(sixDof->writes().back(), (std::vector<std::uint8_t>{4, 0}));  // LED off on close
    EXPECT_EQ(device.state(), DeviceState::Disconnected);
}

TEST(SpaceMouseDevice, ReplaysACaptureIntoSamples) {
    auto backend = std::make_shared<FakeHidBackend>();
    auto unit = backend->add(navigatorInfo("/fake/hidraw1", 1, 8));
    std::vector<FakeHidRead> reads;
    std::string error;
    ASSERT_TRUE((error = loadHidCapture(PALPATE_DEVICE_FIXTURES "/spacemouse_navigator.hidcap", reads)).empty())
        << error;
    ASSERT_EQ(reads.size(), 6u);
    SpaceMouseDeviceDef def;
    def.control.mode = SpaceMouseMode::Position;
    SpaceMouseDevice device(backend, HidSelector{}, def);
    ASSERT_TRUE(device.open()) << device.lastError();
    for (auto& r : reads) unit->pushRead(r);
    ASSERT_TRUE(waitUntil([&] { return unit->pendingReads() == 0 && device.raw().buttons == 1u; }));
    ASSERT_TRUE(waitUntil([&] { return device.shortReports() == 1u; }));
    const SpaceMouseRaw raw = device.raw();
    EXPECT_EQ(raw.translation, (std::array<std::int16_t, 3>{350, 0, 0}));
    EXPECT_EQ(raw.rotation, (std::array<std::int16_t, 3>{-1, 2, -350}));
    EXPECT_EQ(device.reportsDecoded(), 3u);

    DeviceSample a, b;
    device.setTimeS(1.0);
    ASSERT_TRUE(device.read(a));
    device.setTimeS(1.001);
    ASSERT_TRUE(device.read(b));
    EXPECT_GT(b.sequence, a.sequence);  // every read is a fresh reading
    EXPECT_EQ(b.timeS, 1.001);
    EXPECT_NEAR(b.positionMm.x, def.control.homeMm.x + def.control.positionRangeMm, 1e-4);
    EXPECT_EQ(b.buttons, 1u);
}

TEST(SpaceMouseDevice, HidapiErrorMeansDisconnectedThenItReconnects) {
    auto backend = std::make_shared<FakeHidBackend>();
    auto unit = backend->add(navigatorInfo("/fake/hidraw1", 1, 8));
    SpaceMouseDeviceDef def;
    def.reconnectPeriodMs = 1;
    SpaceMouseDevice device(backend, HidSelector{}, def);
    ASSERT_TRUE(device.open());
    unit->pushReport({0x01, 0x5e, 0x01, 0, 0, 0, 0});
    ASSERT_TRUE(waitUntil([&] { return device.raw().translation[0] == 350; }));

    backend->remove("/fake/hidraw1");  // reads now return -1
    ASSERT_TRUE(waitUntil([&] { return device.state() == DeviceState::Disconnected; }));
    DeviceSample sample;
    EXPECT_FALSE(device.read(sample));
    EXPECT_TRUE(contains(device.lastError(), "read failed")) << device.lastError();
    EXPECT_TRUE(contains(device.lastError(), "/fake/hidraw1")) << device.lastError();
    EXPECT_EQ(device.raw().translation[0], 0);  // no drifting at the last rate

    backend->add(navigatorInfo("/fake/hidraw2", 1, 8));  // plugged in again (a new node)
    ASSERT_TRUE(waitUntil([&] { return device.state() == DeviceState::Ready; }));
    EXPECT_EQ(device.reconnects(), 1u);
    EXPECT_EQ(device.devicePath(), "/fake/hidraw2");
    EXPECT_TRUE(device.read(sample));
    EXPECT_EQ(sample.positionMm, def.control.homeMm);  // restarts from home
}

TEST(SpaceMouseDevice, OpenErrorsNameTheDeviceAndTheProblem) {
    auto backend = std::make_shared<FakeHidBackend>();
    SpaceMouseDevice none(backend, HidSelector{});
    EXPECT_FALSE(none.open());
    EXPECT_EQ(none.state(), DeviceState::Disconnected);
    EXPECT_TRUE(contains(none.lastError(), "SpaceMouse: not found")) << none.lastError();

    auto unit = backend->add(navigatorInfo("/dev/hidraw9", 1, 8));
    unit->denyOpen(true);
    SpaceMouseDevice denied(backend, HidSelector{});
    EXPECT_FALSE(denied.open());
    EXPECT_TRUE(contains(denied.lastError(), "permission denied on /dev/hidraw9 (046d:c626)")) << denied.lastError();
    EXPECT_TRUE(contains(denied.lastError(), "70-palpate-spacemouse.rules")) << denied.lastError();

    // A specific unit by VID:PID:SERIAL that is not there.
    HidSelector selector{false, 0x256f, 0xc635, "ABC"};
    SpaceMouseDevice other(backend, selector);
    EXPECT_FALSE(other.open());
    EXPECT_TRUE(contains(other.lastError(), "SpaceMouse 256f:c635 serial ABC: not found")) << other.lastError();

    SpaceMouseDevice noHid(nullptr, HidSelector{});
    EXPECT_FALSE(noHid.open());
    EXPECT_TRUE(contains(noHid.lastError(), "no HID support")) << noHid.lastError();
}

TEST(HidCapture, BadLinesAreNamed) {
    const std::string path = ::testing::TempDir() + "bad.hidcap";
    {
        std::ofstream out(path);
        out << "01 02\n01 zz\n";
    }
    std::vector<FakeHidRead> reads;
    std::string error;
    EXPECT_FALSE((error = loadHidCapture(path, reads)).empty());
    EXPECT_TRUE(contains(error, "line 2")) << error;
    EXPECT_TRUE(contains(error, "'zz'")) << error;
    EXPECT_FALSE((error = loadHidCapture("/no/such.hidcap", reads)).empty());
    EXPECT_TRUE(contains(error, "cannot be read")) << error;
}

TEST(SpaceMouseDevice, HapticThreadCallsDoNotAllocate) {
    auto backend = std::make_shared<FakeHidBackend>();
    auto unit = backend->add(navigatorInfo("/fake/hidraw1", 1, 8));
    SpaceMouseDevice device(backend, HidSelector{});
    ASSERT_TRUE(device.open());
    unit->pushReport({0x01, 0x5e, 0x01, 0, 0, 0, 0});
    ASSERT_TRUE(waitUntil([&] { return device.raw().translation[0] == 350; }));
    DeviceSample sample;
    const test::AllocationCounter counter;
    for (int i = 0; i < 1000; ++i) {
        device.setTimeS(i * 0.001);
        ASSERT_TRUE(device.read(sample));
        device.writeForce(glm::vec3(1.0f));
    }
    EXPECT_EQ(counter.count(), 0u);
    EXPECT_GT(sample.positionMm.x, 0.0f);  // it did move: rate control at full deflection
}

}  // namespace
}  // namespace palpate
