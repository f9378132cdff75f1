// The headless demo: the default scene, a scripted press-and-stroke through a simulated device,
// and a summary of what happened. What the run command does when there is no display.
#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/cli/DefaultScene.h"
#include "device/ScriptedDevice.h"
#include "engine/Octree.h"
#include "engine/SlopeRingDeformer.h"
#include "engine/ToolPath.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <iostream>

namespace palpate::cli {

int demoCommand(const std::vector<std::string>& words) {
    Args args(words, {"json"}, {"mesh", "method"});
    if (!args.ok()) {
        std::cerr << "demo: " << args.error() << "\n";
        return 2;
    }
    std::string meshPath = args.option("mesh").value_or(findResource(kDefaultMesh));
    if (meshPath.empty()) {
        std::cerr << "demo: the default mesh " << kDefaultMesh << " was not found (set PALPATE_RESOURCES)\n";
        return 1;
    }
    const auto method = parseMethod(args.option("method").value_or("palpate"));
    if (!method) {
        std::cerr << "demo: unknown --method (use previous, hybrid, proposed or palpate)\n";
        return 2;
    }
    auto loaded = TissueMesh::load(meshPath);
    if (!loaded.mesh) {
        std::cerr << loaded.report.text();
        return 1;
    }
    const TissueMesh& mesh = *loaded.mesh;
    const Octree octree(mesh, OctreeDef{});
    SlopeRingDeformer deformer(mesh, octree, SlopeRingParams{}, *method);
    ScriptedDevice device(makePressAndStrokePath(mesh));
    device.open();

    std::size_t ticks = 0, contactTicks = 0, touchedChanges = 0;
    double peakForceN = 0.0, peakDisplacementMm = 0.0;
    VertexId lastTouched = kNoVertex;
    DeviceSample sample;
    const auto start = std::chrono::steady_clock::now();
    while (!device.finished() && device.read(sample)) {
        const TickResult r = deformer.step(sample.positionMm, 0.001);
        device.writeForce(r.forceN);
        ++ticks;
        if (r.contact) ++contactTicks;
        if (r.touched != lastTouched) ++touchedChanges;
        lastTouched = r.touched;
        peakForceN = std::max(peakForceN, double(glm::length(r.forceN)));
        if (r.touched != kNoVertex)
            peakDisplacementMm = std::max(peakDisplacementMm, double(glm::length(deformer.positionsMm()[r.touched] -
                                                                                mesh.restPositionsMm()[r.touched])));
    }
    const double elapsedUs = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    // Let the tissue relax after the release and measure what is left.
    const glm::vec3 away = mesh.boundsMaxMm() + glm::vec3(50.0f);
    for (int i = 0; i < 200; ++i) deformer.step(away, 0.001);
    double residualMm = 0.0;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
        residualMm = std::max(residualMm, double(glm::length(deformer.positionsMm()[v] - mesh.restPositionsMm()[v])));

    if (args.flag("json")) {
        nlohmann::json j{{"mesh", meshPath},
                         {"vertices", mesh.vertexCount()},
                         {"triangles", mesh.triangleCount()},
                         {"method", std::string(methodName(*method))},
                         {"ticks", ticks},
                         {"contact_ticks", contactTicks},
                         {"touched_changes", touchedChanges},
                         {"peak_force_n", peakForceN},
                         {"peak_displacement_mm", peakDisplacementMm},
                         {"residual_after_release_mm", residualMm},
                         {"cache_refreshes", deformer.cacheRefreshes()},
                         {"full_searches", deformer.fullSearches()},
                         {"mean_tick_us", elapsedUs / double(std::max<std::size_t>(1, ticks))}};
        std::cout << j.dump(2) << "\n";
    } else {
        std::cout << "Palpate headless demo\n"
                  << "  scene: " << meshPath << " (" << mesh.vertexCount() << " vertices, " << mesh.triangleCount()
                  << " triangles)\n"
                  << "  device: simulated, scripted press-and-stroke (" << ticks << " ticks at 1 kHz)\n"
                  << "  method: " << methodName(*method) << ", " << deformer.params().ringCount << " rings\n"
                  << "  contact on " << contactTicks << " ticks; touched vertex changed " << touchedChanges
                  << " times\n"
                  << "  peak force " << peakForceN << " N, peak displacement " << peakDisplacementMm << " mm\n"
                  << "  after release the surface relaxed to within " << residualMm << " mm of rest\n"
                  << "  touched-vertex search: candidate cache retaken " << deformer.cacheRefreshes()
                  << " times, full octree search " << deformer.fullSearches() << " times\n"
                  << "  mean tick " << elapsedUs / double(std::max<std::size_t>(1, ticks)) << " us\n";
    }
    return 0;
}

}  // namespace palpate::cli
