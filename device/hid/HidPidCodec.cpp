#include "device/hid/HidPidCodec.h"

#include <algorithm>
#include <cmath>

namespace palpate {
namespace {

constexpr std::uint32_t kGenericDesktopX = hidUsage(0x01, 0x30);
constexpr std::uint32_t kGenericDesktopY = hidUsage(0x01, 0x31);

const HidField* findOut(const HidReportDescriptor& d, std::uint32_t collection, std::uint32_t usage) {
    return d.find(HidReportType::Output, collection, usage);
}

/// Array fields take the 1-based position of the chosen usage (offset by logicalMin).
std::int64_t arrayValue(const HidField& field, std::uint32_t usage) {
    const auto it = std::find(field.usages.begin(), field.usages.end(), usage);
    return field.logicalMin + std::int64_t(it - field.usages.begin());
}

std::vector<std::uint8_t> newReport(const HidPidLayout& layout, HidReportType type, std::uint8_t id) {
    const std::size_t offset = layout.descriptor.numberedReports ? 1 : 0;
    std::vector<std::uint8_t> report(offset + layout.descriptor.reportBytes(type, id), 0);
    if (offset) report[0] = id;
    return report;
}

std::size_t dataOffset(const HidPidLayout& layout) { return layout.descriptor.numberedReports ? 1 : 0; }

/// Sets a field to a fraction of its logical range: -1 -> min... for signed, 0..1 -> 0..max.
std::int64_t scaled(const HidField& field, double fraction) {
    fraction = std::clamp(fraction, -1.0, 1.0);
    if (fraction >= 0) return std::llround(fraction * field.logicalMax);
    return std::llround(-fraction * field.logicalMin);
}

}  // namespace

bool descriptorHasPid(const HidReportDescriptor& descriptor) {
    for (const HidField& f : descriptor.fields)
        for (std::uint32_t c : f.collections)
            if ((c >> 16) == pid::kPage) return true;
    return false;
}

std::string resolveHidPidLayout(const std::uint8_t* data, std::size_t length, HidPidLayout& out) {
    std::string error;
    out = HidPidLayout{};
    if (!(error = parseHidReportDescriptor(data, length, out.descriptor)).empty()) return error;
    const HidReportDescriptor& d = out.descriptor;
    struct Need {
        const HidField** slot;
        std::uint32_t collection;
        std::uint32_t usage;
        const char* name;
    };
    const Need needs[] = {
        {&out.setEffectIndex, pid::kSetEffectReport, pid::kEffectBlockIndex, "Set Effect / Effect Block Index"},
        {&out.setEffectType, pid::kSetEffectReport, pid::kConstantForce, "Set Effect / Effect Type: Constant Force"},
        {&out.duration, pid::kSetEffectReport, pid::kDuration, "Set Effect / Duration"},
        {&out.constantIndex, pid::kSetConstantForceReport, pid::kEffectBlockIndex, "Set Constant Force / Effect Block Index"},
        {&out.magnitude, pid::kSetConstantForceReport, pid::kMagnitude, "Set Constant Force / Magnitude"},
        {&out.operationIndex, pid::kEffectOperationReport, pid::kEffectBlockIndex, "Effect Operation / Effect Block Index"},
        {&out.operation, pid::kEffectOperationReport, pid::kOpEffectStart, "Effect Operation / Op Effect Start"},
        {&out.deviceControl, pid::kDeviceControlReport, pid::kStopAllEffects, "PID Device Control / Stop All Effects"},
    };
    for (const Need& n : needs) {
        *n.slot = findOut(d, n.collection, n.usage);
        if (!*n.slot) {
            error = "not a HID PID device we can drive: its report descriptor has no output field " + std::string(n.name);
            return error;
        }
    }
    out.gain = findOut(d, pid::kSetEffectReport, pid::kGain);
    out.triggerButton = findOut(d, pid::kSetEffectReport, pid::kTriggerButton);
    out.directionEnable = findOut(d, pid::kSetEffectReport, pid::kDirectionEnable);
    out.loopCount = findOut(d, pid::kEffectOperationReport, pid::kLoopCount);
    for (std::uint32_t axis : {kGenericDesktopX, kGenericDesktopY})
        if (const HidField* f = findOut(d, pid::kAxesEnable, axis)) out.axisEnableFields.push_back(f);
    for (const HidField& f : d.fields)
        if (f.type == HidReportType::Output && f.inCollection(pid::kDirection) && !f.usages.empty())
            out.directionFields.push_back(&f);
    out.createNewEffectType = d.find(HidReportType::Feature, pid::kCreateNewEffectReport, pid::kConstantForce);
    out.setEffectId = out.setEffectIndex->reportId;
    out.constantForceId = out.magnitude->reportId;
    out.operationId = out.operation->reportId;
    out.deviceControlId = out.deviceControl->reportId;
    out.createNewEffectId = out.createNewEffectType ? out.createNewEffectType->reportId : 0;
    return {};
}

std::vector<std::uint8_t> buildPidSetEffect(const HidPidLayout& layout, std::uint8_t blockIndex, std::uint32_t durationMs,
                                            double directionDeg) {
    if (!layout.setEffectIndex) return {};
    auto report = newReport(layout, HidReportType::Output, layout.setEffectId);
    const std::size_t off = dataOffset(layout);
    hidSetField(report, off, *layout.setEffectIndex, 0, blockIndex);
    hidSetField(report, off, *layout.setEffectType, 0, arrayValue(*layout.setEffectType, pid::kConstantForce));
    // A finite duration: if the host stalls and stops refreshing, the joystick stops pushing by itself.
    hidSetField(report, off, *layout.duration, 0, durationMs);
    if (layout.gain) hidSetField(report, off, *layout.gain, 0, layout.gain->logicalMax);
    // No trigger button: 0, HID's null (out of the 1..N range), as hid-pidff sends for "none".
    if (layout.triggerButton) hidSetField(report, off, *layout.triggerButton, 0, 0, /*clamp=*/false);
    for (const HidField* f : layout.axisEnableFields)
        for (std::uint32_t e = 0; e < f->count; ++e) hidSetField(report, off, *f, e, 1);
    if (layout.directionEnable) hidSetField(report, off, *layout.directionEnable, 0, 1);
    if (!layout.directionFields.empty()) {
        // Direction: the polar angle of the force in the device's range (0..360 degrees mapped onto
        // logical min..max), first direction element only.
        const HidField& f = *layout.directionFields.front();
        double deg = std::fmod(directionDeg, 360.0);
        if (deg < 0) deg += 360.0;
        const double span = double(f.logicalMax) - double(f.logicalMin);
        hidSetField(report, off, f, 0, f.logicalMin + std::llround(deg / 360.0 * span));
    }
    return report;
}

std::vector<std::uint8_t> buildPidSetConstantForce(const HidPidLayout& layout, std::uint8_t blockIndex,
                                                   double magnitudeFraction) {
    if (!layout.magnitude) return {};
    auto report = newReport(layout, HidReportType::Output, layout.constantForceId);
    const std::size_t off = dataOffset(layout);
    hidSetField(report, off, *layout.constantIndex, 0, blockIndex);
    hidSetField(report, off, *layout.magnitude, 0, scaled(*layout.magnitude, magnitudeFraction));
    return report;
}

std::vector<std::uint8_t> buildPidEffectOperation(const HidPidLayout& layout, std::uint8_t blockIndex, bool start) {
    if (!layout.operation) return {};
    auto report = newReport(layout, HidReportType::Output, layout.operationId);
    const std::size_t off = dataOffset(layout);
    hidSetField(report, off, *layout.operationIndex, 0, blockIndex);
    hidSetField(report, off, *layout.operation, 0,
                arrayValue(*layout.operation, start ? pid::kOpEffectStart : pid::kOpEffectStop));
    if (layout.loopCount) hidSetField(report, off, *layout.loopCount, 0, 1);
    return report;
}

std::vector<std::uint8_t> buildPidDeviceControl(const HidPidLayout& layout, HidPidControl control) {
    if (!layout.deviceControl) return {};
    std::uint32_t usage = pid::kStopAllEffects;
    switch (control) {
        case HidPidControl::EnableActuators: usage = pid::kEnableActuators; break;
        case HidPidControl::DisableActuators: usage = pid::kDisableActuators; break;
        case HidPidControl::StopAllEffects: usage = pid::kStopAllEffects; break;
        case HidPidControl::DeviceReset: usage = pid::kDeviceReset; break;
    }
    if (!layout.deviceControl->hasUsage(usage)) return {};
    auto report = newReport(layout, HidReportType::Output, layout.deviceControlId);
    hidSetField(report, dataOffset(layout), *layout.deviceControl, 0, arrayValue(*layout.deviceControl, usage));
    return report;
}

std::vector<std::uint8_t> buildPidCreateNewEffect(const HidPidLayout& layout) {
    if (!layout.createNewEffectType) return {};
    auto report = newReport(layout, HidReportType::Feature, layout.createNewEffectId);
    hidSetField(report, dataOffset(layout), *layout.createNewEffectType, 0,
                arrayValue(*layout.createNewEffectType, pid::kConstantForce));
    return report;
}

}  // namespace palpate
