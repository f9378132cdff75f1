#include "engine/core/TissueMesh.h"

#include "engine/core/PolygonSoup.h"
#include "engine/core/SpaceFillingCurve.h"
#include "base/io/AtomicFile.h"
#include "base/io/InputFile.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <limits>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <numeric>
#include <sstream>

namespace palpate {

namespace {

using OmMesh = OpenMesh::TriMesh_ArrayKernelT<>;

constexpr double kMinDiagonalMm = 1e-3;
constexpr double kMaxDiagonalMm = 1e5;

/// OpenMesh reports reader problems on its global omerr stream, which writes to std::cerr.
/// While one file loads, std::cerr (and std::clog) write into a buffer instead, so the text can be
/// turned into a message that names the file. (Connecting a stream to omerr and disconnecting it
/// leaks inside OpenMesh, so the standard streams' buffers are swapped instead.)
class OmErrCapture {
public:
    OmErrCapture()
        : mLock(mutex()), mOldErr(std::cerr.rdbuf(mText.rdbuf())), mOldLog(std::clog.rdbuf(mText.rdbuf())) {}
    ~OmErrCapture() {
        omerr().flush();
        std::cerr.rdbuf(mOldErr);
        std::clog.rdbuf(mOldLog);
    }
    std::string text() {
        omerr().flush();
        return mText.str();
    }

private:
    static std::mutex& mutex() {
        static std::mutex m;
        return m;
    }
    std::lock_guard<std::mutex> mLock;
    std::ostringstream mText;
    std::streambuf* mOldErr;
    std::streambuf* mOldLog;
};

}  // namespace

/// Validation and flat-array construction, shared by files and generators.
struct MeshBuilder {
    static TissueMesh::LoadResult build(std::vector<glm::vec3> positions,
                                        std::vector<std::array<VertexId, 3>> triangles,
                                        MeshReport report, bool reorder);
    /// A closed surface with negative signed volume is inside out: its triangles are flipped.
    static void orientOutward(TissueMesh& mesh, MeshReport& report);
    /// Area-weighted vertex normals and the mean edge length.
    static void computeNormals(TissueMesh& mesh);
    /// The vertex adjacency (CSR, sorted and unique per vertex) and the largest valence.
    static void computeAdjacency(TissueMesh& mesh);
    /// The triangles around each vertex (CSR, in triangle order) and their smallest height at rest.
    static void computeFans(TissueMesh& mesh);
};

std::string MeshReport::text() const {
    std::ostringstream out;
    out << source << ": " << (valid() ? "valid" : "INVALID") << "\n";
    out << "  vertices: " << vertexCount << "\n";
    out << "  triangles: " << triangleCount << "\n";
    out << "  unit: " << unit.description() << "\n";
    out << "  size: " << sizeMm.x << " x " << sizeMm.y << " x " << sizeMm.z << " mm\n";
    out << "  bounding-box diagonal: " << bboxDiagonalMm << " mm\n";
    out << "  boundary edges: " << boundaryEdgeCount << (boundaryEdgeCount ? " (open surface)" : " (closed)")
        << "\n";
    out << "  non-manifold edges: " << nonManifoldEdgeCount << "\n";
    out << "  non-manifold vertices: " << nonManifoldVertexCount << "\n";
    out << "  degenerate triangles: " << degenerateTriangleCount << "\n";
    out << "  non-finite vertices: " << nonFiniteVertexCount << "\n";
    out << "  unused vertices: " << isolatedVertexCount << "\n";
    out << "  holes: " << holeCount << "\n";
    out << "  components: " << componentCount << "\n";
    out << "  duplicate vertices: " << duplicateVertexCount << "\n";
    out << "  misoriented edges: " << misorientedEdgeCount << "\n";
    for (const std::string& n : notes) out << "  note: " << n << "\n";
    for (const std::string& e : errors) out << "  error: " << e << "\n";
    for (const std::string& w : warnings) out << "  warning: " << w << "\n";
    return out.str();
}

TissueMesh::LoadResult TissueMesh::load(const std::string& path, const MeshUnit& unit) {
    MeshReport report;
    report.source = path;
    report.unit = unit;

    // The file's real polygons, read without imposing topology, so that findMeshFaults (in
    // MeshBuilder::build) names its faults exactly (docs/meshes.md, "Reading").
    PolygonSoup soup;
    if (const std::string problem = readPolygonSoup(path, soup); !problem.empty()) {
        report.errors.push_back(path + ": " + problem);
        return LoadResult{std::nullopt, report};
    }
    std::vector<std::string> notes = std::move(soup.notes);
    const std::vector<std::array<VertexId, 3>> triangles = triangulatePolygons(soup, notes);
    std::vector<glm::vec3> positions(soup.points.size());
    for (std::size_t v = 0; v < positions.size(); ++v) positions[v] = glm::vec3(soup.points[v] * unit.mmPerUnit);
    report.notes = std::move(notes);
    return MeshBuilder::build(std::move(positions), triangles, std::move(report), true);
}

TissueMesh::LoadResult TissueMesh::fromTriangles(std::vector<glm::vec3> positionsMm,
                                                 const std::vector<std::array<VertexId, 3>>& triangles,
                                                 const std::string& sourceName, bool reorderAlongCurve) {
    MeshReport report;
    report.source = sourceName;
    return MeshBuilder::build(std::move(positionsMm), triangles, std::move(report), reorderAlongCurve);
}

TissueMesh::LoadResult MeshBuilder::build(std::vector<glm::vec3> positions,
                                          std::vector<std::array<VertexId, 3>> triangles, MeshReport report,
                                          bool reorder) {
    const std::string& src = report.source;
    auto error = [&](const std::string& problem) { report.errors.push_back(src + ": " + problem); };
    const std::size_t nv = positions.size();
    report.vertexCount = nv;
    report.triangleCount = triangles.size();

    if (nv == 0 || triangles.empty()) {
        error(nv == 0 ? "has no vertices" : "has no triangles");
        return {std::nullopt, report};
    }
    if (nv > kMaxMeshVertices) {
        error("has " + std::to_string(nv) + " vertices, more than the " + std::to_string(kMaxMeshVertices) +
              " a mesh may have");
        return {std::nullopt, report};
    }
    if (triangles.size() > kMaxMeshFaces) {
        error("has " + std::to_string(triangles.size()) + " triangles, more than the " +
              std::to_string(kMaxMeshFaces) + " a mesh may have");
        return {std::nullopt, report};
    }

    // Every fault, counted and named once (engine/core/MeshFaults.h).
    std::vector<glm::dvec3> exact(positions.begin(), positions.end());
    const MeshFaults faults = findMeshFaults(exact, triangles);
    report.nonFiniteVertexCount = faults.nonFiniteVertices;
    report.degenerateTriangleCount = faults.degenerateTriangles;
    report.nonManifoldEdgeCount = faults.nonManifoldEdges;
    report.nonManifoldVertexCount = faults.bowTieVertices;
    report.boundaryEdgeCount = faults.boundaryEdges;
    report.isolatedVertexCount = faults.unusedVertices;
    report.holeCount = faults.holes;
    report.componentCount = faults.components;
    report.duplicateVertexCount = faults.duplicateVertices;
    report.misorientedEdgeCount = faults.misorientedEdges;
    if (faults.invalidIndexTriangles || faults.nonFiniteVertices) {
        for (const std::string& e : faults.errorTexts())
            if (e.find("do not exist") != std::string::npos || e.find("NaN") != std::string::npos) error(e);
        return {std::nullopt, report};
    }
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : positions) {
        lo = glm::min(lo, glm::dvec3(p));
        hi = glm::max(hi, glm::dvec3(p));
    }
    report.bboxDiagonalMm = glm::length(hi - lo);
    report.sizeMm = hi - lo;
    if (report.bboxDiagonalMm < kMinDiagonalMm || report.bboxDiagonalMm > kMaxDiagonalMm) {
        std::ostringstream s;
        s << "absurd size: bounding-box diagonal " << report.bboxDiagonalMm << " mm (expected "
          << kMinDiagonalMm << " to " << kMaxDiagonalMm << " mm)";
        error(s.str());
    }
    for (const std::string& e : faults.errorTexts()) error(e);
    if (faults.hasErrors())
        report.errors.push_back(src + ": to repair it, import it (palpate-cli mesh import --repair, or File > Import Mesh...)");
    for (const std::string& w : faults.warningTexts()) {
        if (w.find("open surface") == 0) {
            report.warnings.push_back(src + ": " + w + " (allowed; contact near the boundary is less accurate)");
        } else if (w.find("used by no triangle") != std::string::npos) {
            report.warnings.push_back(src + ": " + w + " (dropped)");
        } else {
            report.warnings.push_back(src + ": " + w);
        }
    }
    if (!report.valid()) return {std::nullopt, report};
    // Drop unused vertices, then renumber along the Morton curve.
    std::vector<bool> used(nv, false);
    for (const auto& t : triangles)
        for (VertexId v : t) used[v] = true;
    std::vector<VertexId> keep;
    keep.reserve(nv);
    for (VertexId v = 0; v < nv; ++v)
        if (used[v]) keep.push_back(v);
    std::vector<glm::vec3> kept(keep.size());
    for (std::size_t i = 0; i < keep.size(); ++i) kept[i] = positions[keep[i]];
    std::vector<std::uint32_t> order(keep.size());
    if (reorder) order = mortonOrder(kept, mortonCubeFor(kept));
    else std::iota(order.begin(), order.end(), 0u);
    std::vector<VertexId> newIndexOfOld(nv, kNoVertex);
    TissueMesh mesh;
    mesh.mRestMm.resize(keep.size());
    mesh.mOriginalIndex.resize(keep.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        const VertexId old = keep[order[i]];
        newIndexOfOld[old] = VertexId(i);
        mesh.mRestMm[i] = positions[old];
        mesh.mOriginalIndex[i] = old;
    }
    mesh.mTriangles.resize(triangles.size());
    for (std::size_t f = 0; f < triangles.size(); ++f)
        for (int k = 0; k < 3; ++k) mesh.mTriangles[f][k] = newIndexOfOld[triangles[f][k]];

    if (report.boundaryEdgeCount == 0) orientOutward(mesh, report);
    computeNormals(mesh);
    computeAdjacency(mesh);
    computeFans(mesh);
    const std::size_t n = mesh.mRestMm.size();

    mesh.mBoundsMin = glm::vec3(lo);
    mesh.mBoundsMax = glm::vec3(hi);
    report.vertexCount = n;
    mesh.mReport = report;
    return {std::move(mesh), report};
}

void MeshBuilder::orientOutward(TissueMesh& mesh, MeshReport& report) {
    double volume6 = 0.0;
    for (const auto& t : mesh.mTriangles)
        volume6 += glm::dot(glm::dvec3(mesh.mRestMm[t[0]]),
                            glm::cross(glm::dvec3(mesh.mRestMm[t[1]]), glm::dvec3(mesh.mRestMm[t[2]])));
    if (volume6 < 0.0) {
        for (auto& t : mesh.mTriangles) std::swap(t[1], t[2]);
        report.warnings.push_back(report.source + ": triangles faced inward; flipped so normals point out");
    }
}

void MeshBuilder::computeNormals(TissueMesh& mesh) {
    const std::size_t n = mesh.mRestMm.size();
    std::vector<glm::dvec3> normalSum(n, glm::dvec3(0.0));
    double edgeSum = 0.0;
    for (const auto& t : mesh.mTriangles) {
        const glm::dvec3 a(mesh.mRestMm[t[0]]), b(mesh.mRestMm[t[1]]), c(mesh.mRestMm[t[2]]);
        const glm::dvec3 fn = glm::cross(b - a, c - a);
        for (VertexId v : t) normalSum[v] += fn;
        edgeSum += glm::length(b - a) + glm::length(c - b) + glm::length(a - c);
    }
    mesh.mMeanEdgeMm = edgeSum / double(3 * mesh.mTriangles.size());
    mesh.mRestNormals.resize(n);
    for (std::size_t v = 0; v < n; ++v) {
        const double len = glm::length(normalSum[v]);
        mesh.mRestNormals[v] = len > 0.0 ? glm::vec3(normalSum[v] / len) : glm::vec3(0.0f, 0.0f, 1.0f);
    }
}

void MeshBuilder::computeAdjacency(TissueMesh& mesh) {
    const std::size_t n = mesh.mRestMm.size();
    std::vector<std::vector<VertexId>> adjacency(n);
    for (const auto& t : mesh.mTriangles)
        for (int k = 0; k < 3; ++k) {
            adjacency[t[k]].push_back(t[(k + 1) % 3]);
            adjacency[t[k]].push_back(t[(k + 2) % 3]);
        }
    mesh.mNeighbourStart.assign(n + 1, 0);
    for (std::size_t v = 0; v < n; ++v) {
        auto& a = adjacency[v];
        std::sort(a.begin(), a.end());
        a.erase(std::unique(a.begin(), a.end()), a.end());
        mesh.mNeighbourStart[v + 1] = mesh.mNeighbourStart[v] + std::uint32_t(a.size());
        mesh.mMaxValence = std::max(mesh.mMaxValence, a.size());
    }
    mesh.mNeighbours.reserve(mesh.mNeighbourStart.back());
    for (auto& a : adjacency) mesh.mNeighbours.insert(mesh.mNeighbours.end(), a.begin(), a.end());
}

void MeshBuilder::computeFans(TissueMesh& mesh) {
    const std::size_t n = mesh.mRestMm.size();
    // The triangles around each vertex (CSR), in triangle order.
    mesh.mFanStart.assign(n + 1, 0);
    for (const auto& t : mesh.mTriangles)
        for (VertexId v : t) ++mesh.mFanStart[v + 1];
    for (std::size_t v = 0; v < n; ++v) mesh.mFanStart[v + 1] += mesh.mFanStart[v];
    mesh.mFanTriangles.resize(mesh.mFanStart[n]);
    {
        std::vector<std::uint32_t> fill(mesh.mFanStart.begin(), mesh.mFanStart.end() - 1);
        for (std::uint32_t t = 0; t < mesh.mTriangles.size(); ++t)
            for (VertexId v : mesh.mTriangles[t]) mesh.mFanTriangles[fill[v]++] = t;
    }
    // The smallest height of each vertex's fan triangles at rest.
    mesh.mFanMinHeightMm.assign(n, std::numeric_limits<float>::infinity());
    for (const auto& t : mesh.mTriangles) {
        const glm::vec3 a = mesh.mRestMm[t[0]], b = mesh.mRestMm[t[1]], c = mesh.mRestMm[t[2]];
        const float doubleArea = glm::length(glm::cross(b - a, c - a));
        const float longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
        const float height = longest > 0.0f ? doubleArea / longest : 0.0f;
        for (VertexId v : t) mesh.mFanMinHeightMm[v] = std::min(mesh.mFanMinHeightMm[v], height);
    }
}

std::string TissueMesh::save(const std::string& path) const {
    OmMesh om;
    std::vector<OmMesh::VertexHandle> handles(mRestMm.size());
    for (std::size_t v = 0; v < mRestMm.size(); ++v)
        handles[v] = om.add_vertex(OmMesh::Point(mRestMm[v].x, mRestMm[v].y, mRestMm[v].z));
    for (const auto& t : mTriangles) om.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
    // Written in memory first, then atomically (base/io/AtomicFile.h): a full disk or a write
    // error leaves the target as it was and is reported with its reason, never a truncated file.
    std::ostringstream bytes(std::ios::out | std::ios::binary);
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    bool written = false;
    std::string writerText;
    {
        OmErrCapture capture;
        OpenMesh::IO::Options options;
        try {
            written = !extension.empty() && OpenMesh::IO::write_mesh(om, bytes, extension, options, 9) && bytes.good();
        } catch (const std::exception& e) {
            writerText = e.what();
        }
        writerText += capture.text();
    }
    if (!written) {
        std::string why = extension.empty() ? "no extension (use .obj, .off, .ply, .stl or .om)"
                                            : "OpenMesh cannot write '" + extension + "' files";
        if (!writerText.empty()) why += ": " + writerText.substr(0, writerText.find('\n'));
        return path + ": cannot write mesh: " + why;
    }
    const std::string problem = writeFileAtomically(path, bytes.str());
    if (problem.empty()) return {};
    // writeFileAtomically names the path first; say what failed.
    const std::string prefix = path + ": ";
    return prefix + "cannot write mesh: " +
           (problem.compare(0, prefix.size(), prefix) == 0 ? problem.substr(prefix.size()) : problem);
}

}  // namespace palpate
