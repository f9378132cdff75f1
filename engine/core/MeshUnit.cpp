#include "engine/core/MeshUnit.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace palpate {

namespace {

struct NamedUnit {
    const char* name;
    double mmPerUnit;
    const char* plural;
};
constexpr std::array<NamedUnit, 4> kNamedUnits{{
    {"mm", 1.0, "millimetres"},
    {"cm", 10.0, "centimetres"},
    {"m", 1000.0, "metres"},
    {"in", 25.4, "inches"},
}};

/// The size of a typical organ a probe examines (a liver lobe, a breast): the suggestion picks the
/// unit that brings a mesh closest to it.
constexpr double kTypicalTissueDiagonalMm = 150.0;

std::string number(double value) {
    std::ostringstream s;
    s.precision(value >= 100.0 ? 4 : 3);
    s << value;
    return s.str();
}

}  // namespace

std::string MeshUnit::text() const {
    if (!name.empty()) return name;
    std::ostringstream s;
    s.precision(10);
    s << mmPerUnit;
    return s.str();
}

std::string MeshUnit::description() const {
    if (!name.empty()) return name;
    return "scale " + text() + " (mm per file unit)";
}

std::optional<MeshUnit> parseMeshUnit(const std::string& text, std::string& error) {
    std::string lower = text;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    for (const NamedUnit& u : kNamedUnits)
        if (lower == u.name) return MeshUnit{u.name, u.mmPerUnit};
    if (!lower.empty()) {
        char* end = nullptr;
        const double value = std::strtod(lower.c_str(), &end);
        if (end == lower.c_str() + lower.size() && std::isfinite(value) && value >= kMinMmPerUnit &&
            value <= kMaxMmPerUnit) {
            for (const NamedUnit& u : kNamedUnits)
                if (value == u.mmPerUnit) return MeshUnit{u.name, u.mmPerUnit};
            return MeshUnit{"", value};
        }
    }
    std::ostringstream s;
    s << "'" << text.substr(0, 40) << "' is not a mesh unit: use mm, cm, m, in, or a scale factor (mm per file unit) from "
      << kMinMmPerUnit << " to " << kMaxMmPerUnit;
    error = s.str();
    return std::nullopt;
}

std::optional<UnitSuggestion> suggestMeshUnit(double diagonalInFileUnits, const MeshUnit& current) {
    if (!std::isfinite(diagonalInFileUnits) || diagonalInFileUnits <= 0.0) return std::nullopt;
    const double asReadMm = diagonalInFileUnits * current.mmPerUnit;
    const bool tooSmall = asReadMm < kPlausibleTissueDiagonalMinMm;
    if (!tooSmall && asReadMm <= kPlausibleTissueDiagonalMaxMm) return std::nullopt;
    // Metric units first: an inch is suggested only when no metric unit gives a plausible size
    // (cm and in are close, and a segmentation or a simulator is far more often metric).
    const NamedUnit* best = nullptr;
    for (bool metric : {true, false}) {
        double bestDistance = INFINITY;
        for (const NamedUnit& u : kNamedUnits) {
            if ((std::string(u.name) != "in") != metric) continue;
            const double mm = diagonalInFileUnits * u.mmPerUnit;
            if (mm < kPlausibleTissueDiagonalMinMm || mm > kPlausibleTissueDiagonalMaxMm) continue;
            const double distance = std::fabs(std::log(mm / kTypicalTissueDiagonalMm));
            if (distance < bestDistance) {
                bestDistance = distance;
                best = &u;
            }
        }
        if (best) break;
    }
    // No named unit fits (a file far too large, in micrometres or tenths of a mm): the power of ten
    // that brings it closest to a typical organ, as a scale factor.
    MeshUnit suggested;
    std::string inWords;
    if (best) {
        suggested = MeshUnit{best->name, best->mmPerUnit};
        inWords = std::string("in ") + best->plural;
    } else {
        const double factor = std::pow(10.0, std::round(std::log10(kTypicalTissueDiagonalMm / diagonalInFileUnits)));
        if (factor < kMinMmPerUnit || factor > kMaxMmPerUnit) return std::nullopt;
        suggested = MeshUnit{"", factor};
        inWords = "scaled by " + suggested.text();
    }
    if (suggested.mmPerUnit == current.mmPerUnit) return std::nullopt;
    std::ostringstream why;
    why << "read as " << current.description() << " it is " << number(asReadMm) << " mm across, "
        << (tooSmall ? "smaller" : "larger") << " than tissue a probe examines ("
        << number(kPlausibleTissueDiagonalMinMm) << " to " << number(kPlausibleTissueDiagonalMaxMm)
        << " mm); " << inWords << " it is " << number(diagonalInFileUnits * suggested.mmPerUnit) << " mm across";
    return UnitSuggestion{suggested, why.str()};
}

}  // namespace palpate
