#include "device/hid/HidReportDescriptor.h"

#include <algorithm>
#include <array>
#include <map>
#include <utility>

namespace palpate {
namespace {

// Bounds that no real descriptor reaches but that stop a hostile one from costing memory or time.
constexpr std::uint32_t kMaxReportSizeBits = 32;
constexpr std::uint32_t kMaxReportCount = 4096;
constexpr std::uint32_t kMaxReportBits = 8u * 4096u;
constexpr std::size_t kMaxUsagesPerField = 1024;
constexpr std::size_t kMaxStackDepth = 16;
constexpr std::size_t kMaxCollectionDepth = 32;
constexpr std::size_t kMaxFields = 4096;

struct GlobalState {
    std::uint16_t usagePage = 0;
    std::int32_t logicalMin = 0;
    std::int32_t logicalMax = 0;
    std::uint32_t reportSize = 0;
    std::uint32_t reportCount = 0;
    std::uint8_t reportId = 0;
};

struct LocalState {
    std::vector<std::uint32_t> usages;
    bool haveMin = false;
    std::uint32_t usageMin = 0;
};

std::uint32_t unsignedValue(const std::uint8_t* p, int size) {
    std::uint32_t v = 0;
    for (int i = 0; i < size; ++i) v |= std::uint32_t(p[i]) << (8 * i);
    return v;
}

std::int32_t signedValue(const std::uint8_t* p, int size) {
    const std::uint32_t v = unsignedValue(p, size);
    if (size == 1) return std::int8_t(v);
    if (size == 2) return std::int16_t(v);
    return std::int32_t(v);
}

/// A local usage: 4-byte items carry their own page; shorter ones take the global page.
std::uint32_t fullUsage(std::uint32_t value, int size, std::uint16_t page) {
    return size == 4 ? value : hidUsage(page, std::uint16_t(value));
}

}  // namespace

const char* hidReportTypeName(HidReportType type) {
    switch (type) {
        case HidReportType::Input: return "input";
        case HidReportType::Output: return "output";
        case HidReportType::Feature: return "feature";
    }
    return "unknown";
}

bool HidField::inCollection(std::uint32_t usage) const {
    return std::find(collections.begin(), collections.end(), usage) != collections.end();
}

bool HidField::hasUsage(std::uint32_t usage) const { return std::find(usages.begin(), usages.end(), usage) != usages.end(); }

std::size_t HidReportDescriptor::reportBytes(HidReportType type, std::uint8_t reportId) const {
    std::uint32_t bits = 0;
    for (const HidField& f : fields)
        if (f.type == type && f.reportId == reportId) bits = std::max(bits, f.bitOffset + f.bitSize * f.count);
    return (bits + 7) / 8;
}

const HidField* HidReportDescriptor::find(HidReportType type, std::uint32_t collectionUsage, std::uint32_t usage) const {
    for (const HidField& f : fields)
        if (f.type == type && f.inCollection(collectionUsage) && f.hasUsage(usage)) return &f;
    return nullptr;
}

std::string parseHidReportDescriptor(const std::uint8_t* data, std::size_t length, HidReportDescriptor& out) {
    std::string error;
    out = HidReportDescriptor{};
    error.clear();
    if (data == nullptr || length == 0) {
        error = "report descriptor is empty";
        return error;
    }
    GlobalState global;
    std::vector<GlobalState> stack;
    LocalState local;
    std::vector<std::uint32_t> collections;
    // Next free bit per (type, report ID).
    std::map<std::pair<int, int>, std::uint32_t> nextBit;

    auto fail = [&](std::size_t at, const std::string& what) {
        error = "report descriptor byte " + std::to_string(at) + ": " + what;
        out.fields.clear();
        return error;
    };

    std::size_t i = 0;
    while (i < length) {
        const std::size_t at = i;
        const std::uint8_t prefix = data[i++];
        if (prefix == 0xfe) {  // long item: size, tag, data; none is defined, so skip it
            if (i + 2 > length) return fail(at, "long item cut short");
            const std::size_t size = data[i];
            i += 2;
            if (i + size > length) return fail(at, "long item data runs past the end");
            i += size;
            continue;
        }
        static constexpr std::array<int, 4> kSizes{0, 1, 2, 4};
        const int size = kSizes[prefix & 3];
        const int type = (prefix >> 2) & 3;
        const int tag = prefix >> 4;
        if (i + std::size_t(size) > length) return fail(at, "item data runs past the end");
        const std::uint8_t* value = data + i;
        i += std::size_t(size);
        const std::uint32_t u = unsignedValue(value, size);

        if (type == 0) {  // main
            if (tag == 8 || tag == 9 || tag == 11) {
                const HidReportType reportType =
                    tag == 8 ? HidReportType::Input : tag == 9 ? HidReportType::Output : HidReportType::Feature;
                if (global.reportSize > kMaxReportSizeBits) return fail(at, "report size above 32 bits");
                if (global.reportCount > kMaxReportCount) return fail(at, "report count above 4096");
                std::uint32_t& bit = nextBit[{int(reportType), int(global.reportId)}];
                const std::uint32_t bits = global.reportSize * global.reportCount;
                if (bit + bits > kMaxReportBits) return fail(at, "report longer than 4096 bytes");
                HidField field;
                field.type = reportType;
                field.reportId = global.reportId;
                field.bitOffset = bit;
                field.bitSize = global.reportSize;
                field.count = global.reportCount;
                field.flags = u;
                field.logicalMin = global.logicalMin;
                field.logicalMax = global.logicalMax;
                field.usages = std::move(local.usages);
                field.collections = collections;
                bit += bits;
                if (bits > 0) {
                    if (out.fields.size() >= kMaxFields) return fail(at, "more than 4096 fields");
                    out.fields.push_back(std::move(field));
                }
            } else if (tag == 10) {  // collection
                if (collections.size() >= kMaxCollectionDepth) return fail(at, "collections nested deeper than 32");
                const std::uint32_t usage = local.usages.empty() ? 0 : local.usages.front();
                if (collections.empty() && u == 1) out.applications.push_back(usage);
                collections.push_back(usage);
            } else if (tag == 12) {  // end collection
                if (collections.empty()) return fail(at, "End Collection without Collection");
                collections.pop_back();
            } else {
                return fail(at, "unknown main item tag " + std::to_string(tag));
            }
            local = LocalState{};  // local items apply to one main item
        } else if (type == 1) {  // global
            switch (tag) {
                case 0: global.usagePage = std::uint16_t(u); break;
                case 1: global.logicalMin = signedValue(value, size == 0 ? 1 : size); break;
                case 2:
                    // Logical Maximum is signed too, unless Logical Minimum is >= 0 and the value
                    // only fits unsigned (a common "0..255 in one byte" idiom).
                    global.logicalMax = (global.logicalMin >= 0 && size > 0 && size < 4) ? std::int32_t(u)
                                                                                        : signedValue(value, size == 0 ? 1 : size);
                    break;
                case 3: case 4: case 5: case 6: break;  // physical range, unit: not needed
                case 7: global.reportSize = u; break;
                case 8:
                    if (u == 0 || u > 255) return fail(at, "report ID " + std::to_string(u) + " outside 1..255");
                    global.reportId = std::uint8_t(u);
                    out.numberedReports = true;
                    break;
                case 9: global.reportCount = u; break;
                case 10:
                    if (stack.size() >= kMaxStackDepth) return fail(at, "Push nested deeper than 16");
                    stack.push_back(global);
                    break;
                case 11:
                    if (stack.empty()) return fail(at, "Pop without Push");
                    global = stack.back();
                    stack.pop_back();
                    break;
                default: return fail(at, "unknown global item tag " + std::to_string(tag));
            }
        } else if (type == 2) {  // local
            switch (tag) {
                case 0:
                    if (local.usages.size() >= kMaxUsagesPerField) return fail(at, "more than 1024 usages for one item");
                    local.usages.push_back(fullUsage(u, size, global.usagePage));
                    break;
                case 1:
                    local.haveMin = true;
                    local.usageMin = fullUsage(u, size, global.usagePage);
                    break;
                case 2: {
                    if (!local.haveMin) return fail(at, "Usage Maximum without Usage Minimum");
                    const std::uint32_t max = fullUsage(u, size, global.usagePage);
                    if (max < local.usageMin) return fail(at, "Usage Maximum below Usage Minimum");
                    if (max - local.usageMin >= kMaxUsagesPerField - local.usages.size())
                        return fail(at, "usage range of more than 1024 usages");
                    for (std::uint32_t usage = local.usageMin;; ++usage) {
                        local.usages.push_back(usage);
                        if (usage == max) break;
                    }
                    local.haveMin = false;
                    break;
                }
                default: break;  // designators, strings, delimiters: not needed
            }
        } else {
            return fail(at, "reserved item type");
        }
    }
    if (!collections.empty()) return fail(length, std::to_string(collections.size()) + " collection(s) not closed");
    return {};
}

bool hidSetField(std::vector<std::uint8_t>& report, std::size_t dataOffset, const HidField& field, std::uint32_t element,
                 std::int64_t value, bool clamp) {
    if (element >= field.count || field.bitSize == 0 || field.bitSize > 32) return false;
    if (clamp && field.logicalMin <= field.logicalMax) value = std::clamp<std::int64_t>(value, field.logicalMin, field.logicalMax);
    const std::uint64_t bits = std::uint64_t(value) & ((field.bitSize == 32) ? 0xffffffffull : ((1ull << field.bitSize) - 1));
    const std::size_t start = dataOffset * 8 + field.bitOffset + std::size_t(element) * field.bitSize;
    if ((start + field.bitSize + 7) / 8 > report.size()) return false;
    for (std::uint32_t b = 0; b < field.bitSize; ++b) {
        const std::size_t bit = start + b;
        const auto mask = std::uint8_t(1u << (bit % 8));
        if ((bits >> b) & 1u) report[bit / 8] |= mask;
        else report[bit / 8] &= std::uint8_t(~mask);
    }
    return true;
}

bool hidGetField(const std::uint8_t* report, std::size_t length, std::size_t dataOffset, const HidField& field,
                 std::uint32_t element, std::int64_t& value) {
    if (element >= field.count || field.bitSize == 0 || field.bitSize > 32) return false;
    const std::size_t start = dataOffset * 8 + field.bitOffset + std::size_t(element) * field.bitSize;
    if ((start + field.bitSize + 7) / 8 > length) return false;
    std::uint64_t bits = 0;
    for (std::uint32_t b = 0; b < field.bitSize; ++b) {
        const std::size_t bit = start + b;
        if ((report[bit / 8] >> (bit % 8)) & 1u) bits |= 1ull << b;
    }
    if (field.logicalMin < 0 && field.bitSize < 64 && ((bits >> (field.bitSize - 1)) & 1u))
        bits |= ~0ull << field.bitSize;  // sign-extend
    value = std::int64_t(bits);
    return true;
}

}  // namespace palpate
