#include "device/usb/HotplugTracker.h"

namespace palpate {

bool HotplugTracker::arrived(const UsbDeviceInfo& info) {
    std::lock_guard lock(mMutex);
    for (const UsbDeviceInfo& d : mPresent) {
        if (d.sameDevice(info)) {
            ++mIgnored;
            return false;
        }
    }
    mPresent.push_back(info);
    return true;
}

bool HotplugTracker::left(const UsbDeviceInfo& info) {
    std::lock_guard lock(mMutex);
    for (auto it = mPresent.begin(); it != mPresent.end(); ++it) {
        if (it->sameDevice(info)) {
            mPresent.erase(it);
            return true;
        }
    }
    ++mIgnored;
    return false;
}

bool HotplugTracker::present(const UsbDeviceInfo& info) const {
    std::lock_guard lock(mMutex);
    for (const UsbDeviceInfo& d : mPresent)
        if (d.sameDevice(info)) return true;
    return false;
}

std::size_t HotplugTracker::count() const {
    std::lock_guard lock(mMutex);
    return mPresent.size();
}

std::vector<UsbDeviceInfo> HotplugTracker::devices() const {
    std::lock_guard lock(mMutex);
    return mPresent;
}

std::uint64_t HotplugTracker::ignoredEvents() const {
    std::lock_guard lock(mMutex);
    return mIgnored;
}

}  // namespace palpate
