#pragma once
// A HidBackend without hardware: devices and their input reports are scripted, writes are kept.
// Tests drive the SpaceMouse and HID PID backends through it (short reads, -1 from hidapi,
// timeouts, unplug), and `palpate-cli devices` can be pointed at nothing else in CI.

#include "device/hid/HidTransport.h"

#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace palpate {

/// One scripted result of HidTransport::read.
struct FakeHidRead {
    std::vector<std::uint8_t> report;  ///< bytes returned (when result > 0)
    int result = 0;                    ///< > 0: report.size(); kHidReadTimeout; kHidReadError
    static FakeHidRead bytes(std::vector<std::uint8_t> r) {
        FakeHidRead e;
        e.result = int(r.size());
        e.report = std::move(r);
        return e;
    }
    static FakeHidRead timeout() { return {}; }
    static FakeHidRead error() { return {{}, kHidReadError}; }
};

/// The state of one fake device, shared by the backend, its transports and the test.
/// Thread-safe: the device's I/O thread reads while the test thread scripts.
class FakeHidDevice {
public:
    explicit FakeHidDevice(HidDeviceInfo info) : mInfo(std::move(info)) {}
    const HidDeviceInfo& info() const { return mInfo; }

    void pushRead(FakeHidRead read);
    void pushReport(std::vector<std::uint8_t> report) { pushRead(FakeHidRead::bytes(std::move(report))); }
    /// Scripted reads not yet consumed.
    std::size_t pendingReads() const;
    /// Every output report written, in order.
    std::vector<std::vector<std::uint8_t>> writes() const;
    /// Every feature report sent, in order.
    std::vector<std::vector<std::uint8_t>> featureReports() const;
    /// From now on every read and write fails with -1 (an unplugged device).
    void unplug();
    bool unplugged() const;
    /// Writes (output and feature reports) fail with -1 while set, to test the error path.
    void failWrites(bool fail);
    /// The report descriptor reportDescriptor() gives (empty: "cannot read").
    void setReportDescriptor(std::vector<std::uint8_t> descriptor);
    std::vector<std::uint8_t> reportDescriptor() const;
    /// open() fails with a permission error while set.
    void denyOpen(bool deny);
    bool openDenied() const;

    // For FakeHidTransport.
    int read(std::uint8_t* data, std::size_t capacity);
    int write(const std::uint8_t* data, std::size_t length, bool feature);

private:
    HidDeviceInfo mInfo;
    mutable std::mutex mMutex;
    std::deque<FakeHidRead> mReads;
    std::vector<std::vector<std::uint8_t>> mWrites;
    std::vector<std::vector<std::uint8_t>> mFeatureReports;
    std::vector<std::uint8_t> mDescriptor;
    bool mUnplugged = false;
    bool mFailWrites = false;
    bool mDenyOpen = false;
};

class FakeHidBackend final : public HidBackend {
public:
    /// Adds a device (present until removed) and returns its shared state.
    std::shared_ptr<FakeHidDevice> add(HidDeviceInfo info);
    void remove(const std::string& path);

    std::vector<HidDeviceInfo> enumerate(std::uint16_t vendorId = 0, std::uint16_t productId = 0) override;
    std::unique_ptr<HidTransport> open(const HidDeviceInfo& info, std::string& error) override;
    std::string reportDescriptor(const HidDeviceInfo& info, std::vector<std::uint8_t>& out) override;

private:
    std::shared_ptr<FakeHidDevice> find(const std::string& path) const;

    mutable std::mutex mMutex;
    std::vector<std::shared_ptr<FakeHidDevice>> mDevices;
};

}  // namespace palpate
