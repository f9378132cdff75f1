#include "engine/accuracy/AccuracySweep.h"

#include "engine/core/Octree.h"
#include "engine/core/SceneTarget.h"
#include "engine/models/TickTimer.h"
#include "engine/core/ToolPath.h"
#include "engine/models/ModelRegistry.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace palpate {

std::string sweepSeriesName(SlopeRingMethod method, int rings) {
    if (method == SlopeRingMethod::Coherent)
        return rings < 1 ? std::string() : "slope-ring " + std::to_string(rings) + (rings == 1 ? " ring" : " rings");
    // The paper's three methods are measured with the paper's 2 rings only.
    return rings == 2 ? std::string(methodName(method)) + " (paper)" : std::string();
}

std::vector<SweepModelDef> sweepConfigs(const SweepDef& def) {
    std::vector<SweepModelDef> configs;
    for (int r = 1; r <= def.maxRings; ++r) configs.push_back({ModelKind::SlopeRing, SlopeRingMethod::Coherent, r});
    if (def.paperMethods)
        for (auto m : {SlopeRingMethod::Proposed, SlopeRingMethod::Hybrid, SlopeRingMethod::Previous})
            configs.push_back({ModelKind::SlopeRing, m, 2});
    if (def.otherModels)
        for (auto k : {ModelKind::MassSpringLocal, ModelKind::MassSpringSymplectic, ModelKind::MassSpringRk4,
                       ModelKind::MassSpringImplicit, ModelKind::RadiusOfInfluence, ModelKind::Ffd,
                       ModelKind::VolumetricRings})
            configs.push_back({k, SlopeRingMethod::Coherent, 2});
    return configs;
}

std::unique_ptr<DeformationModel> makeSweepModel(const SweepModelDef& config, const TissueMesh& mesh, const Octree& octree,
                                                 VertexId touched, const SweepDef& def, SweepPoint& point) {
    const double punchStiffnessNPerMm = 2.0 * def.contact.toolRadiusMm * planeStrainModulusNPerMm2(def.contact.material);
    SlopeRingParams base = def.base;
    base.ringCount = config.rings;
    SlopeCalibration calibration = calibrateSlopesFromPunch(mesh, touched, def.contact, base);
    if (config.stiffening) applyStiffening(def.stiffening, calibration.params);
    ModelDef modelDef;
    modelDef.kind = config.kind;
    modelDef.slopeRingMethod = config.method;
    modelDef.slopeRing = calibration.params;
    modelDef.radiusOfInfluence.radiusMm = def.press.regionInRadii * def.contact.toolRadiusMm;
    modelDef.radiusOfInfluence.stiffnessNPerMm = punchStiffnessNPerMm;
    modelDef.ffd.stiffnessNPerMm = punchStiffnessNPerMm;
    point.model = modelName(modelDef);
    point.series = config.kind == ModelKind::SlopeRing ? sweepSeriesName(config.method, config.rings) : point.model;
    if (config.stiffening) point.series += " (stiffening)";
    point.rings = config.kind == ModelKind::SlopeRing || config.kind == ModelKind::VolumetricRings ? config.rings : 0;
    point.vertices = mesh.vertexCount();
    return makeModel(modelDef, mesh, octree);
}

SweepPaths makeSweepPaths(const TissueMesh& mesh) {
    SweepPaths p;
    p.full = makePressAndStrokePath(mesh);
    p.shortened = makePressAndStrokePath(mesh, shortenedTenTimes());
    return p;
}

double sweepTickUs(DeformationModel& model, const SweepPaths& paths, const SweepDef& def) {
    // A probe over the path's first ticks says whether the full path would take too long.
    const std::vector<glm::vec3> probe(paths.full.begin(), paths.full.begin() + std::min<std::size_t>(paths.full.size(), 50));
    const double probeUs = medianTickUs(model, probe, {1, 0.0});
    const bool shorten = probeUs * double(paths.full.size()) > def.maxPathSeconds * 1e6;
    return medianTickUs(model, shorten ? paths.shortened : paths.full, {def.timingRepeats, def.minMeasureMs});
}

SweepResult runSweep(const SweepDef& def) {
    if (const std::string e = joinedMessages(validateToolContact(def.contact)); !e.empty())
        throw std::invalid_argument("sweep: " + e);
    if (def.maxRings < 1 || def.maxRings > kMaxRings)
        throw std::invalid_argument("sweep: max rings must be in 1.." + std::to_string(kMaxRings));
    if (def.sizes.empty() || def.shapes.empty()) throw std::invalid_argument("sweep: no shapes or sizes to measure");
    const std::vector<SweepModelDef> configs = sweepConfigs(def);

    SweepResult result;
    const double total = double(def.shapes.size() * def.sizes.size() * configs.size());
    for (GeneratedShape shape : def.shapes) {
        for (std::size_t size : def.sizes) {
            auto generated = generateMesh(shape, size);
            if (!generated.mesh) throw std::runtime_error(generated.error());
            const TissueMesh& mesh = *generated.mesh;
            const Octree octree(mesh, OctreeDef{});
            const SweepPaths paths = makeSweepPaths(mesh);
            const VertexId touched = defaultTargetVertex(mesh);
            for (const SweepModelDef& config : configs) {
                if (def.cancel && def.cancel->load(std::memory_order_relaxed)) {
                    result.cancelled = true;
                    markParetoFront(result.points);
                    return result;
                }
                SweepPoint p;
                p.shape = shape;
                const std::unique_ptr<DeformationModel> model = makeSweepModel(config, mesh, octree, touched, def, p);
                p.error = measureModelError(*model, mesh, touched, def.contact, def.press);
                p.tickUs = sweepTickUs(*model, paths, def);
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
        p.pareto = std::isfinite(p.error.displacementError);  // an unmeasured point is on no front
        if (!p.pareto) continue;
        for (const SweepPoint& q : points) {
            if (&p == &q || q.shape != p.shape || q.site != p.site || !std::isfinite(q.error.displacementError)) continue;
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
           "reference_force_n,vertices_compared,pareto,site,displacement_error_hyperelastic,force_error_hyperelastic\n";
    // Not measured (NaN) is written as an empty field.
    const auto value = [&](double v) -> std::ostream& { return std::isfinite(v) ? out << v : out; };
    for (const SweepPoint& p : points) {
        out << shapeName(p.shape) << ',' << p.vertices << ',' << p.series << ',' << p.model << ',' << p.rings << ','
            << p.tickUs << ',';
        value(p.error.displacementError) << ',';
        value(p.error.forceError) << ',' << p.error.indentationMm << ',' << p.error.forceN << ','
                                  << p.error.referenceForceN << ',' << p.error.verticesCompared << ','
                                  << (p.pareto ? 1 : 0) << ',' << p.site << ',';
        value(p.hyperelasticDisplacementError) << ',';
        value(p.hyperelasticForceError) << '\n';
    }
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
