// Micro-benchmarks: the three nearest-vertex searches and one haptic tick of each method, over the
// press-and-stroke tool path (engine/core/ToolPath.h) on generated spheres.
//   palpate_microbench --benchmark_filter=Search   (or Step)

#include "engine/core/MeshGenerator.h"
#include "engine/core/Octree.h"
#include "engine/models/slopering/SlopeRingModel.h"
#include "engine/core/ToolPath.h"

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
