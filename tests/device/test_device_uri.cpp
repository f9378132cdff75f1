// Device URIs: every scheme parses and creates the right, openable device; unknown schemes, empty
// URIs, 'sim:path:' without a file and bad files are errors that name the URI and the problem.

#include "device/open/DeviceUri.h"
#include "device/open/DeviceDiscovery.h"
#include "device/UdevHint.h"
#include "device/MouseDevice.h"
#include "device/SimulatedDevice.h"
#include "device/hid/FakeHidBackend.h"
#include "device/hid/HidPidDevice.h"
#include "device/hid/SpaceMouseDevice.h"
#include "device/usb/FakeUsbBackend.h"
#include "device/usb/FalconDevice.h"
#include "device/usb/FalconProtocol.h"
#include "tests/device/PidDescriptorFixture.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <cstdlib>
#include <unistd.h>

namespace palpate {
namespace {

bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

struct SchemeCase {
    const char* uri;
    DeviceKind kind;
    SimTrajectory trajectory;  ///< for sim: kinds
};

TEST(DeviceUri, EverySimulatedSchemeParsesAndOpens) {
    const SchemeCase cases[] = {
        {"sim:press", DeviceKind::SimPress, SimTrajectory::PressHold},
        {"sim:stroke", DeviceKind::SimStroke, SimTrajectory::Stroke},
        {"sim:scan", DeviceKind::SimScan, SimTrajectory::Scan},
        {"sim:sine", DeviceKind::SimSine, SimTrajectory::Sine},
    };
    for (const SchemeCase& c : cases) {
        DeviceUri parsed;
        std::string error;
        ASSERT_TRUE((error = parseDeviceUri(c.uri, parsed)).empty()) << c.uri << ": " << error;
        EXPECT_EQ(parsed.kind, c.kind) << c.uri;
        EXPECT_EQ(formatDeviceUri(parsed), c.uri);
        auto device = openDeviceUri(c.uri, error);
        ASSERT_TRUE(device) << c.uri << ": " << error;
        EXPECT_EQ(device->state(), DeviceState::Ready) << c.uri;
        auto* sim = dynamic_cast<SimulatedDevice*>(device.get());
        ASSERT_NE(sim, nullptr) << c.uri;
        EXPECT_EQ(sim->trajectory(), c.trajectory) << c.uri;
        EXPECT_TRUE(device->spec().actuated);
    }
}

TEST(DeviceUri, MouseSchemeParsesAndOpens) {
    DeviceUri parsed;
    std::string error;
    ASSERT_TRUE((error = parseDeviceUri("mouse:", parsed)).empty()) << error;
    EXPECT_EQ(parsed.kind, DeviceKind::Mouse);
    EXPECT_EQ(formatDeviceUri(parsed), "mouse:");
    auto device = openDeviceUri("mouse:", error);
    ASSERT_TRUE(device) << error;
    EXPECT_NE(dynamic_cast<MouseDevice*>(device.get()), nullptr);
    EXPECT_EQ(device->state(), DeviceState::Ready);
    EXPECT_FALSE(device->spec().actuated);
}

TEST(DeviceUri, SimPathLoadsTheFileAndKeepsColonsInThePath) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("palpate_uri_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path file = dir / "a:b.txt";  // the file part may itself contain ':'
    std::ofstream(file) << "0 0 0 2\n1 0 0 -1\n";
    const std::string uri = "sim:path:" + file.string();

    DeviceUri parsed;
    std::string error;
    ASSERT_TRUE((error = parseDeviceUri(uri, parsed)).empty()) << error;
    EXPECT_EQ(parsed.kind, DeviceKind::SimPath);
    EXPECT_EQ(parsed.path, file.string());
    EXPECT_EQ(formatDeviceUri(parsed), uri);
    auto device = openDeviceUri(uri, error);
    ASSERT_TRUE(device) << error;
    auto* sim = dynamic_cast<SimulatedDevice*>(device.get());
    ASSERT_NE(sim, nullptr);
    EXPECT_EQ(sim->trajectory(), SimTrajectory::Waypoints);
    EXPECT_EQ(sim->positionAtMm(0.5), glm::vec3(0.0f, 0.0f, 0.5f));
    fs::remove_all(dir);
}

struct BadUri {
    std::string uri;
    const char* mention;
};

TEST(DeviceUri, BadUrisAreErrorsNamingTheUriAndTheProblem) {
    const BadUri cases[] = {
        {"falcon:", "needs an index"},
        {"falcon:x", "Falcon index 'x' is not a number from 0 to 99"},
        {"falcon:100", "is not a number from 0 to 99"},
        {"falcon:0?firmware=", "option 'firmware' needs a value"},
        {"falcon:0?mode=rate", "unknown option 'mode' (expected firmware)"},
        {"falcon:0?firmware=a&firmware=b", "given twice"},
        {"spacemouse:0", "takes no argument"},
        {"spacemouse:?mode=fast", "mode 'fast' is not 'rate' or 'position'"},
        {"hid:", "needs VID:PID[:SERIAL]"},
        {"hid:046d", "needs VID:PID[:SERIAL]"},
        {"hid:zz:c626", "vendor ID 'zz' is not 1 to 4 hex digits"},
        {"hid:046d:12345", "product ID '12345' is not 1 to 4 hex digits"},
        {"hid:046d:c626:", "empty serial"},
        {"hidpid:?mode=rate", "this scheme takes none"},
        {"replay:", "needs a recording file"},
        {"usb:0403:cb48", "unknown scheme 'usb'"},
        {"SIM:press", "unknown scheme 'SIM'"},
        {"press", "no ':' after the scheme"},
        {"sim:", "needs a trajectory"},
        {"sim:bogus", "unknown simulated trajectory 'bogus'"},
        {"sim:press:extra", "unknown simulated trajectory 'press:extra'"},
        {"sim:path", "needs a waypoint file"},
        {"sim:path:", "needs a waypoint file"},
        {"mouse:left", "takes no argument"},
        {":", "unknown scheme ''"},
        {std::string("sim:\x01", 5), "\\x01"},
    };
    for (const BadUri& c : cases) {
        DeviceUri parsed;
        std::string error;
        EXPECT_FALSE((error = parseDeviceUri(c.uri, parsed)).empty()) << c.uri;
        EXPECT_TRUE(contains(error, c.mention)) << c.uri << " -> " << error;
        EXPECT_TRUE(c.uri.empty() || contains(error, "device URI '")) << error;
        std::string openError;
        EXPECT_EQ(openDeviceUri(c.uri, openError), nullptr) << c.uri;
        EXPECT_EQ(openError, error);
    }
    // Unknown schemes list what is known, so the user can correct the URI.
    std::string error;
    DeviceUri parsed;
    error = parseDeviceUri("usb:1", parsed);
    EXPECT_TRUE(contains(error, "sim:press") && contains(error, "mouse:")) << error;
    EXPECT_TRUE(contains(error, "hid:VID:PID[:SERIAL]") && contains(error, "falcon:")) << error;
}

TEST(DeviceUri, EmptyUriIsAnError) {
    DeviceUri parsed;
    std::string error;
    EXPECT_FALSE((error = parseDeviceUri("", parsed)).empty());
    EXPECT_TRUE(contains(error, "empty")) << error;
    EXPECT_EQ(openDeviceUri("", error), nullptr);
}

TEST(DeviceUri, SimPathWithAMissingFileNamesTheUriAndTheFile) {
    std::string error;
    EXPECT_EQ(openDeviceUri("sim:path:/no/such/path.txt", error), nullptr);
    EXPECT_TRUE(contains(error, "device URI 'sim:path:/no/such/path.txt'")) << error;
    EXPECT_TRUE(contains(error, "/no/such/path.txt: no such file")) << error;
    EXPECT_EQ(openDeviceUri("sim:path:/", error), nullptr);
    EXPECT_TRUE(contains(error, "is a directory")) << error;
}

TEST(DeviceUri, ListedSchemesAreTheOnesParsed) {
    const auto schemes = listDeviceSchemes();
    // The simulated six, and the hardware forms this build has compiled in.
    std::size_t expected = 6;
    for (const BackendInfo& b : listDeviceBackends())
        if (b.compiledIn) ++expected;
    ASSERT_EQ(schemes.size(), expected);
    for (const DeviceSchemeInfo& s : schemes) {
        EXPECT_FALSE(s.description.empty()) << s.uri;
        DeviceUri parsed;
        std::string error;
        EXPECT_TRUE((error = parseDeviceUri(s.uri, parsed)).empty())
            << s.uri << ": " << error;  // FILE parses as a name
    }
    auto has = [&](const char* uri) {
        for (const DeviceSchemeInfo& s : schemes)
            if (s.uri == uri) return true;
        return false;
    };
    for (const char* uri : {"sim:press", "sim:stroke", "sim:scan", "sim:sine", "sim:path:FILE", "mouse:"})
        EXPECT_TRUE(has(uri)) << uri;
}

TEST(DeviceUri, HardwareSchemesParseAndFormatCanonically) {
    struct Case {
        const char* uri;
        const char* canonical;
        DeviceKind kind;
    };
    const Case cases[] = {
        {"spacemouse:", "spacemouse:", DeviceKind::SpaceMouse},
        {"spacemouse:?mode=position", "spacemouse:?mode=position", DeviceKind::SpaceMouse},
        {"spacemouse:?mode=rate", "spacemouse:", DeviceKind::SpaceMouse},
        {"hid:046D:C626", "hid:046d:c626", DeviceKind::Hid},
        {"hid:0x256f:c635:ABC:1?mode=position", "hid:256f:c635:ABC:1?mode=position", DeviceKind::Hid},
        {"hidpid:", "hidpid:", DeviceKind::HidPid},
        {"hidpid:1234:5678", "hidpid:1234:5678", DeviceKind::HidPid},
        {"falcon:0", "falcon:0", DeviceKind::Falcon},
        {"falcon:2?firmware=/opt/novint/test_firmware.bin", "falcon:2?firmware=/opt/novint/test_firmware.bin",
         DeviceKind::Falcon},
        {"replay:/tmp/a:b.rec", "replay:/tmp/a:b.rec", DeviceKind::Replay},
    };
    for (const Case& c : cases) {
        DeviceUri parsed;
        std::string error;
        ASSERT_TRUE((error = parseDeviceUri(c.uri, parsed)).empty()) << c.uri << ": " << error;
        EXPECT_EQ(parsed.kind, c.kind) << c.uri;
        EXPECT_EQ(formatDeviceUri(parsed), c.canonical) << c.uri;
        DeviceUri again;
        ASSERT_TRUE((error = parseDeviceUri(formatDeviceUri(parsed), again)).empty()) << error;
        EXPECT_EQ(again, parsed) << c.uri;
    }
    DeviceUri parsed;
    std::string error;
    ASSERT_TRUE((error = parseDeviceUri("hid:256f:c635:ABC:1", parsed)).empty());
    EXPECT_EQ(parsed.vendorId, 0x256f);
    EXPECT_EQ(parsed.productId, 0xc635);
    EXPECT_EQ(parsed.serial, "ABC:1");  // the serial may contain ':'
    ASSERT_TRUE((error = parseDeviceUri("falcon:2?firmware=/x/fw.bin", parsed)).empty());
    EXPECT_EQ(parsed.index, 2);
    EXPECT_EQ(parsed.firmware, "/x/fw.bin");
}

TEST(DeviceUri, HardwareUrisCreateTheirBackendWithoutTouchingHardware) {
    auto hid = std::make_shared<FakeHidBackend>();
    auto usb = std::make_shared<FakeUsbBackend>();
    const DeviceBackends backends{hid, usb};
    std::string error;
    // Creating needs nothing plugged in (the GUI creates devices for their spec alone).
    auto sm = createDeviceFromUri("spacemouse:?mode=position", error, backends);
    ASSERT_NE(dynamic_cast<SpaceMouseDevice*>(sm.get()), nullptr) << error;
    EXPECT_FALSE(sm->spec().actuated);
    auto byId = createDeviceFromUri("hid:046d:c626", error, backends);  // 3Dconnexion's: a SpaceMouse
    EXPECT_NE(dynamic_cast<SpaceMouseDevice*>(byId.get()), nullptr) << error;
    auto stick = createDeviceFromUri("hid:1234:5678", error, backends);  // anyone else's: HID PID
    EXPECT_NE(dynamic_cast<HidPidDevice*>(stick.get()), nullptr) << error;
    auto falcon = createDeviceFromUri("falcon:0", error, backends);
    ASSERT_NE(dynamic_cast<FalconDevice*>(falcon.get()), nullptr) << error;
    EXPECT_TRUE(falcon->spec().actuated);
    EXPECT_TRUE(hid->enumerate().empty());

    // Opening reports the device's own error.
    EXPECT_EQ(openDeviceUri("spacemouse:", error, backends), nullptr);
    EXPECT_TRUE(contains(error, "device URI 'spacemouse:': SpaceMouse: not found")) << error;
    EXPECT_EQ(openDeviceUri("falcon:0?firmware=/no/fw.bin", error, backends), nullptr);
    EXPECT_TRUE(contains(error, "device URI 'falcon:0?firmware=/no/fw.bin': Falcon 0:")) << error;
    EXPECT_TRUE(contains(error, "'/no/fw.bin': does not exist")) << error;

    // And a SpaceMouse that is there opens through the URI.
    HidDeviceInfo info;
    info.path = "/fake/hidraw0";
    info.vendorId = 0x256f;
    info.productId = 0xc635;
    info.usagePage = 1;
    info.usage = 8;
    hid->add(info);
    auto open = openDeviceUri("hid:256f:c635", error, backends);
    ASSERT_TRUE(open) << error;
    EXPECT_EQ(open->state(), DeviceState::Ready);
}

TEST(DeviceUri, ReplayPointsToTheEngineUntilAFactoryIsRegistered) {
    std::string error;
    EXPECT_EQ(createDeviceFromUri("replay:/tmp/session.rec", error), nullptr);
    EXPECT_TRUE(contains(error, "played back by the engine")) << error;
    EXPECT_TRUE(contains(error, "record replay")) << error;
    for (const DeviceSchemeInfo& s : listDeviceSchemes()) EXPECT_NE(s.uri, "replay:FILE");

    std::string seenPath;
    registerDeviceFactory(DeviceKind::Replay, [&](const DeviceUri& uri, std::string&) -> std::unique_ptr<HapticDevice> {
        seenPath = uri.path;
        return std::make_unique<MouseDevice>();  // any device: the hook is what is tested
    });
    auto device = createDeviceFromUri("replay:/tmp/session.rec", error);
    EXPECT_NE(device, nullptr) << error;
    EXPECT_EQ(seenPath, "/tmp/session.rec");
    bool listed = false;
    for (const DeviceSchemeInfo& s : listDeviceSchemes()) listed = listed || s.uri == "replay:FILE";
    EXPECT_TRUE(listed);
    registerDeviceFactory(DeviceKind::Replay, [](const DeviceUri&, std::string& e) -> std::unique_ptr<HapticDevice> {
        e = "recording 'x' is damaged";
        return nullptr;
    });
    EXPECT_EQ(createDeviceFromUri("replay:x", error), nullptr);
    EXPECT_EQ(error, "device URI 'replay:x': recording 'x' is damaged");
    unregisterDeviceFactory(DeviceKind::Replay);
    EXPECT_EQ(createDeviceFromUri("replay:x", error), nullptr);
    EXPECT_TRUE(contains(error, "played back by the engine")) << error;
}

TEST(DeviceUri, FalconFirmwareFallsBackToTheEnvironment) {
    auto usb = std::make_shared<FakeUsbBackend>();
    ::setenv("PALPATE_FALCON_FIRMWARE", "/env/firmware.bin", 1);
    std::string error;
    EXPECT_EQ(openDeviceUri("falcon:0", error, DeviceBackends{nullptr, usb}), nullptr);
    EXPECT_TRUE(contains(error, "'/env/firmware.bin': does not exist")) << error;
    // The URI's own path wins over the environment.
    EXPECT_EQ(openDeviceUri("falcon:0?firmware=/uri/fw.bin", error, DeviceBackends{nullptr, usb}), nullptr);
    EXPECT_TRUE(contains(error, "'/uri/fw.bin'")) << error;
    ::unsetenv("PALPATE_FALCON_FIRMWARE");
}

TEST(DeviceDiscovery, ListsSpaceMicePidJoysticksAndFalconsWithTheirUris) {
    auto hid = std::make_shared<FakeHidBackend>();
    auto usb = std::make_shared<FakeUsbBackend>();
    HidDeviceInfo sm;
    sm.path = "/fake/hidraw0";
    sm.vendorId = 0x046d;
    sm.productId = 0xc626;
    sm.product = "SpaceNavigator";
    sm.usagePage = 1;
    sm.usage = 8;
    hid->add(sm);
    HidDeviceInfo smOther = sm;  // the same unit's other collection: not listed twice
    smOther.path = "/fake/hidraw1";
    smOther.usagePage = 0x0c;
    smOther.usage = 1;
    hid->add(smOther);
    HidDeviceInfo stick;
    stick.path = "/fake/hidraw2";
    stick.vendorId = 0x1234;
    stick.productId = 0x5678;
    stick.serial = "S1";
    hid->add(stick)->setReportDescriptor(test::pidJoystickDescriptor());
    HidDeviceInfo keyboard;  // neither: not listed
    keyboard.path = "/fake/hidraw3";
    keyboard.vendorId = 0x04d9;
    keyboard.productId = 0x0001;
    hid->add(keyboard)->setReportDescriptor({0x05, 0x01, 0x09, 0x06, 0xA1, 0x01, 0xC0});
    UsbDeviceInfo f;
    f.busNumber = 3;
    f.deviceAddress = 9;
    f.vendorId = kFalconVendorId;
    f.productId = kFalconProductId;
    usb->add(f);

    const auto found = discoverDevices(DeviceBackends{hid, usb});
    ASSERT_EQ(found.size(), 3u);
    EXPECT_EQ(found[0].backend, "spacemouse");
    EXPECT_EQ(found[0].uri, "hid:046d:c626");
    EXPECT_EQ(found[1].backend, "hidpid");
    EXPECT_EQ(found[1].uri, "hid:1234:5678:S1");
    EXPECT_EQ(found[2].backend, "falcon");
    EXPECT_EQ(found[2].uri, "falcon:0");
    EXPECT_EQ(found[2].node, "/dev/bus/usb/003/009");
    for (const auto& d : found) {
        DeviceUri parsed;
        std::string error;
        EXPECT_TRUE((error = parseDeviceUri(d.uri, parsed)).empty()) << d.uri << ": " << error;
    }
}

TEST(UdevHint, PermissionMessagesNameARuleWeShipThatCoversTheDevice) {
    struct Case {
        std::uint16_t vid, pid;
        const char* file;
        const char* mention;  ///< what the rule must match on
    };
    const Case cases[] = {
        {0x256f, 0xc635, "70-palpate-spacemouse.rules", "256f"},
        {0x046d, 0xc626, "70-palpate-spacemouse.rules", "c6??"},
        {0x0403, 0xcb48, "70-palpate-falcon.rules", "cb48"},
        {0x1234, 0x5678, "70-palpate-hid-pid.rules", "idVendor"},
    };
    for (const Case& c : cases) {
        EXPECT_EQ(udevRuleFileFor(c.vid, c.pid), c.file);
        const std::string message = permissionDeniedMessage("/dev/hidraw7", c.vid, c.pid);
        EXPECT_TRUE(contains(message, std::string("resources/udev/") + c.file)) << message;
        EXPECT_TRUE(contains(message, "/dev/hidraw7")) << message;
        EXPECT_TRUE(contains(message, "udevadm")) << message;
        std::ifstream in(std::string(PALPATE_UDEV_DIR) + "/" + c.file);
        ASSERT_TRUE(in) << c.file << " is not shipped";
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_TRUE(contains(text, c.mention)) << c.file;
        EXPECT_TRUE(contains(text, "uaccess")) << c.file;
    }
    EXPECT_TRUE(contains(permissionDeniedMessage("/dev/hidraw7", 0x1234, 0x5678), "edit its VID:PID first"));
}

}  // namespace
}  // namespace palpate
