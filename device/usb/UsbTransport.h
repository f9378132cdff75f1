#pragma once
// The USB layer under the Falcon backend (libusb-1.0 on a real machine), behind an interface so
// that firmware upload, the 1 kHz exchange and every error path run in tests against a fake.
// Error codes are libusb's own values (LIBUSB_ERROR_*), so that the fake and the real backend
// speak the same language without the fake including libusb.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace palpate {

/// libusb_error values (libusb.h), for code that must not include libusb.
enum UsbError : int {
    kUsbSuccess = 0,
    kUsbErrorIo = -1,
    kUsbErrorInvalidParam = -2,
    kUsbErrorAccess = -3,
    kUsbErrorNoDevice = -4,
    kUsbErrorNotFound = -5,
    kUsbErrorBusy = -6,
    kUsbErrorTimeout = -7,
    kUsbErrorOverflow = -8,
    kUsbErrorPipe = -9,
    kUsbErrorInterrupted = -10,
    kUsbErrorNoMem = -11,
    kUsbErrorNotSupported = -12,
    kUsbErrorOther = -99,
};

/// "LIBUSB_ERROR_NO_DEVICE (the device was unplugged)" and so on.
std::string usbErrorText(int code);

struct UsbDeviceInfo {
    std::uint8_t busNumber = 0;
    std::uint8_t deviceAddress = 0;
    std::uint16_t vendorId = 0;
    std::uint16_t productId = 0;
    std::string serial;  ///< may be empty (reading it needs the device opened)
    /// "/dev/bus/usb/BBB/DDD", the node a permission problem is about.
    std::string node() const;
    bool sameDevice(const UsbDeviceInfo& other) const {
        return busNumber == other.busNumber && deviceAddress == other.deviceAddress;
    }
};

/// An opened device with its interface 0 claimed. Used by one thread (the device's I/O thread).
class UsbTransport {
public:
    virtual ~UsbTransport() = default;
    /// A vendor control transfer without data stage (FTDI commands). 0 or a UsbError.
    virtual int controlOut(std::uint8_t requestType, std::uint8_t request, std::uint16_t value, std::uint16_t index,
                           int timeoutMs) = 0;
    /// Bulk OUT; 0 or a UsbError; `transferred` = bytes sent.
    virtual int bulkWrite(std::uint8_t endpoint, const std::uint8_t* data, int length, int& transferred,
                          int timeoutMs) = 0;
    /// Bulk IN; 0 or a UsbError (kUsbErrorTimeout when nothing came); `transferred` = bytes read.
    virtual int bulkRead(std::uint8_t endpoint, std::uint8_t* data, int capacity, int& transferred, int timeoutMs) = 0;
};

/// What a hotplug event says happened.
enum class UsbHotplugEvent { Arrived, Left };

class UsbBackend {
public:
    virtual ~UsbBackend() = default;
    /// Devices present with this VID:PID (0:0 = every device).
    virtual std::vector<UsbDeviceInfo> enumerate(std::uint16_t vendorId, std::uint16_t productId) = 0;
    /// Opens and claims interface 0; null with `error` naming the device and the cause (permission:
    /// names the udev rule) on failure.
    virtual std::unique_ptr<UsbTransport> open(const UsbDeviceInfo& info, std::string& error) = 0;

    using HotplugCallback = std::function<void(UsbHotplugEvent, const UsbDeviceInfo&)>;
    /// Registers for arrival/removal of VID:PID; the callback runs on the backend's event thread.
    /// Returns a handle for removeHotplug, or -1 when hotplug is not available (`error` says why).
    virtual int addHotplug(std::uint16_t vendorId, std::uint16_t productId, HotplugCallback callback,
                           std::string& error) = 0;
    virtual void removeHotplug(int handle) = 0;
};

/// libusb-1.0 when the build has it (PALPATE_HAVE_LIBUSB), else null: one shared instance.
std::shared_ptr<UsbBackend> systemUsbBackend();
/// A fresh libusb context (else null). Tests under umockdev make their own after the testbed is up.
std::shared_ptr<UsbBackend> createLibusbBackend();

}  // namespace palpate
