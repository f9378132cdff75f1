#pragma once
// Recorded HID input, replayed through a FakeHidDevice: one report per line as hex bytes
// ("01 0a 00 f6 ff 00 00"), "timeout" and "error" lines for the other read results, '#' comments.
// Lets a capture taken from a real unit (e.g. with `hexdump /dev/hidrawN`) become a test fixture.

#include "device/hid/FakeHidBackend.h"

#include <string>
#include <vector>

namespace palpate {

/// Parses a capture: "" or the problem naming the file and line.
std::string loadHidCapture(const std::string& path, std::vector<FakeHidRead>& reads);

}  // namespace palpate
