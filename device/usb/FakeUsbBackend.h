#pragma once
// A UsbBackend without hardware. Each fake device answers through a responder (tests put a Falcon
// model there), records every control transfer, and can be told to fail: unplug
// (LIBUSB_ERROR_NO_DEVICE from then on), a scripted error on the next transfer, or open refused
// for permission. Hotplug callbacks fire synchronously from add()/remove().

#include "device/usb/UsbTransport.h"

#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

namespace palpate {

struct UsbControlRecord {
    std::uint8_t requestType = 0;
    std::uint8_t request = 0;
    std::uint16_t value = 0;
    std::uint16_t index = 0;
};

class FakeUsbDevice {
public:
    explicit FakeUsbDevice(UsbDeviceInfo info) : mInfo(info) {}
    const UsbDeviceInfo& info() const { return mInfo; }

    /// Called for every bulk OUT with the bytes; its return goes to the IN queue (may be empty).
    using Responder = std::function<std::vector<std::uint8_t>(std::uint8_t endpoint, const std::uint8_t*, int)>;
    /// Called for every control transfer; its return is the transfer's result (0 = success).
    using ControlHandler = std::function<int(const UsbControlRecord&)>;
    void setResponder(Responder responder);
    void setControlHandler(ControlHandler handler);
    /// Bytes for the next bulk IN reads (each push is one transfer's worth).
    void pushIn(std::vector<std::uint8_t> bytes);
    /// The next transfer of this kind returns `error` (once).
    void failNextRead(int error);
    void failNextWrite(int error);
    void unplug();
    bool unplugged() const;
    void denyOpen(bool deny);
    bool openDenied() const;
    std::vector<UsbControlRecord> controls() const;
    std::vector<std::vector<std::uint8_t>> bulkWrites() const;
    std::size_t bulkWriteCount() const;

    // For the transport.
    int control(const UsbControlRecord& record);
    int bulkWrite(std::uint8_t endpoint, const std::uint8_t* data, int length, int& transferred);
    int bulkRead(std::uint8_t* data, int capacity, int& transferred);

private:
    UsbDeviceInfo mInfo;
    mutable std::mutex mMutex;
    Responder mResponder;
    ControlHandler mControlHandler;
    std::deque<std::vector<std::uint8_t>> mIn;
    std::vector<UsbControlRecord> mControls;
    std::vector<std::vector<std::uint8_t>> mWrites;
    std::size_t mWriteCount = 0;
    int mFailRead = 0;
    int mFailWrite = 0;
    bool mUnplugged = false;
    bool mDenyOpen = false;
};

class FakeUsbBackend final : public UsbBackend {
public:
    /// Plugs a device in (hotplug Arrived fires).
    std::shared_ptr<FakeUsbDevice> add(UsbDeviceInfo info);
    /// Unplugs it: its transfers fail with NO_DEVICE and hotplug Left fires.
    void remove(const UsbDeviceInfo& info);
    /// Fires an event without changing the device list (duplicate arrival, removal of a stranger).
    void fire(UsbHotplugEvent event, const UsbDeviceInfo& info);

    std::vector<UsbDeviceInfo> enumerate(std::uint16_t vendorId, std::uint16_t productId) override;
    std::unique_ptr<UsbTransport> open(const UsbDeviceInfo& info, std::string& error) override;
    int addHotplug(std::uint16_t vendorId, std::uint16_t productId, HotplugCallback callback, std::string& error) override;
    void removeHotplug(int handle) override;

private:
    struct Listener {
        std::uint16_t vendorId, productId;
        HotplugCallback callback;
    };
    mutable std::mutex mMutex;
    std::vector<std::shared_ptr<FakeUsbDevice>> mDevices;
    std::map<int, Listener> mListeners;
    int mNextHandle = 1;
};

}  // namespace palpate
