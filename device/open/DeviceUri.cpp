#include "device/open/DeviceUri.h"

#include "device/MouseDevice.h"
#include "device/SimulatedDevice.h"
#include "device/hid/HidPidDevice.h"
#include "device/hid/SpaceMouseCodec.h"
#include "device/hid/SpaceMouseDevice.h"
#include "device/usb/FalconDevice.h"

#include <cstdio>
#include <exception>
#include <filesystem>
#include <cstdlib>
#include <map>
#include <mutex>
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
    // Hardware forms are parsed in every build; name them even when this build cannot open them.
    for (const char* form : {"spacemouse:", "hid:VID:PID[:SERIAL]", "hidpid:", "falcon:INDEX", "replay:FILE"})
        if (out.find(std::string(form)) == std::string::npos) out += std::string(", ") + form;
    return out;
}

// Whether a backend is compiled in, without creating it (creating libusb's starts its udev monitor).
#ifdef PALPATE_HAVE_HIDAPI
constexpr bool kHaveHid = true;
#else
constexpr bool kHaveHid = false;
#endif
#ifdef PALPATE_HAVE_LIBUSB
constexpr bool kHaveUsb = true;
#else
constexpr bool kHaveUsb = false;
#endif

std::mutex& factoryMutex() {
    static std::mutex m;
    return m;
}
std::map<DeviceKind, DeviceFactory>& factories() {
    static std::map<DeviceKind, DeviceFactory> f;
    return f;
}
DeviceFactory findFactory(DeviceKind kind) {
    std::lock_guard lock(factoryMutex());
    auto it = factories().find(kind);
    return it == factories().end() ? DeviceFactory() : it->second;
}

/// 1..4 hex digits, optional 0x.
bool parseHex16(std::string_view text, std::uint16_t& out) {
    if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) text.remove_prefix(2);
    if (text.empty() || text.size() > 4) return false;
    unsigned value = 0;
    for (char c : text) {
        int digit;
        if (c >= '0' && c <= '9') digit = c - '0';
        else if (c >= 'a' && c <= 'f') digit = c - 'a' + 10;
        else if (c >= 'A' && c <= 'F') digit = c - 'A' + 10;
        else return false;
        value = value * 16 + unsigned(digit);
    }
    out = std::uint16_t(value);
    return true;
}

std::string hex4(std::uint16_t v) {
    char text[8];
    std::snprintf(text, sizeof text, "%04x", unsigned(v));
    return text;
}

/// "VID:PID[:SERIAL]" into `out`: "" or the problem (after `head`).
std::string parseVidPid(std::string_view text, DeviceUri& out, const std::string& head, const char* scheme) {
    std::string error;
    const std::size_t c1 = text.find(':');
    if (c1 == std::string_view::npos) {
        error = head + "'" + scheme + ":' needs VID:PID[:SERIAL] in hex (e.g. " + scheme + ":046d:c626)";
        return error;
    }
    const std::size_t c2 = text.find(':', c1 + 1);
    const std::string_view vid = text.substr(0, c1);
    const std::string_view pid = text.substr(c1 + 1, c2 == std::string_view::npos ? std::string_view::npos : c2 - c1 - 1);
    if (!parseHex16(vid, out.vendorId)) {
        error = head + "vendor ID " + shown(vid) + " is not 1 to 4 hex digits";
        return error;
    }
    if (!parseHex16(pid, out.productId)) {
        error = head + "product ID " + shown(pid) + " is not 1 to 4 hex digits";
        return error;
    }
    if (c2 != std::string_view::npos) {
        out.serial = std::string(text.substr(c2 + 1));
        if (out.serial.empty()) {
            error = head + "empty serial after VID:PID: (leave out the last ':' for any serial)";
            return error;
        }
    }
    return {};
}

/// Options after '?': key=value pairs joined by '&'. Only `allowed` keys; each at most once.
std::string parseOptions(std::string_view text, std::initializer_list<const char*> allowed, DeviceUri& out,
                         const std::string& head) {
    std::string error;
    std::vector<std::string> seen;
    while (!text.empty()) {
        const std::size_t amp = text.find('&');
        const std::string_view pair = text.substr(0, amp);
        text = amp == std::string_view::npos ? std::string_view() : text.substr(amp + 1);
        const std::size_t eq = pair.find('=');
        const std::string key(pair.substr(0, eq));
        const std::string value = eq == std::string_view::npos ? std::string() : std::string(pair.substr(eq + 1));
        bool known = false;
        for (const char* a : allowed) known = known || key == a;
        if (!known) {
            std::string list;
            for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
            error = head + "unknown option " + shown(key) + (list.empty() ? " (this scheme takes none)" : " (expected " + list + ")");
            return error;
        }
        for (const std::string& s : seen)
            if (s == key) {
                error = head + "option '" + key + "' given twice";
                return error;
            }
        seen.push_back(key);
        if (value.empty()) {
            error = head + "option '" + key + "' needs a value (" + key + "=...)";
            return error;
        }
        if (key == "mode") {
            if (value == "rate") out.positionMode = false;
            else if (value == "position") out.positionMode = true;
            else {
                error = head + "mode " + shown(value) + " is not 'rate' or 'position'";
                return error;
            }
        } else if (key == "firmware") {
            out.firmware = value;
        }
    }
    return {};
}

std::string modeSuffix(const DeviceUri& uri) { return uri.positionMode ? "?mode=position" : ""; }

}  // namespace

std::vector<DeviceSchemeInfo> listDeviceSchemes() {
    std::vector<DeviceSchemeInfo> out = {
        {"sim:press", "simulated device: press and hold on the target, then release"},
        {"sim:stroke", "simulated device: press, stroke along the surface and back, release"},
        {"sim:scan", "simulated device: palpation scan, a raster of short presses over a patch"},
        {"sim:sine", "simulated device: press, then sinusoidal probing in depth"},
        {"sim:path:FILE", "simulated device: waypoints from FILE, one 't_s x_mm y_mm z_mm' per line"},
        {"mouse:", "virtual tool steered by the viewport's mouse (input only)"},
    };
    if (kHaveHid) {
        out.push_back({"spacemouse:", "3Dconnexion SpaceMouse, the first found (input only; ?mode=position for "
                                      "position control; hid:VID:PID[:SERIAL] picks one)"});
        out.push_back({"hidpid:", "HID PID force-feedback joystick, the first found (EXPERIMENTAL; "
                                  "hid:VID:PID[:SERIAL] picks one)"});
    }
    if (kHaveUsb)
        out.push_back({"falcon:0", "Novint Falcon number 0 (falcon:INDEX; Novint's firmware file: "
                                   "?firmware=PATH or PALPATE_FALCON_FIRMWARE)"});
    if (findFactory(DeviceKind::Replay)) out.push_back({"replay:FILE", "a recorded session, played back"});
    return out;
}

std::vector<BackendInfo> listDeviceBackends() {
#ifdef PALPATE_HIDAPI_VERSION
    const std::string hid = std::string("hidapi-hidraw ") + PALPATE_HIDAPI_VERSION;
#else
    const std::string hid = "hidapi-hidraw (not found at configure time)";
#endif
#ifdef PALPATE_LIBUSB_VERSION
    const std::string usb = std::string("libusb-1.0 ") + PALPATE_LIBUSB_VERSION;
#else
    const std::string usb = "libusb-1.0 (not found at configure time)";
#endif
    return {
        {"spacemouse", hid, kHaveHid, false},
        {"hidpid", hid, kHaveHid, true},
        {"falcon", usb, kHaveUsb, false},
    };
}

void registerDeviceFactory(DeviceKind kind, DeviceFactory factory) {
    std::lock_guard lock(factoryMutex());
    factories()[kind] = std::move(factory);
}

void unregisterDeviceFactory(DeviceKind kind) {
    std::lock_guard lock(factoryMutex());
    factories().erase(kind);
}

std::string parseDeviceUri(std::string_view uri, DeviceUri& out) {
    std::string error;
    error.clear();
    const std::string head = "device URI " + shown(uri) + ": ";
    if (uri.empty()) {
        error = "device URI is empty (expected one of " + knownForms() + ")";
        return error;
    }
    const std::size_t colon = uri.find(':');
    if (colon == std::string_view::npos) {
        error = head + "no ':' after the scheme (expected one of " + knownForms() + ")";
        return error;
    }
    const std::string_view scheme = uri.substr(0, colon);
    const std::string_view rest = uri.substr(colon + 1);

    if (scheme == "sim") {
        if (rest.empty()) {
            error = head + "'sim:' needs a trajectory: press, stroke, scan, sine or path:FILE";
            return error;
        }
        if (rest == "path" || rest.substr(0, 5) == "path:") {
            const std::string_view file = rest.size() > 5 ? rest.substr(5) : std::string_view();
            if (file.empty()) {
                error = head + "'sim:path:' needs a waypoint file after it (sim:path:FILE)";
                return error;
            }
            out = DeviceUri{};
            out.kind = DeviceKind::SimPath;
            out.path = std::string(file);
            return {};
        }
        for (const SimEntry& e : kSimEntries) {
            if (rest == e.name) {
                out = DeviceUri{};
                out.kind = e.kind;
                return {};
            }
        }
        error = head + "unknown simulated trajectory " + shown(rest) +
                " (expected press, stroke, scan, sine or path:FILE)";
        return error;
    }
    if (scheme == "mouse") {
        if (!rest.empty()) {
            error = head + "'mouse:' takes no argument";
            return error;
        }
        out = DeviceUri{};
        out.kind = DeviceKind::Mouse;
        return {};
    }
    if (scheme == "replay") {
        if (rest.empty()) {
            error = head + "'replay:' needs a recording file after it (replay:FILE)";
            return error;
        }
        out = DeviceUri{};
        out.kind = DeviceKind::Replay;
        out.path = std::string(rest);
        return {};
    }

    // Hardware schemes: "argument?options".
    const std::size_t question = rest.find('?');
    const std::string_view argument = rest.substr(0, question);
    const std::string_view options = question == std::string_view::npos ? std::string_view() : rest.substr(question + 1);
    DeviceUri parsed;
    if (scheme == "spacemouse") {
        parsed.kind = DeviceKind::SpaceMouse;
        if (!argument.empty()) {
            error = head + "'spacemouse:' takes no argument (hid:VID:PID[:SERIAL] picks one unit)";
            return error;
        }
        if (!(error = parseOptions(options, {"mode"}, parsed, head)).empty()) return error;
    } else if (scheme == "hid") {
        parsed.kind = DeviceKind::Hid;
        if (!(error = parseVidPid(argument, parsed, head, "hid")).empty()) return error;
        if (!(error = parseOptions(options, {"mode"}, parsed, head)).empty()) return error;
    } else if (scheme == "hidpid") {
        parsed.kind = DeviceKind::HidPid;
        if (!argument.empty() && !(error = parseVidPid(argument, parsed, head, "hidpid")).empty()) return error;
        if (!(error = parseOptions(options, {}, parsed, head)).empty()) return error;
    } else if (scheme == "falcon") {
        parsed.kind = DeviceKind::Falcon;
        if (argument.empty()) {
            error = head + "'falcon:' needs an index: falcon:0 for the first Falcon";
            return error;
        }
        int index = 0;
        for (char c : argument) {
            if (c < '0' || c > '9' || index > 99) {
                error = head + "Falcon index " + shown(argument) + " is not a number from 0 to 99";
                return error;
            }
            index = index * 10 + (c - '0');
        }
        if (index > 99) {
            error = head + "Falcon index " + shown(argument) + " is not a number from 0 to 99";
            return error;
        }
        parsed.index = index;
        if (!(error = parseOptions(options, {"firmware"}, parsed, head)).empty()) return error;
    } else {
        error = head + "unknown scheme " + shown(scheme) + " (expected one of " + knownForms() + ")";
        return error;
    }
    out = parsed;
    return {};
}

std::string formatDeviceUri(const DeviceUri& uri) {
    switch (uri.kind) {
        case DeviceKind::SimPath: return "sim:path:" + uri.path;
        case DeviceKind::Mouse: return "mouse:";
        case DeviceKind::Replay: return "replay:" + uri.path;
        case DeviceKind::SpaceMouse: return "spacemouse:" + modeSuffix(uri);
        case DeviceKind::Hid:
            return "hid:" + hex4(uri.vendorId) + ":" + hex4(uri.productId) + (uri.serial.empty() ? "" : ":" + uri.serial) +
                   modeSuffix(uri);
        case DeviceKind::HidPid:
            if (uri.vendorId == 0 && uri.productId == 0) return "hidpid:";
            return "hidpid:" + hex4(uri.vendorId) + ":" + hex4(uri.productId) + (uri.serial.empty() ? "" : ":" + uri.serial);
        case DeviceKind::Falcon:
            return "falcon:" + std::to_string(uri.index) + (uri.firmware.empty() ? "" : "?firmware=" + uri.firmware);
        default: break;
    }
    for (const SimEntry& e : kSimEntries)
        if (e.kind == uri.kind) return std::string("sim:") + e.name;
    return "";
}

namespace {

/// Why `path` cannot be a recording to replay before anything reads it ("" when it may be one, or
/// does not exist).
std::string recordingFileProblem(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status)) return {};  // the player says so, with its own words
    if (fs::is_directory(status)) return "recording '" + path + "': is a folder, not a recording";
    if (!fs::is_regular_file(status)) return "recording '" + path + "': is not a regular file";
    return {};
}

}  // namespace

std::unique_ptr<HapticDevice> createDeviceFromUri(std::string_view uri, std::string& error) {
    return createDeviceFromUri(uri, error, DeviceBackends{});
}

std::unique_ptr<HapticDevice> createDeviceFromUri(std::string_view uri, std::string& error,
                                                  const DeviceBackends& backends) {
    DeviceUri parsed;
    if (!(error = parseDeviceUri(uri, parsed)).empty()) return nullptr;
    const std::string head = "device URI " + shown(uri) + ": ";
    if (parsed.kind == DeviceKind::Replay) {
        // Checked without opening it: a FIFO would block the caller (the GUI at start-up) forever,
        // and a folder is not a recording.
        if (std::string problem = recordingFileProblem(parsed.path); !problem.empty()) {
            error = head + problem;
            return nullptr;
        }
    }
    if (DeviceFactory factory = findFactory(parsed.kind)) {
        std::string factoryError;
        std::unique_ptr<HapticDevice> device;
        try {
            device = factory(parsed, factoryError);
        } catch (const std::exception& e) {  // a factory that throws (no memory for the file) is an error too
            factoryError = e.what();
        }
        if (!device) error = head + (factoryError.empty() ? "the registered factory made no device" : factoryError);
        return device;
    }
    switch (parsed.kind) {
        case DeviceKind::Mouse: return std::make_unique<MouseDevice>();
        case DeviceKind::SimPath: {
            std::string fileError;
            auto device = SimulatedDevice::fromWaypointFile(parsed.path, fileError);
            if (!device) {
                error = head + fileError;
                return nullptr;
            }
            return device;
        }
        case DeviceKind::Replay:
            error = head + "a recording is played back by the engine, not opened as a live device here: use "
                           "'palpate-cli record replay FILE' or the GUI's Recorder dock (or register a factory "
                           "for replay: with registerDeviceFactory)";
            return nullptr;
        case DeviceKind::SpaceMouse:
        case DeviceKind::Hid:
        case DeviceKind::HidPid: {
            // Only hardware URIs bring up a backend (libusb's starts a udev monitor thread).
            const std::shared_ptr<HidBackend> hid = backends.hid ? backends.hid : systemHidBackend();
            if (!hid) {
                error = head + "this build has no HID support (hidapi-hidraw was not found at configure time; "
                               "scripts/install-deps.sh installs libhidapi-dev)";
                return nullptr;
            }
            HidSelector selector;
            selector.any = parsed.vendorId == 0 && parsed.productId == 0;
            selector.vendorId = parsed.vendorId;
            selector.productId = parsed.productId;
            selector.serial = parsed.serial;
            const bool spaceMouse = parsed.kind == DeviceKind::SpaceMouse ||
                                    (parsed.kind == DeviceKind::Hid && isSpaceMouseVidPid(parsed.vendorId, parsed.productId));
            if (spaceMouse) {
                SpaceMouseDeviceDef def;
                def.control.mode = parsed.positionMode ? SpaceMouseMode::Position : SpaceMouseMode::Rate;
                return std::make_unique<SpaceMouseDevice>(hid, selector, def);
            }
            return std::make_unique<HidPidDevice>(hid, selector);
        }
        case DeviceKind::Falcon: {
            const std::shared_ptr<UsbBackend> usb = backends.usb ? backends.usb : systemUsbBackend();
            if (!usb) {
                error = head + "this build has no USB support (libusb-1.0 was not found at configure time; "
                               "scripts/install-deps.sh installs libusb-1.0-0-dev)";
                return nullptr;
            }
            FalconDeviceDef def;
            def.index = parsed.index;
            def.firmwarePath = parsed.firmware;
            if (def.firmwarePath.empty())
                if (const char* env = std::getenv("PALPATE_FALCON_FIRMWARE")) def.firmwarePath = env;
            return std::make_unique<FalconDevice>(usb, def);
        }
        default: break;
    }
    for (const SimEntry& e : kSimEntries)
        if (e.kind == parsed.kind) return std::make_unique<SimulatedDevice>(e.trajectory);
    error = head + "no backend for this kind";
    return nullptr;
}

std::unique_ptr<HapticDevice> openDeviceUri(std::string_view uri, std::string& error) {
    return openDeviceUri(uri, error, DeviceBackends{});
}

std::unique_ptr<HapticDevice> openDeviceUri(std::string_view uri, std::string& error, const DeviceBackends& backends) {
    std::unique_ptr<HapticDevice> device = createDeviceFromUri(uri, error, backends);
    if (!device) return nullptr;
    if (!device->open()) {
        const std::string why = device->lastError();
        error = "device URI " + shown(uri) + ": " +
                (why.empty() ? "the device did not open (state " + std::string(deviceStateName(device->state())) + ")"
                             : why);
        return nullptr;
    }
    return device;
}

}  // namespace palpate
