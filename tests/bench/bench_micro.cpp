// Micro-benchmarks: the three nearest-vertex searches and one haptic tick of each method, over the
// press-and-stroke tool path (engine/core/ToolPath.h) on generated spheres.
//   palpate_microbench --benchmark_filter=Search   (or Step)

#include "engine/core/MeshGenerator.h"
#include "engine/core/Octree.h"
#include "engine/models/slopering/SlopeRingModel.h"
#include "engine/core/SceneTarget.h"
#include "engine/core/ToolPath.h"
#include "engine/loop/HapticSnapshot.h"
#include "engine/stability/DivergenceGuard.h"

#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <stdexcept>

namespace palpate {
namespace {

struct Scene {
    TissueMesh mesh;
    std::unique_ptr<Octree> octree;
    std::vector<glm::vec3> path;
};

const Scene& sphereScene(std::size_t vertices) {
    static std::map<std::size_t, std::unique_ptr<Scene>> cache;
    auto& slot = cache[vertices];
    if (!slot) {
        auto loaded = generateMesh(GeneratedShape::Sphere, vertices);
        if (!loaded.mesh) throw std::runtime_error(loaded.error());
        slot = std::make_unique<Scene>(Scene{std::move(*loaded.mesh), nullptr, {}});
        slot->octree = std::make_unique<Octree>(slot->mesh, OctreeDef{});
        slot->path = makePressAndStrokePath(slot->mesh);
    }
    return *slot;
}

void setCounters(benchmark::State& state, const Scene& scene) {
    state.SetItemsProcessed(state.iterations());
    state.counters["vertices"] = double(scene.mesh.vertexCount());
}

void BM_SearchLinear(benchmark::State& state) {
    const Scene& scene = sphereScene(std::size_t(state.range(0)));
    const auto& rest = scene.mesh.restPositionsMm();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(nearestLinear(scene.path[i], rest));
        if (++i == scene.path.size()) i = 0;
    }
    setCounters(state, scene);
}

void BM_SearchNodeFaithful(benchmark::State& state) {
    const Scene& scene = sphereScene(std::size_t(state.range(0)));
    const auto& rest = scene.mesh.restPositionsMm();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(scene.octree->searchNodeFaithful(scene.path[i], rest));
        if (++i == scene.path.size()) i = 0;
    }
    setCounters(state, scene);
}

void BM_SearchExactWarm(benchmark::State& state) {
    const Scene& scene = sphereScene(std::size_t(state.range(0)));
    const auto& rest = scene.mesh.restPositionsMm();
    std::size_t i = 0;
    VertexId last = kNoVertex;
    for (auto _ : state) {
        last = scene.octree->nearestExact(scene.path[i], rest, {}, last);
        benchmark::DoNotOptimize(last);
        if (++i == scene.path.size()) i = 0;
    }
    setCounters(state, scene);
}

void BM_SearchExactCold(benchmark::State& state) {
    const Scene& scene = sphereScene(std::size_t(state.range(0)));
    const auto& rest = scene.mesh.restPositionsMm();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(scene.octree->nearestExact(scene.path[i], rest, {}, kNoVertex));
        if (++i == scene.path.size()) i = 0;
    }
    setCounters(state, scene);
}

void BM_Step(benchmark::State& state) {
    const Scene& scene = sphereScene(std::size_t(state.range(0)));
    const auto method = SlopeRingMethod(state.range(1));
    const auto modelOwner = makeSlopeRing(scene.mesh, *scene.octree, SlopeRingParams{}, method);
    SlopeRingModel& model = *modelOwner;
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(model.step(scene.path[i], 1e-3));
        if (++i == scene.path.size()) i = 0;
    }
    setCounters(state, scene);
    state.SetLabel(std::string(methodName(method)));
}

// Ours as the loop runs it, in parts: the step (a sphere of the default tool radius on the same
// press, its centre the radius further out), the divergence guard, the snapshot's copy of the
// displaced vertices (range(1): 0 step only, 1 + guard, 2 + guard + copy).
void BM_LoopTickOurs(benchmark::State& state) {
    const Scene& scene = sphereScene(std::size_t(state.range(0)));
    const auto modelOwner = makeSlopeRing(scene.mesh, *scene.octree, SlopeRingParams{}, SlopeRingMethod::Coherent);
    SlopeRingModel& model = *modelOwner;
    model.setContact({.toolRadiusMm = 5.0, .staticFriction = 0.3, .dynamicFriction = 0.2});
    const glm::vec3 out = 5.0f * scene.mesh.restNormals()[defaultTargetVertex(scene.mesh)];
    DivergenceGuard guard;
    std::vector<VertexId> ids(HapticSnapshot::kMaxDisplaced);
    std::vector<glm::vec3> positions(HapticSnapshot::kMaxDisplaced);
    std::vector<std::uint8_t> rings(HapticSnapshot::kMaxDisplaced);
    std::size_t i = 0;
    for (auto _ : state) {
        const TickResult r = model.step(scene.path[i] + out, 1e-3);
        benchmark::DoNotOptimize(r);
        if (state.range(1) >= 1) benchmark::DoNotOptimize(guard.check(scene.mesh, model, r));
        if (state.range(1) >= 2)
            benchmark::DoNotOptimize(model.copyDisplaced(ids.data(), positions.data(), rings.data(), ids.size()));
        if (++i == scene.path.size()) i = 0;
    }
    setCounters(state, scene);
}

BENCHMARK(BM_LoopTickOurs)->ArgsProduct({{8664}, {0, 1, 2}})->ArgNames({"vertices", "parts"});
BENCHMARK(BM_SearchLinear)->Arg(1442)->Arg(8664)->Arg(100000);
BENCHMARK(BM_SearchNodeFaithful)->Arg(1442)->Arg(8664)->Arg(100000);
BENCHMARK(BM_SearchExactWarm)->Arg(1442)->Arg(8664)->Arg(100000);
BENCHMARK(BM_SearchExactCold)->Arg(1442)->Arg(8664)->Arg(100000);
BENCHMARK(BM_Step)
    ->ArgsProduct({{1442, 8664},
                   {int(SlopeRingMethod::Previous), int(SlopeRingMethod::Hybrid), int(SlopeRingMethod::Proposed),
                    int(SlopeRingMethod::Coherent)}})
    ->ArgNames({"vertices", "method"});
// Ours on fine meshes, where the touched-vertex search's certificate is hardest.
BENCHMARK(BM_Step)
    ->ArgsProduct({{100000, 1000000}, {int(SlopeRingMethod::Coherent)}})
    ->ArgNames({"vertices", "method"});

}  // namespace
}  // namespace palpate
