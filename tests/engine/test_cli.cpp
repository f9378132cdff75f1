// palpate-cli's mesh commands, run as a separate process: `mesh check` exit codes and messages,
// `mesh generate` writing exactly the requested vertex count.

#include "engine/core/TissueMesh.h"
#include "tests/engine/TestMeshes.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <random>

namespace palpate {
namespace {

using test::runCommand;
using test::shellQuote;
using test::TempDir;

class Cli : public ::testing::Test {
protected:
    void SetUp() override {
        cli = test::cliPath();
        if (cli.empty()) GTEST_SKIP() << "built without PALPATE_CLI_PATH";
        ASSERT_TRUE(std::filesystem::exists(cli)) << cli;
    }
    test::CommandResult run(const std::string& args) const { return runCommand(shellQuote(cli) + " " + args); }
    std::string cli;
};

TEST_F(Cli, CheckAcceptsAGeneratedMesh) {
    TempDir dir;
    const std::string path = dir.file("sphere mesh.off");  // a space in the path, on purpose
    const auto gen = run("mesh generate --shape sphere --vertices 200 --out " + shellQuote(path));
    ASSERT_EQ(gen.exitCode, 0) << gen.output;
    const auto check = run("mesh check " + shellQuote(path));
    EXPECT_EQ(check.exitCode, 0) << check.output;
    EXPECT_NE(check.output.find(path), std::string::npos) << check.output;
    EXPECT_NE(check.output.find("valid"), std::string::npos) << check.output;
    EXPECT_EQ(check.output.find("INVALID"), std::string::npos) << check.output;
}

TEST_F(Cli, CheckRejectsEveryBadFileKindNamingThePath) {
    TempDir dir;
    const test::RawMesh tet{{{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 0, 10}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
    test::RawMesh nanTet = tet;
    nanTet.positions[1].x = std::numeric_limits<float>::quiet_NaN();
    test::RawMesh tiny = tet;
    for (auto& p : tiny.positions) p *= 1e-9f;
    test::RawMesh degenerate = tet;
    degenerate.positions[3] = {5, 0, 0};
    std::string garbage(500, '\0');
    std::mt19937 rng(8);
    for (char& c : garbage) c = char(rng() & 0xff);
    const std::string validOff = test::toOff(tet);

    std::vector<std::string> paths = {
        dir.write("empty.off", ""),
        dir.write("nan.stl", test::toBinaryStl(nanTet)),
        dir.write("degenerate.off", test::toOff(degenerate)),
        dir.write("bowtie.obj", test::toObj(test::bowtieTetrahedra())),
        dir.write("fin.off", test::toOff(test::threeTrianglesOnEdge())),
        dir.write("truncated.off", validOff.substr(0, validOff.size() / 2)),
        dir.write("truncated.stl", test::toBinaryStl(tet).substr(0, 150)),
        dir.write("garbage.ply", garbage),
        dir.write("garbage.obj", garbage),
        dir.write("tiny.off", test::toOff(tiny)),
        dir.write("mesh.xyz", validOff),
        dir.file("missing.off"),
        dir.path().string(),
    };
    for (const std::string& path : paths) {
        const auto r = run("mesh check " + shellQuote(path));
        EXPECT_NE(r.exitCode, 0) << path << "\n" << r.output;
        EXPECT_LT(r.exitCode, 128) << "crashed on " << path << "\n" << r.output;
        EXPECT_NE(r.output.find(path), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("error"), std::string::npos) << r.output;
    }
    // An open surface is valid (exit 0) but warned about.
    const std::string open = dir.write("open.obj", test::toObj(test::gridPatch(4, 4)));
    const auto r = run("mesh check " + shellQuote(open));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("warning"), std::string::npos) << r.output;
}

TEST_F(Cli, GenerateWritesExactlyNVertices) {
    TempDir dir;
    for (const char* shape : {"sphere", "stomach"}) {
        for (std::size_t n : {8u, 9u, 100u, 1442u, 3970u, 5762u, 8664u}) {
            const std::string path = dir.file(std::string(shape) + "-" + std::to_string(n) + ".off");
            const auto r = run(std::string("mesh generate --shape ") + shape + " --vertices " + std::to_string(n) +
                               " --out " + shellQuote(path));
            ASSERT_EQ(r.exitCode, 0) << r.output;
            const auto loaded = TissueMesh::load(path);
            ASSERT_TRUE(loaded.mesh) << loaded.error();
            EXPECT_EQ(loaded.mesh->vertexCount(), n) << shape;
            EXPECT_EQ(loaded.mesh->triangleCount(), 2 * n - 4) << shape;
            EXPECT_EQ(loaded.report.boundaryEdgeCount, 0u) << shape;
        }
    }
    // Other formats by extension.
    for (const char* ext : {"obj", "ply", "stl"}) {
        const std::string path = dir.file(std::string("s.") + ext);
        ASSERT_EQ(run("mesh generate --shape stomach --vertices 321 --out " + shellQuote(path)).exitCode, 0);
        const auto loaded = TissueMesh::load(path);
        ASSERT_TRUE(loaded.mesh) << loaded.error();
        EXPECT_EQ(loaded.mesh->vertexCount(), 321u) << ext;
    }
}

TEST_F(Cli, GenerateRejectsBadArguments) {
    TempDir dir;
    const std::string out = shellQuote(dir.file("x.off"));
    for (const std::string& args : {"mesh generate --shape cube --vertices 100 --out " + out,
                                   "mesh generate --shape sphere --vertices 7 --out " + out,
                                   "mesh generate --shape sphere --vertices -5 --out " + out,
                                   "mesh generate --shape sphere --vertices abc --out " + out,
                                   std::string("mesh generate --shape sphere --vertices 100"),
                                   std::string("mesh check"), std::string("mesh frobnicate")}) {
        const auto r = run(args);
        EXPECT_NE(r.exitCode, 0) << args << "\n" << r.output;
        EXPECT_LT(r.exitCode, 128) << args;
        EXPECT_FALSE(r.output.empty()) << args;
    }
    EXPECT_FALSE(std::filesystem::exists(dir.file("x.off")));
}

}  // namespace
}  // namespace palpate
