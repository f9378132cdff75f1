// Mesh loading and validation: every bad file gives a clear error that names the file and the
// problem, never a crash; open surfaces load with a warning; inside-out meshes are flipped.
// Ends with a small deterministic fuzz test over mutated OFF, OBJ and binary STL files.

#include "engine/core/MeshGenerator.h"
#include "engine/core/TissueMesh.h"
#include "tests/engine/TestMeshes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace palpate {
namespace {

using test::RawMesh;
using test::TempDir;

std::string allErrors(const MeshReport& r) {
    std::string out;
    for (const auto& e : r.errors) out += "  " + e + "\n";
    return out;
}

/// The load failed with at least one error; every error names `source`; one mentions `problem`
/// (any of the alternatives separated by '|', case-insensitive).
::testing::AssertionResult failsClearly(const TissueMesh::LoadResult& result, const std::string& source,
                                        const std::string& problem) {
    if (result.mesh) return ::testing::AssertionFailure() << source << " loaded, expected an error about " << problem;
    if (result.report.errors.empty()) return ::testing::AssertionFailure() << source << ": no mesh but no error";
    if (result.error() != result.report.errors.front())
        return ::testing::AssertionFailure() << "error() is not the first error";
    for (const auto& e : result.report.errors)
        if (e.find(source) == std::string::npos)
            return ::testing::AssertionFailure() << "error does not name the source '" << source << "': " << e;
    auto lower = [](std::string s) {
        for (char& c : s) c = char(std::tolower((unsigned char)c));
        return s;
    };
    std::size_t start = 0;
    while (start <= problem.size()) {
        const std::size_t bar = problem.find('|', start);
        const std::string alternative = problem.substr(start, bar == std::string::npos ? std::string::npos : bar - start);
        for (const auto& e : result.report.errors)
            if (lower(e).find(lower(alternative)) != std::string::npos) return ::testing::AssertionSuccess();
        if (bar == std::string::npos) break;
        start = bar + 1;
    }
    return ::testing::AssertionFailure() << "no error mentions '" << problem << "':\n" << allErrors(result.report);
}

RawMesh tetrahedron(float scale = 10.0f) {
    RawMesh m;
    m.positions = {{0, 0, 0}, {scale, 0, 0}, {0, scale, 0}, {0, 0, scale}};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}

const RawMesh& smallSphere() {
    static const RawMesh raw = test::rawOf(*generateMesh(GeneratedShape::Sphere, 60).mesh);
    return raw;
}

/// Checks that a loaded mesh is internally consistent (the fuzz test's oracle for "loaded").
::testing::AssertionResult consistent(const TissueMesh& mesh) {
    const std::size_t n = mesh.vertexCount();
    if (n == 0 || mesh.triangleCount() == 0) return ::testing::AssertionFailure() << "empty mesh loaded";
    if (!mesh.report().valid()) return ::testing::AssertionFailure() << "mesh with errors";
    if (mesh.restNormals().size() != n || mesh.originalIndex().size() != n || mesh.neighbourStart().size() != n + 1)
        return ::testing::AssertionFailure() << "array sizes disagree";
    for (VertexId v = 0; v < n; ++v) {
        if (!test::isFinite(mesh.restPositionsMm()[v])) return ::testing::AssertionFailure() << "non-finite position";
        const float len = glm::length(mesh.restNormals()[v]);
        if (!(std::abs(len - 1.0f) < 1e-3f)) return ::testing::AssertionFailure() << "normal not unit: " << len;
    }
    for (const auto& t : mesh.triangles())
        for (VertexId v : t)
            if (v >= n) return ::testing::AssertionFailure() << "triangle index out of range";
    for (VertexId w : mesh.neighbours())
        if (w >= n) return ::testing::AssertionFailure() << "neighbour index out of range";
    return ::testing::AssertionSuccess();
}

// --- Files that are not meshes at all ------------------------------------------------------------

TEST(MeshLoad, EmptyFiles) {
    TempDir dir;
    for (const char* name : {"empty.off", "empty.obj", "empty.ply", "empty.stl", "empty.om"}) {
        const std::string path = dir.write(name, "");
        EXPECT_TRUE(failsClearly(TissueMesh::load(path), path, "empty"));
    }
    // Whitespace only, and a header without data.
    for (auto [name, bytes] : {std::pair{"blank.off", "\n\n   \n"}, std::pair{"blank.obj", "# nothing\n\n"},
                               std::pair{"header.off", "OFF\n0 0 0\n"}}) {
        const std::string path = dir.write(name, bytes);
        EXPECT_TRUE(failsClearly(TissueMesh::load(path), path, "no vertices|no header|no faces|no triangles|empty"));
    }
}

TEST(MeshLoad, MissingPathDirectoryAndUnsupportedExtension) {
    TempDir dir;
    const std::string missing = dir.file("does-not-exist.off");
    EXPECT_TRUE(failsClearly(TissueMesh::load(missing), missing, "no such file"));
    const std::string directory = dir.path().string();
    EXPECT_TRUE(failsClearly(TissueMesh::load(directory), directory, "directory"));
    std::filesystem::create_directory(dir.path() / "looks-like.obj");
    const std::string dirObj = dir.file("looks-like.obj");
    EXPECT_TRUE(failsClearly(TissueMesh::load(dirObj), dirObj, "directory"));
    const std::string offText = test::toOff(tetrahedron());
    for (const char* name : {"mesh.xyz", "mesh", "mesh.off.bak"}) {
        const std::string path = dir.write(name, offText);
        EXPECT_TRUE(failsClearly(TissueMesh::load(path), path, "unsupported extension"));
    }
    // The same bytes with the right extension load: the extension is what was wrong.
    EXPECT_TRUE(TissueMesh::load(dir.write("mesh.off", offText)).mesh);
}

TEST(MeshLoad, BinaryGarbageWithMeshExtensions) {
    TempDir dir;
    std::mt19937 rng(31337);
    for (int size : {1, 7, 83, 84, 200, 4096}) {
        std::string bytes(std::size_t(size), '\0');
        for (char& c : bytes) c = char(rng() & 0xff);
        for (const char* ext : {"obj", "off", "stl", "ply"}) {
            const std::string path = dir.write("garbage" + std::to_string(size) + "." + ext, bytes);
            const auto result = TissueMesh::load(path);
            EXPECT_TRUE(failsClearly(result, path, "")) << ext << " " << size << " bytes";
        }
    }
    // Garbage behind a plausible magic.
    std::string tail(300, '\0');
    for (char& c : tail) c = char(rng() & 0xff);
    for (auto [name, magic] : {std::pair{"g.off", "OFF\n"}, std::pair{"g.ply", "ply\n"}, std::pair{"g.stl", "solid x\n"},
                               std::pair{"g.obj", "v 1 2 3\n"}}) {
        const std::string path = dir.write(name, magic + tail);
        EXPECT_TRUE(failsClearly(TissueMesh::load(path), path, "")) << name;
    }
}

// --- Geometry and topology problems ---------------------------------------------------------------

TEST(MeshValidate, NaNAndInfCoordinates) {
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
    constexpr float kInf = std::numeric_limits<float>::infinity();
    for (float bad : {kNaN, kInf, -kInf}) {
        RawMesh m = tetrahedron();
        m.positions[2].y = bad;
        const auto r = m.build("bad-coords");
        EXPECT_TRUE(failsClearly(r, "bad-coords", "NaN or infinite")) << bad;
        EXPECT_EQ(r.report.nonFiniteVertexCount, 1u);
    }
    TempDir dir;
    // Binary STL carries IEEE floats: NaN and Inf exactly.
    for (float bad : {kNaN, kInf}) {
        RawMesh m = tetrahedron();
        m.positions[1].x = bad;
        const std::string path = dir.write(std::isnan(bad) ? "nan.stl" : "inf.stl", test::toBinaryStl(m));
        EXPECT_TRUE(failsClearly(TissueMesh::load(path), path, "NaN or infinite"));
    }
    // Text formats spelling them out.
    for (const char* word : {"nan", "inf", "-inf", "NaN"}) {
        RawMesh m = tetrahedron();
        std::string off = test::toOff(m);
        const std::string line = "10 0 0\n";
        off.replace(off.find(line), line.size(), std::string(word) + " 0 0\n");
        const std::string offPath = dir.write(std::string("coords-") + word + ".off", off);
        EXPECT_TRUE(failsClearly(TissueMesh::load(offPath), offPath, "NaN or infinite|malformed")) << word;

        std::string obj = test::toObj(m);
        const std::string vline = "v 10 0 0\n";
        obj.replace(obj.find(vline), vline.size(), std::string("v ") + word + " 0 0\n");
        const std::string objPath = dir.write(std::string("coords-") + word + ".obj", obj);
        EXPECT_TRUE(failsClearly(TissueMesh::load(objPath), objPath, "NaN or infinite|malformed")) << word;
    }
}

TEST(MeshValidate, DegenerateFaces) {
    {
        RawMesh m = tetrahedron();
        m.triangles.push_back({0, 0, 1});  // repeated index
        EXPECT_TRUE(failsClearly(m.build("repeated"), "repeated", "degenerate"));
    }
    {
        RawMesh m = tetrahedron();
        m.positions[3] = {5, 0, 0};  // on the edge 0-1: face (0, 1, 3) has zero area
        const auto r = m.build("zero-area");
        EXPECT_TRUE(failsClearly(r, "zero-area", "degenerate"));
        EXPECT_GE(r.report.degenerateTriangleCount, 1u);
    }
    TempDir dir;
    {
        std::string off = test::toOff(tetrahedron());
        off.replace(off.find("4 4 0"), 5, "4 5 0");
        off += "3 0 0 1\n";
        const std::string path = dir.write("repeated.off", off);
        EXPECT_TRUE(failsClearly(TissueMesh::load(path), path, "degenerate"));
    }
    {
        RawMesh m = tetrahedron();
        m.positions[3] = {5, 0, 0};
        for (const std::string name : {"zero-area.off", "zero-area.obj", "zero-area.ply"}) {
            const std::string bytes = name.ends_with("off") ? test::toOff(m)
                                      : name.ends_with("obj") ? test::toObj(m)
                                                              : test::toAsciiPly(m);
            const std::string path = dir.write(name, bytes);
            EXPECT_TRUE(failsClearly(TissueMesh::load(path), path, "degenerate"));
        }
    }
}

TEST(MeshValidate, NonManifoldVertexBowtie) {
    const RawMesh bowtie = test::bowtieTetrahedra();
    const auto facts = test::topologyFacts(bowtie.positions.size(), bowtie.triangles);
    ASSERT_EQ(facts.nonManifoldVertices, 1u);  // the premise: only the shared vertex is bad
    ASSERT_EQ(facts.boundaryEdges + facts.nonManifoldEdges + facts.misorientedEdges, 0u);
    const auto r = bowtie.build("bowtie");
    EXPECT_TRUE(failsClearly(r, "bowtie", "non-manifold"));
    EXPECT_EQ(r.report.nonManifoldVertexCount, 1u);
    TempDir dir;
    for (const char* name : {"bowtie.off", "bowtie.obj"}) {
        const std::string path =
            dir.write(name, std::string(name).ends_with("off") ? test::toOff(bowtie) : test::toObj(bowtie));
        EXPECT_TRUE(failsClearly(TissueMesh::load(path), path, "non-manifold"));
    }
}

TEST(MeshValidate, NonManifoldEdge) {
    const RawMesh fin = test::threeTrianglesOnEdge();
    ASSERT_EQ(test::topologyFacts(fin.positions.size(), fin.triangles).nonManifoldEdges, 1u);
    const auto r = fin.build("three-on-edge");
    EXPECT_TRUE(failsClearly(r, "three-on-edge", "non-manifold"));
    EXPECT_GE(r.report.nonManifoldEdgeCount, 1u);
    TempDir dir;
    for (const char* name : {"fin.off", "fin.obj"}) {
        const std::string path =
            dir.write(name, std::string(name).ends_with("off") ? test::toOff(fin) : test::toObj(fin));
        EXPECT_TRUE(failsClearly(TissueMesh::load(path), path, "non-manifold"));
    }
}

TEST(MeshValidate, IndicesOutOfRange) {
    RawMesh m = tetrahedron();
    m.triangles.push_back({0, 1, 17});
    EXPECT_TRUE(failsClearly(m.build("bad-index"), "bad-index", "do not exist"));
    TempDir dir;
    std::string off = test::toOff(tetrahedron());
    off.replace(off.find("4 4 0"), 5, "4 5 0");
    off += "3 0 1 17\n";
    const std::string path = dir.write("bad-index.off", off);
    EXPECT_TRUE(failsClearly(TissueMesh::load(path), path, "do not exist|invalid|corrupt"));
}

TEST(MeshValidate, AbsurdSizes) {
    TempDir dir;
    for (float scale : {1e-9f, 1e-6f, 1e7f, 1e9f}) {
        const RawMesh m = tetrahedron(scale);
        const std::string name = "scale-" + std::to_string(scale);
        EXPECT_TRUE(failsClearly(m.build(name), name, "absurd size")) << scale;
        const std::string path = dir.write(name + ".off", test::toOff(m));
        EXPECT_TRUE(failsClearly(TissueMesh::load(path), path, "absurd size")) << scale;
    }
    // Sane sizes across the range load (a 10 micrometre to 10 metre model).
    for (float scale : {0.01f, 1.0f, 1000.0f, 10000.0f}) {
        const auto r = tetrahedron(scale).build("ok");
        EXPECT_TRUE(r.mesh) << scale << ": " << r.error();
    }
}

TEST(MeshValidate, OpenSurfaceLoadsWithAWarning) {
    const RawMesh grid = test::gridPatch(5, 4, 3.0f);
    const auto r = grid.build("grid");
    ASSERT_TRUE(r.mesh) << r.error();
    EXPECT_TRUE(r.report.valid());
    EXPECT_EQ(r.report.boundaryEdgeCount, std::size_t(2 * 4 + 2 * 3));
    ASSERT_FALSE(r.report.warnings.empty());
    EXPECT_NE(r.report.warnings.front().find("open surface"), std::string::npos) << r.report.warnings.front();
    EXPECT_NE(r.report.warnings.front().find("grid"), std::string::npos);
    // Normals of the flat patch are +z (its triangles are counter-clockwise seen from +z).
    for (const glm::vec3& n : r.mesh->restNormals()) EXPECT_GT(n.z, 0.999f);
    TempDir dir;
    const std::string path = dir.write("grid.obj", test::toObj(grid));
    const auto f = TissueMesh::load(path);
    ASSERT_TRUE(f.mesh) << f.error();
    ASSERT_FALSE(f.report.warnings.empty());
    EXPECT_NE(f.report.warnings.front().find(path), std::string::npos);
}

TEST(MeshValidate, InwardFacingClosedMeshesAreFlipped) {
    for (const RawMesh& outward : {test::icosahedron(10.0f), test::tower(), smallSphere()}) {
        ASSERT_GT(test::signedVolume6(outward.positions, outward.triangles), 0.0);  // premise
        const RawMesh inward = outward.flipped();
        for (int viaFile = 0; viaFile < 2; ++viaFile) {
            TempDir dir;
            const auto r = viaFile ? TissueMesh::load(dir.write("inward.off", test::toOff(inward)))
                                   : inward.build("inward");
            ASSERT_TRUE(r.mesh) << r.error();
            const TissueMesh& mesh = *r.mesh;
            bool warned = false;
            for (const auto& w : r.report.warnings) warned = warned || w.find("flipped") != std::string::npos;
            EXPECT_TRUE(warned);
            EXPECT_GT(test::signedVolume6(mesh.restPositionsMm(), mesh.triangles()), 0.0);
            glm::dvec3 centroid(0.0);
            for (const auto& p : mesh.restPositionsMm()) centroid += glm::dvec3(p);
            centroid /= double(mesh.vertexCount());
            for (VertexId v = 0; v < mesh.vertexCount(); ++v)
                EXPECT_GT(glm::dot(glm::dvec3(mesh.restNormals()[v]), glm::dvec3(mesh.restPositionsMm()[v]) - centroid),
                          0.0)
                    << "vertex " << v;
        }
        // Outward meshes are left alone.
        const auto r = outward.build("outward");
        ASSERT_TRUE(r.mesh);
        EXPECT_TRUE(r.report.warnings.empty());
    }
}

TEST(MeshLoad, RoundTripInEveryFormat) {
    auto generated = generateMesh(GeneratedShape::Stomach, 300);
    ASSERT_TRUE(generated.mesh) << generated.error();
    const RawMesh raw = test::rawOf(*generated.mesh);
    TempDir dir;
    const std::pair<const char*, std::string> files[] = {
        {"m.off", test::toOff(raw)},         {"m.obj", test::toObj(raw)},          {"m.ply", test::toAsciiPly(raw)},
        {"mb.ply", test::toBinaryPly(raw)},  {"mb.stl", test::toBinaryStl(raw)},   {"ma.stl", test::toAsciiStl(raw)},
    };
    for (const auto& [name, bytes] : files) {
        const std::string path = dir.write(name, bytes);
        const auto r = TissueMesh::load(path);
        ASSERT_TRUE(r.mesh) << name << ": " << r.error();
        EXPECT_EQ(r.mesh->vertexCount(), 300u) << name;
        EXPECT_EQ(r.mesh->triangleCount(), 596u) << name;
        EXPECT_EQ(r.report.boundaryEdgeCount, 0u) << name;
        EXPECT_TRUE(consistent(*r.mesh)) << name;
    }
    for (const char* name : {"s.off", "s.obj", "s.ply", "s.stl"}) {
        const std::string path = dir.file(name);
        ASSERT_EQ(generated.mesh->save(path), "") << name;
        const auto r = TissueMesh::load(path);
        ASSERT_TRUE(r.mesh) << name << ": " << r.error();
        EXPECT_EQ(r.mesh->vertexCount(), 300u) << name;
        EXPECT_EQ(r.mesh->triangleCount(), 596u) << name;
    }
}

// --- Truncation -----------------------------------------------------------------------------------

struct Format {
    std::string name;
    std::string bytes;
    std::size_t bodyStart;      ///< first byte after the header
    std::size_t lastRecordStart;  ///< a cut before this removes at least one whole record
    bool mustSayTruncated;
};

std::size_t lastLineStart(const std::string& text) {
    std::size_t end = text.size();
    while (end > 0 && text[end - 1] == '\n') --end;
    const std::size_t nl = text.rfind('\n', end - 1);
    return nl == std::string::npos ? 0 : nl + 1;
}

TEST(MeshLoad, TruncatedFilesNeverCrash) {
    const RawMesh& raw = smallSphere();
    std::vector<Format> formats;
    {
        const std::string off = test::toOff(raw);
        const std::size_t body = off.find('\n', off.find('\n') + 1) + 1;  // after "OFF" and the counts
        formats.push_back({"off", off, body, lastLineStart(off), true});
    }
    {
        const std::string ply = test::toAsciiPly(raw);
        formats.push_back({"ply", ply, ply.find("end_header\n") + 11, lastLineStart(ply), true});
    }
    {
        const std::string ply = test::toBinaryPly(raw);
        formats.push_back({"ply", ply, ply.find("end_header\n") + 11, ply.size(), true});
    }
    {
        const std::string stl = test::toBinaryStl(raw);
        formats.push_back({"stl", stl, 84, stl.size(), true});
    }
    {
        const std::string stl = test::toAsciiStl(raw);
        formats.push_back({"stl", stl, 0, stl.size(), false});
    }
    {
        const std::string obj = test::toObj(raw);
        formats.push_back({"obj", obj, 0, obj.size(), false});
    }
    TempDir dir;
    int cuts = 0, truncatedErrors = 0;
    for (std::size_t f = 0; f < formats.size(); ++f) {
        const Format& format = formats[f];
        const std::size_t size = format.bytes.size();
        std::vector<std::size_t> offsets = {1, 2, 3, 5, 10, 20, 40, 80, 83, 84, 85, 100, 134, size - 1, size - 2,
                                            size - 10, size - 51, size - 60};
        for (int k = 1; k < 20; ++k) offsets.push_back(size * std::size_t(k) / 20);
        for (std::size_t k = 0; k < 8; ++k) offsets.push_back(format.bodyStart + k * 7);
        for (std::size_t cut : offsets) {
            if (cut == 0 || cut >= size) continue;
            const std::string path =
                dir.write("cut" + std::to_string(f) + "-" + std::to_string(cut) + "." + format.name,
                          format.bytes.substr(0, cut));
            const auto r = TissueMesh::load(path);
            ++cuts;
            if (r.mesh) {
                EXPECT_TRUE(consistent(*r.mesh)) << path;
            } else {
                EXPECT_TRUE(failsClearly(r, path, "")) << path;
            }
            if (format.mustSayTruncated && cut >= format.bodyStart && cut < format.lastRecordStart) {
                EXPECT_TRUE(failsClearly(r, path, "truncated")) << "cut at byte " << cut << " of " << size;
                ++truncatedErrors;
            }
        }
    }
    EXPECT_GT(cuts, 200);
    EXPECT_GT(truncatedErrors, 80);
}

// --- Fuzz ---------------------------------------------------------------------------------------

std::string mutate(std::string bytes, std::mt19937& rng) {
    const int operations = 1 + int(rng() % 4);
    for (int op = 0; op < operations; ++op) {
        const std::size_t size = bytes.size();
        const std::size_t at = size ? rng() % size : 0;
        switch (rng() % 6) {
            case 0:  // flip a bit
                if (size) bytes[at] = char(bytes[at] ^ char(1u << (rng() % 8)));
                break;
            case 1:  // replace a byte (often with something meaningful to a parser)
                if (size) {
                    static const char special[] = "0123456789-.eE \n#/fvOFFnaif\0\xff";
                    bytes[at] = (rng() % 2) ? char(rng() & 0xff) : special[rng() % (sizeof(special) - 1)];
                }
                break;
            case 2:  // truncate
                bytes.resize(at);
                break;
            case 3: {  // insert random bytes
                std::string insert(1 + rng() % 16, '\0');
                for (char& c : insert) c = char(rng() & 0xff);
                bytes.insert(at, insert);
                break;
            }
            case 4: {  // delete a range
                const std::size_t n = std::min<std::size_t>(1 + rng() % 32, size - at);
                bytes.erase(at, n);
                break;
            }
            default: {  // duplicate a range
                const std::size_t n = std::min<std::size_t>(1 + rng() % 64, size - at);
                bytes.insert(at, bytes.substr(at, n));
                break;
            }
        }
    }
    return bytes;
}

TEST(MeshFuzz, MutatedFilesNeverCrash) {
    const auto started = std::chrono::steady_clock::now();
    const RawMesh& raw = smallSphere();
    const std::pair<std::string, std::string> seeds[] = {
        {"off", test::toOff(raw)}, {"obj", test::toObj(raw)}, {"stl", test::toBinaryStl(raw)}};
    TempDir dir;
    std::mt19937 rng(0xC0FFEE);
    int loaded = 0, rejected = 0;
    for (const auto& [ext, bytes] : seeds) {
        // The seed itself is valid.
        ASSERT_TRUE(TissueMesh::load(dir.write("seed." + ext, bytes)).mesh) << ext;
        for (int i = 0; i < 300; ++i) {
            const std::string path = dir.write("fuzz" + std::to_string(i) + "." + ext, mutate(bytes, rng));
            const auto r = TissueMesh::load(path);
            if (r.mesh) {
                ++loaded;
                EXPECT_TRUE(consistent(*r.mesh)) << path;
                EXPECT_EQ(r.report.vertexCount, r.mesh->vertexCount());
            } else {
                ++rejected;
                EXPECT_TRUE(failsClearly(r, path, "")) << path;
            }
            std::filesystem::remove(path);
        }
    }
    EXPECT_GT(rejected, 0);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    RecordProperty("seconds", std::to_string(seconds));
    std::printf("fuzz: %d loaded, %d rejected, %.2f s\n", loaded, rejected, seconds);
}

}  // namespace
}  // namespace palpate
