#pragma once
// The byte pipe under every HID backend (SpaceMouse, HID PID joysticks), behind an interface so
// that the codecs and device threads run in tests against fakes and recorded captures, and against
// hidapi's hidraw backend on a real machine (HidapiTransport). Qt-free.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace palpate {

/// One HID interface as enumeration sees it (hidapi's hid_device_info, trimmed to what we use).
struct HidDeviceInfo {
    std::string path;           ///< OS path (/dev/hidrawN on Linux); what open() takes
    std::uint16_t vendorId = 0;
    std::uint16_t productId = 0;
    std::string serial;         ///< may be empty
    std::string manufacturer;
    std::string product;
    std::uint16_t usagePage = 0;  ///< top-level collection's usage page (1 = Generic Desktop)
    std::uint16_t usage = 0;      ///< top-level collection's usage (8 = Multi-axis Controller)
    int interfaceNumber = -1;
};

/// Result of HidTransport::read beyond a byte count.
enum HidReadResult : int {
    kHidReadTimeout = 0,   ///< nothing arrived in time (not an error)
    kHidReadError = -1,    ///< hidapi returned -1: the device is gone or the read failed
};

/// An open HID device. One thread reads; writes may come from the same thread (device threads do
/// both from their own I/O thread).
class HidTransport {
public:
    virtual ~HidTransport() = default;
    /// Reads one input report into `data` (report ID first when the device numbers its reports).
    /// Returns the byte count (> 0), kHidReadTimeout, or kHidReadError (see lastError()).
    virtual int read(std::uint8_t* data, std::size_t capacity, int timeoutMs) = 0;
    /// Writes one output report (first byte: report ID, 0 if unnumbered). Bytes written or -1.
    virtual int write(const std::uint8_t* data, std::size_t length) = 0;
    /// Sends a feature report (first byte: report ID). Bytes sent or -1.
    virtual int sendFeatureReport(const std::uint8_t* data, std::size_t length) = 0;
    /// Reads a feature report; data[0] holds the report ID on entry. Bytes read or -1.
    virtual int getFeatureReport(std::uint8_t* data, std::size_t capacity) = 0;
    /// The last error, in words (hidapi's hid_error), or "" when none.
    virtual std::string lastError() const = 0;
};

/// Finds and opens HID devices. The real one wraps hidapi; tests use a fake.
class HidBackend {
public:
    virtual ~HidBackend() = default;
    /// Every HID interface present (vendorId/productId 0 = any).
    virtual std::vector<HidDeviceInfo> enumerate(std::uint16_t vendorId = 0, std::uint16_t productId = 0) = 0;
    /// Opens by path; null with `error` naming the path and the cause (e.g. permission denied,
    /// with the udev rule to install) on failure.
    virtual std::unique_ptr<HidTransport> open(const HidDeviceInfo& info, std::string& error) = 0;
    /// The raw report descriptor of an interface: "" or why it cannot be read.
    virtual std::string reportDescriptor(const HidDeviceInfo& info, std::vector<std::uint8_t>& out) = 0;
};

/// hidapi's hidraw backend when the build has it (PALPATE_HAVE_HIDAPI), else null.
std::shared_ptr<HidBackend> systemHidBackend();

/// The hidraw report descriptor of a /dev/hidrawN node, from
/// /sys/class/hidraw/hidrawN/device/report_descriptor (hidapi 0.13 has no
/// hid_get_report_descriptor). `sysRoot` lets tests (and umockdev) point elsewhere.
std::string readHidrawReportDescriptor(const std::string& devicePath, std::vector<std::uint8_t>& out,
                                       const std::string& sysRoot = "/sys");

}  // namespace palpate
