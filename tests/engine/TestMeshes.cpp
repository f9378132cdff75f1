#include "tests/engine/TestMeshes.h"

#include <glm/geometric.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iomanip>
#include <map>
#include <numeric>
#include <random>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace palpate::test {

namespace {

/// Reverses `t` if its normal points towards `interior` (for convex pieces).
void orientAwayFrom(std::array<VertexId, 3>& t, const std::vector<glm::vec3>& p, const glm::dvec3& interior) {
    const glm::dvec3 a(p[t[0]]), b(p[t[1]]), c(p[t[2]]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    if (glm::dot(n, (a + b + c) / 3.0 - interior) < 0.0) std::swap(t[1], t[2]);
}

glm::dvec3 centroidOf(const std::vector<glm::vec3>& p) {
    glm::dvec3 c(0.0);
    for (const auto& v : p) c += glm::dvec3(v);
    return c / double(p.size());
}

template <typename T>
void putLE(std::string& out, T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));  // the test machines are little-endian (x86-64, arm64)
    out.append(bytes, sizeof(T));
}

}  // namespace

RawMesh RawMesh::flipped() const {
    RawMesh out = *this;
    for (auto& t : out.triangles) std::swap(t[1], t[2]);
    return out;
}

RawMesh icosahedron(float radiusMm) {
    const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<glm::dvec3> v;
    for (int s1 : {-1, 1})
        for (int s2 : {-1, 1}) {
            v.push_back({0.0, s1 * 1.0, s2 * phi});
            v.push_back({s1 * 1.0, s2 * phi, 0.0});
            v.push_back({s2 * phi, 0.0, s1 * 1.0});
        }
    const double scale = radiusMm / std::sqrt(1.0 + phi * phi);
    RawMesh m;
    for (const auto& p : v) m.positions.push_back(glm::vec3(p * scale));
    // Faces: every triple of mutually adjacent vertices (edge length 2 before scaling).
    auto adjacent = [&](std::size_t a, std::size_t b) { return std::abs(glm::length(v[a] - v[b]) - 2.0) < 1e-9; };
    for (std::size_t a = 0; a < 12; ++a)
        for (std::size_t b = a + 1; b < 12; ++b)
            for (std::size_t c = b + 1; c < 12; ++c)
                if (adjacent(a, b) && adjacent(b, c) && adjacent(a, c)) {
                    std::array<VertexId, 3> t{VertexId(a), VertexId(b), VertexId(c)};
                    orientAwayFrom(t, m.positions, glm::dvec3(0.0));
                    m.triangles.push_back(t);
                }
    if (m.triangles.size() != 20) throw std::logic_error("icosahedron: expected 20 faces");
    return m;
}

RawMesh octahedron(float r) {
    RawMesh m;
    m.positions = {{r, 0, 0}, {-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {0, 0, -r}};
    for (VertexId x : {0u, 1u})
        for (VertexId y : {2u, 3u})
            for (VertexId z : {4u, 5u}) {
                std::array<VertexId, 3> t{x, y, z};
                orientAwayFrom(t, m.positions, glm::dvec3(0.0));
                m.triangles.push_back(t);
            }
    return m;
}

RawMesh tower() {
    RawMesh m;
    m.positions = {{0, 0, 10},                                        // 0 apex
                   {4, 0, 6},  {0, 4, 6},  {-4, 0, 6}, {0, -4, 6},    // 1..4
                   {8, 0, 0},  {0, 8, 0},  {-8, 0, 0}, {0, -8, 0},    // 5..8
                   {0, 0, -10}};                                      // 9 bottom
    auto a = [](int k) { return VertexId(1 + (k % 4)); };
    auto b = [](int k) { return VertexId(5 + (k % 4)); };
    for (int k = 0; k < 4; ++k) {
        m.triangles.push_back({0, a(k), a(k + 1)});
        m.triangles.push_back({a(k), b(k), b(k + 1)});
        m.triangles.push_back({a(k), b(k + 1), a(k + 1)});
        m.triangles.push_back({9, b(k + 1), b(k)});
    }
    const glm::dvec3 c = centroidOf(m.positions);
    for (auto& t : m.triangles) orientAwayFrom(t, m.positions, c);
    return m;
}

RawMesh gridPatch(int nx, int ny, float spacingMm) {
    RawMesh m;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) m.positions.push_back({float(i) * spacingMm, float(j) * spacingMm, 0.0f});
    auto id = [nx](int i, int j) { return VertexId(j * nx + i); };
    for (int j = 0; j + 1 < ny; ++j)
        for (int i = 0; i + 1 < nx; ++i) {
            m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return m;
}

int gridDistance(int i0, int j0, int i1, int j1) {
    const int dx = i1 - i0, dy = j1 - j0;
    if ((dx >= 0 && dy >= 0) || (dx <= 0 && dy <= 0)) return std::max(std::abs(dx), std::abs(dy));
    return std::abs(dx) + std::abs(dy);
}

RawMesh bowtieTetrahedra() {
    RawMesh m;
    m.positions = {{0, 0, 0},
                   {20, 10, -10}, {20, -10, -10}, {20, 0, 10},
                   {-20, 10, -10}, {-20, -10, -10}, {-20, 0, 10}};
    const std::array<std::array<VertexId, 4>, 2> tets{{{0, 1, 2, 3}, {0, 4, 5, 6}}};
    for (const auto& tet : tets) {
        glm::dvec3 c(0.0);
        for (VertexId v : tet) c += glm::dvec3(m.positions[v]) / 4.0;
        for (int skip = 0; skip < 4; ++skip) {
            std::array<VertexId, 3> t{};
            int k = 0;
            for (int i = 0; i < 4; ++i)
                if (i != skip) t[std::size_t(k++)] = tet[std::size_t(i)];
            orientAwayFrom(t, m.positions, c);
            m.triangles.push_back(t);
        }
    }
    return m;
}

RawMesh threeTrianglesOnEdge() {
    RawMesh m;
    m.positions = {{0, 0, 0}, {10, 0, 0}, {5, 10, 0}, {5, -10, 0}, {5, 0, 10}};
    m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    return m;
}

TopologyFacts topologyFacts(std::size_t vertexCount, const Triangles& triangles) {
    TopologyFacts facts;
    std::map<std::pair<VertexId, VertexId>, std::pair<int, int>> uses;  // (forward, backward)
    for (const auto& t : triangles)
        for (int k = 0; k < 3; ++k) {
            const VertexId a = t[std::size_t(k)], b = t[std::size_t((k + 1) % 3)];
            auto& u = uses[{std::min(a, b), std::max(a, b)}];
            (a < b ? u.first : u.second) += 1;
        }
    facts.edgeCount = uses.size();
    for (const auto& [edge, u] : uses) {
        const int n = u.first + u.second;
        if (n == 1) ++facts.boundaryEdges;
        else if (n > 2) ++facts.nonManifoldEdges;
        else if (u.first != 1) ++facts.misorientedEdges;
    }
    // A vertex is manifold when the link edges of its triangles connect all its neighbours.
    std::vector<std::vector<std::array<VertexId, 2>>> link(vertexCount);
    for (const auto& t : triangles)
        for (int k = 0; k < 3; ++k)
            link[t[std::size_t(k)]].push_back({t[std::size_t((k + 1) % 3)], t[std::size_t((k + 2) % 3)]});
    for (std::size_t v = 0; v < vertexCount; ++v) {
        if (link[v].empty()) continue;
        std::map<VertexId, VertexId> parent;
        std::function<VertexId(VertexId)> find = [&](VertexId x) {
            while (parent[x] != x) x = parent[x];
            return x;
        };
        for (const auto& e : link[v]) {
            parent.emplace(e[0], e[0]);
            parent.emplace(e[1], e[1]);
        }
        for (const auto& e : link[v]) parent[find(e[0])] = find(e[1]);
        std::size_t roots = 0;
        for (const auto& [w, p] : parent)
            if (find(w) == w) ++roots;
        if (roots > 1) ++facts.nonManifoldVertices;
    }
    return facts;
}

double signedVolume6(const std::vector<glm::vec3>& p, const Triangles& triangles) {
    double v = 0.0;
    for (const auto& t : triangles)
        v += glm::dot(glm::dvec3(p[t[0]]), glm::cross(glm::dvec3(p[t[1]]), glm::dvec3(p[t[2]])));
    return v;
}

float dist2(const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 d = a - b;
    return d.x * d.x + d.y * d.y + d.z * d.z;
}

bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string toOff(const RawMesh& m) {
    std::ostringstream s;
    s << std::setprecision(9) << "OFF\n" << m.positions.size() << " " << m.triangles.size() << " 0\n";
    for (const auto& p : m.positions) s << p.x << " " << p.y << " " << p.z << "\n";
    for (const auto& t : m.triangles) s << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
    return s.str();
}

std::string toObj(const RawMesh& m) {
    std::ostringstream s;
    s << std::setprecision(9) << "# test mesh\n";
    for (const auto& p : m.positions) s << "v " << p.x << " " << p.y << " " << p.z << "\n";
    for (const auto& t : m.triangles) s << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
    return s.str();
}

std::string toAsciiPly(const RawMesh& m) {
    std::ostringstream s;
    s << std::setprecision(9) << "ply\nformat ascii 1.0\nelement vertex " << m.positions.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << m.triangles.size()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const auto& p : m.positions) s << p.x << " " << p.y << " " << p.z << "\n";
    for (const auto& t : m.triangles) s << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
    return s.str();
}

std::string toBinaryPly(const RawMesh& m) {
    std::ostringstream h;
    h << "ply\nformat binary_little_endian 1.0\nelement vertex " << m.positions.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << m.triangles.size()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
    std::string out = h.str();
    for (const auto& p : m.positions) {
        putLE(out, p.x);
        putLE(out, p.y);
        putLE(out, p.z);
    }
    for (const auto& t : m.triangles) {
        putLE(out, std::uint8_t(3));
        for (VertexId v : t) putLE(out, std::int32_t(v));
    }
    return out;
}

std::string toBinaryStl(const RawMesh& m) {
    std::string out(80, ' ');
    const char title[] = "palpate test binary stl";
    std::memcpy(out.data(), title, sizeof(title) - 1);
    putLE(out, std::uint32_t(m.triangles.size()));
    for (const auto& t : m.triangles) {
        const glm::vec3 a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
        glm::vec3 n = glm::cross(b - a, c - a);
        const float len = glm::length(n);
        if (len > 0.0f) n /= len;
        for (const glm::vec3& v : {n, a, b, c}) {
            putLE(out, v.x);
            putLE(out, v.y);
            putLE(out, v.z);
        }
        putLE(out, std::uint16_t(0));
    }
    return out;
}

std::string toAsciiStl(const RawMesh& m) {
    std::ostringstream s;
    s << std::setprecision(9) << "solid test\n";
    for (const auto& t : m.triangles) {
        s << "  facet normal 0 0 0\n    outer loop\n";
        for (VertexId v : t) {
            const auto& p = m.positions[v];
            s << "      vertex " << p.x << " " << p.y << " " << p.z << "\n";
        }
        s << "    endloop\n  endfacet\n";
    }
    s << "endsolid test\n";
    return s.str();
}

RawMesh rawOf(const TissueMesh& mesh) {
    return RawMesh{mesh.restPositionsMm(), mesh.triangles()};
}

std::string cliPath() {
#ifdef PALPATE_CLI_PATH
    return PALPATE_CLI_PATH;
#else
    return {};
#endif
}

}  // namespace palpate::test
