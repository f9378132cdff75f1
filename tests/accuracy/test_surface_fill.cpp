// The surface filler and the surface indentation: positive, conforming tets between the surface
// and its core; surface nodes exactly on the mesh vertices; thickness halving; bad input
// rejected with a message; a punch on a sphere pushes back and its dent decays with distance.

#include "engine/core/MeshGenerator.h"
#include "engine/fem/SurfaceFill.h"
#include "tests/engine/TestMeshes.h"
#include "tests/support/Meshes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace palpate {
namespace {

constexpr ElasticMaterial kMaterial{0.01, 0.45};

/// Six times the volume enclosed by the triangles over the given node positions.
double enclosed6(const std::vector<glm::dvec3>& p, const std::vector<std::array<VertexId, 3>>& triangles,
                 const std::function<TetNodeId(VertexId)>& node) {
    double v = 0;
    for (const auto& t : triangles) v += glm::dot(p[node(t[0])], glm::cross(p[node(t[1])], p[node(t[2])]));
    return v;
}

void expectValidFill(const TissueMesh& mesh, const FilledSurface& f) {
    ASSERT_EQ(f.surfaceVertexCount, mesh.vertexCount());
    ASSERT_EQ(f.mesh.nodeCount(), mesh.vertexCount() * std::size_t(f.layers + 1));
    ASSERT_EQ(f.mesh.tetCount(), mesh.triangleCount() * std::size_t(f.layers) * 3);
    // Surface nodes are the mesh's vertices, exactly.
    for (VertexId v = 0; v < mesh.vertexCount(); ++v) ASSERT_EQ(f.mesh.nodesMm[f.node(v, 0)], glm::dvec3(mesh.restPositionsMm()[v]));
    // Positive tets; their volumes add up to the shell between the surface and the core.
    double volume6 = 0;
    std::map<std::array<TetNodeId, 3>, int> faces;
    for (const auto& t : f.mesh.tets) {
        const auto& p = f.mesh.nodesMm;
        const double v6 = tetSignedVolume6(p[t[0]], p[t[1]], p[t[2]], p[t[3]]);
        ASSERT_GT(v6, 0.0);
        volume6 += v6;
        for (int skip = 0; skip < 4; ++skip) {
            std::array<TetNodeId, 3> key{};
            for (int i = 0, k = 0; i < 4; ++i)
                if (i != skip) key[std::size_t(k++)] = t[std::size_t(i)];
            std::sort(key.begin(), key.end());
            ++faces[key];
        }
    }
    const double outer = enclosed6(f.mesh.nodesMm, mesh.triangles(), [&](VertexId v) { return f.node(v, 0); });
    const double inner = enclosed6(f.mesh.nodesMm, mesh.triangles(), [&](VertexId v) { return f.node(v, f.layers); });
    EXPECT_NEAR(volume6, outer - inner, 1e-9 * outer);
    // Conforming: every face shared by two tets except the surface and core triangles.
    std::size_t unshared = 0;
    for (const auto& [key, count] : faces) {
        ASSERT_LE(count, 2);
        unshared += count == 1;
    }
    EXPECT_EQ(unshared, 2 * mesh.triangleCount());
}

TEST(SurfaceFill, SphereFillIsPositiveConformingAndOnTheVertices) {
    const TissueMesh mesh = test::sphereMesh(500);
    SurfaceFillDef o;
    o.layers = 3;
    const FilledSurface f = fillSurface(mesh, o);
    EXPECT_EQ(f.halvings, 0);
    EXPECT_NEAR(f.thicknessMm, 25.0, 0.1);  // a quarter of the 100 mm sphere's extent
    EXPECT_GT(f.minTetVolumeMm3, 0.0);
    expectValidFill(mesh, f);
}

TEST(SurfaceFill, HalvesTheThicknessUntilNoTetInvertsAndSaysSo) {
    auto built = test::icosahedron(10.0f).build("icosahedron");
    ASSERT_TRUE(built.mesh) << built.error();
    SurfaceFillDef o;
    o.layers = 2;
    o.thicknessMm = 40.0;  // four times the radius: the core would turn inside out
    const FilledSurface f = fillSurface(*built.mesh, o);
    EXPECT_GE(f.halvings, 2);
    EXPECT_DOUBLE_EQ(f.requestedThicknessMm, 40.0);
    EXPECT_DOUBLE_EQ(f.thicknessMm, 40.0 / std::pow(2.0, f.halvings));
    EXPECT_LT(f.thicknessMm, 10.0);
    expectValidFill(*built.mesh, f);
    // Not allowed to halve: a clear error.
    o.maxHalvings = 0;
    try {
        fillSurface(*built.mesh, o);
        FAIL() << "an inverted fill was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("cannot fill"), std::string::npos) << e.what();
    }
}

void expectRejected(const std::function<void()>& f, const std::string& word) {
    try {
        f();
        FAIL() << "accepted; expected an error mentioning '" << word << "'";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
}

TEST(SurfaceFill, RejectsBadInputWithAMessage) {
    auto open = test::gridPatch(5, 5).build("patch");
    ASSERT_TRUE(open.mesh);
    expectRejected([&] { fillSurface(*open.mesh); }, "open");
    const TissueMesh mesh = test::sphereMesh(200);
    SurfaceFillDef zero;
    zero.thicknessMm = 0.0;
    expectRejected([&] { fillSurface(mesh, zero); }, "thickness");
    SurfaceFillDef nan;
    nan.thicknessMm = std::nan("");
    expectRejected([&] { fillSurface(mesh, nan); }, "thickness");
    SurfaceFillDef noLayers;
    noLayers.layers = 0;
    expectRejected([&] { fillSurface(mesh, noLayers); }, "layers");
    expectRejected([&] { SurfaceIndenter(mesh, ElasticMaterial{std::nan(""), 0.3}); }, "Young");
    expectRejected([&] { SurfaceIndenter(mesh, ElasticMaterial{0.01, 0.5}); }, "Poisson");
    SurfaceFillDef twoLayers;
    twoLayers.layers = 2;
    const SurfaceIndenter indenter(mesh, kMaterial, twoLayers);
    expectRejected([&] { indenter.indent(VertexId(mesh.vertexCount()), 5.0, 1.0); }, "touched vertex");
    expectRejected([&] { indenter.indent(0, std::nan(""), 1.0); }, "punch radius");
    expectRejected([&] { indenter.indent(0, 5.0, std::numeric_limits<double>::infinity()); }, "indentation");
    expectRejected([&] { indenter.indent(0, 5.0, 0.0); }, "indentation");
}

TEST(SurfaceFill, IndentingASpherePushesBackAndTheDentDecaysWithDistance) {
    const TissueMesh mesh = test::sphereMesh(1442);
    const SurfaceIndenter indenter(mesh, kMaterial);
    const VertexId touched = 700;
    const double radius = 6.0, delta = 1.0;
    const SurfaceIndentation r = indenter.indent(touched, radius, delta);
    const glm::dvec3 p0(mesh.restPositionsMm()[touched]);
    const glm::dvec3 n0 = glm::normalize(glm::dvec3(mesh.restNormals()[touched]));
    EXPECT_GT(r.reactionForceN, 0.0);
    EXPECT_GE(r.prescribedVertexCount, 2u);
    EXPECT_EQ(r.displacementMm.size(), mesh.vertexCount());
    EXPECT_EQ(r.nodes, mesh.vertexCount() * 5);
    EXPECT_TRUE(r.solve.converged);
    // Under the punch: exactly delta along -n (frictionless: the tangential part is free).
    for (VertexId v = 0; v < mesh.vertexCount(); ++v)
        if (glm::length(glm::dvec3(mesh.restPositionsMm()[v]) - p0) <= radius) {
            EXPECT_NEAR(glm::dot(r.displacementMm[v], -n0), delta, 1e-12);
        }
    // Mean |u| in 10 mm distance bins falls off with distance from the touched vertex.
    std::vector<double> sum(6, 0.0);
    std::vector<int> count(6, 0);
    for (VertexId v = 0; v < mesh.vertexCount(); ++v) {
        const double d = glm::length(glm::dvec3(mesh.restPositionsMm()[v]) - p0);
        const auto bin = std::size_t(d / 10.0);
        if (bin < sum.size()) {
            sum[bin] += glm::length(r.displacementMm[v]);
            ++count[bin];
        }
    }
    for (std::size_t b = 1; b < sum.size(); ++b) {
        ASSERT_GT(count[b], 0);
        EXPECT_LT(sum[b] / count[b], sum[b - 1] / count[b - 1]) << "bin " << b;
    }
    EXPECT_LT(sum[5] / count[5], 0.2 * delta);
    // Linear: twice the indentation, twice the force and the same shape.
    const SurfaceIndentation twice = indenter.indent(touched, radius, 2 * delta);
    EXPECT_NEAR(twice.reactionForceN, 2 * r.reactionForceN, 1e-5 * r.reactionForceN);
}

}  // namespace
}  // namespace palpate
