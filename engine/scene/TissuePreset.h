#pragma once
// Tissue presets: a named, versioned JSON file with everything an instructor tunes (model, slopes,
// springs, octree, haptic rate). Unknown keys, wrong types and out-of-range values are errors that
// name the key, so a typo never silently falls back to a default. "model" is any registry name
// (engine/models/ModelRegistry.h); the registry models' own parameters are in sections named like
// them ("mass_spring", "radius_of_influence", "ffd"); volumetric-rings takes "slope_ring".

#include "engine/core/Octree.h"
#include "engine/lod/LodNeeds.h"
#include "engine/models/ModelRegistry.h"
#include "base/params/FieldTable.h"

#include <optional>
#include <string>
#include <vector>

namespace palpate {

/// Version 2 adds the registry models; a preset of a slope-ring method is still written as version 1.
inline constexpr int kTissuePresetVersion = 2;

/// Elastic properties the slopes were derived from, when known, with the source (docs/calibration.md):
/// the Parameters panel and the calibration turn them into slopes for the current mesh. The
/// defaults are the gelatin phantom's (what the panel shows for a preset without a tissue).
struct TissueProperties {
    double youngsModulusKPa = 4.34;
    double poissonRatio = 0.45;
    double toolRadiusMm = 5.0;  ///< radius of the probe the slopes are calibrated for, and of the
                                ///< sphere the contact of ours (coherent) touches with
    /// Coulomb friction between tool and tissue (docs/method.md, "Friction"). Moist soft tissue:
    /// static 0.3 (Shacham, Castel and Gefen 2010, fresh porcine muscle, about 0.3 above 4 N);
    /// sliding below it (0.2, our choice: that source measures only the static value).
    double staticFriction = 0.3;
    double dynamicFriction = 0.2;
    /// b of the exponential strain-energy law the hyperelastic reference uses for this tissue
    /// (engine/fem/HyperelasticMaterial.h; 0: neo-Hookean). Calibration turns it into the slope-ring
    /// model's stiffening knots (docs/calibration.md, "Knots from the hyperelastic reference").
    double stiffeningExponent = 0.0;
    std::string source;
    /// Where b came from ("stiffening_source", optional): "" when b is 0 by assumption.
    std::string stiffeningSource;
};
/// The numeric fields of TissueProperties in file order (base/params/FieldTable.h); "source" is
/// a required string beside them.
FieldTable<TissueProperties> tissueFields();
Problems validateTissueProperties(const TissueProperties& tissue);
/// The tool and friction a model touches with, from the tissue (ModelDef::contact).
ContactDef contactDefOf(const TissueProperties& tissue);

/// The stability margin of a preset's parameter set when it was saved (stabilityMargin in
/// engine/stability/StabilityMargin.h: > 0 inside the derived bound, <= 0 beyond) and the loop
/// period it was computed for. Informational: a load does not recompute or enforce it.
struct PresetStabilityMargin {
    double margin = 1.0;
    double dtS = 1e-3;
};
FieldTable<PresetStabilityMargin> stabilityMarginFields();

struct TissuePreset {
    std::string name = "default";
    std::string description;
    /// Which model runs and every model's parameters (engine/models/ModelRegistry.h): the file
    /// holds the model's name, the "slope_ring" section (the slope-ring methods and
    /// volumetric-rings run on it; kept for a switch back) and the model's own section. The
    /// contact (tool radius, friction) is the tissue's: presetModelDef fills it in.
    ModelDef model;
    OctreeDef octree;
    double hapticRateHz = 1000.0;
    std::optional<TissueProperties> tissue;
    /// "needs": the accuracy target and haptic budget a session on this preset must meet
    /// (docs/lod.md); absent means the preset states none.
    std::optional<LodNeeds> needs;
    /// "stability_margin": written by the parameter panel on save (docs/stability.md section 7);
    /// absent in older presets, which stay valid.
    std::optional<PresetStabilityMargin> stabilityMargin;
};

struct PresetLoadResult {
    std::optional<TissuePreset> preset;
    std::vector<std::string> errors;  ///< each names the source and the key
    std::string error() const { return errors.empty() ? std::string() : errors.front(); }
};

/// The registry definition of the preset's model (method and slope-ring parameters included).
ModelDef presetModelDef(const TissuePreset& preset);
/// The radius of the tool the preset's model touches with (DeformationModel::toolRadiusMm): the
/// tissue's tool radius for ours (coherent), 0 (a point) for the others.
double presetToolRadiusMm(const TissuePreset& preset);
/// The preset's model name (modelNames()'s spelling).
std::string presetModelName(const TissuePreset& preset);
/// Sets the preset's model and that model's own section from `def` (the other sections are kept).
void setPresetModel(TissuePreset& preset, const ModelDef& def);
/// Whether the preset's model runs on `model.slopeRing` (slope-ring methods and volumetric-rings).
bool presetUsesSlopeRingParams(const TissuePreset& preset);

/// True when every value of the two presets is the same (exact comparison): the undo check.
bool samePreset(const TissuePreset& a, const TissuePreset& b);

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
