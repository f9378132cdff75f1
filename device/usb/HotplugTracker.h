#pragma once
// Hotplug events are not a clean sequence: libusb may report an arrival twice (once from its
// initial scan, once from udev) and a removal of a device it never announced (it left before we
// registered). The tracker turns them into idempotent state changes: an arrival counts once, a
// removal only of what is present. Thread-safe (events come on libusb's event thread).

#include "device/usb/UsbTransport.h"

#include <cstdint>
#include <mutex>
#include <vector>

namespace palpate {

class HotplugTracker {
public:
    /// True when the device was not present before (a real arrival).
    bool arrived(const UsbDeviceInfo& info);
    /// True when the device was present (a real removal); false for a stranger or a repeat.
    bool left(const UsbDeviceInfo& info);
    bool present(const UsbDeviceInfo& info) const;
    std::size_t count() const;
    std::vector<UsbDeviceInfo> devices() const;
    std::uint64_t ignoredEvents() const;

private:
    mutable std::mutex mMutex;
    std::vector<UsbDeviceInfo> mPresent;
    std::uint64_t mIgnored = 0;
};

}  // namespace palpate
