#include "engine/bench/Table1Bench.h"

#include "engine/core/Octree.h"
#include "engine/core/SceneTarget.h"
#include "engine/loop/HapticSnapshot.h"
#include "engine/stability/DivergenceGuard.h"
#include "engine/models/slopering/CoherentSlopeRing.h"
#include "engine/models/slopering/PaperSlopeRing.h"
#include "engine/core/ToolPath.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace palpate {

namespace {

// The concrete class (final), so that the timed loop calls step() directly.
template <typename Model>
MethodMeasurement measureModel(Model& deformer, const std::vector<glm::vec3>& path, const Table1Def& options) {
    MethodMeasurement m;

    // Exactness: before each tick, compare the method's touched vertex with brute force.
    std::size_t wrong = 0;
    if (deformer.method() == SlopeRingMethod::Coherent) m.wrongPct = NAN;
    else for (const glm::vec3& tool : path) {
        const auto positions = deformer.positionsMm();
        VertexId found = deformer.findTouched(tool);
        if (found == kNoVertex) found = deformer.touchedVertex();
        const VertexId truth = nearestLinear(tool, positions);
        const float trueD = glm::length(positions[truth] - tool);
        const float foundD = found == kNoVertex ? INFINITY : glm::length(positions[found] - tool);
        if (foundD > trueD) {
            ++wrong;  // includes ticks where the search found no vertex at all
            if (found != kNoVertex) m.maxOffMm = std::max(m.maxOffMm, double(foundD - trueD));
        }
        deformer.step(tool, 0.001);
    }
    if (deformer.method() != SlopeRingMethod::Coherent) m.wrongPct = 100.0 * double(wrong) / double(path.size());

    // The loop's work per tick besides the step (engine/loop/HapticLoop.cpp): the guard, and the
    // displaced vertices copied into the snapshot it publishes.
    const TissueMesh& mesh = deformer.mesh();
    DivergenceGuard guard;
    std::vector<VertexId> ids(HapticSnapshot::kMaxDisplaced);
    std::vector<glm::vec3> positions(HapticSnapshot::kMaxDisplaced);
    std::vector<std::uint8_t> rings(HapticSnapshot::kMaxDisplaced);
    volatile std::size_t sink = 0;
    const auto median = [&](bool asTheLoopRunsIt) {
        std::vector<double> perTickUs;
        for (int r = 0; r < options.repeats; ++r) {
            double elapsedUs = 0.0;
            std::size_t ticks = 0;
            while (elapsedUs < options.minMeasureMs * 1000.0) {
                deformer.reset();
                guard.reset();
                const auto start = std::chrono::steady_clock::now();
                if (asTheLoopRunsIt) {
                    for (const glm::vec3& tool : path) {
                        const TickResult result = deformer.step(tool, 0.001);
                        sink = sink + std::size_t(guard.check(mesh, deformer, result).kind);
                        sink = sink + deformer.copyDisplaced(ids.data(), positions.data(), rings.data(), ids.size());
                    }
                } else {
                    for (const glm::vec3& tool : path) deformer.step(tool, 0.001);
                }
                const auto stop = std::chrono::steady_clock::now();
                elapsedUs += std::chrono::duration<double, std::micro>(stop - start).count();
                ticks += path.size();
            }
            perTickUs.push_back(elapsedUs / double(ticks));
        }
        std::sort(perTickUs.begin(), perTickUs.end());
        return perTickUs[perTickUs.size() / 2];
    };
    m.tickUs = median(true);
    m.stepUs = median(false);
    return m;
}

MethodMeasurement measure(const TissueMesh& mesh, const Octree& octree, const std::vector<glm::vec3>& path,
                          const Table1Def& options, SlopeRingMethod method, bool eager = false) {
    if (method == SlopeRingMethod::Coherent) {
        CoherentSlopeRing model(mesh, octree, options.params, eager);
        model.setContact(options.contact);
        // The same press for a sphere: its centre the radius out along the target's normal.
        const glm::vec3 out = float(options.contact.toolRadiusMm) * mesh.restNormals()[defaultTargetVertex(mesh)];
        std::vector<glm::vec3> shifted(path);
        for (glm::vec3& p : shifted) p += out;
        return measureModel(model, shifted, options);
    }
    PaperSlopeRing model(mesh, octree, options.params, method);
    return measureModel(model, path, options);
}

Table1Row runRow(GeneratedShape shape, std::size_t vertices, bool wholeModel, const Table1Def& options) {
    auto say = [&](const std::string& line) {
        if (options.progress) options.progress(line);
    };
    say("generating " + std::string(shapeName(shape)) + " with " + std::to_string(vertices) + " vertices");
    auto generated = generateMesh(shape, vertices);
    if (!generated.mesh) throw std::runtime_error(generated.error());
    const TissueMesh& mesh = *generated.mesh;
    const Octree octree(mesh, OctreeDef{});
    const auto path = makePressAndStrokePath(mesh);
    Table1Row row;
    row.shape = shape;
    row.vertices = mesh.vertexCount();
    row.triangles = mesh.triangleCount();
    row.ticks = path.size();
    for (auto method : {SlopeRingMethod::Previous, SlopeRingMethod::Hybrid, SlopeRingMethod::Proposed,
                        SlopeRingMethod::Coherent}) {
        if (!wholeModel && (method == SlopeRingMethod::Previous || method == SlopeRingMethod::Hybrid)) continue;
        say("  " + std::string(methodName(method)));
        row.methods[std::size_t(method)] = measure(mesh, octree, path, options, method);
    }
    say("  coherent (positions written every tick)");
    row.coherentEager = measure(mesh, octree, path, options, SlopeRingMethod::Coherent, true);
    return row;
}

}  // namespace

std::vector<Table1Row> runTable1(const Table1Def& options) {
    std::vector<Table1Row> rows;
    for (auto shape : {GeneratedShape::Sphere, GeneratedShape::Stomach})
        for (std::size_t n : options.paperSizes) rows.push_back(runRow(shape, n, true, options));
    for (std::size_t n : options.largeSphereSizes) rows.push_back(runRow(GeneratedShape::Sphere, n, false, options));
    return rows;
}

}  // namespace palpate
