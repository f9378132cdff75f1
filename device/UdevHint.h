#pragma once
// What to tell a user whose device node is not accessible: the udev rule we ship for it
// (resources/udev/, docs/devices.md), so that "permission denied" ends in a fix, not a search.

#include <cstdint>
#include <string>

namespace palpate {

/// Which shipped rules file covers a device: 70-palpate-spacemouse.rules (3Dconnexion),
/// 70-palpate-falcon.rules (Novint Falcon), else 70-palpate-hid-pid.rules (a template to edit).
std::string udevRuleFileFor(std::uint16_t vendorId, std::uint16_t productId);

/// "permission denied on NODE (VID:PID): install resources/udev/FILE into /etc/udev/rules.d/, then
/// 'sudo udevadm control --reload && sudo udevadm trigger' and replug (docs/devices.md)".
std::string permissionDeniedMessage(const std::string& node, std::uint16_t vendorId, std::uint16_t productId);

/// "VVVV:PPPP" in lower-case hex, as lsusb prints it.
std::string formatVidPid(std::uint16_t vendorId, std::uint16_t productId);

}  // namespace palpate
