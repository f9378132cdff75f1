// Tissue presets with the registry models (docs/models.md): every model name, each model's own
// section round trips, its validator's problems and unknown keys are named by key, and presets of
// the slope-ring methods are written as before.
#include "engine/scene/TissuePreset.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace palpate;

namespace {

TissuePreset presetFor(const std::string& name) {
    TissuePreset p;
    p.name = "models";
    const auto def = modelDefForName(name);
    EXPECT_TRUE(def) << name;
    if (def) setPresetModel(p, *def);
    return p;
}

/// Replaces the first occurrence of `from` in `text`.
std::string edited(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from << " in " << text;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

void expectErrorNaming(const std::string& text, const std::string& key, const std::string& problem = "") {
    const auto r = parseTissuePreset(text, "my.json");
    ASSERT_FALSE(r.preset) << "accepted: " << text;
    bool found = false;
    for (const auto& e : r.errors)
        if (e.find("my.json: " + key) == 0 && e.find(problem) != std::string::npos) found = true;
    EXPECT_TRUE(found) << "no error naming '" << key << "' / '" << problem << "' in:\n" << [&] {
        std::string all;
        for (const auto& e : r.errors) all += e + "\n";
        return all;
    }();
}

}  // namespace

TEST(TissuePresetModels, EveryRegistryNameLoadsAndRoundTrips) {
    for (const std::string& name : modelNames()) {
        const TissuePreset p = presetFor(name);
        EXPECT_EQ(presetModelName(p), name);
        const std::string text = tissuePresetToJson(p);
        const auto r = parseTissuePreset(text, "my.json");
        ASSERT_TRUE(r.preset) << name << ": " << r.error();
        EXPECT_EQ(presetModelName(*r.preset), name);
        EXPECT_EQ(tissuePresetToJson(*r.preset), text) << name;
        EXPECT_TRUE(messagesOf(validateModelDef(presetModelDef(*r.preset))).empty()) << name;
    }
}

TEST(TissuePresetModels, SlopeRingPresetsAreWrittenAsBefore) {
    TissuePreset p;
    p.model.slopeRingMethod = SlopeRingMethod::Hybrid;
    const std::string text = tissuePresetToJson(p);
    EXPECT_NE(text.find("\"version\": 1,"), std::string::npos) << text;
    EXPECT_NE(text.find("\"model\": \"hybrid\""), std::string::npos);
    EXPECT_EQ(text.find("mass_spring"), std::string::npos);
    EXPECT_EQ(text.find("radius_of_influence"), std::string::npos);
    EXPECT_EQ(text.find("\"ffd\""), std::string::npos);
    const TissuePreset roi = presetFor("radius-of-influence");
    EXPECT_NE(tissuePresetToJson(roi).find("\"version\": 2,"), std::string::npos);
}

TEST(TissuePresetModels, OnlyTheSectionOfTheModelInUseIsWritten) {
    const std::string text = tissuePresetToJson(presetFor("ffd"));
    EXPECT_NE(text.find("\"ffd\""), std::string::npos);
    EXPECT_NE(text.find("\"slope_ring\""), std::string::npos);
    EXPECT_EQ(text.find("mass_spring"), std::string::npos);
    EXPECT_EQ(text.find("radius_of_influence"), std::string::npos);
}

TEST(TissuePresetModels, EachModelsParametersRoundTrip) {
    TissuePreset ms = presetFor("mass-spring-local");
    ms.model.massSpring.vertexMassKg = 0.002;
    ms.model.massSpring.anchorStiffnessNPerMm = 0.3;
    ms.model.massSpring.edgeStiffnessNPerMm = 0.7;
    ms.model.massSpring.contactStiffnessNPerMm = 1.25;
    ms.model.massSpring.dampingRatio = 0.5;
    ms.model.massSpring.substeps = 3;
    ms.model.massSpring.maxSubsteps = 64;
    ms.model.massSpring.cgMaxIterations = 40;
    ms.model.massSpring.cgTolerance = 1e-7;
    ms.model.massSpring.localRingCount = 4;
    ms.model.massSpring.localIntegrator = MassSpringIntegrator::Rk4;
    ms.model.massSpring.restEpsilonMm = 2e-4;
    auto r = parseTissuePreset(tissuePresetToJson(ms), "my.json");
    ASSERT_TRUE(r.preset) << r.error();
    const MassSpringParams& m = r.preset->model.massSpring;
    EXPECT_EQ(r.preset->model.kind, ModelKind::MassSpringLocal);
    EXPECT_EQ(m.vertexMassKg, 0.002);
    EXPECT_EQ(m.anchorStiffnessNPerMm, 0.3);
    EXPECT_EQ(m.edgeStiffnessNPerMm, 0.7);
    EXPECT_EQ(m.contactStiffnessNPerMm, 1.25);
    EXPECT_EQ(m.dampingRatio, 0.5);
    EXPECT_EQ(m.substeps, 3);
    EXPECT_EQ(m.maxSubsteps, 64);
    EXPECT_EQ(m.cgMaxIterations, 40);
    EXPECT_EQ(m.cgTolerance, 1e-7);
    EXPECT_EQ(m.localRingCount, 4);
    EXPECT_EQ(m.localIntegrator, MassSpringIntegrator::Rk4);
    EXPECT_EQ(m.restEpsilonMm, 2e-4);

    TissuePreset roi = presetFor("radius-of-influence");
    roi.model.radiusOfInfluence.radiusMm = 17.5;
    roi.model.radiusOfInfluence.degree = 4;
    roi.model.radiusOfInfluence.coefficients = powerProfileCoefficients(4);
    roi.model.radiusOfInfluence.stiffnessNPerMm = 0.2;
    r = parseTissuePreset(tissuePresetToJson(roi), "my.json");
    ASSERT_TRUE(r.preset) << r.error();
    EXPECT_EQ(r.preset->model.radiusOfInfluence.radiusMm, 17.5);
    EXPECT_EQ(r.preset->model.radiusOfInfluence.degree, 4);
    EXPECT_EQ(r.preset->model.radiusOfInfluence.coefficients, powerProfileCoefficients(4));
    EXPECT_EQ(r.preset->model.radiusOfInfluence.stiffnessNPerMm, 0.2);

    TissuePreset ffd = presetFor("ffd");
    ffd.model.ffd.controlPointsPerAxis = 12;
    ffd.model.ffd.movedPerAxis = 5;
    ffd.model.ffd.marginFraction = 0.1;
    ffd.model.ffd.stiffnessNPerMm = 0.3;
    r = parseTissuePreset(tissuePresetToJson(ffd), "my.json");
    ASSERT_TRUE(r.preset) << r.error();
    EXPECT_EQ(r.preset->model.ffd.controlPointsPerAxis, 12);
    EXPECT_EQ(r.preset->model.ffd.movedPerAxis, 5);
    EXPECT_EQ(r.preset->model.ffd.marginFraction, 0.1);
    EXPECT_EQ(r.preset->model.ffd.stiffnessNPerMm, 0.3);

    // volumetric-rings runs on the slope_ring section.
    TissuePreset vol = presetFor("volumetric-rings");
    vol.model.slopeRing.ringCount = 3;
    r = parseTissuePreset(tissuePresetToJson(vol), "my.json");
    ASSERT_TRUE(r.preset) << r.error();
    EXPECT_EQ(r.preset->model.kind, ModelKind::VolumetricRings);
    EXPECT_EQ(presetModelDef(*r.preset).slopeRing.ringCount, 3);
}

TEST(TissuePresetModels, PresetsWrittenBeforeTheRenameReadAsTheCoherentMethod) {
    // Before the rename the coherent method was called "palpate"; such presets (and the presets
    // inside exercises and recordings) still load, and are written with the current name.
    const std::string text = R"({
  "format": "palpate-tissue-preset",
  "version": 2,
  "name": "old",
  "model": "palpate"
})";
    const auto r = parseTissuePreset(text, "old.json");
    ASSERT_TRUE(r.preset) << r.error();
    EXPECT_EQ(r.preset->model.kind, ModelKind::SlopeRing);
    EXPECT_EQ(r.preset->model.slopeRingMethod, SlopeRingMethod::Coherent);
    EXPECT_EQ(presetModelName(*r.preset), "coherent");
    EXPECT_NE(tissuePresetToJson(*r.preset).find("\"model\": \"coherent\""), std::string::npos);
    const auto again = parseTissuePreset(tissuePresetToJson(*r.preset), "new.json");
    ASSERT_TRUE(again.preset) << again.error();
    EXPECT_EQ(again.preset->model.slopeRingMethod, SlopeRingMethod::Coherent);
}

TEST(TissuePresetModels, ADegreeWithoutCoefficientsIsThePowerProfile) {
    const std::string text = R"({
  "format": "palpate-tissue-preset",
  "version": 2,
  "name": "roi",
  "model": "radius-of-influence",
  "radius_of_influence": {"radius_mm": 20, "degree": 3}
})";
    const auto r = parseTissuePreset(text, "my.json");
    ASSERT_TRUE(r.preset) << r.error();
    EXPECT_EQ(r.preset->model.kind, ModelKind::RadiusOfInfluence);
    EXPECT_EQ(r.preset->model.radiusOfInfluence.radiusMm, 20.0);
    EXPECT_EQ(r.preset->model.radiusOfInfluence.coefficients, powerProfileCoefficients(3));
}

TEST(TissuePresetModels, BadValuesAreNamedByKey) {
    const std::string ms = tissuePresetToJson(presetFor("mass-spring-symplectic"));
    const std::size_t massSpring = ms.find("\"mass_spring\"");
    ASSERT_NE(massSpring, std::string::npos);
    expectErrorNaming(ms.substr(0, massSpring) +
                          edited(ms.substr(massSpring), "\"vertex_mass_kg\": 0.001,", "\"vertex_mass_kg\": -1,"),
                      "mass_spring.vertex_mass_kg",
                      "positive");
    expectErrorNaming(edited(ms, "\"local_ring_count\": 6", "\"local_ring_count\": 2.5"), "mass_spring.local_ring_count",
                      "whole number");
    expectErrorNaming(edited(ms, "\"local_ring_count\": 6", "\"local_ring_count\": 99"), "mass_spring.local_ring_count");
    expectErrorNaming(edited(ms, "\"local_integrator\": \"implicit\"", "\"local_integrator\": \"euler\""),
                      "mass_spring.local_integrator", "unknown integrator");
    expectErrorNaming(edited(ms, "\"damping_ratio\": 1.0,\n    \"substeps\"", "\"damping_ratio\": \"x\",\n    \"substeps\""),
                      "mass_spring.damping_ratio", "must be a number");

    const std::string roi = tissuePresetToJson(presetFor("radius-of-influence"));
    expectErrorNaming(edited(roi, "\"radius_mm\": 25.0", "\"radius_mm\": 0"), "radius_of_influence.radius_mm", "radiusMm");
    expectErrorNaming(edited(roi, "-2.0", "-3.0"), "radius_of_influence.coefficients", "phi(1)");
    expectErrorNaming(edited(roi, "\"degree\": 2", "\"degree\": 4"), "radius_of_influence.coefficients", "needs 5");
    expectErrorNaming(edited(roi, "\"degree\": 2", "\"degree\": 12"), "radius_of_influence.degree", "out of range");

    const std::string ffd = tissuePresetToJson(presetFor("ffd"));
    expectErrorNaming(edited(ffd, "\"moved_per_axis\": 4", "\"moved_per_axis\": 9"), "ffd.moved_per_axis", "movedPerAxis");
    expectErrorNaming(edited(ffd, "\"control_points_per_axis\": 8", "\"control_points_per_axis\": 1"),
                      "ffd.control_points_per_axis");
    expectErrorNaming(edited(ffd, "\"margin_fraction\": 0.05", "\"margin_fraction\": 0"), "ffd.margin_fraction");

    const std::string vol = tissuePresetToJson(presetFor("volumetric-rings"));
    expectErrorNaming(edited(vol, "\"force_relaxation\": 0.0", "\"force_relaxation\": 2"), "slope_ring.force_relaxation");
}

TEST(TissuePresetModels, UnknownKeysAndModelsAreNamed) {
    const std::string ms = tissuePresetToJson(presetFor("mass-spring-rk4"));
    expectErrorNaming(edited(ms, "\"mass_spring\": {", "\"mass_spring\": {\"vertex_mass_g\": 1, "),
                      "mass_spring.vertex_mass_g", "unknown key");
    const std::string roi = tissuePresetToJson(presetFor("radius-of-influence"));
    expectErrorNaming(edited(roi, "\"radius_mm\"", "\"radius\": 3, \"radius_mm\""), "radius_of_influence.radius",
                      "unknown key");
    const std::string ffd = tissuePresetToJson(presetFor("ffd"));
    expectErrorNaming(edited(ffd, "\"moved_per_axis\"", "\"lattice\": 3, \"moved_per_axis\""), "ffd.lattice", "unknown key");
    expectErrorNaming(edited(ffd, "\"ffd\": {", "\"ffd\": 3, \"x\": {"), "ffd", "must be an object");
    expectErrorNaming(edited(ffd, "\"model\": \"ffd\"", "\"model\": \"fem\""), "model", "radius-of-influence");
    expectErrorNaming(edited(ffd, "\"model\": \"ffd\"", "\"model\": \"ffd\", \"volumetric_rings\": {}"),
                      "volumetric_rings", "unknown key");
}

TEST(TissuePresetModels, OldPresetsLoadAsSlopeRingMethods) {
    const std::string old = R"({
  "format": "palpate-tissue-preset",
  "version": 1,
  "name": "old",
  "model": "previous",
  "slope_ring": {"ring_count": 1, "slopes_mm_per_n": [0.5, 0.2]}
})";
    const auto r = parseTissuePreset(old, "old.json");
    ASSERT_TRUE(r.preset) << r.error();
    EXPECT_EQ(r.preset->model.kind, ModelKind::SlopeRing);
    EXPECT_EQ(r.preset->model.slopeRingMethod, SlopeRingMethod::Previous);
    EXPECT_EQ(presetModelName(*r.preset), "previous");
}

// One descriptor per model says its name, kind, texts and section; the registry's names, the
// definitions it makes and the preset's own section all follow from it.
TEST(TissuePresetModels, EveryModelIsOneDescriptorWhoseSectionThePresetWrites) {
    std::vector<std::string> names;
    for (const ModelDescriptor& d : modelDescriptors()) {
        names.emplace_back(d.name);
        const auto def = modelDefForName(d.name);
        ASSERT_TRUE(def) << d.name;
        EXPECT_EQ(def->kind, d.kind) << d.name;
        EXPECT_EQ(modelName(*def), d.name);
        EXPECT_EQ(&modelDescriptor(*def), &d) << d.name;
        if (d.kind == ModelKind::SlopeRing) {
            EXPECT_EQ(methodName(d.slopeRingMethod), d.name);
        }
        EXPECT_GT(std::string_view(d.label).size(), 3u) << d.name;
        EXPECT_NE(std::string_view(d.description).find("Cost:"), std::string_view::npos) << d.name;
        // The preset file carries the model's own section (and the slope rings, always).
        const auto json = nlohmann::json::parse(tissuePresetToJson(presetFor(d.name)));
        EXPECT_TRUE(json.contains(d.section)) << d.name << " " << d.section;
        EXPECT_EQ(slopeRingParamsOf(*def) != nullptr, std::string_view(d.section) == "slope_ring") << d.name;
    }
    EXPECT_EQ(names, modelNames());
    // "palpate", the coherent method's former name, still finds it.
    ASSERT_NE(findModelDescriptor("palpate"), nullptr);
    EXPECT_STREQ(findModelDescriptor("palpate")->name, "coherent");
    EXPECT_EQ(findModelDescriptor("no-such-model"), nullptr);
}

// A preset holds one ModelDef: setting a model keeps the other models' sections, and two presets
// differing only in another model's section are not the same (the undo check sees every edit).
TEST(TissuePresetModels, APresetKeepsEveryModelsSectionAndComparesThemAll) {
    TissuePreset p = presetFor("ffd");
    const double slope = p.model.slopeRing.slopeMagnitudeMmPerN[0];
    setPresetModel(p, *modelDefForName("mass-spring-rk4"));
    EXPECT_EQ(presetModelName(p), "mass-spring-rk4");
    EXPECT_EQ(p.model.slopeRing.slopeMagnitudeMmPerN[0], slope);
    TissuePreset q = p;
    EXPECT_TRUE(samePreset(p, q));
    q.model.radiusOfInfluence.radiusMm += 1.0;
    EXPECT_FALSE(samePreset(p, q));
}
