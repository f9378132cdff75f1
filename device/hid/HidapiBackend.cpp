// The real HidBackend: hidapi's hidraw backend (Linux). Compiled only when pkg-config finds
// hidapi-hidraw (PALPATE_HAVE_HIDAPI); otherwise systemHidBackend() returns null and the HID
// schemes say that the build has no HID support.
#include "device/hid/HidTransport.h"

#include "device/UdevHint.h"

#ifdef PALPATE_HAVE_HIDAPI
#include <hidapi/hidapi.h>

#include <cerrno>
#include <climits>
#include <cstring>
#include <cwchar>
#include <mutex>
#include <unistd.h>
#endif

namespace palpate {

#ifdef PALPATE_HAVE_HIDAPI
namespace {

std::string narrow(const wchar_t* text) {
    std::string out;
    if (!text) return out;
    for (; *text; ++text) out += (*text >= 0x20 && *text < 0x7f) ? char(*text) : '?';
    return out;
}

/// hid_init is process-wide and not thread-safe; do it once.
bool initHidapi() {
    static std::once_flag once;
    static bool ok = false;
    std::call_once(once, [] { ok = hid_init() == 0; });
    return ok;
}

class HidapiTransport final : public HidTransport {
public:
    explicit HidapiTransport(hid_device* device) : mDevice(device) {}
    ~HidapiTransport() override { hid_close(mDevice); }

    int read(std::uint8_t* data, std::size_t capacity, int timeoutMs) override {
        const int n = hid_read_timeout(mDevice, data, capacity, timeoutMs);
        return n < 0 ? kHidReadError : n;
    }
    int write(const std::uint8_t* data, std::size_t length) override { return hid_write(mDevice, data, length); }
    int sendFeatureReport(const std::uint8_t* data, std::size_t length) override {
        return hid_send_feature_report(mDevice, data, length);
    }
    int getFeatureReport(std::uint8_t* data, std::size_t capacity) override {
        return hid_get_feature_report(mDevice, data, capacity);
    }
    std::string lastError() const override { return narrow(hid_error(mDevice)); }

private:
    hid_device* mDevice;
};

class HidapiBackend final : public HidBackend {
public:
    std::vector<HidDeviceInfo> enumerate(std::uint16_t vendorId, std::uint16_t productId) override {
        std::vector<HidDeviceInfo> out;
        if (!initHidapi()) return out;
        hid_device_info* list = hid_enumerate(vendorId, productId);
        for (hid_device_info* d = list; d; d = d->next) {
            HidDeviceInfo info;
            info.path = d->path ? d->path : "";
            info.vendorId = d->vendor_id;
            info.productId = d->product_id;
            info.serial = narrow(d->serial_number);
            info.manufacturer = narrow(d->manufacturer_string);
            info.product = narrow(d->product_string);
            info.usagePage = d->usage_page;
            info.usage = d->usage;
            info.interfaceNumber = d->interface_number;
            out.push_back(std::move(info));
        }
        hid_free_enumeration(list);
        return out;
    }

    std::unique_ptr<HidTransport> open(const HidDeviceInfo& info, std::string& error) override {
        error.clear();
        const std::string name = "HID device " + formatVidPid(info.vendorId, info.productId) + " at " + info.path;
        if (!initHidapi()) {
            error = name + ": hidapi did not initialise";
            return nullptr;
        }
        // hidapi's open error does not carry errno; ask the node directly so that a permission
        // problem is named as one, with the rule that fixes it.
        if (::access(info.path.c_str(), R_OK | W_OK) != 0 && errno == EACCES) {
            error = permissionDeniedMessage(info.path, info.vendorId, info.productId);
            return nullptr;
        }
        hid_device* device = hid_open_path(info.path.c_str());
        if (!device) {
            const int savedErrno = errno;
            error = name + ": cannot open (" + narrow(hid_error(nullptr)) +
                    (savedErrno ? std::string(", ") + std::strerror(savedErrno) : std::string()) + ")";
            if (savedErrno == EACCES || savedErrno == EPERM)
                error = permissionDeniedMessage(info.path, info.vendorId, info.productId);
            return nullptr;
        }
        return std::make_unique<HidapiTransport>(device);
    }

    std::string reportDescriptor(const HidDeviceInfo& info, std::vector<std::uint8_t>& out) override {
        return readHidrawReportDescriptor(info.path, out);
    }
};

}  // namespace

std::shared_ptr<HidBackend> systemHidBackend() {
    static std::shared_ptr<HidBackend> backend = std::make_shared<HidapiBackend>();
    return backend;
}

#else

std::shared_ptr<HidBackend> systemHidBackend() { return nullptr; }

#endif

}  // namespace palpate
