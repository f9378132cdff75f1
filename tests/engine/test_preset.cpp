// Tissue presets: round trip, and every malformed file gives an error naming the key.
#include "engine/scene/TissuePreset.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

using namespace palpate;

namespace {

std::string validText() {
    TissuePreset p;
    p.name = "test";
    p.description = "a preset";
    p.model.slopeRing.ringCount = 3;
    p.model.slopeRing.slopeMagnitudeMmPerN = {0.7, 0.4, 0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.001};
    p.model.slopeRing.springStiffnessNPerMm = 2.0;
    p.octree.maxDepth = 8;
    p.octree.leafCapacity = 32;
    p.hapticRateHz = 2000;
    p.model.slopeRingMethod = SlopeRingMethod::Proposed;
    p.tissue = TissueProperties{.youngsModulusKPa = 5.0, .poissonRatio = 0.45, .toolRadiusMm = 4.0, .staticFriction = 0.4, .dynamicFriction = 0.25, .source = "a textbook"};
    return tissuePresetToJson(p);
}

/// Replaces the first occurrence of `from` in the valid text.
std::string edited(const std::string& from, const std::string& to) {
    std::string text = validText();
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    return text;
}

void expectErrorNaming(const std::string& text, const std::string& key, const std::string& problem = "") {
    const auto r = parseTissuePreset(text, "my.json");
    ASSERT_FALSE(r.preset) << "accepted: " << text;
    ASSERT_FALSE(r.errors.empty());
    bool found = false;
    for (const auto& e : r.errors)
        if (e.find("my.json") == 0 && e.find(key) != std::string::npos && e.find(problem) != std::string::npos) found = true;
    EXPECT_TRUE(found) << "no error naming '" << key << "' / '" << problem << "' in: " << r.error();
}

}  // namespace

TEST(TissuePreset, RoundTripKeepsEveryField) {
    const auto r = parseTissuePreset(validText(), "my.json");
    ASSERT_TRUE(r.preset) << r.error();
    const TissuePreset& p = *r.preset;
    EXPECT_EQ(p.name, "test");
    EXPECT_EQ(p.description, "a preset");
    EXPECT_EQ(p.model.slopeRing.ringCount, 3);
    EXPECT_EQ(p.model.slopeRing.slopeMagnitudeMmPerN[2], 0.2);
    EXPECT_EQ(p.model.slopeRing.springStiffnessNPerMm, 2.0);
    EXPECT_EQ(p.octree.maxDepth, 8);
    EXPECT_EQ(p.octree.leafCapacity, 32);
    EXPECT_EQ(p.hapticRateHz, 2000);
    EXPECT_EQ(p.model.slopeRingMethod, SlopeRingMethod::Proposed);
    ASSERT_TRUE(p.tissue);
    EXPECT_EQ(p.tissue->source, "a textbook");
    EXPECT_EQ(tissuePresetToJson(p), validText());
}

TEST(TissuePreset, SaveIsAtomicAndLoadsBack) {
    const auto path = (std::filesystem::temp_directory_path() / "palpate_preset_test.json").string();
    TissuePreset p;
    p.name = "saved";
    ASSERT_EQ(saveTissuePreset(p, path), "");
    EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
    const auto r = loadTissuePreset(path);
    ASSERT_TRUE(r.preset) << r.error();
    EXPECT_EQ(r.preset->name, "saved");
    std::filesystem::remove(path);
    EXPECT_NE(saveTissuePreset(p, "/nonexistent-dir/x.json"), "");
}

TEST(TissuePreset, EveryBadKeyIsNamed) {
    expectErrorNaming(edited("\"name\"", "\"nmae\""), "nmae", "unknown key");
    expectErrorNaming(edited("\"damping_ratio\"", "\"damping\""), "slope_ring.damping", "unknown key");
    expectErrorNaming(edited("\"haptic_rate_hz\": 2000.0", "\"haptic_rate_hz\": \"fast\""), "haptic_rate_hz", "number");
    expectErrorNaming(edited("\"haptic_rate_hz\": 2000.0", "\"haptic_rate_hz\": 50000"), "haptic_rate_hz", "out of range");
    expectErrorNaming(edited("\"ring_count\": 3", "\"ring_count\": 2"), "slope_ring.slopes_mm_per_n", "needs 3");
    expectErrorNaming(edited("\"ring_count\": 3", "\"ring_count\": 2.5"), "slope_ring.ring_count", "whole");
    expectErrorNaming(edited("0.4,", "0.9,"), "slope_ring", "decrease");
    expectErrorNaming(edited("0.7,", "1.7,"), "slope_ring", "slope limit");
    expectErrorNaming(edited("0.7,", "\"x\","), "slope_ring.slopes_mm_per_n[0]", "number");
    expectErrorNaming(edited("\"max_depth\": 8", "\"max_depth\": 40"), "octree.max_depth", "out of range");
    expectErrorNaming(edited("\"poisson_ratio\": 0.45", "\"poisson_ratio\": 0.6"), "tissue.poisson_ratio", "out of range");
    expectErrorNaming(edited("\"tool_radius_mm\": 4.0", "\"tool_radius_mm\": 0"), "tissue.tool_radius_mm", "out of range");
    expectErrorNaming(edited("\"model\": \"proposed\"", "\"model\": \"fem\""), "model", "unknown model");
    expectErrorNaming(edited("\"palpate-tissue-preset\"", "\"something-else\""), "format");
    expectErrorNaming(edited("\"version\": 1", "\"version\": 7"), "version", "not supported");
    expectErrorNaming(edited("\"version\": 1,", ""), "version", "missing");
    expectErrorNaming(edited("\"slope_ring\": {", "\"slope_ring\": [{") , "");
    expectErrorNaming("[1, 2, 3]", "must be an object");
    expectErrorNaming("{\"format\": ", "not valid JSON");
    expectErrorNaming("", "not valid JSON");
}

// A preset path that names a file that is not JSON (a file of secrets) is refused without
// repeating the file's text: the error says where, not what it read.
TEST(TissuePreset, AFileThatIsNotJsonIsNotQuoted) {
    const auto path = std::filesystem::temp_directory_path() / "palpate-not-json-preset.txt";
    {
        std::ofstream out(path);
        out << "\"dbpassword hunter2secret\nsecond line\n";  // a quote first: the parser reads the line
    }
    const std::string error = loadTissuePreset(path.string()).error();
    std::filesystem::remove(path);
    EXPECT_NE(error.find("not valid JSON"), std::string::npos) << error;
    EXPECT_NE(error.find("at line"), std::string::npos) << error;
    EXPECT_EQ(error.find("hunter2"), std::string::npos) << error;
    EXPECT_EQ(error.find("dbpass"), std::string::npos) << error;
}

TEST(TissuePreset, FilesystemProblemsAreNamed) {
    EXPECT_NE(loadTissuePreset("/no/such/preset.json").error().find("no such file"), std::string::npos);
    EXPECT_NE(loadTissuePreset(std::filesystem::temp_directory_path().string()).error().find("directory"),
              std::string::npos);
}

TEST(TissuePreset, ShippedPresetsLoad) {
    std::size_t count = 0;
    std::size_t tissues = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(PALPATE_SOURCE_DIR "/resources/presets")) {
        if (!entry.is_regular_file() || entry.path().extension() != ".json") continue;
        const auto r = loadTissuePreset(entry.path().string());
        EXPECT_TRUE(r.preset) << r.error();
        ++count;
        // Tissue presets say where their elastic constants come from.
        if (entry.path().parent_path().filename() == "tissues") {
            ++tissues;
            ASSERT_TRUE(r.preset && r.preset->tissue) << entry.path();
            EXPECT_GT(r.preset->tissue->source.size(), 40u) << entry.path();
        }
    }
    EXPECT_GE(count, 7u);
    EXPECT_EQ(tissues, 6u);  // liver, fat, muscle, skin, stomach wall, phantom gel
}

TEST(TissuePresetFuzz, MutationsNeverCrash) {
    const std::string valid = validText();
    std::mt19937 rng(99);
    int accepted = 0;
    for (int i = 0; i < 2000; ++i) {
        std::string text = valid;
        const int edits = 1 + int(rng() % 4);
        for (int k = 0; k < edits; ++k) {
            const std::size_t at = rng() % (text.size() + 1);
            switch (rng() % 4) {
                case 0: if (at < text.size()) text[at] = char(rng() % 256); break;
                case 1: text.insert(at, 1, "{}[]\",:0-e.9a "[rng() % 14]); break;
                case 2: if (at < text.size()) text.erase(at, 1 + rng() % 8); break;
                case 3: text.resize(at); break;
            }
        }
        const auto r = parseTissuePreset(text, "fuzz.json");
        EXPECT_TRUE(r.preset.has_value() == r.errors.empty());
        if (r.preset) ++accepted;
    }
    EXPECT_LT(accepted, 2000);
}

// "needs" (docs/lod.md): optional; round-trips; absurd values name the key.
TEST(TissuePreset, NeedsAreOptionalRoundTripAndNamedWhenBad) {
    const auto without = parseTissuePreset(validText(), "my.json");
    ASSERT_TRUE(without.preset) << without.error();
    EXPECT_FALSE(without.preset->needs);
    EXPECT_EQ(validText().find("needs"), std::string::npos);  // a preset without needs is written without

    TissuePreset p = *without.preset;
    p.needs = LodNeeds{0.12, 250.0};
    const std::string text = tissuePresetToJson(p);
    const auto back = parseTissuePreset(text, "my.json");
    ASSERT_TRUE(back.preset) << back.error();
    ASSERT_TRUE(back.preset->needs);
    EXPECT_EQ(back.preset->needs->maxErrorFraction, 0.12);
    EXPECT_EQ(back.preset->needs->budgetUs, 250.0);
    EXPECT_EQ(tissuePresetToJson(*back.preset), text);

    auto withNeeds = [&](const std::string& needs) {
        std::string t = text;
        const auto at = t.find("\"needs\"");
        const auto end = t.find('}', at);
        t.replace(at, end - at + 1, "\"needs\": " + needs);
        return t;
    };
    expectErrorNaming(withNeeds(R"({"max_error": -0.1, "budget_us": 100})"), "needs.max_error", "above 0");
    expectErrorNaming(withNeeds(R"({"max_error": 0.1, "budget_us": 0})"), "needs.budget_us", "above 0");
    expectErrorNaming(withNeeds(R"({"max_error": 0.1, "budget_us": 1e12})"), "needs.budget_us", "absurd");
    expectErrorNaming(withNeeds(R"({"max_error": 0.1})"), "needs.budget_us", "missing");
    expectErrorNaming(withNeeds(R"({"max_error": "small", "budget_us": 100})"), "needs.max_error", "number");
    expectErrorNaming(withNeeds(R"({"max_error": 0.1, "budget_us": 100, "rings": 2})"), "needs.rings", "unknown key");
    expectErrorNaming(withNeeds("[0.1, 100]"), "needs", "must be an object");

    // An absurd target is not saved.
    p.needs = LodNeeds{0.1, -5.0};
    const auto path = (std::filesystem::temp_directory_path() / "palpate_preset_needs_test.json").string();
    const std::string problem = saveTissuePreset(p, path);
    EXPECT_NE(problem.find("needs.budget_us"), std::string::npos) << problem;
    EXPECT_FALSE(std::filesystem::exists(path));
}

// "stability_margin" (docs/stability.md section 7): written on save by the parameter panel
// with the period it was computed for; informational on load (type and range checked, by key);
// presets without it stay valid.
TEST(TissuePreset, StabilityMarginIsOptionalRoundTripsAndIsNamedWhenBad) {
    const auto without = parseTissuePreset(validText(), "my.json");
    ASSERT_TRUE(without.preset) << without.error();
    EXPECT_FALSE(without.preset->stabilityMargin);
    EXPECT_EQ(validText().find("stability_margin"), std::string::npos);

    TissuePreset p = *without.preset;
    p.stabilityMargin = PresetStabilityMargin{0.42, 5e-4};
    const std::string text = tissuePresetToJson(p);
    const auto back = parseTissuePreset(text, "my.json");
    ASSERT_TRUE(back.preset) << back.error();
    ASSERT_TRUE(back.preset->stabilityMargin);
    EXPECT_EQ(back.preset->stabilityMargin->margin, 0.42);
    EXPECT_EQ(back.preset->stabilityMargin->dtS, 5e-4);
    EXPECT_EQ(tissuePresetToJson(*back.preset), text);
    // A set beyond its bound has a negative margin: stored as it is (informational).
    p.stabilityMargin = PresetStabilityMargin{-0.3, 1e-3};
    const auto beyond = parseTissuePreset(tissuePresetToJson(p), "my.json");
    ASSERT_TRUE(beyond.preset) << beyond.error();
    EXPECT_EQ(beyond.preset->stabilityMargin->margin, -0.3);

    auto withMargin = [&](const std::string& margin) {
        std::string t = text;
        const auto at = t.find("\"stability_margin\"");
        const auto end = t.find('}', at);
        t.replace(at, end - at + 1, "\"stability_margin\": " + margin);
        return t;
    };
    expectErrorNaming(withMargin(R"({"margin": 1.5, "dt_s": 0.001})"), "stability_margin.margin", "out of range");
    expectErrorNaming(withMargin(R"({"margin": "ok", "dt_s": 0.001})"), "stability_margin.margin", "number");
    expectErrorNaming(withMargin(R"({"margin": 0.5, "dt_s": 0})"), "stability_margin.dt_s", "out of range");
    expectErrorNaming(withMargin(R"({"margin": 0.5})"), "stability_margin.dt_s", "missing");
    expectErrorNaming(withMargin(R"({"margin": 0.5, "dt_s": 0.001, "model": 1})"), "stability_margin.model", "unknown key");
    expectErrorNaming(withMargin("0.5"), "stability_margin", "must be an object");
}
