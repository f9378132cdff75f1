// The real UsbBackend: libusb-1.0 (PALPATE_HAVE_LIBUSB). One libusb context for the process, and
// one event thread that runs only while someone listens for hotplug events.
#include "device/usb/UsbTransport.h"

#include "device/UdevHint.h"

#include <cstdio>

#ifdef PALPATE_HAVE_LIBUSB
#include <libusb.h>

#include <atomic>
#include <map>
#include <mutex>
#include <thread>
#include <vector>
#endif

namespace palpate {

std::string usbErrorText(int code) {
    switch (code) {
        case kUsbSuccess: return "success";
        case kUsbErrorIo: return "LIBUSB_ERROR_IO (input/output error)";
        case kUsbErrorInvalidParam: return "LIBUSB_ERROR_INVALID_PARAM (invalid parameter)";
        case kUsbErrorAccess: return "LIBUSB_ERROR_ACCESS (permission denied)";
        case kUsbErrorNoDevice: return "LIBUSB_ERROR_NO_DEVICE (the device was unplugged)";
        case kUsbErrorNotFound: return "LIBUSB_ERROR_NOT_FOUND (entity not found)";
        case kUsbErrorBusy: return "LIBUSB_ERROR_BUSY (another program or a kernel driver holds the device)";
        case kUsbErrorTimeout: return "LIBUSB_ERROR_TIMEOUT (the device did not answer in time)";
        case kUsbErrorOverflow: return "LIBUSB_ERROR_OVERFLOW (the device sent more than asked)";
        case kUsbErrorPipe: return "LIBUSB_ERROR_PIPE (endpoint stalled)";
        case kUsbErrorInterrupted: return "LIBUSB_ERROR_INTERRUPTED";
        case kUsbErrorNoMem: return "LIBUSB_ERROR_NO_MEM";
        case kUsbErrorNotSupported: return "LIBUSB_ERROR_NOT_SUPPORTED";
        default: return "libusb error " + std::to_string(code);
    }
}

std::string UsbDeviceInfo::node() const {
    char text[32];
    std::snprintf(text, sizeof text, "/dev/bus/usb/%03u/%03u", unsigned(busNumber), unsigned(deviceAddress));
    return text;
}

#ifdef PALPATE_HAVE_LIBUSB
namespace {

UsbDeviceInfo infoOf(libusb_device* device) {
    UsbDeviceInfo info;
    info.busNumber = libusb_get_bus_number(device);
    info.deviceAddress = libusb_get_device_address(device);
    libusb_device_descriptor desc{};
    if (libusb_get_device_descriptor(device, &desc) == 0) {
        info.vendorId = desc.idVendor;
        info.productId = desc.idProduct;
    }
    return info;
}

class LibusbTransport final : public UsbTransport {
public:
    explicit LibusbTransport(libusb_device_handle* handle) : mHandle(handle) {}
    ~LibusbTransport() override {
        libusb_release_interface(mHandle, 0);
        libusb_close(mHandle);
    }
    int controlOut(std::uint8_t requestType, std::uint8_t request, std::uint16_t value, std::uint16_t index,
                   int timeoutMs) override {
        const int r = libusb_control_transfer(mHandle, requestType, request, value, index, nullptr, 0, unsigned(timeoutMs));
        return r < 0 ? r : 0;
    }
    int bulkWrite(std::uint8_t endpoint, const std::uint8_t* data, int length, int& transferred, int timeoutMs) override {
        transferred = 0;
        return libusb_bulk_transfer(mHandle, endpoint, const_cast<unsigned char*>(data), length, &transferred,
                                    unsigned(timeoutMs));
    }
    int bulkRead(std::uint8_t endpoint, std::uint8_t* data, int capacity, int& transferred, int timeoutMs) override {
        transferred = 0;
        return libusb_bulk_transfer(mHandle, endpoint, data, capacity, &transferred, unsigned(timeoutMs));
    }

private:
    libusb_device_handle* mHandle;
};

class LibusbBackend final : public UsbBackend {
public:
    LibusbBackend() { mInitResult = libusb_init(&mContext); }
    ~LibusbBackend() override {
        stopEvents();
        for (auto& [handle, holder] : mCallbacks) {
            libusb_hotplug_deregister_callback(mContext, handle);
            delete holder;
        }
        for (HotplugCallback* holder : mRetired) delete holder;
        if (mContext) libusb_exit(mContext);
    }

    std::vector<UsbDeviceInfo> enumerate(std::uint16_t vendorId, std::uint16_t productId) override {
        std::vector<UsbDeviceInfo> out;
        if (!mContext) return out;
        libusb_device** list = nullptr;
        const ssize_t n = libusb_get_device_list(mContext, &list);
        for (ssize_t i = 0; i < n; ++i) {
            const UsbDeviceInfo info = infoOf(list[i]);
            if ((vendorId == 0 || info.vendorId == vendorId) && (productId == 0 || info.productId == productId))
                out.push_back(info);
        }
        if (list) libusb_free_device_list(list, 1);
        return out;
    }

    std::unique_ptr<UsbTransport> open(const UsbDeviceInfo& info, std::string& error) override {
        error.clear();
        const std::string name = "USB device " + formatVidPid(info.vendorId, info.productId) + " at " + info.node();
        if (!mContext) {
            error = name + ": libusb did not initialise (" + usbErrorText(mInitResult) + ")";
            return nullptr;
        }
        libusb_device** list = nullptr;
        const ssize_t n = libusb_get_device_list(mContext, &list);
        libusb_device* found = nullptr;
        for (ssize_t i = 0; i < n; ++i)
            if (infoOf(list[i]).sameDevice(info)) found = list[i];
        libusb_device_handle* handle = nullptr;
        int r = found ? libusb_open(found, &handle) : kUsbErrorNoDevice;
        if (list) libusb_free_device_list(list, 1);
        if (r == kUsbErrorAccess) {
            error = permissionDeniedMessage(info.node(), info.vendorId, info.productId);
            return nullptr;
        }
        if (r != 0) {
            error = name + ": cannot open (" + usbErrorText(r) + ")";
            return nullptr;
        }
        // ftdi_sio may have bound the FTDI chip; detach it while we use the device.
        libusb_set_auto_detach_kernel_driver(handle, 1);
        r = libusb_claim_interface(handle, 0);
        if (r != 0) {
            libusb_close(handle);
            error = name + ": cannot claim interface 0 (" + usbErrorText(r) + ")";
            return nullptr;
        }
        return std::make_unique<LibusbTransport>(handle);
    }

    int addHotplug(std::uint16_t vendorId, std::uint16_t productId, HotplugCallback callback, std::string& error) override {
        if (!mContext) {
            error = "libusb did not initialise (" + usbErrorText(mInitResult) + ")";
            return -1;
        }
        if (!libusb_has_capability(LIBUSB_CAP_HAS_HOTPLUG)) {
            error = "this libusb has no hotplug support";
            return -1;
        }
        auto* holder = new HotplugCallback(std::move(callback));
        libusb_hotplug_callback_handle handle = 0;
        const int r = libusb_hotplug_register_callback(
            mContext, libusb_hotplug_event(LIBUSB_HOTPLUG_EVENT_DEVICE_ARRIVED | LIBUSB_HOTPLUG_EVENT_DEVICE_LEFT),
            libusb_hotplug_flag(0), vendorId ? vendorId : LIBUSB_HOTPLUG_MATCH_ANY,
            productId ? productId : LIBUSB_HOTPLUG_MATCH_ANY, LIBUSB_HOTPLUG_MATCH_ANY, &LibusbBackend::onHotplug,
            holder, &handle);
        if (r != 0) {
            delete holder;
            error = "libusb_hotplug_register_callback failed (" + usbErrorText(r) + ")";
            return -1;
        }
        {
            std::lock_guard lock(mMutex);
            mCallbacks[handle] = holder;
        }
        startEvents();
        return handle;
    }

    void removeHotplug(int handle) override {
        HotplugCallback* holder = nullptr;
        {
            std::lock_guard lock(mMutex);
            auto it = mCallbacks.find(handle);
            if (it == mCallbacks.end()) return;
            holder = it->second;
            mCallbacks.erase(it);
        }
        // Deregistering wakes the event thread; after it returns the callback is not called again.
        libusb_hotplug_deregister_callback(mContext, handle);
        bool none = false;
        {
            std::lock_guard lock(mMutex);
            none = mCallbacks.empty();
        }
        if (none) {
            stopEvents();  // joined: the callback cannot be running any more
            delete holder;
        } else {
            // The event thread may be inside this very callback right now; free it with the backend.
            std::lock_guard lock(mMutex);
            mRetired.push_back(holder);
        }
    }

private:
    static int LIBUSB_CALL onHotplug(libusb_context*, libusb_device* device, libusb_hotplug_event event, void* user) {
        const auto& callback = *static_cast<HotplugCallback*>(user);
        callback(event == LIBUSB_HOTPLUG_EVENT_DEVICE_ARRIVED ? UsbHotplugEvent::Arrived : UsbHotplugEvent::Left,
                 infoOf(device));
        return 0;  // stay registered
    }

    void startEvents() {
        std::lock_guard lock(mMutex);
        if (mEventThread.joinable()) return;
        mStopEvents.store(false);
        mEventThread = std::thread([this] {
            while (!mStopEvents.load()) {
                timeval tv{0, 100000};  // wake now and then to see the stop request
                libusb_handle_events_timeout_completed(mContext, &tv, nullptr);
            }
        });
    }

    void stopEvents() {
        std::thread thread;
        {
            std::lock_guard lock(mMutex);
            mStopEvents.store(true);
            thread = std::move(mEventThread);
        }
        if (thread.joinable()) {
            libusb_interrupt_event_handler(mContext);
            thread.join();
        }
    }

    libusb_context* mContext = nullptr;
    int mInitResult = 0;
    std::mutex mMutex;
    std::map<int, HotplugCallback*> mCallbacks;
    std::vector<HotplugCallback*> mRetired;
    std::thread mEventThread;
    std::atomic<bool> mStopEvents{true};
};

}  // namespace

std::shared_ptr<UsbBackend> createLibusbBackend() { return std::make_shared<LibusbBackend>(); }

std::shared_ptr<UsbBackend> systemUsbBackend() {
    static std::shared_ptr<UsbBackend> backend = createLibusbBackend();
    return backend;
}

#else

std::shared_ptr<UsbBackend> createLibusbBackend() { return nullptr; }
std::shared_ptr<UsbBackend> systemUsbBackend() { return nullptr; }

#endif

}  // namespace palpate
