#pragma once
// Devices are named by URI, one syntax everywhere (GUI, CLI, settings): "scheme:argument[?options]".
//   sim:press  sim:stroke  sim:scan  sim:sine  sim:path:FILE  mouse:  replay:FILE
//   spacemouse:[?mode=rate|position]         the first 3Dconnexion unit found
//   hid:VID:PID[:SERIAL][?mode=...]          one HID device: a SpaceMouse when VID:PID is
//                                            3Dconnexion's, else a HID PID joystick (experimental)
//   hidpid:                                  the first HID PID force-feedback joystick (experimental)
//   falcon:INDEX[?firmware=PATH]             Novint Falcon number INDEX (0 = the first)
// Hardware schemes parse in every build; creating one in a build without hidapi/libusb is an
// error that says so. docs/devices.md documents them.

#include "device/HapticDevice.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace palpate {

class HidBackend;
class UsbBackend;

enum class DeviceKind { SimPress, SimStroke, SimScan, SimSine, SimPath, Mouse, Replay, SpaceMouse, Hid, HidPid, Falcon };

/// A parsed device URI.
struct DeviceUri {
    DeviceKind kind = DeviceKind::SimPress;
    std::string path;  ///< SimPath: the waypoint file; Replay: the recording (may contain ':')
    // Hid (and HidPid with an argument): which device.
    std::uint16_t vendorId = 0;
    std::uint16_t productId = 0;
    std::string serial;       ///< empty: any
    int index = 0;            ///< Falcon: which one, in enumeration order
    std::string firmware;     ///< Falcon: ?firmware=PATH (empty: PALPATE_FALCON_FIRMWARE, if set)
    bool positionMode = false;  ///< SpaceMouse / Hid: ?mode=position (default rate)
    bool operator==(const DeviceUri&) const = default;
};

/// What a device URI is created with: the hardware layers (null = the system's hidapi/libusb, or
/// "not compiled in"). Tests pass fakes.
struct DeviceBackends {
    std::shared_ptr<HidBackend> hid;
    std::shared_ptr<UsbBackend> usb;
};

/// One entry of listDeviceSchemes(): the URI as typed (FILE is a placeholder) and what it gives.
struct DeviceSchemeInfo {
    std::string uri;
    std::string description;
};

/// Every URI form this build can create, for --help, the GUI's device menu and error messages:
/// the simulated ones, hardware ones whose library was compiled in, and replay:FILE once a
/// factory for it is registered (registerDeviceFactory).
std::vector<DeviceSchemeInfo> listDeviceSchemes();

/// Which hardware backends this build has ("hidapi-hidraw 0.13.1", "libusb-1.0 1.0.26"), and which
/// it lacks, for `palpate-cli devices`.
struct BackendInfo {
    std::string name;       ///< "spacemouse", "falcon", "hidpid"
    std::string library;    ///< what it is built on
    bool compiledIn = false;
    bool experimental = false;
};
std::vector<BackendInfo> listDeviceBackends();

/// A creator for a kind that device/ cannot make itself: replay:FILE needs the engine's recording
/// player (engine/record/ReplayDevice), and device/ must not depend on engine/. The engine (or
/// an app) registers one at start-up; until then creating replay:FILE is an error that says so.
using DeviceFactory = std::function<std::unique_ptr<HapticDevice>(const DeviceUri& uri, std::string& error)>;
void registerDeviceFactory(DeviceKind kind, DeviceFactory factory);
/// Removes a registered factory (tests).
void unregisterDeviceFactory(DeviceKind kind);

/// Parses without touching any file or device: "" or the problem, naming the URI.
std::string parseDeviceUri(std::string_view uri, DeviceUri& out);

/// The canonical text of a parsed URI (parseDeviceUri(formatDeviceUri(u)) gives u back).
std::string formatDeviceUri(const DeviceUri& uri);

/// Creates the device a URI names, not yet opened. Null with `error` (naming the URI) on failure,
/// e.g. an unknown scheme or a waypoint file that does not parse.
/// Creating touches no hardware (the GUI creates devices for their spec alone); open() does.
std::unique_ptr<HapticDevice> createDeviceFromUri(std::string_view uri, std::string& error);
std::unique_ptr<HapticDevice> createDeviceFromUri(std::string_view uri, std::string& error,
                                                  const DeviceBackends& backends);

/// createDeviceFromUri, then open(); null with `error` if either fails (with the device's own
/// lastError() when it has one: not found, permission denied and the udev rule, missing firmware).
std::unique_ptr<HapticDevice> openDeviceUri(std::string_view uri, std::string& error);
std::unique_ptr<HapticDevice> openDeviceUri(std::string_view uri, std::string& error, const DeviceBackends& backends);

}  // namespace palpate
