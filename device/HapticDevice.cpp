#include "device/HapticDevice.h"

namespace palpate {

const char* deviceStateName(DeviceState state) {
    switch (state) {
        case DeviceState::Disconnected: return "Disconnected";
        case DeviceState::Opening: return "Opening";
        case DeviceState::NeedsCalibration: return "NeedsCalibration";
        case DeviceState::Ready: return "Ready";
        case DeviceState::Fault: return "Fault";
    }
    return "Unknown";
}

}  // namespace palpate
