// Reading meshes made by other tools (docs/meshes.md, "Reading"): what the polygon-soup reader
// tolerates (trailing NULs, line ends, OBJ corner syntax and records, polygons), that every format
// gives the file's real polygons, and that TissueMesh::load then names each fault exactly instead
// of a reader's side effect of it. The files are generated here, from hand-written coordinates.

#include "engine/core/MeshHash.h"
#include "engine/core/PolygonSoup.h"
#include "engine/core/TissueMesh.h"
#include "tests/engine/TestMeshes.h"

#include <gtest/gtest.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace palpate {
namespace {

using test::RawMesh;
using test::TempDir;

bool anyContains(const std::vector<std::string>& lines, const std::string& what) {
    return std::any_of(lines.begin(), lines.end(),
                       [&](const std::string& l) { return l.find(what) != std::string::npos; });
}

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const auto& l : lines) out += "  " + l + "\n";
    return out;
}

/// A unit cube of side 10 as six outward quads; vertex x + 2y + 4z is at (x, y, z) * 10.
struct Quads {
    std::vector<glm::dvec3> points;
    std::vector<std::vector<std::uint32_t>> faces;
};
Quads cube() {
    Quads c;
    for (int i = 0; i < 8; ++i) c.points.push_back(glm::dvec3(i & 1, (i >> 1) & 1, (i >> 2) & 1) * 10.0);
    c.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    return c;
}

std::string cubeObj() {
    const Quads c = cube();
    std::ostringstream s;
    for (const auto& p : c.points) s << "v " << p.x << " " << p.y << " " << p.z << "\n";
    for (const auto& f : c.faces)
        s << "f " << f[0] + 1 << " " << f[1] + 1 << " " << f[2] + 1 << " " << f[3] + 1 << "\n";
    return s.str();
}

/// The cube's triangles (each quad split along its first diagonal), for the formats without quads.
RawMesh cubeTriangles() {
    const Quads c = cube();
    RawMesh m;
    for (const auto& p : c.points) m.positions.push_back(glm::vec3(p));
    for (const auto& f : c.faces) {
        m.triangles.push_back({f[0], f[1], f[2]});
        m.triangles.push_back({f[0], f[2], f[3]});
    }
    return m;
}

std::string lines(const std::string& text, const std::vector<std::string>& ends) {
    std::string out;
    std::size_t start = 0, k = 0;
    for (std::size_t nl = text.find('\n'); nl != std::string::npos; nl = text.find('\n', start)) {
        out += text.substr(start, nl - start) + ends[k++ % ends.size()];
        start = nl + 1;
    }
    return out;
}

TissueMesh::LoadResult loadText(const TempDir& dir, const std::string& name, const std::string& bytes) {
    return TissueMesh::load(dir.write(name, bytes));
}

// --- Tolerated bytes --------------------------------------------------------------------------

TEST(MeshReading, ObjWithATrailingNulLoadsWithANote) {
    TempDir dir;
    const RawMesh oct = test::octahedron();
    const auto plain = loadText(dir, "plain.obj", test::toObj(oct));
    ASSERT_TRUE(plain.mesh) << plain.error();
    const auto padded = loadText(dir, "padded.obj", test::toObj(oct) + std::string(1, '\0'));
    ASSERT_TRUE(padded.mesh) << padded.error();
    EXPECT_EQ(meshHash(*padded.mesh), meshHash(*plain.mesh));
    EXPECT_TRUE(anyContains(padded.report.notes, "1 trailing NUL byte")) << joined(padded.report.notes);
    EXPECT_NE(padded.report.text().find("note: 1 trailing NUL byte"), std::string::npos) << padded.report.text();

    // A NUL inside the text is still binary data.
    std::string inner = test::toObj(oct);
    inner[inner.find("\nf ") + 1] = '\0';
    const auto corrupt = loadText(dir, "inner-nul.obj", inner);
    EXPECT_FALSE(corrupt.mesh);
    EXPECT_NE(corrupt.error().find("binary data"), std::string::npos) << corrupt.error();
}

TEST(MeshReading, MixedLineEndsAndTabsLoadTheSameMesh) {
    TempDir dir;
    const RawMesh ico = test::icosahedron();
    const auto plain = loadText(dir, "plain.obj", test::toObj(ico));
    ASSERT_TRUE(plain.mesh) << plain.error();
    std::string mixed = lines(test::toObj(ico), {"\r\n", "\n", "\r"});
    std::replace(mixed.begin(), mixed.end(), ' ', '\t');
    const auto r = loadText(dir, "mixed.obj", mixed);
    ASSERT_TRUE(r.mesh) << r.error();
    EXPECT_EQ(meshHash(*r.mesh), meshHash(*plain.mesh));
    EXPECT_TRUE(anyContains(r.report.notes, "mixed line ends (CR LF, LF and CR)")) << joined(r.report.notes);
    EXPECT_TRUE(anyContains(r.report.notes, "read as spaces")) << joined(r.report.notes);

    const auto crOnly = loadText(dir, "cr.off", lines(test::toOff(ico), {"\r"}));
    ASSERT_TRUE(crOnly.mesh) << crOnly.error();
    EXPECT_EQ(meshHash(*crOnly.mesh), meshHash(*plain.mesh));
    EXPECT_TRUE(anyContains(crOnly.report.notes, "CR line ends")) << joined(crOnly.report.notes);

    const auto bom = loadText(dir, "bom.obj", "\xEF\xBB\xBF" + test::toObj(ico));
    ASSERT_TRUE(bom.mesh) << bom.error();
    EXPECT_TRUE(anyContains(bom.report.notes, "byte-order mark")) << joined(bom.report.notes);
}

TEST(MeshReading, ObjCornerSyntaxAndNegativeIndicesGiveTheSameMesh) {
    TempDir dir;
    const RawMesh oct = test::octahedron();
    const auto plain = loadText(dir, "plain.obj", test::toObj(oct));
    ASSERT_TRUE(plain.mesh) << plain.error();

    // Each face written after its own copy of nothing: the vertices first, then faces in three
    // corner styles, every third face with relative indices (-1 is the last vertex so far).
    std::ostringstream s;
    s << std::setprecision(9);
    for (const auto& p : oct.positions) s << "v " << p.x << " " << p.y << " " << p.z << "\n";
    s << "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n";
    const int n = int(oct.positions.size());
    for (std::size_t f = 0; f < oct.triangles.size(); ++f) {
        s << "f";
        for (VertexId v : oct.triangles[f]) {
            const int index = f % 3 == 2 ? int(v) - n : int(v) + 1;
            if (f % 3 == 0) s << " " << index << "/1/1";
            else if (f % 3 == 1) s << " " << index << "//1";
            else s << " " << index << "/2";
        }
        s << "\n";
    }
    const auto r = loadText(dir, "corners.obj", s.str());
    ASSERT_TRUE(r.mesh) << r.error();
    EXPECT_EQ(meshHash(*r.mesh), meshHash(*plain.mesh));
    EXPECT_TRUE(anyContains(r.report.notes, "negative (relative)")) << joined(r.report.notes);
    EXPECT_TRUE(anyContains(r.report.notes, "texture and normal indices")) << joined(r.report.notes);
}

TEST(MeshReading, ObjGroupsMaterialsCommentsAndPolylinesAreIgnoredWithNotes) {
    TempDir dir;
    const RawMesh oct = test::octahedron();
    const auto plain = loadText(dir, "plain.obj", test::toObj(oct));
    ASSERT_TRUE(plain.mesh) << plain.error();
    std::ostringstream s;
    s << std::setprecision(9) << "# made by another tool\nmtllib organ.mtl\no liver\n";
    for (const auto& p : oct.positions) s << "v " << p.x << " " << p.y << " " << p.z << "\n";
    s << "g lobe\nusemtl tissue\ns 1\n";
    for (const auto& t : oct.triangles) s << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "  # a face\n";
    s << "l 1 2 3\np 4\ns off\n";
    const auto r = loadText(dir, "groups.obj", s.str());
    ASSERT_TRUE(r.mesh) << r.error();
    EXPECT_EQ(meshHash(*r.mesh), meshHash(*plain.mesh));
    EXPECT_TRUE(anyContains(r.report.notes, "material records ignored")) << joined(r.report.notes);
    EXPECT_TRUE(anyContains(r.report.notes, "2 polyline and point records ignored")) << joined(r.report.notes);
    EXPECT_TRUE(anyContains(r.report.notes, "comment")) << joined(r.report.notes);
}

TEST(MeshReading, ObjErrorsNameTheLine) {
    TempDir dir;
    const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    const auto beyond = loadText(dir, "beyond.obj", v + "# comment\nf 1 2 3\nf 1 2 40\n");
    EXPECT_FALSE(beyond.mesh);
    EXPECT_NE(beyond.error().find("line 6: a face refers to vertex 40, but the file has 3"), std::string::npos)
        << beyond.error();
    const auto relative = loadText(dir, "relative.obj", v + "f -1 -2 -4\n");
    EXPECT_NE(relative.error().find("line 4:"), std::string::npos) << relative.error();
    const auto zero = loadText(dir, "zero.obj", v + "f 0 1 2\n");
    EXPECT_NE(zero.error().find("line 4: a face refers to vertex 0"), std::string::npos) << zero.error();
}

// --- Polygons ---------------------------------------------------------------------------------

TEST(MeshReading, QuadsAreTriangulatedIntoAClosedMesh) {
    TempDir dir;
    const auto r = loadText(dir, "cube.obj", cubeObj());
    ASSERT_TRUE(r.mesh) << r.error();
    EXPECT_EQ(r.mesh->triangleCount(), 12u);
    EXPECT_EQ(r.report.boundaryEdgeCount, 0u);
    EXPECT_EQ(r.report.misorientedEdgeCount, 0u);
    EXPECT_TRUE(anyContains(r.report.notes, "6 quads triangulated")) << joined(r.report.notes);
}

TEST(MeshReading, AConcavePentagonIsCoveredExactlyWithoutFlippedTriangles) {
    // In the plane z = x (tilted), an arrow shape whose reflex corner (index 3) is not the first:
    // a fan from corner 0 would fold triangle (0, 2, 3) over.
    const std::vector<glm::dvec2> flat = {{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}};
    PolygonSoup soup;
    for (const auto& p : flat) soup.points.push_back({p.x, p.y, p.x});
    soup.polygons = {{0, 1, 2, 3, 4}};
    std::vector<std::string> notes;
    const auto triangles = triangulatePolygons(soup, notes);
    ASSERT_EQ(triangles.size(), 3u);
    double shoelace = 0.0;
    for (std::size_t i = 0; i < flat.size(); ++i)
        shoelace += flat[i].x * flat[(i + 1) % flat.size()].y - flat[(i + 1) % flat.size()].x * flat[i].y;
    const double polygonArea = 0.5 * shoelace * std::sqrt(2.0);  // the tilt stretches x by sqrt(2)
    const glm::dvec3 polygonNormal = glm::normalize(glm::dvec3(-1, 0, 1));
    double area = 0.0;
    for (const auto& t : triangles) {
        const glm::dvec3 n = glm::cross(soup.points[t[1]] - soup.points[t[0]], soup.points[t[2]] - soup.points[t[0]]);
        EXPECT_GT(glm::dot(n, polygonNormal), 0.0) << "flipped triangle " << t[0] << " " << t[1] << " " << t[2];
        area += 0.5 * glm::length(n);
    }
    EXPECT_NEAR(area, polygonArea, 1e-9 * polygonArea);
    EXPECT_TRUE(anyContains(notes, "1 polygon of more than 4 corners triangulated")) << joined(notes);
}

TEST(MeshReading, PolygonsOfFewerThanThreeCornersAreDroppedWithANote) {
    PolygonSoup soup;
    soup.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    soup.polygons = {{0, 1, 2}, {0, 1}, {2}};
    std::vector<std::string> notes;
    EXPECT_EQ(triangulatePolygons(soup, notes).size(), 1u);
    EXPECT_TRUE(anyContains(notes, "2 polygons of fewer than 3 corners dropped")) << joined(notes);
}

// --- Every format gives the file's polygons ---------------------------------------------------

void expectSoupIs(const PolygonSoup& soup, const RawMesh& raw, const std::string& what) {
    ASSERT_EQ(soup.points.size(), raw.positions.size()) << what;
    for (std::size_t v = 0; v < raw.positions.size(); ++v)
        EXPECT_EQ(glm::vec3(soup.points[v]), raw.positions[v]) << what << " vertex " << v;
    ASSERT_EQ(soup.polygons.size(), raw.triangles.size()) << what;
    for (std::size_t f = 0; f < raw.triangles.size(); ++f)
        EXPECT_EQ(soup.polygons[f], std::vector<std::uint32_t>(raw.triangles[f].begin(), raw.triangles[f].end()))
            << what << " face " << f;
}

TEST(MeshReading, OffAndPlyGiveTheFilesPolygons) {
    const RawMesh ico = test::icosahedron();
    for (const auto& [name, bytes, ext] :
         std::vector<std::tuple<std::string, std::string, std::string>>{{"OFF", test::toOff(ico), "off"},
                                                                        {"ASCII PLY", test::toAsciiPly(ico), "ply"},
                                                                        {"binary PLY", test::toBinaryPly(ico), "ply"},
                                                                        {"OBJ", test::toObj(ico), "obj"}}) {
        PolygonSoup soup;
        ASSERT_EQ(readPolygonSoupBytes(bytes, ext, soup), "") << name;
        expectSoupIs(soup, ico, name);
    }
}

TEST(MeshReading, BinaryAndAsciiStlOfTheSameCubeGiveTheSameSoup) {
    const RawMesh c = cubeTriangles();
    PolygonSoup binary, ascii;
    ASSERT_EQ(readPolygonSoupBytes(test::toBinaryStl(c), "stl", binary), "");
    ASSERT_EQ(readPolygonSoupBytes(lines(test::toAsciiStl(c), {"\r\n"}), "stl", ascii), "");
    // STL repeats each corner per triangle; merged, the cube has its 8 corners again.
    EXPECT_EQ(binary.points.size(), 8u);
    EXPECT_EQ(binary.polygons.size(), 12u);
    EXPECT_EQ(ascii.points, binary.points);
    EXPECT_EQ(ascii.polygons, binary.polygons);
    for (std::size_t f = 0; f < c.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(glm::vec3(binary.points[binary.polygons[f][k]]), c.positions[c.triangles[f][k]]);

    // Some exporters begin a binary STL's header with "solid" (and may name a facet in it): the
    // size that matches the declared count makes it binary.
    std::string solidHeader = test::toBinaryStl(c);
    const std::string header = "solid cube facet exported";
    solidHeader.replace(0, header.size(), header);
    PolygonSoup fromSolid;
    ASSERT_EQ(readPolygonSoupBytes(solidHeader, "stl", fromSolid), "");
    EXPECT_EQ(fromSolid.points, binary.points);
    EXPECT_EQ(fromSolid.polygons, binary.polygons);
}

// A binary STL whose header understates its triangle count would be read as the smaller mesh:
// refused, saying how much follows; a few padding bytes after the last triangle load with a note.
TEST(MeshReading, ABinaryStlThatUnderstatesItsTrianglesIsRefusedAndPaddingNoted) {
    const RawMesh c = cubeTriangles();  // 12 triangles
    std::string understated = test::toBinaryStl(c);
    const std::uint32_t ten = 10;
    std::memcpy(understated.data() + 80, &ten, 4);
    PolygonSoup soup;
    const std::string problem = readPolygonSoupBytes(understated, "stl", soup);
    EXPECT_NE(problem.find("declares 10 triangles"), std::string::npos) << problem;
    EXPECT_NE(problem.find("2 more triangles"), std::string::npos) << problem;
    const std::string padded = test::toBinaryStl(c) + std::string(3, '\0');
    ASSERT_EQ(readPolygonSoupBytes(padded, "stl", soup), "");
    EXPECT_EQ(soup.polygons.size(), 12u);
    bool noted = false;
    for (const std::string& note : soup.notes)
        noted |= note.find("3 bytes after the last triangle") != std::string::npos;
    EXPECT_TRUE(noted);
}

TEST(MeshReading, OpenMeshFilesGiveTheirPolygonsAndHostileOnesAreRefused) {
    TempDir dir;
    const RawMesh ico = test::icosahedron();
    OpenMesh::TriMesh_ArrayKernelT<> om;
    std::vector<OpenMesh::VertexHandle> handles;
    for (const auto& p : ico.positions) handles.push_back(om.add_vertex({p.x, p.y, p.z}));
    for (const auto& t : ico.triangles) om.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
    const std::string path = dir.file("ico.om");
    ASSERT_TRUE(OpenMesh::IO::write_mesh(om, path));
    PolygonSoup soup;
    ASSERT_EQ(readPolygonSoup(path, soup), "");
    ASSERT_EQ(soup.points.size(), ico.positions.size());
    for (std::size_t v = 0; v < ico.positions.size(); ++v) EXPECT_EQ(glm::vec3(soup.points[v]), ico.positions[v]);
    // The same triangles, each perhaps starting at another corner.
    ASSERT_EQ(soup.polygons.size(), ico.triangles.size());
    for (std::size_t f = 0; f < ico.triangles.size(); ++f) {
        std::vector<std::uint32_t> expected(ico.triangles[f].begin(), ico.triangles[f].end());
        const auto& got = soup.polygons[f];
        ASSERT_EQ(got.size(), 3u);
        const bool rotated = std::any_of(expected.begin(), expected.end(), [&](std::uint32_t) {
            std::rotate(expected.begin(), expected.begin() + 1, expected.end());
            return expected == got;
        });
        EXPECT_TRUE(rotated) << "face " << f;
    }

    // A position chunk of one dimension: OpenMesh's reader asserts on it (and aborted the program).
    std::string bytes = test::readFile(path).substr(0, 16) + std::string("\x00\x06", 2) + std::string(20, '\0');
    const auto r = loadText(dir, "bad-dimension.om", bytes);
    EXPECT_FALSE(r.mesh);
    EXPECT_NE(r.error().find("not support"), std::string::npos) << r.error();
}

// --- Faults named exactly ---------------------------------------------------------------------

TEST(MeshReading, FlippedFacesAreNamedAsInconsistentOrientationNotNonManifold) {
    TempDir dir;
    RawMesh m = test::icosahedron();
    for (std::size_t f : {0u, 7u, 13u}) std::swap(m.triangles[f][1], m.triangles[f][2]);
    const std::size_t expected = test::topologyFacts(m.positions.size(), m.triangles)
                                     .misorientedEdges;  // hand-computed from the triangles
    ASSERT_GT(expected, 0u);
    const auto r = loadText(dir, "flipped.obj", test::toObj(m));
    EXPECT_FALSE(r.mesh);
    EXPECT_TRUE(anyContains(r.report.errors, std::to_string(expected) +
                                                 " edges where neighbouring triangles are inconsistently oriented"))
        << joined(r.report.errors);
    EXPECT_FALSE(anyContains(r.report.errors, "non-manifold")) << joined(r.report.errors);
    EXPECT_EQ(r.report.misorientedEdgeCount, expected);
    EXPECT_EQ(r.report.triangleCount, m.triangles.size());
}

TEST(MeshReading, ANonManifoldEdgeIsNamed) {
    TempDir dir;
    const RawMesh m = test::threeTrianglesOnEdge();
    const auto r = loadText(dir, "edge.off", test::toOff(m));
    EXPECT_FALSE(r.mesh);
    EXPECT_TRUE(anyContains(r.report.errors, "non-manifold: 1 edge shared by three or more triangles"))
        << joined(r.report.errors);
    EXPECT_EQ(r.report.triangleCount, m.triangles.size());
}

TEST(MeshReading, ABowTieVertexIsNamed) {
    TempDir dir;
    const RawMesh m = test::bowtieTetrahedra();
    const auto r = loadText(dir, "bowtie.obj", test::toObj(m));
    EXPECT_FALSE(r.mesh);
    EXPECT_TRUE(anyContains(r.report.errors, "1 bow-tie vertex")) << joined(r.report.errors);
    EXPECT_EQ(r.report.vertexCount, m.positions.size());
}

TEST(MeshReading, AHoleLoadsWithAWarning) {
    TempDir dir;
    RawMesh m = test::octahedron();
    m.triangles.pop_back();
    const auto r = loadText(dir, "hole.obj", test::toObj(m));
    ASSERT_TRUE(r.mesh) << r.error();
    EXPECT_TRUE(anyContains(r.report.warnings, "1 hole")) << joined(r.report.warnings);
    const std::string text = r.report.text();
    EXPECT_NE(text.find("holes: 1"), std::string::npos) << text;
    EXPECT_NE(text.find("size: 20 x 20 x 20 mm"), std::string::npos) << text;
    EXPECT_NE(text.find("unit: "), std::string::npos) << text;
}

TEST(MeshReading, DuplicateVerticesAndComponentsAreNamed) {
    TempDir dir;
    RawMesh m = test::octahedron();
    // A second copy of vertex 0, used by the first triangle: the surface is split along it.
    m.positions.push_back(m.positions[0]);
    for (VertexId& v : m.triangles[0])
        if (v == 0) v = VertexId(m.positions.size() - 1);
    const auto dup = loadText(dir, "dup.obj", test::toObj(m));
    EXPECT_TRUE(anyContains(dup.report.warnings, "1 duplicate vertex")) << joined(dup.report.warnings);
    EXPECT_EQ(dup.report.duplicateVertexCount, 1u);

    RawMesh two = test::octahedron();
    const RawMesh other = test::octahedron();
    const VertexId offset = VertexId(two.positions.size());
    for (const auto& p : other.positions) two.positions.push_back(p + glm::vec3(50, 0, 0));
    for (auto t : other.triangles) two.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    const auto r = loadText(dir, "two.obj", test::toObj(two));
    ASSERT_TRUE(r.mesh) << r.error();
    EXPECT_TRUE(anyContains(r.report.warnings, "2 separate components")) << joined(r.report.warnings);
    EXPECT_EQ(r.report.componentCount, 2u);
}

// --- The shipped meshes load exactly as OpenMesh read them -------------------------------------

TEST(MeshReading, ResourceMeshesLoadToTheSameMeshAsOpenMeshReadsThem) {
    const std::filesystem::path meshes = std::filesystem::path(PALPATE_SOURCE_DIR) / "resources" / "meshes";
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(meshes)) {
        if (entry.path().extension() != ".off") continue;
        ++files;
        const std::string path = entry.path().string();
        OpenMesh::TriMesh_ArrayKernelT<> om;
        OpenMesh::IO::Options options;
        ASSERT_TRUE(OpenMesh::IO::read_mesh(om, path, options)) << path;
        std::vector<glm::vec3> positions;
        for (auto vh : om.vertices()) {
            const auto& p = om.point(vh);
            positions.push_back(glm::vec3(glm::dvec3(p[0], p[1], p[2])));
        }
        test::Triangles triangles;
        for (auto fh : om.faces()) {
            std::array<VertexId, 3> t{};
            int k = 0;
            for (auto vh : om.fv_range(fh)) t[std::size_t(k++)] = VertexId(vh.idx());
            triangles.push_back(t);
        }
        const auto viaOpenMesh = TissueMesh::fromTriangles(positions, triangles, path);
        const auto loaded = TissueMesh::load(path);
        ASSERT_TRUE(viaOpenMesh.mesh) << viaOpenMesh.error();
        ASSERT_TRUE(loaded.mesh) << loaded.error();
        EXPECT_EQ(meshHash(*loaded.mesh), meshHash(*viaOpenMesh.mesh)) << path;
        EXPECT_EQ(loaded.mesh->restPositionsMm(), viaOpenMesh.mesh->restPositionsMm()) << path;
        EXPECT_EQ(loaded.mesh->triangles(), viaOpenMesh.mesh->triangles()) << path;
    }
    EXPECT_EQ(files, 8);
}

}  // namespace
}  // namespace palpate
