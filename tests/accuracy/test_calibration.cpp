// Calibration from the flat punch: the calibrated slopes reproduce the punch profile at the ring
// radii when the real model is pressed; least squares recovers known ring displacements; the
// error against the punch falls as rings cover the loaded region; the sweep measures and ranks.
#include "engine/core/MeshGenerator.h"
#include "engine/core/Octree.h"
#include "engine/core/Rings.h"
#include "engine/core/SceneTarget.h"
#include "engine/models/slopering/CoherentSlopeRing.h"
#include "engine/accuracy/AccuracySweep.h"
#include "engine/accuracy/Calibration.h"
#include "engine/accuracy/ModelError.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <numbers>

using namespace palpate;

namespace {

const TissueMesh& sphere3970() {
    static const auto generated = generateMesh(GeneratedShape::Sphere, 3970);
    return *generated.mesh;
}

ToolContact liverLike() {
    ToolContact c;
    c.material = {5.4e-3, 0.49};
    c.toolRadiusMm = 2.5;
    return c;
}

double tangentDistance(const TissueMesh& mesh, VertexId t, VertexId v) {
    const glm::dvec3 n(mesh.restNormals()[t]);
    const glm::dvec3 d = glm::dvec3(mesh.restPositionsMm()[v]) - glm::dvec3(mesh.restPositionsMm()[t]);
    return glm::length(d - glm::dot(d, n) * n);
}

}  // namespace

TEST(Calibration, SlopesFollowThePunchFormula) {
    const TissueMesh& mesh = sphere3970();
    const VertexId t = defaultTargetVertex(mesh);
    SlopeRingParams base;
    base.ringCount = 4;
    const ToolContact contact = liverLike();
    const SlopeCalibration c = calibrateSlopesFromPunch(mesh, t, contact, base);
    const double eStar = 5.4e-3 / (1.0 - 0.49 * 0.49);
    const double m1 = 1.0 / (2.0 * 2.5 * eStar);
    EXPECT_NEAR(c.params.slopeMagnitudeMmPerN[0], m1, 1e-12 * m1);
    ASSERT_EQ(c.ringRadiiMm.size(), 4u);
    for (int r = 1; r <= 4; ++r) {
        const double rk = c.ringRadiiMm[std::size_t(r - 1)];
        ASSERT_GT(rk, contact.toolRadiusMm) << "this mesh's rings lie outside a 2.5 mm tool";
        EXPECT_NEAR(c.params.slopeMagnitudeMmPerN[std::size_t(r)], m1 * 2.0 / std::numbers::pi * std::asin(2.5 / rk), 1e-12 * m1);
    }
    EXPECT_NEAR(c.params.springStiffnessNPerMm, 1.0 / m1, 1e-12);
    EXPECT_TRUE(c.outsidePaperRange);  // soft liver under a small tool: ~20 mm/N
    EXPECT_TRUE(messagesOf(validateSlopeRingParams(c.params)).empty());
}

TEST(Calibration, RingRadiiAreMeanTangentDistances) {
    const TissueMesh& mesh = sphere3970();
    const VertexId t = defaultTargetVertex(mesh);
    RingFinder finder(mesh);
    RingSet rings = finder.makeRingSet();
    finder.find(t, 2, rings);
    const auto radii = ringMeanRadiiMm(mesh, t, 2);
    for (int r = 1; r <= 2; ++r) {
        double sum = 0.0;
        for (VertexId v : rings.ring(r)) sum += tangentDistance(mesh, t, v);
        EXPECT_NEAR(radii[std::size_t(r - 1)], sum / double(rings.ring(r).size()), 1e-9);
    }
    EXPECT_LT(radii[0], radii[1]);
}

TEST(Calibration, PressedModelReproducesThePunchProfileAtTheRingRadii) {
    const TissueMesh& mesh = sphere3970();
    const VertexId t = defaultTargetVertex(mesh);
    SlopeRingParams base;
    base.ringCount = 3;
    const ToolContact contact = liverLike();
    const SlopeCalibration c = calibrateSlopesFromPunch(mesh, t, contact, base);
    const Octree octree(mesh, OctreeDef{});
    CoherentSlopeRing model(mesh, octree, c.params);
    const ModelError e = measureModelError(model, mesh, t, contact);
    ASSERT_GT(e.indentationMm, 0.5);

    // Mean normal displacement of each ring against the punch profile at that ring's mean radius.
    const glm::dvec3 n(mesh.restNormals()[t]);
    const auto positions = model.positionsMm();
    RingFinder finder(mesh);
    RingSet rings = finder.makeRingSet();
    finder.find(t, 3, rings);
    for (int r = 1; r <= 3; ++r) {
        double sum = 0.0;
        for (VertexId v : rings.ring(r))
            sum += glm::dot(glm::dvec3(mesh.restPositionsMm()[v]) - glm::dvec3(positions[v]), n);
        const double mean = sum / double(rings.ring(r).size());
        const double punch = punchSurfaceDisplacementMm(contact.toolRadiusMm, e.indentationMm, c.ringRadiiMm[std::size_t(r - 1)]);
        EXPECT_NEAR(mean, punch, 0.01 * punch) << "ring " << r;
    }
    // k = 1/|m1|: the rendered force is the punch force at the same indentation.
    EXPECT_LT(e.forceError, 0.01);
}

TEST(Calibration, ErrorFallsAsRingsCoverTheLoadedRegion) {
    const TissueMesh& mesh = sphere3970();
    const VertexId t = defaultTargetVertex(mesh);
    const ToolContact contact = liverLike();
    const Octree octree(mesh, OctreeDef{});
    double previous = INFINITY;
    for (int rings : {1, 3, 6}) {
        SlopeRingParams base;
        base.ringCount = rings;
        const SlopeCalibration c = calibrateSlopesFromPunch(mesh, t, contact, base);
        CoherentSlopeRing model(mesh, octree, c.params);
        const ModelError e = measureModelError(model, mesh, t, contact);
        EXPECT_LT(e.displacementError, previous) << rings << " rings";
        EXPECT_GT(e.verticesCompared, 20);
        previous = e.displacementError;
    }
    EXPECT_LT(previous, 0.1);
}

TEST(Calibration, UncalibratedPaperSlopesHaveALargeForceError) {
    const TissueMesh& mesh = sphere3970();
    const VertexId t = defaultTargetVertex(mesh);
    const Octree octree(mesh, OctreeDef{});
    CoherentSlopeRing model(mesh, octree, SlopeRingParams{});  // 0.6/0.35/0.15, k = 1.5
    const ModelError e = measureModelError(model, mesh, t, liverLike());
    EXPECT_GT(e.forceError, 1.0);  // k = 1.5 N/mm against the punch's 2 a E* ~ 0.04 N/mm
}

TEST(Calibration, LeastSquaresRecoversRingDisplacements) {
    const TissueMesh& mesh = sphere3970();
    const VertexId t = defaultTargetVertex(mesh);
    RingFinder finder(mesh);
    RingSet rings = finder.makeRingSet();
    finder.find(t, 3, rings);
    // A field constant per ring (plus noise that averages out per ring): slopes = value / F.
    std::vector<double> u(mesh.vertexCount(), 0.0);
    const double values[] = {2.0, 1.2, 0.7, 0.3};
    for (int r = 0; r <= 3; ++r) {
        int i = 0;
        for (VertexId v : rings.ring(r)) u[v] = values[r] + ((i++ % 2) ? 0.05 : -0.05) * (rings.ring(r).size() % 2 ? 0 : 1);
    }
    SlopeRingParams base;
    base.ringCount = 3;
    const SlopeCalibration c = calibrateSlopesFromDisplacements(mesh, t, u, 0.5, base);
    for (int r = 0; r <= 3; ++r) EXPECT_NEAR(c.params.slopeMagnitudeMmPerN[std::size_t(r)], values[r] / 0.5, 1e-9) << r;
    EXPECT_NEAR(c.params.springStiffnessNPerMm, 0.5 / 2.0, 1e-12);
    for (const std::string& note : c.notes) EXPECT_EQ(note.find("ring"), std::string::npos) << note;

    // A reference where ring 2 moves as far as ring 1 is made strictly decreasing, with a note.
    for (VertexId v : rings.ring(2)) u[v] = 1.2;
    for (VertexId v : rings.ring(1)) u[v] = 1.2;
    const SlopeCalibration d = calibrateSlopesFromDisplacements(mesh, t, u, 0.5, base);
    EXPECT_LT(d.params.slopeMagnitudeMmPerN[2], d.params.slopeMagnitudeMmPerN[1]);
    EXPECT_FALSE(d.notes.empty());
    EXPECT_TRUE(messagesOf(validateSlopeRingParams(d.params)).empty());
}

TEST(Calibration, BadInputIsNamed) {
    const TissueMesh& mesh = sphere3970();
    SlopeRingParams base;
    ToolContact bad = liverLike();
    bad.toolRadiusMm = 0.0;
    try {
        calibrateSlopesFromPunch(mesh, 0, bad, base);
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("tool radius"), std::string::npos);
    }
    bad = liverLike();
    bad.material.poissonRatio = 0.7;
    EXPECT_THROW(calibrateSlopesFromPunch(mesh, 0, bad, base), std::invalid_argument);
    EXPECT_THROW(calibrateSlopesFromPunch(mesh, VertexId(mesh.vertexCount()), liverLike(), base), std::invalid_argument);
    EXPECT_THROW(calibrateSlopesFromDisplacements(mesh, 0, {1.0, 2.0}, 1.0, base), std::invalid_argument);
}

TEST(ModelError, NoContactIsAnErrorNamingTheVertex) {
    const TissueMesh& mesh = sphere3970();
    const Octree octree(mesh, OctreeDef{});
    CoherentSlopeRing model(mesh, octree, SlopeRingParams{});
    PressDef above;
    above.toolDepthMm = -2.0;  // 2 mm above the surface
    const VertexId t = defaultTargetVertex(mesh);
    try {
        measureModelError(model, mesh, t, liverLike(), above);
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(std::to_string(t)), std::string::npos);
    }
}

TEST(ModelError, ThePunchFieldItselfHasZeroError) {
    const TissueMesh& mesh = sphere3970();
    const VertexId t = defaultTargetVertex(mesh);
    std::vector<double> u(mesh.vertexCount());
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
        u[v] = punchSurfaceDisplacementMm(3.0, 1.5, tangentDistance(mesh, t, VertexId(v)));
    int compared = 0;
    EXPECT_NEAR(displacementErrorAgainstPunch(mesh, t, u, 3.0, 5.0, &compared), 0.0, 1e-12);
    EXPECT_GT(compared, 50);
    for (double& x : u) x *= 0.5;
    u[t] = 1.5;  // peak kept, the rest halved: a large error
    EXPECT_GT(displacementErrorAgainstPunch(mesh, t, u, 3.0), 0.1);
}

TEST(Sweep, MeasuresEveryConfigurationAndMarksTheParetoFront) {
    SweepDef def;
    def.contact = liverLike();
    def.shapes = {GeneratedShape::Sphere};
    def.sizes = {1442};
    def.maxRings = 3;
    def.paperMethods = true;
    def.otherModels = false;
    def.timingRepeats = 1;
    def.minMeasureMs = 1.0;
    int progressCalls = 0;
    def.progress = [&](double fraction, const std::string&) {
        ++progressCalls;
        EXPECT_GT(fraction, 0.0);
        EXPECT_LE(fraction, 1.0);
    };
    const SweepResult result = runSweep(def);
    ASSERT_EQ(result.points.size(), 6u);  // 3 slope-ring + proposed, hybrid, previous
    EXPECT_EQ(progressCalls, 6);
    bool anyPareto = false;
    for (const SweepPoint& p : result.points) {
        EXPECT_GT(p.tickUs, 0.0);
        EXPECT_TRUE(std::isfinite(p.error.displacementError));
        anyPareto = anyPareto || p.pareto;
    }
    EXPECT_TRUE(anyPareto);
    // The paper's methods share the 2-ring model: the same surface, so the same error.
    EXPECT_NEAR(result.points[3].error.displacementError, result.points[1].error.displacementError, 1e-6);
    EXPECT_NEAR(result.points[5].error.displacementError, result.points[1].error.displacementError, 1e-6);
    const std::string csv = sweepToCsv(result.points);
    EXPECT_EQ(csv.substr(0, csv.find('\n')).find("shape,vertices,series"), 0u);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 7);
}

TEST(Sweep, ParetoFrontByHand) {
    auto point = [](double us, double err) {
        SweepPoint p;
        p.tickUs = us;
        p.error.displacementError = err;
        return p;
    };
    std::vector<SweepPoint> points{point(1, 0.5), point(2, 0.2), point(3, 0.3), point(4, 0.1), point(2, 0.6)};
    markParetoFront(points);
    EXPECT_TRUE(points[0].pareto);
    EXPECT_TRUE(points[1].pareto);
    EXPECT_FALSE(points[2].pareto);  // (2, 0.2) is faster and better
    EXPECT_TRUE(points[3].pareto);
    EXPECT_FALSE(points[4].pareto);
}

TEST(Sweep, CancelReturnsWhatWasMeasured) {
    SweepDef def;
    def.contact = liverLike();
    def.shapes = {GeneratedShape::Sphere};
    def.sizes = {1442};
    def.maxRings = 8;
    def.paperMethods = false;
    def.otherModels = false;
    def.timingRepeats = 1;
    def.minMeasureMs = 1.0;
    std::atomic<bool> cancel{false};
    def.cancel = &cancel;
    def.progress = [&](double, const std::string&) { cancel = true; };  // stop after the first point
    const SweepResult result = runSweep(def);
    EXPECT_TRUE(result.cancelled);
    EXPECT_EQ(result.points.size(), 1u);
    def.maxRings = 0;
    EXPECT_THROW(runSweep(def), std::invalid_argument);
}

TEST(Sweep, OtherModelsGetAPointEachWithTheirForceCalibratedWherePossible) {
    SweepDef def;
    def.contact = liverLike();
    def.shapes = {GeneratedShape::Sphere};
    def.sizes = {1442};
    def.maxRings = 1;
    def.paperMethods = false;
    def.otherModels = true;
    def.timingRepeats = 1;
    def.minMeasureMs = 0.0;
    const SweepResult result = runSweep(def);
    ASSERT_EQ(result.points.size(), 8u);  // slope-ring 1 ring + 7 other models
    std::set<std::string> names;
    for (const SweepPoint& p : result.points) {
        names.insert(p.model);
        EXPECT_EQ(p.series.empty(), false);
        EXPECT_GT(p.tickUs, 0.0) << p.model;
        EXPECT_TRUE(std::isfinite(p.error.displacementError)) << p.model;
        EXPECT_GT(p.error.indentationMm, 0.0) << p.model;
        // Radius of influence and FFD render k_s = 2 a E* times their indentation: the punch force.
        if (p.model == "radius-of-influence" || p.model == "ffd") {
            EXPECT_LT(p.error.forceError, 0.01) << p.model;
        }
    }
    for (const char* name : {"mass-spring-local", "mass-spring-symplectic", "mass-spring-rk4", "mass-spring-implicit",
                             "radius-of-influence", "ffd", "volumetric-rings", "coherent"})
        EXPECT_EQ(names.count(name), 1u) << name;
}

TEST(Calibration, FromTheFemFitsTheFemBetterThanThePunchFormulaDoes) {
    static const auto generated = generateMesh(GeneratedShape::Sphere, 1442);
    const TissueMesh& mesh = *generated.mesh;
    const VertexId t = defaultTargetVertex(mesh);
    ToolContact contact;
    contact.material = {4.34e-3, 0.45};
    contact.toolRadiusMm = 5.0;
    SlopeRingParams base;
    base.ringCount = 4;
    std::vector<double> femField;
    const SlopeCalibration fem = calibrateSlopesFromFem(mesh, t, contact, base, 1.0, &femField);
    const SlopeCalibration punch = calibrateSlopesFromPunch(mesh, t, contact, base);
    ASSERT_EQ(femField.size(), mesh.vertexCount());
    EXPECT_NEAR(femField[t], 1.0, 1e-6);  // the touched vertex is under the tool: prescribed
    EXPECT_TRUE(messagesOf(validateSlopeRingParams(fem.params)).empty());
    // Same order of compliance as the half-space (the FEM layer sits on a rigid core: stiffer).
    const double ratio = fem.params.slopeMagnitudeMmPerN[0] / punch.params.slopeMagnitudeMmPerN[0];
    EXPECT_GT(ratio, 0.5);
    EXPECT_LT(ratio, 1.2);

    const Octree octree(mesh, OctreeDef{});
    auto errorAgainstFem = [&](const SlopeRingParams& params) {
        CoherentSlopeRing model(mesh, octree, params);
        measureModelError(model, mesh, t, contact);  // presses and settles
        return displacementErrorAgainstField(mesh, t, normalDisplacementsMm(model, mesh, t), femField, contact.toolRadiusMm);
    };
    const double femFit = errorAgainstFem(fem.params);
    const double punchFit = errorAgainstFem(punch.params);
    EXPECT_LT(femFit, punchFit);
    EXPECT_LT(femFit, 0.15);
}
