#pragma once
// HID PID (Physical Interface Device, USB-IF "Device Class Definition for PID 1.0", usage page
// 0x0F) output reports for one constant-force effect, built from the device's own report
// descriptor: which report IDs it uses, where each field sits and what range it takes differ
// between joysticks. EXPERIMENTAL (docs/devices.md): tested on descriptors, not on hardware.
// Linux's hid-pidff.c drives the same reports; we follow the spec's usage names.

#include "device/hid/HidReportDescriptor.h"

#include <cstdint>
#include <string>
#include <vector>

namespace palpate {

namespace pid {
constexpr std::uint16_t kPage = 0x0f;
constexpr std::uint32_t u(std::uint16_t id) { return hidUsage(kPage, id); }
constexpr std::uint32_t kSetEffectReport = u(0x21), kEffectBlockIndex = u(0x22), kEffectType = u(0x25),
                        kConstantForce = u(0x26), kDuration = u(0x50), kSamplePeriod = u(0x51), kGain = u(0x52),
                        kTriggerButton = u(0x53), kAxesEnable = u(0x55), kDirectionEnable = u(0x56),
                        kDirection = u(0x57), kStartDelay = u(0xa7), kSetConstantForceReport = u(0x73),
                        kMagnitude = u(0x70), kEffectOperationReport = u(0x77), kEffectOperation = u(0x78),
                        kOpEffectStart = u(0x79), kOpEffectStop = u(0x7b), kLoopCount = u(0x7c),
                        kDeviceControlReport = u(0x96),
                        kEnableActuators = u(0x97), kDisableActuators = u(0x98), kStopAllEffects = u(0x99),
                        kDeviceReset = u(0x9a), kCreateNewEffectReport = u(0xab), kBlockLoadReport = u(0x89),
                        kBlockLoadStatus = u(0x8b), kBlockLoadSuccess = u(0x8c), kDeviceGainReport = u(0x7d),
                        kDeviceGain = u(0x7e);
}  // namespace pid

/// The reports of one effect, located in a parsed descriptor.
struct HidPidLayout {
    HidPidLayout() = default;
    HidPidLayout(const HidPidLayout&) = delete;  // the field pointers point into `descriptor`
    HidPidLayout& operator=(const HidPidLayout&) = delete;
    HidPidLayout(HidPidLayout&&) = default;      // a moved vector keeps its buffer: pointers stay valid
    HidPidLayout& operator=(HidPidLayout&&) = default;

    HidReportDescriptor descriptor;
    const HidField* setEffectIndex = nullptr;
    const HidField* setEffectType = nullptr;
    const HidField* duration = nullptr;
    const HidField* gain = nullptr;
    const HidField* triggerButton = nullptr;
    const HidField* axesEnable = nullptr;       ///< first axis bit (element per axis when count > 1)
    std::vector<const HidField*> axisEnableFields;
    const HidField* directionEnable = nullptr;
    std::vector<const HidField*> directionFields;
    const HidField* constantIndex = nullptr;
    const HidField* magnitude = nullptr;
    const HidField* operationIndex = nullptr;
    const HidField* operation = nullptr;
    const HidField* loopCount = nullptr;
    const HidField* deviceControl = nullptr;
    const HidField* createNewEffectType = nullptr;  ///< optional (feature report)
    std::uint8_t setEffectId = 0, constantForceId = 0, operationId = 0, deviceControlId = 0, createNewEffectId = 0;
};

/// Finds the PID reports: "" or the problem naming the first missing usage (the device is then
/// not a PID joystick we can drive). Keeps a copy of the descriptor; fields point into it, so the
/// layout must not be copied (it is moved only as a whole unique_ptr by its owner).
std::string resolveHidPidLayout(const std::uint8_t* descriptor, std::size_t length, HidPidLayout& out);

/// Whether the descriptor declares PID usages at all (for `palpate-cli devices`).
bool descriptorHasPid(const HidReportDescriptor& descriptor);

enum class HidPidControl { EnableActuators, DisableActuators, StopAllEffects, DeviceReset };

/// Each returns a complete output report (ID byte first when the device numbers reports), or empty
/// when the layout lacks the report.
std::vector<std::uint8_t> buildPidSetEffect(const HidPidLayout& layout, std::uint8_t blockIndex, std::uint32_t durationMs,
                                            double directionDeg);
std::vector<std::uint8_t> buildPidSetConstantForce(const HidPidLayout& layout, std::uint8_t blockIndex,
                                                   double magnitudeFraction);
std::vector<std::uint8_t> buildPidEffectOperation(const HidPidLayout& layout, std::uint8_t blockIndex, bool start);
std::vector<std::uint8_t> buildPidDeviceControl(const HidPidLayout& layout, HidPidControl control);
/// Feature report "Create New Effect" for a constant force (empty when the device has none).
std::vector<std::uint8_t> buildPidCreateNewEffect(const HidPidLayout& layout);

}  // namespace palpate
