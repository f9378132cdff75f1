#include "device/open/DeviceDiscovery.h"

#include "device/UdevHint.h"
#include "device/hid/HidPidCodec.h"
#include "device/hid/HidTransport.h"
#include "device/hid/SpaceMouseCodec.h"
#include "device/usb/FalconProtocol.h"
#include "device/usb/UsbTransport.h"

#include <cerrno>
#include <unistd.h>

namespace palpate {
namespace {

/// Only real device nodes are checked (fakes have made-up paths).
void checkAccess(ConnectedDevice& d) {
    if (d.node.rfind("/dev/", 0) != 0) return;
    if (::access(d.node.c_str(), R_OK | W_OK) == 0) return;
    if (errno == EACCES) {
        d.accessible = false;
        d.problem = permissionDeniedMessage(d.node, d.vendorId, d.productId);
    }
}

std::string hex4(std::uint16_t v) { return formatVidPid(v, 0).substr(0, 4); }

}  // namespace

std::vector<ConnectedDevice> discoverDevices(const DeviceBackends& backends) {
    std::vector<ConnectedDevice> out;
    const auto hid = backends.hid ? backends.hid : systemHidBackend();
    const auto usb = backends.usb ? backends.usb : systemUsbBackend();
    if (hid) {
        for (const HidDeviceInfo& info : hid->enumerate()) {
            ConnectedDevice d;
            d.node = info.path;
            d.vendorId = info.vendorId;
            d.productId = info.productId;
            d.serial = info.serial;
            d.description = (info.manufacturer.empty() ? "" : info.manufacturer + " ") + info.product;
            const std::string selector = "hid:" + hex4(info.vendorId) + ":" + hex4(info.productId) +
                                         (info.serial.empty() ? "" : ":" + info.serial);
            if (isSpaceMouseVidPid(info.vendorId, info.productId)) {
                // One entry per unit: the multi-axis interface only.
                if (info.usagePage != 0 && !(info.usagePage == kHidUsagePageGenericDesktop &&
                                             info.usage == kHidUsageMultiAxisController))
                    continue;
                d.backend = "spacemouse";
                d.uri = selector;
            } else {
                std::vector<std::uint8_t> bytes;
                std::string error;
                HidReportDescriptor descriptor;
                if (!(error = hid->reportDescriptor(info, bytes)).empty() ||
                    !(error = parseHidReportDescriptor(bytes.data(), bytes.size(), descriptor)).empty() ||
                    !descriptorHasPid(descriptor))
                    continue;  // neither a SpaceMouse nor a PID device: not ours to list
                d.backend = "hidpid";
                d.uri = selector;
                d.description += " (HID PID, experimental)";
            }
            checkAccess(d);
            out.push_back(std::move(d));
        }
    }
    if (usb) {
        int index = 0;
        for (const UsbDeviceInfo& info : usb->enumerate(kFalconVendorId, kFalconProductId)) {
            ConnectedDevice d;
            d.backend = "falcon";
            d.uri = "falcon:" + std::to_string(index++);
            d.description = "Novint Falcon";
            d.node = info.node();
            d.vendorId = info.vendorId;
            d.productId = info.productId;
            checkAccess(d);
            out.push_back(std::move(d));
        }
    }
    return out;
}

}  // namespace palpate
