// readHidrawReportDescriptor: hidapi 0.13 cannot give a report descriptor (hid_get_report_descriptor
// came in 0.14), but the kernel exports it for every hidraw node under sysfs.
#include "device/hid/HidTransport.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

namespace palpate {

std::string readHidrawReportDescriptor(const std::string& devicePath, std::vector<std::uint8_t>& out,
                                       const std::string& sysRoot) {
    std::string error;
    out.clear();
    error.clear();
    const std::size_t slash = devicePath.find_last_of('/');
    const std::string node = slash == std::string::npos ? devicePath : devicePath.substr(slash + 1);
    if (node.rfind("hidraw", 0) != 0 || node.size() == 6) {
        error = "HID device '" + devicePath + "': not a hidraw node, so its report descriptor cannot be read from sysfs";
        return error;
    }
    const std::string file = sysRoot + "/class/hidraw/" + node + "/device/report_descriptor";
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        error = "HID device '" + devicePath + "': cannot read its report descriptor " + file + " (" +
                std::strerror(errno) + ")";
        return error;
    }
    out.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    // The kernel caps descriptors at HID_MAX_DESCRIPTOR_SIZE (4096 bytes).
    if (out.empty() || out.size() > 4096) {
        error = "HID device '" + devicePath + "': report descriptor " + file + " has " + std::to_string(out.size()) +
                " bytes (expected 1..4096)";
        out.clear();
        return error;
    }
    return {};
}

}  // namespace palpate
