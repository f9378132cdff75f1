#pragma once
// What is plugged in that a device URI could name: SpaceMice and HID PID joysticks (hidapi), and
// Falcons (libusb), each with the URI to use and whether its node is accessible (else the udev
// rule to install). For `palpate-cli devices` and the GUI's device list. Touches no device beyond
// enumeration and reading report descriptors from sysfs.

#include "device/open/DeviceUri.h"

#include <cstdint>
#include <string>
#include <vector>

namespace palpate {

struct ConnectedDevice {
    std::string backend;      ///< "spacemouse", "hidpid", "falcon"
    std::string uri;          ///< what to pass as --device
    std::string description;  ///< product name or what we know
    std::string node;         ///< /dev/hidrawN or /dev/bus/usb/BBB/DDD
    std::uint16_t vendorId = 0;
    std::uint16_t productId = 0;
    std::string serial;
    bool accessible = true;   ///< the node can be opened read/write by this user
    std::string problem;      ///< when not: what to do (the udev rule)
};

/// Everything found through `backends` (null members: the system's, when compiled in).
std::vector<ConnectedDevice> discoverDevices(const DeviceBackends& backends = {});

}  // namespace palpate
