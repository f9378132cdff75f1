// The parameter field tables: each field's range is what its validator enforces (a value just
// outside names that field, a value inside is accepted), every field goes through a preset file
// and back, keys are unique, and a file that cannot be represented (1e400) is refused by name.

#include "engine/loop/HapticLoop.h"
#include "engine/core/HapticRate.h"
#include "engine/core/Octree.h"
#include "engine/models/slopering/SlopeRingParams.h"
#include "engine/scene/TissuePreset.h"
#include "engine/models/FfdParams.h"
#include "engine/models/MassSpringParams.h"
#include "engine/models/RadiusOfInfluenceParams.h"
#include "engine/exercise/ExerciseFile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace palpate {
namespace {

/// A value just outside each finite end of the field's range (and NaN), and one inside.
template <class S>
std::vector<double> outsideValues(const FieldDef<S>& f) {
    std::vector<double> out{std::nan("")};
    const FieldSpec& s = f.spec;
    const double eps = (f.type == FieldType::Real || f.type == FieldType::RealList)
                           ? 1e-9 * std::max(1.0, std::abs(s.lo))
                           : 1.0;
    if (std::isfinite(s.lo)) out.push_back(s.lower == Bound::Open ? s.lo : s.lo - eps);
    if (std::isfinite(s.hi)) out.push_back(s.upper == Bound::Open ? s.hi : s.hi + std::max(eps, 1e-9 * std::abs(s.hi)));
    return out;
}

/// Every field of `table`: outside its range the validator names it (and only through its key),
/// at its default the set is valid.
template <class S>
void expectValidatorFollowsTable(FieldTable<S> table, Problems (*validate)(const S&)) {
    const S defaults{};
    EXPECT_TRUE(validate(defaults).empty()) << joinedMessages(validate(defaults));
    std::set<std::string> keys, jsonKeys;
    for (const FieldDef<S>& f : table) {
        EXPECT_TRUE(keys.insert(f.spec.key).second) << "duplicate key " << f.spec.key;
        EXPECT_TRUE(jsonKeys.insert(f.spec.jsonKey).second) << "duplicate file key " << f.spec.jsonKey;
        EXPECT_TRUE(inRange(f, f.defaultValue(0))) << f.spec.key << "'s default is outside its own range";
        EXPECT_GE(f.spec.lo, entryLowOf(f.spec)) << f.spec.key << ": the panel cannot show the lowest valid value";
        if (std::isfinite(f.spec.hi)) {
            EXPECT_LE(f.spec.hi, entryHighOf(f.spec)) << f.spec.key;
        }
        // A list none of whose entries the defaults use (the stiffening knots: 0) is not validated there.
        if (f.type == FieldType::RealList && f.usedCount(defaults) == 0) continue;
        for (double bad : outsideValues(f)) {
            if (f.type == FieldType::Choice && std::isnan(bad)) continue;  // an enum holds no NaN
            S s = defaults;
            f.set(s, 0, bad);
            const Problems problems = validate(s);
            EXPECT_TRUE(hasProblem(problems, f.spec.key))
                << f.spec.key << " = " << bad << " not named; problems: " << joinedMessages(problems);
            for (const Problem& p : problems)
                EXPECT_NE(p.message.find(f.nameOf(f.type == FieldType::RealList ? 0 : -1)), std::string::npos)
                    << "a problem of " << p.field << " does not name it: " << p.message;
        }
    }
}

TEST(FieldTables, EveryValidatorEnforcesItsTablesRanges) {
    expectValidatorFollowsTable(slopeRingFields(), validateSlopeRingParams);
    expectValidatorFollowsTable(massSpringFields(), validateMassSpringParams);
    expectValidatorFollowsTable(ffdFields(), validateFfdParams);
    expectValidatorFollowsTable(octreeFields(), validateOctreeDef);
    expectValidatorFollowsTable(tissueFields(), validateTissueProperties);
    // The profile's coefficients have no range of their own (their sums are checked instead).
    const FieldDef<RadiusOfInfluenceParams>* radius = findField(radiusOfInfluenceFields(), "radiusMm");
    ASSERT_NE(radius, nullptr);
    RadiusOfInfluenceParams roi;
    radius->set(roi, -1, 0.0);
    EXPECT_TRUE(hasProblem(validateRadiusOfInfluenceParams(roi), "radiusMm"));
}

TEST(FieldTables, CrossFieldRulesNameTheirFields) {
    TissueProperties tissue;
    tissue.dynamicFriction = tissue.staticFriction + 0.1;  // slides harder than it sticks
    EXPECT_TRUE(hasProblem(validateTissueProperties(tissue), "dynamicFriction"));
    tissue.dynamicFriction = tissue.staticFriction;
    EXPECT_TRUE(validateTissueProperties(tissue).empty());

    SlopeRingParams p;
    p.slopeMagnitudeMmPerN[1] = p.slopeMagnitudeMmPerN[0];  // not decreasing
    const Problems problems = validateSlopeRingParams(p);
    ASSERT_TRUE(hasProblem(problems, "slopeMagnitudeMmPerN", 1)) << joinedMessages(problems);
    EXPECT_TRUE(hasProblem(problems, "slopeMagnitudeMmPerN", 0)) << "both slopes of the pair are named";
    EXPECT_FALSE(hasProblem(problems, "slopeMagnitudeMmPerN", 2));

    MassSpringParams m;
    m.maxSubsteps = 4;
    m.substeps = 5;
    EXPECT_TRUE(hasProblem(validateMassSpringParams(m), "substeps"));
    FfdParams f;
    f.movedPerAxis = f.controlPointsPerAxis + 1;
    EXPECT_TRUE(hasProblem(validateFfdParams(f), "movedPerAxis"));
}

/// A valid value of `f` other than its default.
template <class S>
double otherValidValue(const FieldDef<S>& f) {
    const double d = f.defaultValue(0);
    if (f.type == FieldType::Choice) return d == f.spec.hi ? f.spec.lo : d + 1;
    if (f.type == FieldType::Whole) return d + 1 <= f.spec.hi ? d + 1 : d - 1;
    const double up = d * 0.75 + (std::isfinite(f.spec.hi) ? 0.25 * f.spec.hi : 0.5 * std::abs(d) + 0.125);
    return inRange(f, up) ? up : 0.5 * (d + f.spec.lo);
}

TEST(FieldTables, EveryFieldRoundTripsThroughAPresetFile) {
    // One preset per model section, each field changed in turn to another valid value.
    auto roundTrip = [](const TissuePreset& preset, const std::string& what) {
        const PresetLoadResult back = parseTissuePreset(tissuePresetToJson(preset), "p.json");
        ASSERT_TRUE(back.preset) << what << ": " << back.error();
        EXPECT_TRUE(samePreset(*back.preset, preset)) << what << " did not survive the file:\n"
                                                      << tissuePresetToJson(preset);
    };
    for (const FieldDef<MassSpringParams>& f : massSpringFields()) {
        TissuePreset preset = *parseTissuePreset(tissuePresetToJson(TissuePreset{}), "p.json").preset;
        setPresetModel(preset, *modelDefForName("mass-spring-local"));
        f.set(preset.model.massSpring, -1, otherValidValue(f));
        ASSERT_TRUE(validateMassSpringParams(preset.model.massSpring).empty()) << f.spec.key;
        roundTrip(preset, f.spec.key);
    }
    for (const FieldDef<FfdParams>& f : ffdFields()) {
        TissuePreset preset;
        setPresetModel(preset, *modelDefForName("ffd"));
        f.set(preset.model.ffd, -1, f.spec.key == std::string("controlPointsPerAxis") ? 9 : otherValidValue(f));
        ASSERT_TRUE(validateFfdParams(preset.model.ffd).empty())
            << f.spec.key << joinedMessages(validateFfdParams(preset.model.ffd));
        roundTrip(preset, f.spec.key);
    }
    for (const FieldDef<OctreeDef>& f : octreeFields()) {
        TissuePreset preset;
        f.set(preset.octree, -1, otherValidValue(f));
        roundTrip(preset, f.spec.key);
    }
    for (const FieldDef<TissueProperties>& f : tissueFields()) {
        TissuePreset preset;
        preset.tissue = TissueProperties{};
        preset.tissue->source = "a test";
        f.set(*preset.tissue, -1, otherValidValue(f));
        // The sliding friction may not exceed the static one: lower it instead.
        if (!validateTissueProperties(*preset.tissue).empty()) f.set(*preset.tissue, -1, 0.5 * f.defaultValue(0));
        ASSERT_TRUE(validateTissueProperties(*preset.tissue).empty()) << f.spec.key;
        roundTrip(preset, f.spec.key);
    }
    TissuePreset slopes;
    slopes.model.slopeRing.springStiffnessNPerMm = 2.5;
    slopes.model.slopeRing.dampingRatio = 0.3;
    slopes.model.slopeRing.ringCount = 4;
    roundTrip(slopes, "slope-ring fields");
}

TEST(FieldTables, TheHapticRateRangeIsOneDefinition) {
    HapticLoopDef def;
    def.rateHz = kMaxHapticRateHz;
    EXPECT_TRUE(validateHapticLoopDef(def).empty());
    def.rateHz = kMaxHapticRateHz * 1.01;
    EXPECT_FALSE(validateHapticLoopDef(def).empty());
    def.rateHz = kMinHapticRateHz * 0.99;
    EXPECT_FALSE(validateHapticLoopDef(def).empty());
    TissuePreset preset;
    preset.hapticRateHz = kMaxHapticRateHz * 1.01;
    EXPECT_FALSE(parseTissuePreset(tissuePresetToJson(preset), "p.json").preset);
    preset.hapticRateHz = kMaxHapticRateHz;
    EXPECT_TRUE(parseTissuePreset(tissuePresetToJson(preset), "p.json").preset);
}

TEST(FieldTables, ANumberTooLargeForADoubleIsAnErrorNamingTheFile) {
    std::string text = tissuePresetToJson(TissuePreset{});
    const std::string key = "\"damping_ratio\": 1.0";
    ASSERT_NE(text.find(key), std::string::npos);
    text.replace(text.find(key), key.size(), "\"damping_ratio\": 1e400");
    const PresetLoadResult preset = parseTissuePreset(text, "big.json");
    EXPECT_FALSE(preset.preset);
    EXPECT_NE(preset.error().find("big.json"), std::string::npos) << preset.error();
    EXPECT_NE(preset.error().find("too large"), std::string::npos) << preset.error();

    const ExerciseLoadResult exercise = parseExercise(R"({"format": "palpate-exercise", "version": 1e400})", "e.json");
    ASSERT_FALSE(exercise.errors.empty());
    EXPECT_NE(exercise.errors.front().find("e.json"), std::string::npos) << exercise.errors.front();
}

}  // namespace
}  // namespace palpate
