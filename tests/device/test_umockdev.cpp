// libusb and hidapi under umockdev (run through umockdev-wrapper, see CMakeLists.txt): a Novint Falcon that
// exists only in umockdev's fake sysfs/udev is enumerated by our real libusb backend, its arrival
// and removal reach our hotplug callback as libusb hotplug events (udev uevents emitted by the
// testbed), and the idempotent tracker and the device discovery see them. umockdev cannot open a
// usbfs node without an ioctl recording of real hardware, so open() is tested for its error: the
// real libusb says NO_DEVICE, and our message names the Falcon and the node.

#include "device/open/DeviceDiscovery.h"
#include "device/hid/HidTransport.h"
#include "device/hid/SpaceMouseDevice.h"
#include "device/usb/FalconDevice.h"
#include "device/usb/FalconProtocol.h"
#include "device/usb/HotplugTracker.h"
#include "device/usb/UsbTransport.h"
#include "tests/device/DeviceTestSupport.h"

#include <umockdev.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <condition_variable>
#include <mutex>
#include <vector>

namespace palpate {
namespace {

using test::waitUntil;

bool contains(const std::string& haystack, const std::string& needle) { return haystack.find(needle) != std::string::npos; }

/// A full-speed FTDI device 0403:cb48 at bus 1, address `devnum`: sysfs attributes, udev
/// properties, and the binary "descriptors" file libusb reads (device descriptor, then one
/// configuration with one vendor interface and bulk endpoints 0x81 / 0x02, as on the Falcon).
gchar* addFalcon(UMockdevTestbed* testbed, const char* name, const char* devnum) {
    const std::string devnum3 = std::string(3 - std::string(devnum).size(), '0') + devnum;
    const std::string node = "/dev/bus/usb/001/" + devnum3;
    gchar* sysPath = umockdev_testbed_add_device(testbed, "usb", name, nullptr,
                                                 // sysfs attributes
                                                 "busnum", "1", "devnum", devnum, "idVendor", "0403", "idProduct",
                                                 "cb48", "speed", "12", nullptr,
                                                 // udev properties
                                                 "BUSNUM", "001", "DEVNUM", devnum3.c_str(), "DEVTYPE", "usb_device",
                                                 "DEVNAME", node.c_str(), "PRODUCT", "403/cb48/0", nullptr);
    guint8 descriptors[] = {
        0x12, 0x01, 0x00, 0x02, 0x00, 0x00, 0x00, 0x08, 0x03, 0x04, 0x48, 0xcb, 0x00, 0x00, 0x01, 0x02, 0x03, 0x01,
        0x09, 0x02, 0x20, 0x00, 0x01, 0x01, 0x00, 0x80, 0x32,  // configuration
        0x09, 0x04, 0x00, 0x00, 0x02, 0xff, 0xff, 0xff, 0x02,  // interface 0, vendor class
        0x07, 0x05, 0x81, 0x02, 0x40, 0x00, 0x00,              // bulk IN 0x81, 64 bytes
        0x07, 0x05, 0x02, 0x02, 0x40, 0x00, 0x00,              // bulk OUT 0x02, 64 bytes
    };
    umockdev_testbed_set_attribute_binary(testbed, sysPath, "descriptors", descriptors, sizeof descriptors);
    return sysPath;
}

class Umockdev : public ::testing::Test {
protected:
    void SetUp() override {
        mTestbed = umockdev_testbed_new();  // first: it is what sets up the mock environment
        ASSERT_TRUE(umockdev_in_mock_environment())
            << "run this test under umockdev-wrapper (ctest does: see tests/device/CMakeLists.txt)";
    }
    void TearDown() override {
        if (mTestbed) g_object_unref(mTestbed);
    }
    UMockdevTestbed* mTestbed = nullptr;
};

TEST_F(Umockdev, EnumeratesAFakeFalconAndDiscoveryListsIt) {
    gchar* sysPath = addFalcon(mTestbed, "1-1", "7");
    auto usb = createLibusbBackend();
    ASSERT_TRUE(usb);
    const auto found = usb->enumerate(kFalconVendorId, kFalconProductId);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].busNumber, 1);
    EXPECT_EQ(found[0].deviceAddress, 7);
    EXPECT_EQ(found[0].node(), "/dev/bus/usb/001/007");
    EXPECT_TRUE(usb->enumerate(0x046d, 0xc626).empty());

    const auto devices = discoverDevices(DeviceBackends{nullptr, usb});
    std::size_t falcons = 0;
    for (const auto& d : devices)
        if (d.backend == "falcon") {
            ++falcons;
            EXPECT_EQ(d.uri, "falcon:0");
        }
    EXPECT_EQ(falcons, 1u);
    g_free(sysPath);
}

TEST_F(Umockdev, OpeningWithoutUsbfsIsAClearNoDeviceError) {
    gchar* sysPath = addFalcon(mTestbed, "1-1", "7");
    auto usb = createLibusbBackend();
    FalconDevice device(usb, FalconDeviceDef{});
    EXPECT_FALSE(device.open());
    EXPECT_EQ(device.state(), DeviceState::Disconnected);
    EXPECT_TRUE(contains(device.lastError(), "Falcon 0: USB device 0403:cb48 at /dev/bus/usb/001/007")) << device.lastError();
    EXPECT_TRUE(contains(device.lastError(), "LIBUSB_ERROR_NO_DEVICE")) << device.lastError();
    g_free(sysPath);
}

struct Events {
    std::mutex mutex;
    std::vector<std::pair<UsbHotplugEvent, UsbDeviceInfo>> seen;
    HotplugTracker tracker;
    int realArrivals = 0, realRemovals = 0;
    std::size_t count() {
        std::lock_guard lock(mutex);
        return seen.size();
    }
};

TEST_F(Umockdev, HotplugArrivalAndRemovalReachOurCallback) {
    auto usb = createLibusbBackend();
    ASSERT_TRUE(usb->enumerate(0, 0).empty());
    Events events;
    std::string error;
    const int handle = usb->addHotplug(
        kFalconVendorId, kFalconProductId,
        [&](UsbHotplugEvent e, const UsbDeviceInfo& info) {
            std::lock_guard lock(events.mutex);
            events.seen.emplace_back(e, info);
            if (e == UsbHotplugEvent::Arrived ? events.tracker.arrived(info) : events.tracker.left(info))
                ++(e == UsbHotplugEvent::Arrived ? events.realArrivals : events.realRemovals);
        },
        error);
    ASSERT_GE(handle, 0) << error;

    gchar* sysPath = addFalcon(mTestbed, "1-1", "9");
    umockdev_testbed_uevent(mTestbed, sysPath, "add");
    ASSERT_TRUE(waitUntil([&] { return events.count() >= 1; })) << "no arrival event from libusb";
    {
        std::lock_guard lock(events.mutex);
        EXPECT_EQ(events.seen[0].first, UsbHotplugEvent::Arrived);
        EXPECT_EQ(events.seen[0].second.deviceAddress, 9);
        EXPECT_EQ(events.seen[0].second.vendorId, kFalconVendorId);
    }
    EXPECT_EQ(usb->enumerate(kFalconVendorId, kFalconProductId).size(), 1u);

    umockdev_testbed_uevent(mTestbed, sysPath, "remove");
    ASSERT_TRUE(waitUntil([&] { return events.count() >= 2; })) << "no removal event from libusb";
    {
        std::lock_guard lock(events.mutex);
        EXPECT_EQ(events.seen[1].first, UsbHotplugEvent::Left);
        EXPECT_EQ(events.seen[1].second.deviceAddress, 9);
        EXPECT_EQ(events.realArrivals, 1);
        EXPECT_EQ(events.realRemovals, 1);
    }
    EXPECT_TRUE(usb->enumerate(kFalconVendorId, kFalconProductId).empty());
    usb->removeHotplug(handle);
    g_free(sysPath);
}

TEST_F(Umockdev, ARemovalOfADeviceNeverSeenArrivingIsIgnored) {
    gchar* sysPath = addFalcon(mTestbed, "1-1", "5");  // present before we listen: no arrival event
    auto usb = createLibusbBackend();
    Events events;
    std::string error;
    const int handle = usb->addHotplug(
        kFalconVendorId, kFalconProductId,
        [&](UsbHotplugEvent e, const UsbDeviceInfo& info) {
            std::lock_guard lock(events.mutex);
            events.seen.emplace_back(e, info);
            if (e == UsbHotplugEvent::Left && events.tracker.left(info)) ++events.realRemovals;
        },
        error);
    ASSERT_GE(handle, 0) << error;
    umockdev_testbed_uevent(mTestbed, sysPath, "remove");
    ASSERT_TRUE(waitUntil([&] { return events.count() >= 1; })) << "no removal event from libusb";
    std::lock_guard lock(events.mutex);
    EXPECT_EQ(events.seen[0].first, UsbHotplugEvent::Left);
    EXPECT_EQ(events.realRemovals, 0);  // the tracker never saw it arrive
    EXPECT_EQ(events.tracker.ignoredEvents(), 1u);
    usb->removeHotplug(handle);
    g_free(sysPath);
}

/// A SpaceMouse Compact (256f:c635) as udev and sysfs show it: USB device -> interface -> HID
/// device (uevent HID_ID/HID_NAME/HID_UNIQ, binary report_descriptor: Generic Desktop /
/// Multi-axis Controller, report 1 = 3 x int16) -> hidraw0. hidapi's hidraw backend reads all of
/// these; the "device" link from the hidraw node to its HID device is what the kernel provides
/// and umockdev does not, so the test makes it.
gchar* addSpaceMouse(UMockdevTestbed* testbed) {
    gchar* usbDevice = umockdev_testbed_add_device(testbed, "usb", "1-2", nullptr, "idVendor", "256f", "idProduct", "c635",
                                                   "busnum", "1", "devnum", "4", "manufacturer", "3Dconnexion", "product",
                                                   "SpaceMouse Compact", "serial", "XYZ", nullptr, "DEVTYPE", "usb_device",
                                                   nullptr);
    gchar* interface = umockdev_testbed_add_device(testbed, "usb", "1-2:1.0", usbDevice, "bInterfaceNumber", "00", nullptr,
                                                   "DEVTYPE", "usb_interface", nullptr);
    gchar* hid = umockdev_testbed_add_device(testbed, "hid", "0003:256F:C635.0001", interface, nullptr, "HID_ID",
                                             "0003:0000256F:0000C635", "HID_NAME", "3Dconnexion SpaceMouse Compact",
                                             "HID_UNIQ", "XYZ", nullptr);
    guint8 descriptor[] = {0x05, 0x01, 0x09, 0x08, 0xA1, 0x01, 0x85, 0x01, 0x16, 0xA2, 0xFE, 0x26, 0x5E, 0x01,
                           0x09, 0x30, 0x09, 0x31, 0x09, 0x32, 0x75, 0x10, 0x95, 0x03, 0x81, 0x02, 0xC0};
    umockdev_testbed_set_attribute_binary(testbed, hid, "report_descriptor", descriptor, sizeof descriptor);
    gchar* hidraw = umockdev_testbed_add_device(testbed, "hidraw", "hidraw0", hid, "dev", "241:0", nullptr, "DEVNAME",
                                                "/dev/hidraw0", nullptr);
    const std::string link = std::string(umockdev_testbed_get_root_dir(testbed)) + hidraw + "/device";
    EXPECT_EQ(::symlink("..", link.c_str()), 0) << link;
    g_free(usbDevice);
    g_free(interface);
    g_free(hid);
    return hidraw;
}

TEST_F(Umockdev, HidapiEnumeratesAFakeSpaceMouseAndItsDescriptorIsReadFromSysfs) {
    gchar* hidraw = addSpaceMouse(mTestbed);
    auto hid = systemHidBackend();
    ASSERT_TRUE(hid);
    const auto found = hid->enumerate(0x256f, 0xc635);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].path, "/dev/hidraw0");
    EXPECT_EQ(found[0].serial, "XYZ");
    EXPECT_EQ(found[0].usagePage, 1);  // hidapi parsed our descriptor: Generic Desktop ...
    EXPECT_EQ(found[0].usage, 8);      // ... Multi-axis Controller
    std::vector<std::uint8_t> descriptor;
    std::string error;
    ASSERT_TRUE((error = hid->reportDescriptor(found[0], descriptor)).empty()) << error;  // via /sys/class/hidraw
    EXPECT_EQ(descriptor.size(), 27u);
    EXPECT_EQ(descriptor[3], 0x08);

    const auto devices = discoverDevices(DeviceBackends{hid, nullptr});
    ASSERT_EQ(devices.size(), 1u);
    EXPECT_EQ(devices[0].backend, "spacemouse");
    EXPECT_EQ(devices[0].uri, "hid:256f:c635:XYZ");

    // umockdev makes no hidraw node (and would not answer hidraw ioctls): open fails, clearly.
    SpaceMouseDevice device(hid, HidSelector{});
    EXPECT_FALSE(device.open());
    EXPECT_TRUE(contains(device.lastError(), "SpaceMouse: HID device 256f:c635 at /dev/hidraw0: cannot open"))
        << device.lastError();
    g_free(hidraw);
}

}  // namespace
}  // namespace palpate
