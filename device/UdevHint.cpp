#include "device/UdevHint.h"

#include <cstdio>

namespace palpate {

std::string formatVidPid(std::uint16_t vendorId, std::uint16_t productId) {
    char text[16];
    std::snprintf(text, sizeof text, "%04x:%04x", unsigned(vendorId), unsigned(productId));
    return text;
}

std::string udevRuleFileFor(std::uint16_t vendorId, std::uint16_t productId) {
    // 0x046d is Logitech's (3Dconnexion's older units), 0x256f 3Dconnexion's own.
    if (vendorId == 0x256f || (vendorId == 0x046d && productId >= 0xc600 && productId <= 0xc6ff))
        return "70-palpate-spacemouse.rules";
    if (vendorId == 0x0403 && productId == 0xcb48) return "70-palpate-falcon.rules";
    return "70-palpate-hid-pid.rules";
}

std::string permissionDeniedMessage(const std::string& node, std::uint16_t vendorId, std::uint16_t productId) {
    const std::string file = udevRuleFileFor(vendorId, productId);
    std::string out = "permission denied on " + node + " (" + formatVidPid(vendorId, productId) +
                      "): install resources/udev/" + file + " into /etc/udev/rules.d/";
    if (file == "70-palpate-hid-pid.rules") out += " (edit its VID:PID first)";
    out += ", run 'sudo udevadm control --reload && sudo udevadm trigger', and replug the device "
           "(docs/devices.md, 'Permissions')";
    return out;
}

}  // namespace palpate
