// The headless demo: the default scene and a simulated device driven through the haptic loop in
// stepped mode (the same tick as the real thread, on a virtual clock), and a summary of what
// happened. What the run command does when there is no display.
#include "app/cli/Commands.h"
#include "app/cli/MeshOption.h"
#include "base/resources/ShippedResources.h"
#include "device/open/DeviceUri.h"
#include "device/SimulatedDevice.h"
#include "engine/loop/HapticLoop.h"
#include "engine/core/SceneTarget.h"
#include "engine/models/ModelRegistry.h"
#include "engine/scene/TissuePreset.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <iostream>

namespace palpate::cli {

namespace {

int demoCommand(const Given& args) {
    const std::string meshPath = args.option("mesh").value_or(findResource(kDefaultMesh));
    if (meshPath.empty()) {
        std::cerr << "demo: the default mesh " << kDefaultMesh << " was not found (set PALPATE_RESOURCES)\n";
        return 1;
    }
    const auto method = parseMethod(args.option("method").value_or("coherent"));
    if (!method) {
        std::cerr << "demo: unknown --method (use previous, hybrid, proposed or coherent)\n";
        return 2;
    }
    // --model NAME: any registry model (docs/models.md); --method stays for the slope-ring methods.
    // The default tissue's tool and friction (ours touches with its sphere).
    ModelDef model;
    model.slopeRingMethod = *method;
    model.contact = presetModelDef(TissuePreset{}).contact;
    if (auto name = args.option("model")) {
        const auto def = modelDefForName(*name);
        if (!def) {
            std::string names;
            for (const std::string& n : modelNames()) names += (names.empty() ? "" : ", ") + n;
            std::cerr << "demo: unknown --model '" << *name << "' (use one of " << names << ")\n";
            return 2;
        }
        if (args.option("method") && def->kind == ModelKind::SlopeRing && def->slopeRingMethod != *method) {
            std::cerr << "demo: --model " << *name << " and --method " << methodName(*method) << " disagree\n";
            return 2;
        }
        const ContactDef contact = model.contact;
        model = *def;
        model.contact = contact;
    }
    std::string unitError;
    const auto meshUnit = meshUnitFromArgs(args, unitError);
    if (!meshUnit) {
        std::cerr << "demo: " << unitError << "\n";
        return 2;
    }
    auto loaded = loadMeshFile("demo: ", meshPath, *meshUnit);
    if (!loaded.mesh) {
        std::cerr << loaded.report.text();
        return 1;
    }
    const std::string uri = args.option("device").value_or("sim:stroke");
    std::string error;
    auto device = openDeviceUri(uri, error);
    if (!device) {
        std::cerr << "demo: " << error << "\n";
        return 1;
    }
    const auto* simulated = dynamic_cast<const SimulatedDevice*>(device.get());
    if (!simulated || !std::isfinite(simulated->durationS())) {
        std::cerr << "demo: " << uri << " has no end; use sim:press, sim:stroke, sim:scan or sim:path:FILE\n";
        return 2;
    }
    const double durationS = simulated->durationS();
    const std::size_t vertices = loaded.mesh->vertexCount(), triangles = loaded.mesh->triangleCount();
    const std::vector<glm::vec3> rest = loaded.mesh->restPositionsMm();
    aimAtDefaultTarget(*device, *loaded.mesh, float(modelToolRadiusMm(model)));

    HapticLoopDef def;
    std::unique_ptr<HapticScene> scene;
    try {
        scene = HapticScene::create(std::move(*loaded.mesh), model);
    } catch (const std::exception& e) {
        std::cerr << "demo: " << e.what() << "\n";
        return 1;
    }
    HapticLoop loop(def, std::move(scene), std::move(device));
    const auto ticksToRun = std::uint64_t(std::ceil(durationS / loop.periodS())) + 300;  // then relax
    std::uint64_t contactTicks = 0, touchedChanges = 0;
    double peakForceN = 0.0, peakDisplacementMm = 0.0;
    VertexId lastTouched = kNoVertex;
    const auto start = std::chrono::steady_clock::now();
    for (std::uint64_t i = 0; i < ticksToRun; ++i) {
        loop.stepOnce();
        const HapticSnapshot& s = loop.newestSnapshot();
        if (s.contact) ++contactTicks;
        if (s.touched != lastTouched && s.touched != kNoVertex) ++touchedChanges;
        lastTouched = s.touched;
        peakForceN = std::max(peakForceN, double(glm::length(s.forceN)));
        for (std::uint32_t k = 0; k < s.displacedCount; ++k)
            peakDisplacementMm = std::max(
                peakDisplacementMm, double(glm::length(s.displacedPositionsMm[k] - rest[s.displacedIds[k]])));
    }
    const double elapsedUs = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    const HapticSnapshot& last = loop.newestSnapshot();
    double residualMm = 0.0;
    for (std::uint32_t k = 0; k < last.displacedCount; ++k)
        residualMm = std::max(residualMm, double(glm::length(last.displacedPositionsMm[k] - rest[last.displacedIds[k]])));
    const LoopReport report = loop.report();

    if (args.flag("json")) {
        nlohmann::json j{{"mesh", meshPath},
                         {"vertices", vertices},
                         {"triangles", triangles},
                         {"method", std::string(methodName(*method))},
                         {"model", modelName(model)},
                         {"device", uri},
                         {"ticks", report.counters.ticks},
                         {"contact_ticks", contactTicks},
                         {"touched_changes", touchedChanges},
                         {"peak_force_n", peakForceN},
                         {"peak_displacement_mm", peakDisplacementMm},
                         {"residual_after_release_mm", residualMm},
                         {"determinism_hash", report.determinismHash},
                         {"mean_tick_us", elapsedUs / double(report.counters.ticks)}};
        std::cout << j.dump(2) << "\n";
    } else {
        std::cout << "Palpate headless demo (haptic loop in stepped mode)\n"
                  << "  scene: " << meshPath << " (" << vertices << " vertices, " << triangles << " triangles)\n"
                  << "  device: " << uri << ", " << report.counters.ticks << " ticks at "
                  << 1.0 / loop.periodS() << " Hz of loop time\n"
                  << "  model: " << modelName(model) << "\n"
                  << "  contact on " << contactTicks << " ticks; touched vertex changed " << touchedChanges
                  << " times\n"
                  << "  peak force sent to the device " << peakForceN << " N (after the safety filter), peak "
                  << "displacement " << peakDisplacementMm << " mm\n"
                  << "  after release the surface relaxed to within " << residualMm << " mm of rest\n"
                  << "  determinism hash " << std::hex << report.determinismHash << std::dec << "\n"
                  << "  mean tick " << elapsedUs / double(report.counters.ticks) << " us (wall clock, with snapshots)\n";
    }
    return 0;
}

}  // namespace

void defineDemoCommand(CommandLine& cli) {
    CLI::App* demo = cli.command(cli.root(), "demo", "a simulated press on the default scene, in stepped mode",
                                 demoCommand);
    addValue(*demo, "mesh", "FILE", "the tissue mesh (default: the shipped one)");
    addMeshUnitOption(*demo);
    addValue(*demo, "method", "M", "the slope-ring method: previous, hybrid, proposed or coherent (default)");
    addValue(*demo, "model", "NAME", "any deformation model (docs/models.md)");
    addValue(*demo, "device", "URI", "a simulated device with an end (default sim:stroke)");
    addFlag(*demo, "json", "print JSON");
}

}  // namespace palpate::cli
