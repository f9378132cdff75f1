// Importing a mesh made by another tool, through the API and end to end through palpate-cli: a
// cm-scaled, mis-oriented quad OBJ with a hole, imported, repaired, remeshed, pressed in `demo`,
// calibrated and planned (docs/meshes.md).

#include "engine/core/MeshFaults.h"
#include "engine/core/TissueMesh.h"
#include "engine/meshimport/MeshImport.h"
#include "tests/engine/TestMeshes.h"
#include "tests/meshimport/ImportMeshes.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>

#include <filesystem>
#include <set>
#include <sstream>

namespace palpate {
namespace {

using test::TempDir;

/// An 8 x 8 x 8 unit box (80 mm in cm) of 10 x 10 quads a side, as a sculpting tool writes it:
/// texture and normal indices, groups, CR LF line ends and a trailing NUL; every 17th quad wound
/// the wrong way and two neighbouring quads missing (a hole of 6 edges).
struct FaultyObj {
    std::string text;
    std::size_t flippedQuads = 0;
    std::size_t quads = 0;
};

FaultyObj faultyCmObj() {
    test::QuadBox box = test::quadBox(10, 8.0);
    FaultyObj out;
    test::QuadBox written;
    written.positions = box.positions;
    for (std::size_t q = 0; q < box.quads.size(); ++q) {
        if (q == 250 || q == 251) continue;
        auto quad = box.quads[q];
        if (q % 17 == 0) {
            std::reverse(quad.begin(), quad.end());
            ++out.flippedQuads;
        }
        written.quads.push_back(quad);
    }
    out.quads = written.quads.size();
    std::string text = "mtllib organ.mtl\ng organ\n" + test::objText(written, 1.0, true);
    std::string crlf;
    for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    out.text = crlf + '\0';
    return out;
}

TEST(MeshImport, AFaultyCmObjIsScaledRepairedRemeshedAndItsRingsGetRounder) {
    TempDir dir;
    const FaultyObj obj = faultyCmObj();
    const std::string path = dir.write("organ.obj", obj.text);

    // As read in mm it is 8 mm across: the import suggests cm and says why.
    const MeshImportResult asMm = importMesh(path, {});
    ASSERT_TRUE(asMm.suggestion);
    EXPECT_EQ(asMm.suggestion->unit.text(), "cm");
    EXPECT_FALSE(asMm.ok());  // faults, and no repair asked for
    EXPECT_EQ(asMm.faults.nonManifoldEdges, 0u);
    EXPECT_GT(asMm.faults.misorientedEdges, 0u);
    EXPECT_EQ(asMm.faults.holes, 1u);

    MeshImportDef def;
    def.unit = MeshUnit{"cm", 10.0};
    def.repair = true;
    def.remeshEdgeMm = 4.0;
    std::vector<std::string> stages;
    const MeshImportResult r = importMesh(path, def, [&](double, const std::string& stage) {
        if (stages.empty() || stages.back() != stage) stages.push_back(stage);
        return true;
    });
    ASSERT_TRUE(r.ok()) << r.text();
    EXPECT_FALSE(r.suggestion);
    EXPECT_NEAR(r.sizeMm.x, 80.0, 1e-3);
    EXPECT_EQ(r.sourcePolygons, obj.quads);
    // Every tolerated thing is noted.
    const std::string text = r.text();
    for (const char* note : {"trailing NUL", "line ends", "quads triangulated", "texture and normal indices"})
        EXPECT_NE(text.find(note), std::string::npos) << note << "\n" << text;
    // Every change is reported: the wrong quads' triangles reversed, the hole filled, the remeshing.
    const std::string reversed = "reversed " + std::to_string(obj.flippedQuads) + " faces";
    bool sawReversed = false, sawHole = false, sawRemesh = false;
    for (const std::string& c : r.changes) {
        sawReversed |= c.find(reversed) != std::string::npos;
        sawHole |= c.find("filled a hole of 6 edges") != std::string::npos;
        sawRemesh |= c.find("remeshed to 4 mm edges") != std::string::npos;
    }
    EXPECT_TRUE(sawReversed) << text;
    EXPECT_TRUE(sawHole) << text;
    EXPECT_TRUE(sawRemesh) << text;
    // The result: closed, no faults, in mm, edges near the target, rounder rings.
    const MeshFaults after = findMeshFaults(std::vector<glm::dvec3>(r.mesh->restPositionsMm().begin(), r.mesh->restPositionsMm().end()),
                                            r.mesh->triangles());
    EXPECT_FALSE(after.hasErrors());
    EXPECT_EQ(after.boundaryEdges, 0u);
    EXPECT_NEAR(r.mesh->boundsMaxMm().x - r.mesh->boundsMinMm().x, 80.0, 0.5);
    ASSERT_TRUE(r.roundnessBefore && r.roundnessAfter);
    EXPECT_TRUE(r.roundnessBeforeIsRepaired);
    EXPECT_LT(r.roundnessAfter->edgeLengthCv, r.roundnessBefore->edgeLengthCv);
    EXPECT_LT(r.roundnessAfter->worstRingCv(), r.roundnessBefore->worstRingCv());
    EXPECT_NEAR(r.roundnessAfter->meanEdgeMm, 4.0, 1.0);
    EXPECT_EQ(stages.front(), "reading");
    EXPECT_NE(std::find(stages.begin(), stages.end(), "remeshing"), stages.end());
}

TEST(MeshImport, CancellingEndsWithoutAMesh) {
    TempDir dir;
    const std::string path = dir.write("organ.obj", faultyCmObj().text);
    MeshImportDef def;
    def.unit = MeshUnit{"cm", 10.0};
    def.repair = true;
    def.remeshEdgeMm = 4.0;
    const MeshImportResult r = importMesh(path, def, [](double, const std::string& stage) { return stage != "remeshing"; });
    EXPECT_FALSE(r.ok());
    ASSERT_FALSE(r.errors.empty());
    EXPECT_NE(r.errors.front().find("cancelled"), std::string::npos);
}

TEST(MeshImport, BadOptionsAndUnreadableFilesAreErrorsNamingThem) {
    TempDir dir;
    const std::string path = dir.write("organ.obj", faultyCmObj().text);
    MeshImportDef def;
    def.remeshEdgeMm = 0.001;
    MeshImportResult r = importMesh(path, def);
    ASSERT_FALSE(r.errors.empty());
    EXPECT_NE(r.errors.front().find("remeshing edge length"), std::string::npos) << r.errors.front();
    r = importMesh(dir.file("missing.obj"), {});
    ASSERT_FALSE(r.errors.empty());
    EXPECT_NE(r.errors.front().find("missing.obj"), std::string::npos);
    r = importMesh(dir.write("junk.obj", "v 1 2\nf 1 2 3\n"), {});
    EXPECT_FALSE(r.ok());
    ASSERT_FALSE(r.errors.empty());
    EXPECT_NE(r.errors.front().find("junk.obj"), std::string::npos);
}

// ---- end to end through palpate-cli ----

class MeshImportCli : public ::testing::Test {
protected:
    void SetUp() override {
        cli = test::cliPath();
        if (cli.empty()) GTEST_SKIP() << "built without PALPATE_CLI_PATH";
    }
    test::CommandResult run(const std::string& args) const {
        return test::runCommand(test::shellQuote(cli) + " " + args);
    }
    std::string cli;
};

TEST_F(MeshImportCli, ACmMisorientedQuadObjWithAHoleIsImportedPressedCalibratedAndPlanned) {
    TempDir dir;
    const std::string in = dir.write("organ.obj", faultyCmObj().text);
    const std::string out = dir.file("organ.off");
    const std::string q = test::shellQuote(in), o = test::shellQuote(out);

    // mesh check names the real faults and suggests the unit.
    const auto check = run("mesh check " + q);
    EXPECT_EQ(check.exitCode, 1) << check.output;
    EXPECT_NE(check.output.find("inconsistently oriented"), std::string::npos) << check.output;
    EXPECT_EQ(check.output.find("non-manifold: "), std::string::npos) << check.output;
    EXPECT_NE(check.output.find("1 hole"), std::string::npos) << check.output;
    EXPECT_NE(check.output.find("--unit cm"), std::string::npos) << check.output;

    // Without --repair the import refuses, naming the faults, and writes nothing.
    const auto refused = run("mesh import " + q + " --out " + o + " --unit cm");
    EXPECT_EQ(refused.exitCode, 1) << refused.output;
    EXPECT_NE(refused.output.find("--repair"), std::string::npos) << refused.output;
    EXPECT_FALSE(std::filesystem::exists(out));

    const std::string before = test::readFile(in);
    const auto imported = run("mesh import " + q + " --out " + o + " --unit cm --repair --remesh-edge-mm 4 --json");
    ASSERT_EQ(imported.exitCode, 0) << imported.output;
    const auto j = nlohmann::json::parse(imported.output.substr(imported.output.find('{')));
    EXPECT_TRUE(j["written"].get<bool>());
    EXPECT_EQ(j["unit"], "cm");
    EXPECT_LT(j["roundness_after"]["edge_length_cv"].get<double>(), j["roundness_before"]["edge_length_cv"].get<double>());
    EXPECT_EQ(test::readFile(in), before);  // the input is untouched

    // The output is a valid mm mesh of the right size.
    const auto loaded = TissueMesh::load(out);
    ASSERT_TRUE(loaded.mesh) << loaded.error();
    EXPECT_NEAR(loaded.report.sizeMm.x, 80.0, 0.5);
    EXPECT_EQ(loaded.report.boundaryEdgeCount, 0u);

    // An existing output is not replaced without --overwrite; the input is never the output.
    EXPECT_EQ(run("mesh import " + q + " --out " + o + " --unit cm --repair").exitCode, 2);
    EXPECT_EQ(run("mesh import " + q + " --out " + q + " --unit cm --repair --overwrite").exitCode, 2);
    EXPECT_EQ(test::readFile(in), before);

    // Pressed in demo, calibrated, and planned for.
    const auto demo = run("demo --mesh " + o + " --json");
    ASSERT_EQ(demo.exitCode, 0) << demo.output;
    const auto d = nlohmann::json::parse(demo.output.substr(demo.output.find('{')));
    EXPECT_GT(d["contact_ticks"].get<long long>(), 0) << demo.output;
    const auto calibrate = run("calibrate --mesh " + o + " --json");
    ASSERT_EQ(calibrate.exitCode, 0) << calibrate.output;
    const auto c = nlohmann::json::parse(calibrate.output.substr(calibrate.output.find('{')));
    EXPECT_GT(c["spring_stiffness_n_per_mm"].get<double>(), 0.0) << calibrate.output;
    const auto plan = run("lod plan --mesh " + o + " --error 10 --budget-us 500 --quick --json");
    EXPECT_EQ(plan.exitCode, 0) << plan.output;
}

}  // namespace
}  // namespace palpate
