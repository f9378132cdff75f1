#include "device/usb/FakeUsbBackend.h"

#include "device/UdevHint.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <thread>

namespace palpate {
namespace {

class FakeUsbTransport final : public UsbTransport {
public:
    explicit FakeUsbTransport(std::shared_ptr<FakeUsbDevice> device) : mDevice(std::move(device)) {}
    int controlOut(std::uint8_t requestType, std::uint8_t request, std::uint16_t value, std::uint16_t index,
                   int) override {
        return mDevice->control({requestType, request, value, index});
    }
    int bulkWrite(std::uint8_t endpoint, const std::uint8_t* data, int length, int& transferred, int) override {
        return mDevice->bulkWrite(endpoint, data, length, transferred);
    }
    int bulkRead(std::uint8_t, std::uint8_t* data, int capacity, int& transferred, int timeoutMs) override {
        const int r = mDevice->bulkRead(data, capacity, transferred);
        // A quiet device: pause briefly before the timeout so that a polling thread does not spin.
        if (r == kUsbErrorTimeout && timeoutMs > 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        return r;
    }

private:
    std::shared_ptr<FakeUsbDevice> mDevice;
};

}  // namespace

void FakeUsbDevice::setResponder(Responder responder) {
    std::lock_guard lock(mMutex);
    mResponder = std::move(responder);
}
void FakeUsbDevice::setControlHandler(ControlHandler handler) {
    std::lock_guard lock(mMutex);
    mControlHandler = std::move(handler);
}
void FakeUsbDevice::pushIn(std::vector<std::uint8_t> bytes) {
    std::lock_guard lock(mMutex);
    mIn.push_back(std::move(bytes));
}
void FakeUsbDevice::failNextRead(int error) {
    std::lock_guard lock(mMutex);
    mFailRead = error;
}
void FakeUsbDevice::failNextWrite(int error) {
    std::lock_guard lock(mMutex);
    mFailWrite = error;
}
void FakeUsbDevice::unplug() {
    std::lock_guard lock(mMutex);
    mUnplugged = true;
}
bool FakeUsbDevice::unplugged() const {
    std::lock_guard lock(mMutex);
    return mUnplugged;
}
void FakeUsbDevice::denyOpen(bool deny) {
    std::lock_guard lock(mMutex);
    mDenyOpen = deny;
}
bool FakeUsbDevice::openDenied() const {
    std::lock_guard lock(mMutex);
    return mDenyOpen;
}
std::vector<UsbControlRecord> FakeUsbDevice::controls() const {
    std::lock_guard lock(mMutex);
    return mControls;
}
std::vector<std::vector<std::uint8_t>> FakeUsbDevice::bulkWrites() const {
    std::lock_guard lock(mMutex);
    return mWrites;
}
std::size_t FakeUsbDevice::bulkWriteCount() const {
    std::lock_guard lock(mMutex);
    return mWriteCount;
}

int FakeUsbDevice::control(const UsbControlRecord& record) {
    ControlHandler handler;
    {
        std::lock_guard lock(mMutex);
        if (mUnplugged) return kUsbErrorNoDevice;
        mControls.push_back(record);
        handler = mControlHandler;
    }
    return handler ? handler(record) : kUsbSuccess;
}

int FakeUsbDevice::bulkWrite(std::uint8_t endpoint, const std::uint8_t* data, int length, int& transferred) {
    transferred = 0;
    Responder responder;
    {
        std::lock_guard lock(mMutex);
        if (mUnplugged) return kUsbErrorNoDevice;
        if (mFailWrite) {
            const int e = mFailWrite;
            mFailWrite = 0;
            return e;
        }
        ++mWriteCount;
        // Keep the first writes only: a 1 kHz exchange would otherwise grow without bound.
        if (mWrites.size() < 4096) mWrites.emplace_back(data, data + length);
        responder = mResponder;
    }
    transferred = length;
    if (responder) {
        std::vector<std::uint8_t> reply = responder(endpoint, data, length);
        if (!reply.empty()) pushIn(std::move(reply));
    }
    return kUsbSuccess;
}

int FakeUsbDevice::bulkRead(std::uint8_t* data, int capacity, int& transferred) {
    transferred = 0;
    std::lock_guard lock(mMutex);
    if (mUnplugged) return kUsbErrorNoDevice;
    if (mFailRead) {
        const int e = mFailRead;
        mFailRead = 0;
        return e;
    }
    if (mIn.empty()) return kUsbErrorTimeout;
    std::vector<std::uint8_t>& front = mIn.front();
    const int n = std::min<int>(capacity, int(front.size()));
    std::memcpy(data, front.data(), std::size_t(n));
    if (n < int(front.size()))
        front.erase(front.begin(), front.begin() + n);
    else
        mIn.pop_front();
    transferred = n;
    return kUsbSuccess;
}

std::shared_ptr<FakeUsbDevice> FakeUsbBackend::add(UsbDeviceInfo info) {
    auto device = std::make_shared<FakeUsbDevice>(info);
    {
        std::lock_guard lock(mMutex);
        mDevices.push_back(device);
    }
    fire(UsbHotplugEvent::Arrived, info);
    return device;
}

void FakeUsbBackend::remove(const UsbDeviceInfo& info) {
    {
        std::lock_guard lock(mMutex);
        for (auto it = mDevices.begin(); it != mDevices.end(); ++it) {
            if ((*it)->info().sameDevice(info)) {
                (*it)->unplug();
                mDevices.erase(it);
                break;
            }
        }
    }
    fire(UsbHotplugEvent::Left, info);
}

void FakeUsbBackend::fire(UsbHotplugEvent event, const UsbDeviceInfo& info) {
    std::vector<HotplugCallback> callbacks;
    {
        std::lock_guard lock(mMutex);
        for (const auto& [handle, l] : mListeners)
            if ((l.vendorId == 0 || l.vendorId == info.vendorId) && (l.productId == 0 || l.productId == info.productId))
                callbacks.push_back(l.callback);
    }
    for (const auto& cb : callbacks) cb(event, info);
}

std::vector<UsbDeviceInfo> FakeUsbBackend::enumerate(std::uint16_t vendorId, std::uint16_t productId) {
    std::lock_guard lock(mMutex);
    std::vector<UsbDeviceInfo> out;
    for (const auto& d : mDevices)
        if ((vendorId == 0 || d->info().vendorId == vendorId) && (productId == 0 || d->info().productId == productId))
            out.push_back(d->info());
    return out;
}

std::unique_ptr<UsbTransport> FakeUsbBackend::open(const UsbDeviceInfo& info, std::string& error) {
    std::shared_ptr<FakeUsbDevice> device;
    {
        std::lock_guard lock(mMutex);
        for (const auto& d : mDevices)
            if (d->info().sameDevice(info)) device = d;
    }
    if (!device) {
        error = "USB device " + formatVidPid(info.vendorId, info.productId) + " at " + info.node() + ": cannot open (" +
                usbErrorText(kUsbErrorNoDevice) + ")";
        return nullptr;
    }
    if (device->openDenied()) {
        error = permissionDeniedMessage(info.node(), info.vendorId, info.productId);
        return nullptr;
    }
    return std::make_unique<FakeUsbTransport>(device);
}

int FakeUsbBackend::addHotplug(std::uint16_t vendorId, std::uint16_t productId, HotplugCallback callback, std::string&) {
    std::lock_guard lock(mMutex);
    const int handle = mNextHandle++;
    mListeners[handle] = Listener{vendorId, productId, std::move(callback)};
    return handle;
}

void FakeUsbBackend::removeHotplug(int handle) {
    std::lock_guard lock(mMutex);
    mListeners.erase(handle);
}

}  // namespace palpate
