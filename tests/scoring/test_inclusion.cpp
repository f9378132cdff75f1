// Find the lump's physics: CoherentSlopeRing's per-vertex compliance factors. Absent, or all 1,
// the model is bit for bit what it was; inside an inclusion the same depth renders more force
// (the closed form of the exact one-tick solve); the tick still allocates nothing.
#include "engine/scene/HapticScene.h"
#include "engine/models/slopering/CoherentSlopeRing.h"
#include "engine/scene/TissuePreset.h"
#include "engine/exercise/ExerciseGeometry.h"
#include "tests/scoring/ScoringTestRig.h"
#include "tests/support/AllocationCounter.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace palpate {
namespace {

struct Model {
    std::unique_ptr<HapticScene> scene;
    CoherentSlopeRing* deformer = nullptr;  // null for the paper's methods: they take no compliance
};

const TissueMesh& sphere() {
    static const TissueMesh mesh = *TissueMesh::load(test::resourcesDir() + "/meshes/sphere_1442.off").mesh;
    return mesh;
}

TissuePreset preset(const std::string& name) {
    const auto p = loadTissuePreset(test::resourcesDir() + "/presets/" + name + ".json");
    if (!p.preset) throw std::runtime_error(p.error());
    return *p.preset;
}

Model model(const TissuePreset& p, SlopeRingMethod method = SlopeRingMethod::Coherent) {
    Model m;
    m.scene = HapticScene::create(sphere(), slopeRingModelDef(p.model.slopeRing, method), p.octree);
    m.deformer = dynamic_cast<CoherentSlopeRing*>(&m.scene->model());
    return m;
}

VertexId fileVertex(std::uint32_t v) {
    SurfacePoint p;
    p.vertex = v;
    return ExerciseGeometry::snap(p, sphere());
}

/// A press and a slide around vertex `v`: the tool path of the equality test.
glm::vec3 toolAt(int tick, VertexId v) {
    const glm::vec3 rest = sphere().restPositionsMm()[v], n = sphere().restNormals()[v];
    const glm::vec3 side = glm::normalize(glm::cross(n, glm::vec3(0, 0, 1)));
    const float t = float(tick) / 1000.0f;
    const float depth = t < 1.0f ? 10.0f * t - 2.0f : 8.0f + std::sin(3.0f * t);
    return rest - depth * n + (t < 1.0f ? 0.0f : 12.0f * (t - 1.0f)) * side;
}

TEST(Inclusion, AllOnesIsBitForBitTheModelWithout) {
    for (const char* name : {"default", "tissues/liver"}) {
        Model plain = model(preset(name)), ones = model(preset(name));
        ones.deformer->setCompliance(std::vector<float>(sphere().vertexCount(), 1.0f));
        const VertexId v = fileVertex(1365);
        for (int tick = 0; tick < 3000; ++tick) {
            const TickResult a = plain.deformer->step(toolAt(tick, v), 0.001);
            const TickResult b = ones.deformer->step(toolAt(tick, v), 0.001);
            ASSERT_EQ(std::memcmp(&a.forceN, &b.forceN, sizeof(glm::vec3)), 0) << name << " tick " << tick;
            ASSERT_EQ(a.touched, b.touched);
            ASSERT_EQ(a.contact, b.contact);
        }
        const auto pa = plain.deformer->positionsMm(), pb = ones.deformer->positionsMm();
        EXPECT_EQ(std::memcmp(pa.data(), pb.data(), pa.size_bytes()), 0) << name;
    }
}

TEST(Inclusion, StifferInsideByTheClosedForm) {
    const TissuePreset liver = preset("tissues/liver");
    const SlopeRingParams& p = liver.model.slopeRing;
    const double m1 = p.slopeMagnitudeMmPerN[0], kc = p.contactStiffnessNPerMm, ks = p.springStiffnessNPerMm;
    const VertexId v = fileVertex(1365);
    const glm::vec3 rest = sphere().restPositionsMm()[v], n = sphere().restNormals()[v];
    const double depthMm = 8.0;
    for (const float c : {1.0f, 0.5f, 0.25f}) {
        Model m = model(liver);
        std::vector<float> factors(sphere().vertexCount(), 1.0f);
        factors[v] = c;
        m.deformer->setCompliance(factors);
        TickResult r;
        for (int tick = 0; tick < 5; ++tick) r = m.deformer->step(rest - float(depthMm) * n, 0.001);
        ASSERT_EQ(r.touched, v);
        ASSERT_TRUE(r.contact);
        // The exact solve: F = k_c d / (1 + k_c c |m1|); rendered k_s |m1| F along the normal (the
        // touched spring is stiffer by 1 / c); the touched vertex moves c |m1| F.
        const double f = kc * depthMm / (1.0 + kc * double(c) * m1);
        EXPECT_NEAR(m.deformer->contactForceN(), f, 1e-4 * f) << "c " << c;
        EXPECT_NEAR(glm::length(r.forceN), ks * m1 * f, 1e-4 * ks * m1 * f) << "c " << c;
        const double moved = glm::length(m.deformer->positionsMm()[v] - rest);
        EXPECT_NEAR(moved, double(c) * m1 * f, 1e-3) << "c " << c;
    }
    // Liver at 8 mm: 0.53 N outside, 1.77 N in a 0.25 inclusion: palpable.
    EXPECT_GT(kc * depthMm / (1.0 + kc * 0.25 * m1) / (kc * depthMm / (1.0 + kc * m1)), 3.0);
}

TEST(Inclusion, FactorsAreValidated) {
    Model m = model(preset("default"));
    const std::size_t n = sphere().vertexCount();
    EXPECT_THROW(m.deformer->setCompliance(std::vector<float>(n - 1, 1.0f)), std::invalid_argument);
    for (const float bad : {0.0f, -0.5f, 1.5f, std::nanf("")}) {
        std::vector<float> f(n, 1.0f);
        f[7] = bad;
        EXPECT_THROW(m.deformer->setCompliance(f), std::invalid_argument) << bad;
    }
    EXPECT_TRUE(m.deformer->compliance().empty());
    m.deformer->setCompliance(std::vector<float>(n, 0.5f));
    EXPECT_EQ(m.deformer->compliance().size(), n);
    m.deformer->setCompliance({});
    EXPECT_TRUE(m.deformer->compliance().empty());
    for (SlopeRingMethod method : {SlopeRingMethod::Previous, SlopeRingMethod::Hybrid, SlopeRingMethod::Proposed}) {
        Model paper = model(preset("default"), method);
        EXPECT_EQ(paper.deformer, nullptr) << "the paper's methods stay as published: no compliance factors";
    }
}

TEST(Inclusion, TickAllocatesNothing) {
    Model m = model(preset("tissues/liver"));
    std::vector<float> factors(sphere().vertexCount(), 1.0f);
    const VertexId v = fileVertex(1365);
    for (VertexId w = 0; w < factors.size(); ++w)
        if (glm::length(sphere().restPositionsMm()[w] - sphere().restPositionsMm()[v]) < 10.0f) factors[w] = 0.25f;
    m.deformer->setCompliance(factors);
    for (int tick = 0; tick < 200; ++tick) m.deformer->step(toolAt(tick, v), 0.001);  // warm up
    test::AllocationCounter counter;
    for (int tick = 200; tick < 3000; ++tick) m.deformer->step(toolAt(tick, v), 0.001);
    EXPECT_EQ(counter.count(), 0u);
}

}  // namespace
}  // namespace palpate
