// Units, faults, ring roundness, repair and remeshing of meshes from other tools (docs/meshes.md).
// The meshes are generated here with known faults; counts are worked out from their construction.

#include "engine/core/MeshFaults.h"
#include "engine/core/MeshUnit.h"
#include "engine/core/RingRoundness.h"
#include "engine/meshimport/MeshRemesh.h"
#include "engine/meshimport/MeshRepair.h"
#include "tests/meshimport/ImportMeshes.h"
#include "tests/engine/TestMeshes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace palpate {
namespace {

using test::quadBox;
using test::trianglesOf;
using Tris = std::vector<std::array<std::uint32_t, 3>>;

std::vector<glm::dvec3> exact(const std::vector<glm::vec3>& p) { return {p.begin(), p.end()}; }

PolygonSoup soupOf(const std::vector<glm::dvec3>& positions, const Tris& triangles) {
    PolygonSoup soup;
    soup.points = positions;
    for (const auto& t : triangles) soup.polygons.push_back({t[0], t[1], t[2]});
    return soup;
}

TissueMesh meshOf(const TriangleSurface& s) {
    auto built = TissueMesh::fromTriangles(std::vector<glm::vec3>(s.positionsMm.begin(), s.positionsMm.end()), s.triangles, "test");
    EXPECT_TRUE(built.mesh) << built.error();
    return std::move(*built.mesh);
}

bool anyContains(const std::vector<std::string>& lines, const std::string& word) {
    return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l.find(word) != std::string::npos; });
}

double signedVolume(const TriangleSurface& s) {
    double v6 = 0.0;
    for (const auto& t : s.triangles)
        v6 += glm::dot(s.positionsMm[t[0]], glm::cross(s.positionsMm[t[1]], s.positionsMm[t[2]]));
    return v6 / 6.0;
}

// ---- units ----

TEST(MeshUnit, NamedUnitsAndScaleFactorsParse) {
    std::string error;
    EXPECT_EQ(parseMeshUnit("cm", error)->mmPerUnit, 10.0);
    EXPECT_EQ(parseMeshUnit("M", error)->mmPerUnit, 1000.0);
    EXPECT_EQ(parseMeshUnit("in", error)->mmPerUnit, 25.4);
    const auto factor = parseMeshUnit("2.5", error);
    ASSERT_TRUE(factor);
    EXPECT_EQ(factor->mmPerUnit, 2.5);
    EXPECT_EQ(factor->text(), "2.5");
    EXPECT_EQ(parseMeshUnit("25.4", error)->text(), "in");  // a factor that is a named unit is named
    for (const char* bad : {"furlong", "0", "-1", "1e9", "nan", "", "3mm"}) {
        error.clear();
        EXPECT_FALSE(parseMeshUnit(bad, error)) << bad;
        EXPECT_NE(error.find("mm, cm, m, in"), std::string::npos) << error;
    }
}

TEST(MeshUnit, AnImplausibleSizeSuggestsTheUnitThatMakesItTissueAndSaysWhy) {
    // A liver 9 units across: 9 mm is smaller than tissue; in cm it is 90 mm (cm before inches).
    const auto liver = suggestMeshUnit(9.0);
    ASSERT_TRUE(liver);
    EXPECT_EQ(liver->unit.text(), "cm");
    EXPECT_NE(liver->reason.find("9 mm"), std::string::npos) << liver->reason;
    EXPECT_NE(liver->reason.find("90 mm"), std::string::npos) << liver->reason;
    EXPECT_NE(liver->reason.find("smaller"), std::string::npos) << liver->reason;
    // Blender: 0.15 units (metres).
    EXPECT_EQ(suggestMeshUnit(0.15)->unit.text(), "m");
    // Far too large in mm (a scene in micrometres would be 150000 "mm").
    // No named unit makes 1500 plausible: a power-of-ten scale factor does (150 mm).
    const auto large = suggestMeshUnit(1500.0);
    ASSERT_TRUE(large);
    EXPECT_NE(large->reason.find("larger"), std::string::npos);
    EXPECT_EQ(large->unit.name, "");
    EXPECT_DOUBLE_EQ(large->unit.mmPerUnit, 0.1);
    // Plausible as read: no suggestion; read as cm, 9 units are plausible too.
    EXPECT_FALSE(suggestMeshUnit(150.0));
    EXPECT_FALSE(suggestMeshUnit(9.0, MeshUnit{"cm", 10.0}));
    // Only inches make 1 unit plausible (25.4 mm).
    EXPECT_EQ(suggestMeshUnit(1.0)->unit.text(), "in");
}

TEST(MeshUnit, LoadScalesTheFileToMillimetres) {
    const auto box = quadBox(4, 6.0);  // a 6-unit box, in cm a 60 mm one
    const auto tris = trianglesOf(box);
    test::TempDir dir;
    const std::string path = dir.file("box.off");
    {
        auto built = TissueMesh::fromTriangles(std::vector<glm::vec3>(box.positions.begin(), box.positions.end()), tris, "box");
        ASSERT_TRUE(built.mesh);
        ASSERT_EQ(built.mesh->save(path), "");
    }
    const auto inCm = TissueMesh::load(path, MeshUnit{"cm", 10.0});
    ASSERT_TRUE(inCm.mesh) << inCm.error();
    EXPECT_NEAR(inCm.report.sizeMm.x, 60.0, 1e-4);
    EXPECT_NEAR(inCm.mesh->boundsMaxMm().x - inCm.mesh->boundsMinMm().x, 60.0, 1e-4);
    EXPECT_EQ(inCm.report.unit.text(), "cm");
    const auto inMm = TissueMesh::load(path);
    EXPECT_NEAR(inMm.report.sizeMm.x, 6.0, 1e-5);
}

// ---- faults ----

TEST(MeshFaults, ACleanClosedBoxHasNone) {
    const auto box = quadBox(3, 10.0);
    const MeshFaults f = findMeshFaults(box.positions, trianglesOf(box));
    EXPECT_FALSE(f.hasErrors());
    EXPECT_EQ(f.boundaryEdges, 0u);
    EXPECT_EQ(f.holes, 0u);
    EXPECT_EQ(f.components, 1u);
    EXPECT_EQ(f.duplicateVertices, 0u);
    EXPECT_TRUE(f.warningTexts().empty());
}

TEST(MeshFaults, FlippedTrianglesAreNamedAsInconsistentOrientationNotNonManifold) {
    const auto box = quadBox(3, 10.0);
    Tris tris = trianglesOf(box);
    // Two triangles far apart (not sharing an edge): 3 misoriented edges each.
    std::swap(tris[0][1], tris[0][2]);
    std::swap(tris[40][1], tris[40][2]);
    const MeshFaults f = findMeshFaults(box.positions, tris);
    EXPECT_EQ(f.misorientedEdges, 6u);
    EXPECT_EQ(f.nonManifoldEdges, 0u);
    EXPECT_EQ(f.bowTieVertices, 0u);
    ASSERT_EQ(f.errorTexts().size(), 1u);
    EXPECT_NE(f.errorTexts()[0].find("6 edges where neighbouring triangles are inconsistently oriented"), std::string::npos);
}

TEST(MeshFaults, HolesNonManifoldEdgesBowTiesDuplicatesAndComponentsAreCounted) {
    const auto box = quadBox(3, 10.0);
    Tris tris = trianglesOf(box);
    // A hole: one quad (two triangles) removed leaves one loop of 4 boundary edges.
    Tris holed(tris.begin() + 2, tris.end());
    MeshFaults f = findMeshFaults(box.positions, holed);
    EXPECT_EQ(f.holes, 1u);
    EXPECT_EQ(f.boundaryEdges, 4u);
    EXPECT_FALSE(f.hasErrors());
    EXPECT_TRUE(anyContains(f.warningTexts(), "1 hole"));

    // A fin: a third triangle on an existing edge.
    auto withFin = box.positions;
    withFin.push_back({0.0, 0.0, 30.0});
    Tris fin = tris;
    fin.push_back({tris[0][0], tris[0][1], std::uint32_t(withFin.size() - 1)});
    f = findMeshFaults(withFin, fin);
    EXPECT_EQ(f.nonManifoldEdges, 1u);
    EXPECT_TRUE(anyContains(f.errorTexts(), "shared by three or more triangles"));

    // Two boxes sharing one corner: a bow-tie vertex, one component (through the vertex).
    auto two = box.positions;
    Tris twoTris = tris;
    const glm::dvec3 corner = box.positions[twoTris[0][0]];
    const std::uint32_t offset = std::uint32_t(two.size());
    for (const auto& p : box.positions) two.push_back(2.0 * corner - p);  // point reflection through the corner
    for (auto t : tris) {
        for (auto& v : t) v = (box.positions[v] == corner) ? twoTris[0][0] : v + offset;
        twoTris.push_back(t);
    }
    f = findMeshFaults(two, twoTris);
    EXPECT_EQ(f.bowTieVertices, 1u);
    EXPECT_EQ(f.unusedVertices, 1u);  // the reflected copy of the shared corner is not used
    EXPECT_TRUE(anyContains(f.errorTexts(), "bow-tie"));

    // Every triangle with its own corners (what an STL holds): duplicates and a split surface.
    std::vector<glm::dvec3> soupPositions;
    Tris soupTris;
    for (const auto& t : tris) {
        const std::uint32_t base = std::uint32_t(soupPositions.size());
        for (auto v : t) soupPositions.push_back(box.positions[v]);
        soupTris.push_back({base, base + 1, base + 2});
    }
    f = findMeshFaults(soupPositions, soupTris);
    EXPECT_EQ(f.duplicateVertices, soupPositions.size() - box.positions.size());
    EXPECT_EQ(f.components, tris.size());
    EXPECT_TRUE(anyContains(f.warningTexts(), "duplicate vertices"));
    EXPECT_TRUE(anyContains(f.warningTexts(), "separate components"));
}

TEST(MeshFaults, TheLoaderNamesTheRealFaultAndPointsToTheRepair) {
    const auto box = quadBox(3, 40.0);
    Tris tris = trianglesOf(box);
    std::swap(tris[5][1], tris[5][2]);
    auto loaded = TissueMesh::fromTriangles(std::vector<glm::vec3>(box.positions.begin(), box.positions.end()), tris, "flip");
    EXPECT_FALSE(loaded.mesh);
    EXPECT_TRUE(anyContains(loaded.report.errors, "3 edges where neighbouring triangles are inconsistently oriented"));
    EXPECT_FALSE(anyContains(loaded.report.errors, "non-manifold"));
    EXPECT_TRUE(anyContains(loaded.report.errors, "mesh import --repair"));
}

// ---- ring roundness ----

TEST(RingRoundness, SliversMakeRingsLessRoundThanAnEvenGrid) {
    const auto even = quadBox(12, 60.0, 0.0), uneven = quadBox(12, 60.0, 0.9);
    const TissueMesh evenMesh = meshOf({even.positions, trianglesOf(even)});
    const TissueMesh unevenMesh = meshOf({uneven.positions, trianglesOf(uneven)});
    const RingRoundness e = measureRingRoundness(evenMesh, 2), u = measureRingRoundness(unevenMesh, 2);
    EXPECT_GT(e.sampledCentres, 100u);
    // An even grid's edges are the cell side or its diagonal (sqrt 2): CV well below an uneven one's.
    EXPECT_GT(u.edgeLengthCv, 1.5 * e.edgeLengthCv);
    EXPECT_GT(u.ringDistanceCv[1], e.ringDistanceCv[1]);
    EXPECT_GT(u.ringDistanceCv[2], e.ringDistanceCv[2]);
    // Even grid, ring 1 of an interior vertex: 4 sides of length s and 2 diagonals of s*sqrt2
    // (6 neighbours), or 4 sides and 4 diagonals... the CV is that of {s, s*sqrt2} mixtures: < 0.25.
    EXPECT_LT(e.ringDistanceCv[1], 0.25);
    EXPECT_GT(e.ringDistanceCv[1], 0.05);
    EXPECT_NEAR(e.meanEdgeMm, 5.0 * (2.0 + std::sqrt(2.0)) / 3.0, 0.5);  // sides 5 mm, a third diagonals
}

TEST(RingRoundness, BoundaryCentresAreSkipped) {
    const auto box = quadBox(8, 40.0);
    Tris tris = trianglesOf(box);
    Tris open(tris.begin() + 2 * 64, tris.end());  // one whole side removed
    const TissueMesh mesh = meshOf({box.positions, open});
    const RingRoundness r = measureRingRoundness(mesh, 2);
    const RingRoundness closed = measureRingRoundness(meshOf({box.positions, tris}), 2);
    EXPECT_LT(r.sampledCentres, closed.sampledCentres);
    EXPECT_GT(r.sampledCentres, 0u);
}

// ---- repair ----

TEST(MeshRepair, FlippedFacesAreReversedAndTheResultIsClosedAndOutward) {
    const auto box = quadBox(4, 40.0);
    Tris tris = trianglesOf(box);
    for (std::size_t i = 0; i < tris.size(); i += 7) std::swap(tris[i][1], tris[i][2]);
    for (auto& t : tris) std::swap(t[1], t[2]);  // and the whole thing inside out
    const auto out = repairPolygonSoup(soupOf(box.positions, tris), {});
    ASSERT_TRUE(out.surface) << out.error;
    const MeshFaults f = findMeshFaults(out.surface->positionsMm, out.surface->triangles);
    EXPECT_FALSE(f.hasErrors()) << (f.errorTexts().empty() ? "" : f.errorTexts()[0]);
    EXPECT_EQ(f.boundaryEdges, 0u);
    EXPECT_GT(signedVolume(*out.surface), 0.9 * 40.0 * 40.0 * 40.0);
    EXPECT_TRUE(anyContains(out.changes, "to make the orientation consistent")) << out.changes.size();
}

TEST(MeshRepair, DuplicateVerticesAreMergedIntoOneClosedSurface) {
    const auto box = quadBox(3, 30.0);
    const Tris tris = trianglesOf(box);
    PolygonSoup soup;
    for (const auto& t : tris) {
        const std::uint32_t base = std::uint32_t(soup.points.size());
        for (auto v : t) soup.points.push_back(box.positions[v]);
        soup.polygons.push_back({base, base + 1, base + 2});
    }
    const auto out = repairPolygonSoup(soup, {});
    ASSERT_TRUE(out.surface) << out.error;
    EXPECT_EQ(out.surface->positionsMm.size(), box.positions.size());
    EXPECT_EQ(out.surface->triangles.size(), tris.size());
    EXPECT_TRUE(anyContains(out.changes, "merged " + std::to_string(soup.points.size() - box.positions.size()) + " duplicate vertices"));
    EXPECT_EQ(findMeshFaults(out.surface->positionsMm, out.surface->triangles).boundaryEdges, 0u);
}

TEST(MeshRepair, AHoleIsFilledAndReported) {
    const auto box = quadBox(6, 30.0);
    const Tris tris = trianglesOf(box);
    Tris holed;
    for (std::size_t q = 0; q < box.quads.size(); ++q)
        if (q != 14 && q != 15) holed.insert(holed.end(), {tris[2 * q], tris[2 * q + 1]});  // two neighbouring quads
    ASSERT_EQ(findMeshFaults(box.positions, holed).holes, 1u);
    const auto out = repairPolygonSoup(soupOf(box.positions, holed), {});
    ASSERT_TRUE(out.surface) << out.error;
    const MeshFaults f = findMeshFaults(out.surface->positionsMm, out.surface->triangles);
    EXPECT_EQ(f.boundaryEdges, 0u);
    EXPECT_FALSE(f.hasErrors());
    EXPECT_TRUE(anyContains(out.changes, "filled a hole of 6 edges")) << (out.changes.empty() ? "" : out.changes.back());
    // Not asked to fill: the hole stays.
    const auto kept = repairPolygonSoup(soupOf(box.positions, holed), {KeepComponents::Largest, false});
    ASSERT_TRUE(kept.surface);
    EXPECT_EQ(findMeshFaults(kept.surface->positionsMm, kept.surface->triangles).holes, 1u);
}

TEST(MeshRepair, TheLargestComponentIsKeptUnlessAllAreAsked) {
    const auto big = quadBox(4, 40.0), small = quadBox(2, 5.0);
    PolygonSoup soup = soupOf(big.positions, trianglesOf(big));
    const std::uint32_t offset = std::uint32_t(soup.points.size());
    for (const auto& p : small.positions) soup.points.push_back(p + glm::dvec3(100.0, 0.0, 0.0));
    for (const auto& t : trianglesOf(small)) soup.polygons.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    const auto largest = repairPolygonSoup(soup, {KeepComponents::Largest, true});
    ASSERT_TRUE(largest.surface);
    EXPECT_EQ(largest.surface->triangles.size(), trianglesOf(big).size());
    EXPECT_TRUE(anyContains(largest.changes, "kept the largest of 2 components"));
    const auto all = repairPolygonSoup(soup, {KeepComponents::All, true});
    ASSERT_TRUE(all.surface);
    EXPECT_EQ(all.surface->triangles.size(), trianglesOf(big).size() + trianglesOf(small).size());
}

TEST(MeshRepair, QuadsAreTriangulated) {
    const auto box = quadBox(3, 30.0);
    PolygonSoup soup;
    soup.points = box.positions;
    for (const auto& q : box.quads) soup.polygons.push_back(q);
    const auto out = repairPolygonSoup(soup, {});
    ASSERT_TRUE(out.surface) << out.error;
    EXPECT_EQ(out.surface->triangles.size(), 2 * box.quads.size());
    EXPECT_FALSE(findMeshFaults(out.surface->positionsMm, out.surface->triangles).hasErrors());
}

TEST(MeshRepair, CancellingStopsWithoutASurface) {
    const auto box = quadBox(3, 30.0);
    const auto out = repairPolygonSoup(soupOf(box.positions, trianglesOf(box)), {}, [] { return true; });
    EXPECT_FALSE(out.surface);
    EXPECT_EQ(out.error, "cancelled");
}

// ---- remeshing ----

TEST(MeshRemesh, UnevenTrianglesBecomeUniformAndRingsRounder) {
    const auto uneven = quadBox(10, 60.0, 0.9);
    TriangleSurface surface{uneven.positions, trianglesOf(uneven)};
    const RingRoundness before = measureRingRoundness(meshOf(surface), 2);
    std::vector<std::string> changes;
    ASSERT_EQ(remeshIsotropic(surface, {4.0, 5}, {}, changes), "");
    const TissueMesh after = meshOf(surface);
    const RingRoundness r = measureRingRoundness(after, 2);
    EXPECT_LT(r.edgeLengthCv, 0.5 * before.edgeLengthCv);
    EXPECT_LT(r.ringDistanceCv[2], before.ringDistanceCv[2]);
    EXPECT_NEAR(r.meanEdgeMm, 4.0, 1.0);
    const MeshFaults f = findMeshFaults(surface.positionsMm, surface.triangles);
    EXPECT_FALSE(f.hasErrors());
    EXPECT_EQ(f.boundaryEdges, 0u);
    ASSERT_EQ(changes.size(), 1u);
    EXPECT_NE(changes[0].find("remeshed to 4 mm edges"), std::string::npos) << changes[0];
}

TEST(MeshRemesh, AnOpenSurfaceKeepsItsBorder) {
    const auto box = quadBox(6, 60.0);
    Tris tris = trianglesOf(box);
    Tris open(tris.begin() + 2 * 36, tris.end());
    TriangleSurface surface{box.positions, open};
    std::vector<std::string> changes;
    ASSERT_EQ(remeshIsotropic(surface, {5.0, 3}, {}, changes), "");
    const MeshFaults f = findMeshFaults(surface.positionsMm, surface.triangles);
    EXPECT_EQ(f.holes, 1u);
    EXPECT_FALSE(f.hasErrors());
    // The border stays on the removed side's square (x = -30).
    std::size_t onBorderPlane = 0;
    for (const auto& p : surface.positionsMm) onBorderPlane += std::fabs(p.x + 30.0) < 1e-6 ? 1 : 0;
    EXPECT_GE(onBorderPlane, 4u * 60u / 5u - 4u);
}

TEST(MeshRemesh, ATargetThatWouldMakeTooManyTrianglesIsRefusedBeforeRemeshing) {
    const auto box = quadBox(3, 600.0);
    TriangleSurface surface{box.positions, trianglesOf(box)};
    std::vector<std::string> changes;
    const std::string problem = remeshIsotropic(surface, {0.05, 3}, {}, changes);
    EXPECT_NE(problem.find("choose a longer edge"), std::string::npos) << problem;
    EXPECT_EQ(surface.triangles.size(), trianglesOf(box).size());
    EXPECT_TRUE(changes.empty());
}

TEST(MeshRemesh, CancellingStopsAfterAnIteration) {
    const auto box = quadBox(4, 40.0);
    TriangleSurface surface{box.positions, trianglesOf(box)};
    std::vector<std::string> changes;
    int calls = 0;
    EXPECT_EQ(remeshIsotropic(surface, {3.0, 5}, [&](double) { return ++calls < 2; }, changes), "cancelled");
    EXPECT_EQ(calls, 2);
}

}  // namespace
}  // namespace palpate
