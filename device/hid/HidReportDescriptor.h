#pragma once
// A HID report descriptor parser (HID 1.11 §6.2.2): items -> the fields of every input, output
// and feature report, with their report ID, bit position, size, count, usages, logical range and
// enclosing collections. Enough to build HID PID reports for a device we have never seen
// (HidPidCodec). Descriptors come from devices (untrusted): every length and count is bounded,
// malformed input ends in an error naming the byte offset, never a crash (fuzz-tested).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace palpate {

enum class HidReportType : std::uint8_t { Input, Output, Feature };

const char* hidReportTypeName(HidReportType type);

/// Usage = page << 16 | id.
constexpr std::uint32_t hidUsage(std::uint16_t page, std::uint16_t id) { return std::uint32_t(page) << 16 | id; }

struct HidField {
    HidReportType type = HidReportType::Input;
    std::uint8_t reportId = 0;     ///< 0: the device does not number its reports
    std::uint32_t bitOffset = 0;   ///< from the start of the report's data (after the ID byte)
    std::uint32_t bitSize = 0;     ///< of one element
    std::uint32_t count = 0;       ///< elements
    std::uint32_t flags = 0;       ///< main item data: bit 0 constant, bit 1 variable (else array)
    std::int32_t logicalMin = 0;
    std::int32_t logicalMax = 0;
    std::vector<std::uint32_t> usages;       ///< variable: one per element (last repeats); array: the choices
    std::vector<std::uint32_t> collections;  ///< usages of the enclosing collections, outermost first
    bool isConstant() const { return (flags & 1u) != 0; }
    bool isVariable() const { return (flags & 2u) != 0; }
    bool inCollection(std::uint32_t usage) const;
    bool hasUsage(std::uint32_t usage) const;
};

struct HidReportDescriptor {
    std::vector<HidField> fields;
    bool numberedReports = false;  ///< some Report ID item appeared: every report starts with its ID byte
    /// Data bytes of a report (without the ID byte); 0 if no such report.
    std::size_t reportBytes(HidReportType type, std::uint8_t reportId) const;
    /// The first field of that type inside collection `collectionUsage` carrying `usage`; null if none.
    const HidField* find(HidReportType type, std::uint32_t collectionUsage, std::uint32_t usage) const;
    /// The top-level application collection usages (e.g. Generic Desktop / Joystick).
    std::vector<std::uint32_t> applications;
};

/// Parses: "" or the problem of malformed input ("report descriptor byte N: ...").
std::string parseHidReportDescriptor(const std::uint8_t* data, std::size_t length, HidReportDescriptor& out);

/// Writes `value` into element `element` of `field` in `report` (report[0] is the ID byte when
/// numbered, so data starts at `dataOffset`). Clamps to the logical range unless `clamp` is false
/// (HID's "null" value is deliberately out of range). False if out of bounds.
bool hidSetField(std::vector<std::uint8_t>& report, std::size_t dataOffset, const HidField& field, std::uint32_t element,
                 std::int64_t value, bool clamp = true);
/// Reads element `element` of `field` (sign-extended when logicalMin < 0).
bool hidGetField(const std::uint8_t* report, std::size_t length, std::size_t dataOffset, const HidField& field,
                 std::uint32_t element, std::int64_t& value);

}  // namespace palpate
