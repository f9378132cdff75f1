// The divergence guard: each kind of divergence detected on hand-made inputs and on the real
// models beyond their bounds, nothing on a stable press, no allocation per tick, and its reaction
// inside the haptic loop (zero force that tick, tissue at rest, event counted and published).
#include "engine/stability/DivergenceGuard.h"
#include "engine/stability/StabilityBounds.h"

#include "device/SimulatedDevice.h"
#include "engine/loop/HapticLoop.h"
#include "engine/core/MeshGenerator.h"
#include "engine/models/slopering/CoherentSlopeRing.h"
#include "engine/models/MassSpringModel.h"
#include "tests/support/AllocationCounter.h"
#include "tests/support/Meshes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace palpate;

namespace {

/// A hexagonal fan (a vertex and its six neighbours, flat) closed underneath by a seventh vertex:
/// a closed mesh whose vertex 0 has exactly the six fan triangles on top.
TissueMesh hexagonPatch() {
    std::vector<glm::vec3> p{{0, 0, 0}};
    for (int i = 0; i < 6; ++i) p.emplace_back(10.0f * std::cos(i * 1.0471976f), 10.0f * std::sin(i * 1.0471976f), 0.0f);
    p.emplace_back(0.0f, 0.0f, -8.0f);
    std::vector<std::array<VertexId, 3>> t;
    for (VertexId i = 0; i < 6; ++i) {
        const VertexId a = 1 + i, b = 1 + (i + 1) % 6;
        t.push_back({0, a, b});  // top, counter-clockwise seen from +z
        t.push_back({7, b, a});  // bottom cone
    }
    auto loaded = TissueMesh::fromTriangles(p, t, "hexagon", false);
    if (!loaded.mesh) throw std::runtime_error(loaded.error());
    return std::move(*loaded.mesh);
}

/// A model that only holds positions: the guard's model variant (what the loop calls) reads them
/// through copyPositionsMm.
class HeldPositions final : public DeformationModel {
public:
    explicit HeldPositions(std::vector<glm::vec3> p) : mPositions(std::move(p)) {}
    TickResult step(const glm::vec3&, double) override { return {}; }
    std::span<const glm::vec3> positionsMm() const override { return mPositions; }
    void reset() override {}
    std::string name() const override { return "held"; }
    std::size_t copyDisplaced(VertexId*, glm::vec3*, std::uint8_t*, std::size_t) const override { return 0; }
    std::vector<glm::vec3> mPositions;
};

TickResult touching(VertexId v, glm::vec3 force = glm::vec3(0.0f, 0.0f, 1.0f)) {
    TickResult r;
    r.touched = v;
    r.forceN = force;
    r.contact = true;
    return r;
}

}  // namespace

TEST(DivergenceGuard, InversionOnAHandBuiltPatch) {
    const TissueMesh mesh = hexagonPatch();
    std::vector<glm::vec3> positions = mesh.restPositionsMm();
    EXPECT_FALSE(DivergenceGuard::fanInverted(mesh, positions, 0));
    // The centre slides sideways by less than its height over the opposite edges (10 cos 30 = 8.66 mm):
    // nothing flips.
    positions[0] = glm::vec3(8.0f, 0.0f, 0.0f);
    EXPECT_FALSE(DivergenceGuard::fanInverted(mesh, positions, 0));
    // Past the edge (5, +-8.66): the triangle beyond it turns over.
    const glm::vec3 towardsEdge(std::cos(0.5236f), std::sin(0.5236f), 0.0f);  // normal to edge (v1, v2)
    positions[0] = 8.0f * towardsEdge;
    EXPECT_FALSE(DivergenceGuard::fanInverted(mesh, positions, 0));
    positions[0] = 9.5f * towardsEdge;
    EXPECT_TRUE(DivergenceGuard::fanInverted(mesh, positions, 0));
    DivergenceGuard guard;
    EXPECT_EQ(guard.check(mesh, positions, touching(0)).kind, DivergenceKind::Inversion);
    // The loop's variant, which caches the fan's triangles per touched vertex, agrees, before and
    // after the fan is cached, and on the side where nothing flips.
    DivergenceGuard loopGuard;
    HeldPositions held(mesh.restPositionsMm());
    held.mPositions[0] = 8.0f * towardsEdge;
    EXPECT_FALSE(loopGuard.check(mesh, held, touching(0)));
    held.mPositions[0] = 9.5f * towardsEdge;
    EXPECT_EQ(loopGuard.check(mesh, held, touching(0)).kind, DivergenceKind::Inversion);
    loopGuard.reset();
    EXPECT_EQ(loopGuard.check(mesh, held, touching(0)).kind, DivergenceKind::Inversion);
    // The derived bound: |m1 - m2| |F_t| = height over the opposite edge.
    EXPECT_NEAR(minHeightOverOppositeEdgeMm(mesh, 0), 8.660254, 1e-4);
    const double maxForce = inversionMaxTangentialForceN(0.6, 0.35, minHeightOverOppositeEdgeMm(mesh, 0));
    for (double f : {0.97, 1.03}) {
        std::vector<glm::vec3> q = mesh.restPositionsMm();
        const float shift = float((0.6 - 0.35) * f * maxForce);  // relative shift towards edge (v1, v2)
        const glm::vec3 towards = glm::normalize(glm::vec3(std::cos(0.5236f), std::sin(0.5236f), 0.0f));
        q[0] += shift * towards;
        EXPECT_EQ(DivergenceGuard::fanInverted(mesh, q, 0), f > 1.0) << f;
    }
}

TEST(DivergenceGuard, InversionBoundOfTheSlopeUpdateOnARaisedPatch) {
    // The hexagon's centre raised 2 mm: its rest normal is +z, its faces are tilted, and pressing
    // it in along -z flips its fan at the derived force (both sides).
    std::vector<glm::vec3> p{{0, 0, 2}};
    for (int i = 0; i < 6; ++i) p.emplace_back(10.0f * std::cos(i * 1.0471976f), 10.0f * std::sin(i * 1.0471976f), 0.0f);
    p.emplace_back(0.0f, 0.0f, -8.0f);
    std::vector<std::array<VertexId, 3>> t;
    for (VertexId i = 0; i < 6; ++i) {
        t.push_back({0, VertexId(1 + i), VertexId(1 + (i + 1) % 6)});
        t.push_back({7, VertexId(1 + (i + 1) % 6), VertexId(1 + i)});
    }
    auto loaded = TissueMesh::fromTriangles(p, t, "raised", false);
    ASSERT_TRUE(loaded.mesh) << loaded.error();
    const TissueMesh& mesh = *loaded.mesh;
    const double m1 = 0.6, m2 = 0.35;
    const double force = inversionMaxForceAlongNormalN(mesh, 0, m1, m2);
    // By hand: apothem a = 8.66, height H = 2: the apex must go (a^2 + H^2) / H below itself.
    EXPECT_NEAR(force * (m1 - m2), (75.0 + 4.0) / 2.0, 1e-3);
    for (double f : {0.97, 1.03}) {
        std::vector<glm::vec3> q = mesh.restPositionsMm();
        const glm::vec3 n = mesh.restNormals()[0];
        q[0] -= float(m1 * f * force) * n;  // the slope update: ring r moves m_r F along -n
        for (VertexId v = 1; v <= 6; ++v) q[v] -= float(m2 * f * force) * n;
        EXPECT_EQ(DivergenceGuard::fanInverted(mesh, q, 0), f > 1.0) << f;
    }
}

TEST(DivergenceGuard, NonFiniteForceOrPosition) {
    const TissueMesh mesh = test::sphereMesh(242);
    const VertexId v = test::sideVertex(mesh);
    DivergenceGuard guard;
    std::vector<glm::vec3> positions = mesh.restPositionsMm();
    EXPECT_FALSE(guard.check(mesh, positions, touching(v)));
    EXPECT_EQ(guard.check(mesh, positions, touching(v, glm::vec3(NAN, 0, 0))).kind, DivergenceKind::NonFinite);
    positions[mesh.neighbours()[mesh.neighbourStart()[v]]].y = INFINITY;
    EXPECT_EQ(guard.check(mesh, positions, touching(v)).kind, DivergenceKind::NonFinite);
}

TEST(DivergenceGuard, EnergyGrowthButNotAFastPress) {
    const TissueMesh mesh = test::sphereMesh(242);
    const VertexId v = test::sideVertex(mesh);
    const std::vector<glm::vec3> positions = mesh.restPositionsMm();
    {
        // A hard press: 0 to 5 N in 50 ms, held: no verdict.
        DivergenceGuard guard;
        for (int t = 0; t < 2000; ++t) {
            const float f = 5.0f * std::min(1.0f, t / 50.0f);
            ASSERT_FALSE(guard.check(mesh, positions, touching(v, glm::vec3(0, 0, f)))) << t;
        }
    }
    {
        // Exponential growth of 30 % per tick (an explicit integrator far beyond its bound).
        DivergenceGuard guard;
        float f = 1e-3f;
        int detectedAt = -1;
        for (int t = 0; t < 200 && detectedAt < 0; ++t, f *= 1.3f)
            if (guard.check(mesh, positions, touching(v, glm::vec3(0, 0, f))).kind == DivergenceKind::EnergyGrowth)
                detectedAt = t;
        EXPECT_GE(detectedAt, 0);
        EXPECT_LE(detectedAt, 4 * guard.def().windowTicks);
    }
}

TEST(DivergenceGuard, SlopeRingBeyondItsBoundIsCaughtAndInsideIsNot) {
    const TissueMesh mesh = test::sphereMesh(242);
    const Octree octree(mesh, OctreeDef{});
    const VertexId v = test::sideVertex(mesh);
    const glm::vec3 tool = mesh.restPositionsMm()[v] - 0.5f * mesh.restNormals()[v];
    for (double factor : {0.95, 1.05}) {
        CoherentSlopeRing model(mesh, octree, SlopeRingParams{});
        SlopeRingParams p;
        p.forceRelaxation = 1.0;  // bound: gain < 1
        p.slopeLimitMmPerN = 100.0;
        p.contactStiffnessNPerMm = factor / p.slopeMagnitudeMmPerN[0];
        model.applyModelParams(slopeRingModelDef(p));
        DivergenceGuard guard;
        DivergenceKind seen = DivergenceKind::None;
        for (int t = 0; t < 3000 && seen == DivergenceKind::None; ++t)
            seen = guard.check(mesh, model.positionsMm(), model.step(tool, 1e-3)).kind;
        EXPECT_EQ(seen, factor > 1.0 ? DivergenceKind::Oscillation : DivergenceKind::None) << factor;
    }
}

TEST(DivergenceGuard, MassSpringBeyondItsBoundIsCaughtAndInsideIsNot) {
    const TissueMesh mesh = test::sphereMesh(242);
    const Octree octree(mesh, OctreeDef{});
    const VertexId v = test::sideVertex(mesh);
    const glm::vec3 tool = mesh.restPositionsMm()[v] - 0.5f * mesh.restNormals()[v];
    MassSpringParams p;
    p.dampingRatio = 0.0;
    p.substeps = 1;
    const double dtBound = symplecticEulerMaxStepS(massSpringOmegaMaxRadPerS(mesh, p, v));
    for (double factor : {0.95, 1.05}) {
        MassSpringModel model(mesh, octree, p, MassSpringIntegrator::SymplecticEuler, MassSpringScope::Whole);
        DivergenceGuard guard;
        DivergenceKind seen = DivergenceKind::None;
        int tick = 0;
        for (; tick < 3000 && seen == DivergenceKind::None; ++tick)
            seen = guard.check(mesh, model.positionsMm(), model.step(tool, factor * dtBound)).kind;
        if (factor < 1.0) EXPECT_EQ(seen, DivergenceKind::None);
        else EXPECT_NE(seen, DivergenceKind::None);  // growth, NaN, or the top mode folding the fan
        // Caught while the force is still finite: before the state overflows.
        if (factor > 1.0) {
            EXPECT_LT(tick, 3000);
        }
    }
}

TEST(DivergenceGuard, CheckDoesNotAllocate) {
    const TissueMesh mesh = test::sphereMesh(242);
    const Octree octree(mesh, OctreeDef{});
    const VertexId v = test::sideVertex(mesh);
    const glm::vec3 tool = mesh.restPositionsMm()[v] - 0.5f * mesh.restNormals()[v];
    CoherentSlopeRing model(mesh, octree, SlopeRingParams{});
    DivergenceGuard guard;
    model.step(tool, 1e-3);
    const test::AllocationCounter counter;
    for (int t = 0; t < 500; ++t) (void)guard.check(mesh, model.positionsMm(), model.step(tool, 1e-3));
    EXPECT_EQ(counter.count(), 0u);
}

TEST(DivergenceGuard, TheLoopZeroesTheForceResetsTheTissueAndRecordsTheEvent) {
    TissueMesh mesh = test::sphereMesh(1442);
    const VertexId v = test::sideVertex(mesh);
    auto device = std::make_unique<SimulatedDevice>(SimTrajectory::PressHold);
    device->setScene(mesh.restPositionsMm()[v], mesh.restNormals()[v], glm::vec3(0, 1, 0));
    ASSERT_TRUE(device->open());
    HapticLoopDef def;
    def.trySchedFifo = false;
    HapticLoop loop(def, HapticScene::create(std::move(mesh), slopeRingModelDef(SlopeRingParams{})), std::move(device));
    // Beyond the loop-gain bound (the validator refuses this set; the model's real-time apply
    // does not check, which is what a wrong set would do at run time).
    SlopeRingParams bad;
    bad.forceRelaxation = 1.0;
    bad.slopeLimitMmPerN = 100.0;
    bad.contactStiffnessNPerMm = 1.5 / bad.slopeMagnitudeMmPerN[0];
    ASSERT_FALSE(messagesOf(validateSlopeRingParams(bad)).empty());
    ASSERT_TRUE(loop.scene().model().applyModelParams(slopeRingModelDef(bad)));
    std::uint64_t before = 0;
    bool caught = false;
    for (int t = 0; t < 5000 && !caught; ++t) {
        const test::AllocationCounter counter;
        loop.stepOnce();
        EXPECT_EQ(counter.count(), 0u);
        const HapticSnapshot& s = loop.newestSnapshot();
        if (s.counters.divergences > before) {
            caught = true;
            EXPECT_EQ(s.counters.lastDivergence, DivergenceKind::Oscillation);
            EXPECT_EQ(s.counters.lastDivergenceTick, s.tick);
            EXPECT_EQ(s.commandedForceN, glm::vec3(0.0f));  // zero force within the tick
            EXPECT_EQ(s.forceN, glm::vec3(0.0f));
            EXPECT_FALSE(s.contact);
            EXPECT_EQ(s.displacedTotal, 0u);  // the tissue is at rest
            const auto positions = loop.scene().model().positionsMm();
            const auto& rest = loop.scene().mesh().restPositionsMm();
            for (std::size_t i = 0; i < rest.size(); ++i) ASSERT_EQ(positions[i], rest[i]);
            EXPECT_NE(std::string(divergenceAdvice(s.counters.lastDivergence)).find("forceRelaxation"), std::string::npos);
        }
        before = s.counters.divergences;
    }
    EXPECT_TRUE(caught);
    // The session keeps running: with a stable set the loop renders a force again.
    SlopeRingParams good;
    ASSERT_TRUE(loop.scene().model().applyModelParams(slopeRingModelDef(good)));
    bool forceAgain = false;
    for (int t = 0; t < 3000; ++t) {
        loop.stepOnce();
        forceAgain = forceAgain || glm::length(loop.newestSnapshot().forceN) > 0.0f;
    }
    EXPECT_TRUE(forceAgain);
    EXPECT_EQ(loop.newestSnapshot().counters.divergences, before);
}

TEST(DivergenceGuard, NoFalseAlarmOnTheSimulatedTrajectoriesWithEveryMethod) {
    for (auto method : {SlopeRingMethod::Coherent, SlopeRingMethod::Proposed, SlopeRingMethod::Previous})
        for (auto trajectory : {SimTrajectory::PressHold, SimTrajectory::Stroke, SimTrajectory::Scan, SimTrajectory::Sine}) {
            TissueMesh mesh = test::sphereMesh(1442);
            const VertexId v = test::sideVertex(mesh);
            auto device = std::make_unique<SimulatedDevice>(trajectory);
            device->setScene(mesh.restPositionsMm()[v], mesh.restNormals()[v], glm::vec3(0, 1, 0));
            ASSERT_TRUE(device->open());
            HapticLoopDef def;
            def.trySchedFifo = false;
            HapticLoop loop(def, HapticScene::create(std::move(mesh), slopeRingModelDef(SlopeRingParams{}, method)), std::move(device));
            bool contact = false;
            for (int t = 0; t < 6000; ++t) {
                loop.stepOnce();
                contact = contact || loop.newestSnapshot().contact;
            }
            EXPECT_TRUE(contact) << simTrajectoryName(trajectory);
            EXPECT_EQ(loop.newestSnapshot().counters.divergences, 0u)
                << simTrajectoryName(trajectory) << " " << divergenceKindName(loop.newestSnapshot().counters.lastDivergence);
        }
}
