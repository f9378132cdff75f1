// Device URIs: every scheme parses and creates the right, openable device; unknown schemes, empty
// URIs, 'sim:path:' without a file and bad files are errors that name the URI and the problem.

#include "device/DeviceUri.h"
#include "device/MouseDevice.h"
#include "device/SimulatedDevice.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
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
        ASSERT_TRUE(parseDeviceUri(c.uri, parsed, error)) << c.uri << ": " << error;
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
    ASSERT_TRUE(parseDeviceUri("mouse:", parsed, error)) << error;
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
    ASSERT_TRUE(parseDeviceUri(uri, parsed, error)) << error;
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
        {"falcon:", "unknown scheme 'falcon'"},
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
        EXPECT_FALSE(parseDeviceUri(c.uri, parsed, error)) << c.uri;
        EXPECT_TRUE(contains(error, c.mention)) << c.uri << " -> " << error;
        EXPECT_TRUE(c.uri.empty() || contains(error, "device URI '")) << error;
        std::string openError;
        EXPECT_EQ(openDeviceUri(c.uri, openError), nullptr) << c.uri;
        EXPECT_EQ(openError, error);
    }
    // Unknown schemes list what is known, so the user can correct the URI.
    std::string error;
    DeviceUri parsed;
    parseDeviceUri("falcon:", parsed, error);
    EXPECT_TRUE(contains(error, "sim:press") && contains(error, "mouse:")) << error;
}

TEST(DeviceUri, EmptyUriIsAnError) {
    DeviceUri parsed;
    std::string error;
    EXPECT_FALSE(parseDeviceUri("", parsed, error));
    EXPECT_TRUE(contains(error, "empty")) << error;
    EXPECT_EQ(openDeviceUri("", error), nullptr);
}

TEST(DeviceUri, SimPathWithAMissingFileNamesTheUriAndTheFile) {
    std::string error;
    EXPECT_EQ(openDeviceUri("sim:path:/no/such/path.txt", error), nullptr);
    EXPECT_TRUE(contains(error, "device URI 'sim:path:/no/such/path.txt'")) << error;
    EXPECT_TRUE(contains(error, "waypoint file '/no/such/path.txt': does not exist")) << error;
    EXPECT_EQ(openDeviceUri("sim:path:/", error), nullptr);
    EXPECT_TRUE(contains(error, "is a directory")) << error;
}

TEST(DeviceUri, ListedSchemesAreTheOnesParsed) {
    const auto schemes = listDeviceSchemes();
    ASSERT_EQ(schemes.size(), 6u);
    for (const DeviceSchemeInfo& s : schemes) {
        EXPECT_FALSE(s.description.empty()) << s.uri;
        DeviceUri parsed;
        std::string error;
        EXPECT_TRUE(parseDeviceUri(s.uri, parsed, error)) << s.uri << ": " << error;  // FILE parses as a name
    }
    auto has = [&](const char* uri) {
        for (const DeviceSchemeInfo& s : schemes)
            if (s.uri == uri) return true;
        return false;
    };
    for (const char* uri : {"sim:press", "sim:stroke", "sim:scan", "sim:sine", "sim:path:FILE", "mouse:"})
        EXPECT_TRUE(has(uri)) << uri;
}

}  // namespace
}  // namespace palpate
