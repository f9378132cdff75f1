#pragma once
// The length unit a mesh file's coordinates are in. Palpate works in millimetres; a mesh from
// another tool (metres from Blender, inches from CAD, centimetres or a unit of its own from another
// simulator) is scaled to mm when it is loaded (docs/meshes.md, "Units").

#include <optional>
#include <string>

namespace palpate {

struct MeshUnit {
    /// "mm", "cm", "m", "in", or "" for a plain scale factor.
    std::string name = "mm";
    /// Millimetres per file unit: a file coordinate times this is mm.
    double mmPerUnit = 1.0;

    bool isMillimetres() const { return mmPerUnit == 1.0; }
    /// What is written to files and shown: "mm", "cm", "m", "in", or the factor ("2.5").
    std::string text() const;
    /// For people: "cm", or "scale 2.5 (mm per file unit)".
    std::string description() const;
    bool operator==(const MeshUnit& other) const { return mmPerUnit == other.mmPerUnit; }
};

inline const MeshUnit kMillimetres{"mm", 1.0};

/// "mm", "cm", "m", "in" (case-insensitive), or a positive finite number of mm per file unit,
/// from kMinMmPerUnit to kMaxMmPerUnit. On failure returns nullopt and `error` says what is
/// accepted.
std::optional<MeshUnit> parseMeshUnit(const std::string& text, std::string& error);
inline constexpr double kMinMmPerUnit = 1e-6;
inline constexpr double kMaxMmPerUnit = 1e6;

/// The sizes, in mm, that are plausible for tissue a probe examines: from a sample a few tool
/// widths across to a whole abdomen (docs/meshes.md, "Units").
inline constexpr double kPlausibleTissueDiagonalMinMm = 20.0;
inline constexpr double kPlausibleTissueDiagonalMaxMm = 600.0;

struct UnitSuggestion {
    MeshUnit unit;
    std::string reason;  ///< one sentence: the size as given, why it is implausible, the size in the suggested unit
};

/// When a bounding-box diagonal of `diagonalInFileUnits` read as `current` is implausible for
/// tissue, the named unit (mm, cm, m, in) that makes it plausible and closest to a typical organ;
/// nullopt when it is plausible as read, or when no named unit makes it so.
std::optional<UnitSuggestion> suggestMeshUnit(double diagonalInFileUnits, const MeshUnit& current = kMillimetres);

}  // namespace palpate
