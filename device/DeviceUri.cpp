#include "device/DeviceUri.h"

#include "device/MouseDevice.h"
#include "device/SimulatedDevice.h"

#include <stdexcept>

namespace palpate {
namespace {

struct SimEntry {
    const char* name;
    DeviceKind kind;
    SimTrajectory trajectory;
};

constexpr SimEntry kSimEntries[] = {
    {"press", DeviceKind::SimPress, SimTrajectory::PressHold},
    {"stroke", DeviceKind::SimStroke, SimTrajectory::Stroke},
    {"scan", DeviceKind::SimScan, SimTrajectory::Scan},
    {"sine", DeviceKind::SimSine, SimTrajectory::Sine},
};

/// The URI as it may appear in a message: control characters escaped, very long ones cut.
std::string shown(std::string_view uri) {
    static const char* kHex = "0123456789abcdef";
    std::string out = "'";
    const std::size_t n = uri.size() < 200 ? uri.size() : 200;
    for (std::size_t i = 0; i < n; ++i) {
        const auto c = static_cast<unsigned char>(uri[i]);
        if (c < 0x20 || c == 0x7f) {
            out += "\\x";
            out += kHex[c >> 4];
            out += kHex[c & 15];
        } else {
            out += char(c);
        }
    }
    if (n < uri.size()) out += "...";
    return out + "'";
}

std::string knownForms() {
    std::string out;
    for (const DeviceSchemeInfo& s : listDeviceSchemes()) out += (out.empty() ? "" : ", ") + s.uri;
    return out;
}

}  // namespace

std::vector<DeviceSchemeInfo> listDeviceSchemes() {
    return {
        {"sim:press", "simulated device: press and hold on the target, then release"},
        {"sim:stroke", "simulated device: press, stroke along the surface and back, release"},
        {"sim:scan", "simulated device: palpation scan, a raster of short presses over a patch"},
        {"sim:sine", "simulated device: press, then sinusoidal probing in depth"},
        {"sim:path:FILE", "simulated device: waypoints from FILE, one 't_s x_mm y_mm z_mm' per line"},
        {"mouse:", "virtual tool steered by the viewport's mouse (input only)"},
    };
}

bool parseDeviceUri(std::string_view uri, DeviceUri& out, std::string& error) {
    error.clear();
    const std::string head = "device URI " + shown(uri) + ": ";
    if (uri.empty()) {
        error = "device URI is empty (expected one of " + knownForms() + ")";
        return false;
    }
    const std::size_t colon = uri.find(':');
    if (colon == std::string_view::npos) {
        error = head + "no ':' after the scheme (expected one of " + knownForms() + ")";
        return false;
    }
    const std::string_view scheme = uri.substr(0, colon);
    const std::string_view rest = uri.substr(colon + 1);

    if (scheme == "sim") {
        if (rest.empty()) {
            error = head + "'sim:' needs a trajectory: press, stroke, scan, sine or path:FILE";
            return false;
        }
        if (rest == "path" || rest.substr(0, 5) == "path:") {
            const std::string_view file = rest.size() > 5 ? rest.substr(5) : std::string_view();
            if (file.empty()) {
                error = head + "'sim:path:' needs a waypoint file after it (sim:path:FILE)";
                return false;
            }
            out = DeviceUri{DeviceKind::SimPath, std::string(file)};
            return true;
        }
        for (const SimEntry& e : kSimEntries) {
            if (rest == e.name) {
                out = DeviceUri{e.kind, {}};
                return true;
            }
        }
        error = head + "unknown simulated trajectory " + shown(rest) +
                " (expected press, stroke, scan, sine or path:FILE)";
        return false;
    }
    if (scheme == "mouse") {
        if (!rest.empty()) {
            error = head + "'mouse:' takes no argument";
            return false;
        }
        out = DeviceUri{DeviceKind::Mouse, {}};
        return true;
    }
    error = head + "unknown scheme " + shown(scheme) + " (expected one of " + knownForms() + ")";
    return false;
}

std::string formatDeviceUri(const DeviceUri& uri) {
    switch (uri.kind) {
        case DeviceKind::SimPath: return "sim:path:" + uri.path;
        case DeviceKind::Mouse: return "mouse:";
        default: break;
    }
    for (const SimEntry& e : kSimEntries)
        if (e.kind == uri.kind) return std::string("sim:") + e.name;
    return "";
}

std::unique_ptr<HapticDevice> createDeviceFromUri(std::string_view uri, std::string& error) {
    DeviceUri parsed;
    if (!parseDeviceUri(uri, parsed, error)) return nullptr;
    switch (parsed.kind) {
        case DeviceKind::Mouse: return std::make_unique<MouseDevice>();
        case DeviceKind::SimPath: {
            std::string fileError;
            auto device = SimulatedDevice::fromWaypointFile(parsed.path, fileError);
            if (!device) {
                error = "device URI " + shown(uri) + ": " + fileError;
                return nullptr;
            }
            return device;
        }
        default: break;
    }
    for (const SimEntry& e : kSimEntries)
        if (e.kind == parsed.kind) return std::make_unique<SimulatedDevice>(e.trajectory);
    error = "device URI " + shown(uri) + ": no backend for this kind";
    return nullptr;
}

std::unique_ptr<HapticDevice> openDeviceUri(std::string_view uri, std::string& error) {
    std::unique_ptr<HapticDevice> device = createDeviceFromUri(uri, error);
    if (!device) return nullptr;
    if (!device->open()) {
        error = "device URI " + shown(uri) + ": the device did not open (state " +
                deviceStateName(device->state()) + ")";
        return nullptr;
    }
    return device;
}

}  // namespace palpate
