#include "engine/accuracy/AccuracySweep.h"

#include "engine/core/Octree.h"
#include "engine/core/SceneTarget.h"
#include "engine/models/TickTimer.h"
#include "engine/core/ToolPath.h"
#include "engine/models/ModelRegistry.h"

#include <nlohmann/json.hpp>

#include <sstream>
#include <stdexcept>

namespace palpate {

std::string sweepSeriesName(SlopeRingMethod method, int rings) {
    if (method == SlopeRingMethod::Coherent)
        return rings < 1 ? std::string() : "slope-ring " + std::to_string(rings) + (rings == 1 ? " ring" : " rings");
    // The paper's three methods are measured with the paper's 2 rings only.
    return rings == 2 ? std::string(methodName(method)) + " (paper)" : std::string();
}

SweepResult runSweep(const SweepDef& def) {
    if (const std::string e = validateToolContact(def.contact); !e.empty()) throw std::invalid_argument("sweep: " + e);
    if (def.maxRings < 1 || def.maxRings > kMaxRings)
        throw std::invalid_argument("sweep: max rings must be in 1.." + std::to_string(kMaxRings));
    if (def.sizes.empty() || def.shapes.empty()) throw std::invalid_argument("sweep: no shapes or sizes to measure");

    struct Config {
        ModelKind kind;
        SlopeRingMethod method;
        int rings;
    };
    std::vector<Config> configs;
    for (int r = 1; r <= def.maxRings; ++r) configs.push_back({ModelKind::SlopeRing, SlopeRingMethod::Coherent, r});
    if (def.paperMethods)
        for (auto m : {SlopeRingMethod::Proposed, SlopeRingMethod::Hybrid, SlopeRingMethod::Previous})
            configs.push_back({ModelKind::SlopeRing, m, 2});
    if (def.otherModels)
        for (auto k : {ModelKind::MassSpringLocal, ModelKind::MassSpringSymplectic, ModelKind::MassSpringRk4,
                       ModelKind::MassSpringImplicit, ModelKind::RadiusOfInfluence, ModelKind::Ffd,
                       ModelKind::VolumetricRings})
            configs.push_back({k, SlopeRingMethod::Coherent, 2});
    const double punchStiffnessNPerMm = 2.0 * def.contact.toolRadiusMm * planeStrainModulusNPerMm2(def.contact.material);

    SweepResult result;
    const double total = double(def.shapes.size() * def.sizes.size() * configs.size());
    for (GeneratedShape shape : def.shapes) {
        for (std::size_t size : def.sizes) {
            auto generated = generateMesh(shape, size);
            if (!generated.mesh) throw std::runtime_error(generated.error());
            const TissueMesh& mesh = *generated.mesh;
            const Octree octree(mesh, OctreeDef{});
            const auto path = makePressAndStrokePath(mesh);
            ToolPathDef shortDef;
            shortDef.approachTicks /= 10;
            shortDef.pressTicks /= 10;
            shortDef.holdTicks /= 10;
            shortDef.strokeTicks /= 10;
            shortDef.releaseTicks /= 10;
            shortDef.strokeLengthMm /= 10.0;
            const auto shortPath = makePressAndStrokePath(mesh, shortDef);
            const VertexId touched = defaultTargetVertex(mesh);
            for (const Config& config : configs) {
                if (def.cancel && def.cancel->load(std::memory_order_relaxed)) {
                    result.cancelled = true;
                    markParetoFront(result.points);
                    return result;
                }
                SlopeRingParams base = def.base;
                base.ringCount = config.rings;
                const SlopeCalibration calibration = calibrateSlopesFromPunch(mesh, touched, def.contact, base);
                ModelDef modelDef;
                modelDef.kind = config.kind;
                modelDef.slopeRingMethod = config.method;
                modelDef.slopeRing = calibration.params;
                modelDef.volumetricRings.slopeRing = calibration.params;
                modelDef.radiusOfInfluence.radiusMm = def.press.regionInRadii * def.contact.toolRadiusMm;
                modelDef.radiusOfInfluence.stiffnessNPerMm = punchStiffnessNPerMm;
                modelDef.ffd.stiffnessNPerMm = punchStiffnessNPerMm;
                const std::unique_ptr<DeformationModel> model = makeModel(modelDef, mesh, octree);

                SweepPoint p;
                p.model = modelName(modelDef);
                p.series = config.kind == ModelKind::SlopeRing ? sweepSeriesName(config.method, config.rings) : p.model;
                p.rings = config.kind == ModelKind::SlopeRing || config.kind == ModelKind::VolumetricRings ? config.rings : 0;
                p.shape = shape;
                p.vertices = mesh.vertexCount();
                p.error = measureModelError(*model, mesh, touched, def.contact, def.press);
                // A probe over the path's first ticks says whether the full path would take too long.
                const std::vector<glm::vec3> probe(path.begin(), path.begin() + std::min<std::size_t>(path.size(), 50));
                const double probeUs = medianTickUs(*model, probe, {1, 0.0});
                const bool shorten = probeUs * double(path.size()) > def.maxPathSeconds * 1e6;
                p.tickUs = medianTickUs(*model, shorten ? shortPath : path, {def.timingRepeats, def.minMeasureMs});
                result.points.push_back(p);
                if (def.progress) {
                    std::ostringstream line;
                    line << shapeName(shape) << " " << p.vertices << " " << p.series << ": " << p.tickUs
                         << " us, displacement error " << p.error.displacementError;
                    def.progress(double(result.points.size()) / total, line.str());
                }
            }
        }
    }
    markParetoFront(result.points);
    return result;
}

void markParetoFront(std::vector<SweepPoint>& points) {
    for (SweepPoint& p : points) {
        p.pareto = true;
        for (const SweepPoint& q : points) {
            if (&p == &q || q.shape != p.shape) continue;
            const bool noWorse = q.tickUs <= p.tickUs && q.error.displacementError <= p.error.displacementError;
            const bool better = q.tickUs < p.tickUs || q.error.displacementError < p.error.displacementError;
            if (noWorse && better) {
                p.pareto = false;
                break;
            }
        }
    }
}

std::string sweepToCsv(const std::vector<SweepPoint>& points) {
    std::ostringstream out;
    out << "shape,vertices,series,model,rings,tick_us,displacement_error,force_error,indentation_mm,force_n,"
           "reference_force_n,vertices_compared,pareto\n";
    for (const SweepPoint& p : points)
        out << shapeName(p.shape) << ',' << p.vertices << ',' << p.series << ',' << p.model << ',' << p.rings << ','
            << p.tickUs << ',' << p.error.displacementError << ',' << p.error.forceError << ',' << p.error.indentationMm
            << ',' << p.error.forceN << ',' << p.error.referenceForceN << ',' << p.error.verticesCompared << ','
            << (p.pareto ? 1 : 0) << '\n';
    return out.str();
}

std::string sweepToJson(const SweepResult& result, const SweepDef& def) {
    nlohmann::ordered_json j;
    j["tool_radius_mm"] = def.contact.toolRadiusMm;
    j["youngs_modulus_kpa"] = def.contact.material.youngsModulusNPerMm2 * 1000.0;
    j["poisson_ratio"] = def.contact.material.poissonRatio;
    j["reference"] = "punch";
    j["cancelled"] = result.cancelled;
    j["points"] = nlohmann::ordered_json::array();
    for (const SweepPoint& p : result.points)
        j["points"].push_back({{"shape", std::string(shapeName(p.shape))},
                               {"vertices", p.vertices},
                               {"series", p.series},
                               {"model", p.model},
                               {"rings", p.rings},
                               {"tick_us", p.tickUs},
                               {"displacement_error", p.error.displacementError},
                               {"force_error", p.error.forceError},
                               {"indentation_mm", p.error.indentationMm},
                               {"pareto", p.pareto}});
    return j.dump(2) + "\n";
}

}  // namespace palpate
