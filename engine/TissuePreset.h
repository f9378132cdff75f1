#pragma once
// Tissue presets: a named, versioned JSON file with everything an instructor tunes (model, slopes,
// springs, octree, haptic rate). Unknown keys, wrong types and out-of-range values are errors that
// name the key, so a typo never silently falls back to a default.

#include "engine/Octree.h"
#include "engine/SlopeRingMethod.h"
#include "engine/SlopeRingParams.h"

#include <optional>
#include <string>
#include <vector>

namespace palpate {

inline constexpr int kTissuePresetVersion = 1;

/// Elastic properties the slopes were derived from, when known, with the source (DESIGN §3):
/// the Parameters panel and the calibration turn them into slopes for the current mesh.
struct TissueProperties {
    double youngsModulusKPa = 0.0;
    double poissonRatio = 0.0;
    double toolRadiusMm = 5.0;  ///< radius of the probe the slopes are calibrated for
    std::string source;
};

struct TissuePreset {
    std::string name = "default";
    std::string description;
    SlopeRingMethod method = SlopeRingMethod::Palpate;
    SlopeRingParams params;
    OctreeDef octree;
    double hapticRateHz = 1000.0;
    std::optional<TissueProperties> tissue;
};

struct PresetLoadResult {
    std::optional<TissuePreset> preset;
    std::vector<std::string> errors;  ///< each names the source and the key
    std::string error() const { return errors.empty() ? std::string() : errors.front(); }
};

/// Parses preset JSON text; `sourceName` (a path) prefixes every message.
PresetLoadResult parseTissuePreset(const std::string& text, const std::string& sourceName);
/// Reads and parses a file; a missing file, a directory or unreadable bytes are errors too.
PresetLoadResult loadTissuePreset(const std::string& path);
/// The preset as JSON text (what saveTissuePreset writes).
std::string tissuePresetToJson(const TissuePreset& preset);
/// Writes atomically (temporary file, then rename) so a crash never leaves half a preset.
/// Returns "" or the problem.
std::string saveTissuePreset(const TissuePreset& preset, const std::string& path);

}  // namespace palpate
