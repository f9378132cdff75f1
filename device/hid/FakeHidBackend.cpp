#include "device/hid/FakeHidBackend.h"

#include "device/UdevHint.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <thread>

namespace palpate {
namespace {

class FakeHidTransport final : public HidTransport {
public:
    explicit FakeHidTransport(std::shared_ptr<FakeHidDevice> device) : mDevice(std::move(device)) {}

    int read(std::uint8_t* data, std::size_t capacity, int timeoutMs) override {
        const int n = mDevice->read(data, capacity);
        // An empty script behaves like a quiet device: a short wait, then a timeout, so that a
        // reading thread does not spin. (Only the pace of the fake depends on it, no test result.)
        if (n == kHidReadTimeout && timeoutMs != 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        if (n == kHidReadError) mError = "read failed (fake device unplugged or scripted error)";
        return n;
    }
    int write(const std::uint8_t* data, std::size_t length) override { return checked(mDevice->write(data, length, false)); }
    int sendFeatureReport(const std::uint8_t* data, std::size_t length) override {
        return checked(mDevice->write(data, length, true));
    }
    int getFeatureReport(std::uint8_t*, std::size_t) override {
        mError = "the fake device has no feature reports to read";
        return -1;
    }
    std::string lastError() const override { return mError; }

private:
    int checked(int n) {
        if (n < 0) mError = "write failed (fake device unplugged or scripted error)";
        return n;
    }
    std::shared_ptr<FakeHidDevice> mDevice;
    std::string mError;
};

}  // namespace

void FakeHidDevice::pushRead(FakeHidRead read) {
    std::lock_guard lock(mMutex);
    mReads.push_back(std::move(read));
}

std::size_t FakeHidDevice::pendingReads() const {
    std::lock_guard lock(mMutex);
    return mReads.size();
}

std::vector<std::vector<std::uint8_t>> FakeHidDevice::writes() const {
    std::lock_guard lock(mMutex);
    return mWrites;
}

std::vector<std::vector<std::uint8_t>> FakeHidDevice::featureReports() const {
    std::lock_guard lock(mMutex);
    return mFeatureReports;
}

void FakeHidDevice::unplug() {
    std::lock_guard lock(mMutex);
    mUnplugged = true;
}

bool FakeHidDevice::unplugged() const {
    std::lock_guard lock(mMutex);
    return mUnplugged;
}

void FakeHidDevice::failWrites(bool fail) {
    std::lock_guard lock(mMutex);
    mFailWrites = fail;
}

void FakeHidDevice::setReportDescriptor(std::vector<std::uint8_t> descriptor) {
    std::lock_guard lock(mMutex);
    mDescriptor = std::move(descriptor);
}

std::vector<std::uint8_t> FakeHidDevice::reportDescriptor() const {
    std::lock_guard lock(mMutex);
    return mDescriptor;
}

void FakeHidDevice::denyOpen(bool deny) {
    std::lock_guard lock(mMutex);
    mDenyOpen = deny;
}

bool FakeHidDevice::openDenied() const {
    std::lock_guard lock(mMutex);
    return mDenyOpen;
}

int FakeHidDevice::read(std::uint8_t* data, std::size_t capacity) {
    std::lock_guard lock(mMutex);
    if (mUnplugged) return kHidReadError;
    if (mReads.empty()) return kHidReadTimeout;
    FakeHidRead next = std::move(mReads.front());
    mReads.pop_front();
    if (next.result <= 0) return next.result;
    // Like hidraw, a report longer than the buffer is cut to the buffer.
    const std::size_t n = std::min(capacity, next.report.size());
    std::memcpy(data, next.report.data(), n);
    return int(n);
}

int FakeHidDevice::write(const std::uint8_t* data, std::size_t length, bool feature) {
    std::lock_guard lock(mMutex);
    if (mUnplugged || mFailWrites) return -1;
    (feature ? mFeatureReports : mWrites).emplace_back(data, data + length);
    return int(length);
}

std::shared_ptr<FakeHidDevice> FakeHidBackend::add(HidDeviceInfo info) {
    auto device = std::make_shared<FakeHidDevice>(std::move(info));
    std::lock_guard lock(mMutex);
    mDevices.push_back(device);
    return device;
}

void FakeHidBackend::remove(const std::string& path) {
    std::lock_guard lock(mMutex);
    for (auto it = mDevices.begin(); it != mDevices.end(); ++it) {
        if ((*it)->info().path == path) {
            (*it)->unplug();
            mDevices.erase(it);
            return;
        }
    }
}

std::shared_ptr<FakeHidDevice> FakeHidBackend::find(const std::string& path) const {
    std::lock_guard lock(mMutex);
    for (const auto& d : mDevices)
        if (d->info().path == path) return d;
    return nullptr;
}

std::vector<HidDeviceInfo> FakeHidBackend::enumerate(std::uint16_t vendorId, std::uint16_t productId) {
    std::lock_guard lock(mMutex);
    std::vector<HidDeviceInfo> out;
    for (const auto& d : mDevices) {
        if (vendorId && d->info().vendorId != vendorId) continue;
        if (productId && d->info().productId != productId) continue;
        out.push_back(d->info());
    }
    return out;
}

std::unique_ptr<HidTransport> FakeHidBackend::open(const HidDeviceInfo& info, std::string& error) {
    error.clear();
    auto device = find(info.path);
    if (!device) {
        error = "HID device " + formatVidPid(info.vendorId, info.productId) + " at " + info.path + ": not present";
        return nullptr;
    }
    if (device->openDenied()) {
        error = permissionDeniedMessage(info.path, info.vendorId, info.productId);
        return nullptr;
    }
    return std::make_unique<FakeHidTransport>(device);
}

std::string FakeHidBackend::reportDescriptor(const HidDeviceInfo& info, std::vector<std::uint8_t>& out) {
    std::string error;
    auto device = find(info.path);
    out = device ? device->reportDescriptor() : std::vector<std::uint8_t>{};
    if (out.empty()) {
        error = "HID device " + formatVidPid(info.vendorId, info.productId) + " at " + info.path +
                ": no report descriptor";
        return error;
    }
    return {};
}

}  // namespace palpate
