#include "engine/accuracy/OrganSweep.h"

#include "engine/core/Octree.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace palpate {

OrganSweepResult runOrganSweep(const OrganSweepDef& def) {
    const SweepDef& sweep = def.sweep;
    if (const std::string e = joinedMessages(validateToolContact(sweep.contact)); !e.empty())
        throw std::invalid_argument("sweep: " + e);
    if (sweep.maxRings < 1 || sweep.maxRings > kMaxRings)
        throw std::invalid_argument("sweep: max rings must be in 1.." + std::to_string(kMaxRings));
    if (def.sizes.empty()) throw std::invalid_argument("sweep: no sizes to measure");

    OrganSweepResult result;
    SweepDef run = sweep;
    std::vector<SweepModelDef> configs = sweepConfigs(run);
    if (def.stiffeningSeries) {
        StiffeningCalibrationDef stiff;
        stiff.material = hyperelasticMaterialOf(sweep.contact);
        stiff.toolRadiusMm = sweep.contact.toolRadiusMm;
        const StiffeningCalibration reference = calibrateStiffening(stiff);
        run.stiffening = knotsFromCurve(reference.curve, punchFirstSlopeMmPerN(sweep.contact));
        result.stiffening = run.stiffening;
        configs.push_back({ModelKind::SlopeRing, SlopeRingMethod::Coherent, sweep.maxRings, true});
    }
    OrganReferenceDef refDef = def.reference;
    refDef.contact = sweep.contact;

    const double total = double(def.sizes.size() * 3 * configs.size());
    for (std::size_t size : def.sizes) {
        auto generated = generateMesh(def.shape, size);
        if (!generated.mesh) throw std::runtime_error(generated.error());
        const TissueMesh& mesh = *generated.mesh;
        const Octree octree(mesh, OctreeDef{});
        const SweepPaths paths = makeSweepPaths(mesh);
        const OrganReferenceSolver solver(mesh, refDef);
        for (const OrganSite& site : chooseOrganSites(mesh, solver.filled(), sweep.contact.toolRadiusMm)) {
            const OrganReference ref = solver.solve(site);
            OrganSiteSummary summary;
            summary.vertices = mesh.vertexCount();
            summary.site = site;
            summary.depthMm = ref.maxDepthMm;
            summary.linearForceN = ref.linear.forceN;
            if (!ref.hyperelastic.empty()) {
                summary.hyperelasticForceN = ref.hyperelastic.back().forceN;
                summary.hyperelasticDepthMm = ref.hyperelastic.back().depthMm;
            }
            summary.hyperelasticCompleted = ref.hyperelasticCompleted;
            summary.failure = ref.failure;
            summary.nodes = ref.nodes;
            summary.tets = ref.tets;
            summary.seconds = ref.seconds;
            result.sites.push_back(summary);
            if (sweep.progress) {
                std::ostringstream line;
                line << shapeName(def.shape) << " " << mesh.vertexCount() << " " << site.name << " (vertex " << site.vertex
                     << ", layer " << site.thicknessMm << " mm): FEM to " << ref.maxDepthMm << " mm, linear "
                     << ref.linear.forceN << " N, hyperelastic " << summary.hyperelasticForceN << " N"
                     << (ref.hyperelasticCompleted ? "" : " (stopped: " + ref.failure + ")") << ", " << ref.seconds << " s";
                sweep.progress(double(result.sweep.points.size()) / total, line.str());
            }
            PressDef press = sweep.press;
            press.toolDepthMm = ref.maxDepthMm;
            for (const SweepModelDef& config : configs) {
                if (sweep.cancel && sweep.cancel->load(std::memory_order_relaxed)) {
                    result.sweep.cancelled = true;
                    markParetoFront(result.sweep.points);
                    return result;
                }
                SweepPoint p;
                p.shape = def.shape;
                p.site = site.name;
                const std::unique_ptr<DeformationModel> model = makeSweepModel(config, mesh, octree, site.vertex, run, p);
                // A model that touches another vertex than the site has no error here (the paper's
                // methods under a curved patch); it is kept, unmeasured, so the table says so.
                const double a = sweep.contact.toolRadiusMm;
                std::string failure;
                try {
                    const ModelError pressed = measureModelError(*model, mesh, site.vertex, sweep.contact, press);
                    const std::vector<double> field = normalDisplacementsMm(*model, mesh, site.vertex);
                    const OrganError lin = errorAgainstLinear(ref, mesh, field, pressed.indentationMm, pressed.forceN, a);
                    const OrganError hyper =
                        errorAgainstHyperelastic(ref, mesh, field, pressed.indentationMm, pressed.forceN, a);
                    p.error = pressed;
                    p.error.displacementError = lin.measured ? lin.displacementError : std::nan("");
                    p.error.forceError = lin.measured ? lin.forceError : std::nan("");
                    p.error.referenceForceN = lin.referenceForceN;
                    p.hyperelasticDisplacementError = hyper.displacementError;
                    p.hyperelasticForceError = hyper.forceError;
                } catch (const std::runtime_error& e) {
                    failure = e.what();
                    p.error.displacementError = p.error.forceError = std::nan("");
                }
                p.tickUs = sweepTickUs(*model, paths, run);
                result.sweep.points.push_back(p);
                if (sweep.progress) {
                    std::ostringstream line;
                    line << shapeName(def.shape) << " " << p.vertices << " " << site.name << " " << p.series << ": "
                         << p.tickUs << " us, displacement error " << p.error.displacementError << " (linear FEM), "
                         << p.hyperelasticDisplacementError << " (hyperelastic)"
                         << (failure.empty() ? "" : "; not measured: " + failure);
                    sweep.progress(double(result.sweep.points.size()) / total, line.str());
                }
            }
        }
    }
    markParetoFront(result.sweep.points);
    return result;
}

namespace {

nlohmann::ordered_json numberOrNull(double v) { return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr); }

}  // namespace

std::string organSweepToJson(const OrganSweepResult& result, const OrganSweepDef& def) {
    nlohmann::ordered_json j;
    j["tool_radius_mm"] = def.sweep.contact.toolRadiusMm;
    j["youngs_modulus_kpa"] = def.sweep.contact.material.youngsModulusNPerMm2 * 1000.0;
    j["poisson_ratio"] = def.sweep.contact.material.poissonRatio;
    j["stiffening_exponent"] = def.sweep.contact.stiffeningExponent;
    j["reference"] = "fem";
    j["shape"] = std::string(shapeName(def.shape));
    j["cancelled"] = result.sweep.cancelled;
    j["sites"] = nlohmann::ordered_json::array();
    for (const OrganSiteSummary& s : result.sites)
        j["sites"].push_back({{"vertices", s.vertices},
                              {"site", s.site.name},
                              {"vertex", s.site.vertex},
                              {"thickness_mm", s.site.thicknessMm},
                              {"curvature_per_mm", s.site.curvaturePerMm},
                              {"reason", s.site.reason},
                              {"depth_mm", s.depthMm},
                              {"linear_force_n", s.linearForceN},
                              {"hyperelastic_force_n", s.hyperelasticForceN},
                              {"hyperelastic_depth_mm", s.hyperelasticDepthMm},
                              {"hyperelastic_completed", s.hyperelasticCompleted},
                              {"failure", s.failure},
                              {"nodes", s.nodes},
                              {"tets", s.tets},
                              {"seconds", s.seconds}});
    j["stiffening_knots"] = result.stiffening.knots;
    j["points"] = nlohmann::ordered_json::array();
    for (const SweepPoint& p : result.sweep.points)
        j["points"].push_back({{"shape", std::string(shapeName(p.shape))},
                               {"vertices", p.vertices},
                               {"site", p.site},
                               {"series", p.series},
                               {"model", p.model},
                               {"rings", p.rings},
                               {"tick_us", p.tickUs},
                               {"displacement_error", numberOrNull(p.error.displacementError)},
                               {"force_error", numberOrNull(p.error.forceError)},
                               {"displacement_error_hyperelastic", numberOrNull(p.hyperelasticDisplacementError)},
                               {"force_error_hyperelastic", numberOrNull(p.hyperelasticForceError)},
                               {"indentation_mm", p.error.indentationMm},
                               {"force_n", p.error.forceN},
                               {"pareto", p.pareto}});
    return j.dump(2) + "\n";
}

}  // namespace palpate
