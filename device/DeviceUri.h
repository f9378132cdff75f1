#pragma once
// Devices are named by URI, one syntax everywhere (GUI, CLI, settings): "scheme:argument".
//   sim:press  sim:stroke  sim:scan  sim:sine  sim:path:FILE  mouse:
// Later backends add their schemes here (spacemouse:, falcon:, hidpid:), so that every front end
// learns them at once.

#include "device/HapticDevice.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace palpate {

enum class DeviceKind { SimPress, SimStroke, SimScan, SimSine, SimPath, Mouse };

/// A parsed device URI.
struct DeviceUri {
    DeviceKind kind = DeviceKind::SimPress;
    std::string path;  ///< SimPath: the waypoint file (may itself contain ':')
};

/// One entry of listDeviceSchemes(): the URI as typed (FILE is a placeholder) and what it gives.
struct DeviceSchemeInfo {
    std::string uri;
    std::string description;
};

/// Every URI form this build understands, for --help, the GUI's device menu and error messages.
std::vector<DeviceSchemeInfo> listDeviceSchemes();

/// Parses without touching any file or device. On failure returns false and sets `error` to a
/// message naming the URI and the problem.
bool parseDeviceUri(std::string_view uri, DeviceUri& out, std::string& error);

/// The canonical text of a parsed URI (parseDeviceUri(formatDeviceUri(u)) gives u back).
std::string formatDeviceUri(const DeviceUri& uri);

/// Creates the device a URI names, not yet opened. Null with `error` (naming the URI) on failure,
/// e.g. an unknown scheme or a waypoint file that does not parse.
std::unique_ptr<HapticDevice> createDeviceFromUri(std::string_view uri, std::string& error);

/// createDeviceFromUri, then open(); null with `error` if either fails.
std::unique_ptr<HapticDevice> openDeviceUri(std::string_view uri, std::string& error);

}  // namespace palpate
