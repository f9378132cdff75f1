// Tissue that stiffens with depth in the slope-ring model (docs/method.md, "Tissue that stiffens
// with depth"): the effective force E(F) of the knots, the exact contact solve on it (plain tissue
// and over a lump), the relaxed update settling on the same force, validation naming the field,
// and a tick that still allocates nothing.
#include "engine/exercise/ExerciseGeometry.h"
#include "engine/models/slopering/CoherentSlopeRing.h"
#include "engine/scene/HapticScene.h"
#include "engine/scene/TissuePreset.h"
#include "tests/scoring/ScoringTestRig.h"
#include "tests/support/AllocationCounter.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <functional>

#include <cmath>

namespace palpate {
namespace {

const TissueMesh& sphere() {
    static const TissueMesh mesh = *TissueMesh::load(test::resourcesDir() + "/meshes/sphere_8664.off").mesh;
    return mesh;
}

/// Muscle (|m1| = 6.49 mm/N, k_c = 1 N/mm) stiffening twice: half as compliant above 0.4 N, a
/// quarter above 1 N.
TissuePreset stiffeningMuscle(int knots = 2) {
    const auto loaded = loadTissuePreset(test::resourcesDir() + "/presets/tissues/muscle.json");
    if (!loaded.preset) throw std::runtime_error(loaded.error());
    TissuePreset p = *loaded.preset;
    p.model.slopeRing.stiffeningKnots = knots;
    p.model.slopeRing.stiffeningForceN[0] = 0.4;
    p.model.slopeRing.stiffeningCompliance[0] = 0.5;
    p.model.slopeRing.stiffeningForceN[1] = 1.0;
    p.model.slopeRing.stiffeningCompliance[1] = 0.25;
    return p;
}

/// E(F) by hand for the knots above.
double effectiveByHand(double f) {
    if (f <= 0.4) return f;
    if (f <= 1.0) return 0.4 + 0.5 * (f - 0.4);
    return 0.4 + 0.5 * 0.6 + 0.25 * (f - 1.0);
}

struct Pressed {
    double renderedN = 0.0, contactN = 0.0, sinkMm = 0.0;
};

Pressed press(const TissuePreset& p, double depthMm, int ticks = 5, const Exercise* exercise = nullptr) {
    auto scene = HapticScene::create(sphere(), slopeRingModelDef(p.model.slopeRing), p.octree);
    auto* model = dynamic_cast<CoherentSlopeRing*>(&scene->model());
    EXPECT_NE(model, nullptr);
    if (exercise) {
        std::string error;
        const auto geometry = ExerciseGeometry::build(*exercise, sphere(), error);
        EXPECT_EQ(error, "");
        EXPECT_EQ(applyExercisePhysics(*geometry, *scene), "");
    }
    SurfacePoint at;
    at.pointMm = glm::vec3(50.0f, 0.0f, 0.0f);
    const VertexId v = ExerciseGeometry::snap(at, sphere());
    const glm::vec3 rest = sphere().restPositionsMm()[v], n = sphere().restNormals()[v];
    TickResult r;
    for (int tick = 0; tick < ticks; ++tick) r = model->step(rest - float(depthMm) * n, 0.001);
    return {glm::length(glm::dvec3(r.forceN)), model->contactForceN(), glm::length(model->positionsMm()[v] - rest)};
}

}  // namespace

TEST(Stiffening, TheEffectiveForceFollowsTheKnotsAndInvertsExactly) {
    const SlopeRingConstants c = slopeRingConstants(stiffeningMuscle().model.slopeRing);
    ASSERT_EQ(c.stiffeningKnots, 2);
    for (double f : {0.0, 0.2, 0.4, 0.7, 1.0, 2.5, 10.0}) {
        EXPECT_NEAR(stiffenedForceN(c, float(f)), effectiveByHand(f), 1e-6) << f;
        EXPECT_NEAR(unstiffenedForceN(c, stiffenedForceN(c, float(f))), f, 1e-5) << f;
    }
    // No knots: E(F) = F.
    const SlopeRingConstants linear = slopeRingConstants(stiffeningMuscle(0).model.slopeRing);
    EXPECT_EQ(stiffenedForceN(linear, 1.2345f), 1.2345f);
}

TEST(Stiffening, TheContactForceSolvesTheStiffenedSinkExactly) {
    const TissuePreset p = stiffeningMuscle();
    const double m1 = p.model.slopeRing.slopeMagnitudeMmPerN[0], kc = p.model.slopeRing.contactStiffnessNPerMm;
    const double ks = p.model.slopeRing.springStiffnessNPerMm;
    const TissuePreset linear = stiffeningMuscle(0);
    for (double d : {1.0, 4.0, 8.0, 14.0, 25.0}) {
        const Pressed r = press(p, d);
        // d = sink + F / k_c with sink = |m1| E(F).
        EXPECT_NEAR(m1 * effectiveByHand(r.contactN) + r.contactN / kc, d, 1e-3 * d) << d;
        EXPECT_NEAR(r.sinkMm, m1 * effectiveByHand(r.contactN), 2e-3 * d) << d;
        EXPECT_NEAR(r.renderedN, ks * m1 * r.contactN, 1e-4 * r.renderedN) << d;
        const Pressed lin = press(linear, d);
        if (lin.contactN <= 0.4) {
            EXPECT_NEAR(r.contactN, lin.contactN, 1e-5) << "below the first knot the tissue is linear, " << d;
        } else {
            EXPECT_GT(r.renderedN, 1.1 * lin.renderedN) << "stiffer beyond the first knot, " << d;
            EXPECT_LT(r.sinkMm, lin.sinkMm) << d;
        }
    }
    // The margins read the stiffest piece: k_s |m1| k_c / (1 + g q_K), above the linear value.
    EXPECT_NEAR(p.model.slopeRing.renderedStiffnessNPerMm(), ks * m1 * kc / (1.0 + m1 * kc * 0.25), 1e-12);
    EXPECT_GT(p.model.slopeRing.renderedStiffnessNPerMm(), 2.0 * linear.model.slopeRing.renderedStiffnessNPerMm());
    const double deepSlope = (press(p, 25.0).renderedN - press(p, 24.0).renderedN) / 1.0;
    EXPECT_NEAR(deepSlope, p.model.slopeRing.renderedStiffnessNPerMm(), 1e-3);
    // Twice as deep, more than twice the force once it stiffens.
    EXPECT_GT(press(p, 25.0).renderedN, 2.2 * press(p, 12.5).renderedN);
}

TEST(Stiffening, TheRelaxedUpdateSettlesOnTheSameForce) {
    TissuePreset p = stiffeningMuscle();
    const double exact = press(p, 14.0).contactN;
    p.model.slopeRing.forceRelaxation = 0.05;
    EXPECT_NEAR(press(p, 14.0, 3000).contactN, exact, 1e-3 * exact);
}

TEST(Stiffening, OverALumpTheSinkIsTheLumpsOnTheStiffenedForce) {
    Exercise e = test::loadExampleExercise("detect_lumps");
    LumpDef lump;
    lump.at.pointMm = glm::vec3(50.0f, 0.0f, 0.0f);
    lump.depthMm = 3.0;
    lump.contrast = 4.0;
    lump.radiusMm = 6.0;
    e.detectLumps.lumps = {lump};
    const TissuePreset p = stiffeningMuscle();
    const double m1 = p.model.slopeRing.slopeMagnitudeMmPerN[0], kc = p.model.slopeRing.contactStiffnessNPerMm, c = 0.25, z = 3.0;
    for (double d : {2.0, 6.0, 12.0, 20.0}) {
        const Pressed r = press(p, d, 5, &e);
        const double soft = m1 * effectiveByHand(r.contactN);
        const double sink = std::min(soft, c * soft + (1.0 - c) * z);
        EXPECT_NEAR(sink + r.contactN / kc, d, 1e-3 * d) << d;
    }
}

TEST(Stiffening, BadKnotsAreNamedAndTheTickAllocatesNothing) {
    SlopeRingParams p = stiffeningMuscle().model.slopeRing;
    EXPECT_TRUE(validateSlopeRingParams(p).empty());
    p.stiffeningForceN[1] = 0.3;  // below knot 1
    auto problems = validateSlopeRingParams(p);
    ASSERT_FALSE(problems.empty());
    EXPECT_EQ(problems[0].field, "stiffeningForceN");
    p = stiffeningMuscle().model.slopeRing;
    p.stiffeningCompliance[1] = 0.9;  // softer again
    problems = validateSlopeRingParams(p);
    ASSERT_FALSE(problems.empty());
    EXPECT_EQ(problems[0].field, "stiffeningCompliance");
    p.stiffeningCompliance[1] = 1.5;  // out of (0, 1]
    EXPECT_FALSE(validateSlopeRingParams(p).empty());
    // Forces no tissue reaches, and that overflow the tick's floats (the tool then never touched).
    for (const double hugeN : {3.4e38, 1e39, 1e308, kMaxStiffeningForceN * 1.01}) {
        p = stiffeningMuscle().model.slopeRing;
        p.stiffeningForceN[std::size_t(p.stiffeningKnots - 1)] = hugeN;
        problems = validateSlopeRingParams(p);
        ASSERT_FALSE(problems.empty()) << hugeN;
        EXPECT_EQ(problems[0].field, "stiffeningForceN") << hugeN;
    }
    // And a preset file with one is refused, naming the key.
    {
        TissuePreset preset = stiffeningMuscle();
        nlohmann::json j = nlohmann::json::parse(tissuePresetToJson(preset));
        bool set = false;
        std::function<void(nlohmann::json&)> setLastKnot = [&](nlohmann::json& o) {
            if (!o.is_object()) return;
            for (auto& [key, value] : o.items()) {
                if (key == "stiffening_force_n" && value.is_array() && !value.empty()) {
                    value.back() = 1e39;
                    set = true;
                }
                setLastKnot(value);
            }
        };
        setLastKnot(j);
        ASSERT_TRUE(set) << j.dump();
        const std::string json = j.dump();
        const auto loaded = parseTissuePreset(json, "huge.json");
        ASSERT_FALSE(loaded.preset.has_value());
        EXPECT_NE(loaded.error().find("stiffening_force_n"), std::string::npos) << loaded.error();
    }

    const TissuePreset preset = stiffeningMuscle();
    auto scene = HapticScene::create(sphere(), slopeRingModelDef(preset.model.slopeRing), preset.octree);
    auto& model = scene->model();
    const glm::vec3 rest(50.0f, 0.0f, 0.0f);
    for (int tick = 0; tick < 50; ++tick) model.step(rest - glm::vec3(0.1f * float(tick), 0.0f, 0.0f), 0.001);
    test::AllocationCounter counter;
    for (int tick = 50; tick < 400; ++tick)
        model.step(rest - glm::vec3(5.0f + 5.0f * std::sin(0.02f * float(tick)), 0.01f * float(tick), 0.0f), 0.001);
    EXPECT_EQ(counter.count(), 0u);
}
}  // namespace palpate
