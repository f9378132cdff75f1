// palpate-cli calibrate: slopes and spring stiffness for a mesh from E, nu and the tool radius
// (flat-punch calibration, docs/calibration.md), the error they leave against the punch, and optionally a
// tissue preset written with them.
#include "app/cli/Commands.h"
#include "app/cli/MeshOption.h"
#include "base/resources/ShippedResources.h"
#include "app/cli/ToolContactOptions.h"
#include "engine/core/Octree.h"
#include "engine/core/SceneTarget.h"
#include "engine/models/slopering/CoherentSlopeRing.h"
#include "engine/scene/TissuePreset.h"
#include "engine/accuracy/ModelError.h"
#include "engine/accuracy/StiffeningCalibration.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <optional>
#include <iostream>

namespace palpate::cli {

namespace {

/// What a calibration found, for its report.
struct CalibrationReport {
    const std::string& meshPath;
    VertexId touched;
    const ToolContactChoice& choice;
    const SlopeCalibration& calibration;
    const SlopeRingParams& p;
    bool fem;
    const ModelError& error;
    double femError;
    const std::optional<StiffeningCalibration>& stiffening;
};

void printJson(const CalibrationReport& r) {
    const SlopeRingParams& p = r.p;
    nlohmann::ordered_json j;
    j["mesh"] = r.meshPath;
    j["vertex"] = r.touched;
    j["youngs_modulus_kpa"] = r.choice.contact.material.youngsModulusNPerMm2 * 1000.0;
    j["poisson_ratio"] = r.choice.contact.material.poissonRatio;
    j["tool_radius_mm"] = r.choice.contact.toolRadiusMm;
    j["ring_radii_mm"] = r.calibration.ringRadiiMm;
    std::vector<double> slopes(p.slopeMagnitudeMmPerN.begin(), p.slopeMagnitudeMmPerN.begin() + p.ringCount + 1);
    j["slopes_mm_per_n"] = slopes;
    j["spring_stiffness_n_per_mm"] = p.springStiffnessNPerMm;
    j["outside_paper_range"] = r.calibration.outsidePaperRange;
    j["reference"] = r.fem ? "fem" : "punch";
    j["displacement_error"] = r.error.displacementError;
    if (r.fem) j["displacement_error_vs_fem"] = r.femError;
    j["force_error"] = r.error.forceError;
    j["notes"] = r.calibration.notes;
    if (r.stiffening) {
        nlohmann::ordered_json st;
        st["law"] = hyperelasticLawName(hyperelasticMaterialOf(r.choice.contact).law);
        st["stiffening_exponent"] = r.choice.contact.stiffeningExponent;
        st["knots"] = r.stiffening->knots;
        st["force_n"] = r.stiffening->knotForceN;
        st["compliance"] = r.stiffening->knotCompliance;
        st["worst_knot_error_pct"] = 100.0 * r.stiffening->worstKnotErrorFraction;
        st["completed"] = r.stiffening->completed;
        st["seconds"] = r.stiffening->seconds;
        st["curve"] = nlohmann::ordered_json::array();
        for (const auto& c : r.stiffening->curve)
            st["curve"].push_back(
                {{"depth_mm", c.depthMm}, {"force_n", c.forceN}, {"ratio", c.ratio}, {"knot", c.knot}});
        st["notes"] = r.stiffening->notes;
        j["stiffening"] = st;
    }
    std::cout << j.dump(2) << "\n";
}

void printText(const CalibrationReport& r) {
    const SlopeRingParams& p = r.p;
    std::cout << "mesh " << r.meshPath << ", vertex " << r.touched
              << "; E = " << r.choice.contact.material.youngsModulusNPerMm2 * 1000.0
              << " kPa, nu = " << r.choice.contact.material.poissonRatio << ", tool radius "
              << r.choice.contact.toolRadiusMm << " mm (" << r.choice.source << ")\n";
    std::cout << "ring  radius mm  slope mm/N\n";
    for (int ring = 0; ring <= p.ringCount; ++ring)
        std::cout << std::setw(4) << ring << std::setw(11) << std::fixed << std::setprecision(2)
                  << (ring == 0 ? 0.0 : r.calibration.ringRadiiMm[std::size_t(ring - 1)]) << std::setw(12)
                  << std::setprecision(4) << p.slopeMagnitudeMmPerN[std::size_t(ring)] << "\n";
    std::cout << "spring k = " << p.springStiffnessNPerMm
              << " N/mm (= 1/|m1|: the rendered force equals the reference force at the same indentation)\n";
    std::cout << "error against the flat punch: displacement " << std::setprecision(3) << r.error.displacementError
              << " (RMS/peak over r <= 5a, " << r.error.verticesCompared << " vertices), force " << r.error.forceError
              << "\n";
    if (r.fem)
        std::cout << "error against this mesh's FEM (shape at equal indentation): displacement " << r.femError << "\n";
    for (const std::string& note : r.calibration.notes) std::cout << "note: " << note << "\n";
    if (r.stiffening) {
        std::cout << "stiffening (" << hyperelasticLawName(hyperelasticMaterialOf(r.choice.contact).law)
                  << ", b = " << r.choice.contact.stiffeningExponent
                  << "): depth mm, reference force N, ratio to linear, "
                  << "knot model force N\n";
        for (const auto& c : r.stiffening->curve)
            std::cout << std::setw(9) << std::setprecision(3) << c.depthMm << std::setw(12) << std::setprecision(5)
                      << c.forceN << std::setw(10) << std::setprecision(4) << c.ratio << std::setw(12)
                      << std::setprecision(5) << knotForceAtDepthN(p, c.depthMm) << (c.knot ? "  (fitted)" : "")
                      << "\n";
        std::cout << r.stiffening->knots << " knots; worst force error of the knots against the reference "
                  << std::setprecision(3) << 100.0 * r.stiffening->worstKnotErrorFraction << " %\n";
        for (const std::string& note : r.stiffening->notes) std::cout << "note: " << note << "\n";
    }
}

/// --out PRESET: the preset with the calibrated slopes and the tissue they are for.
bool writePreset(const Given& args, TissuePreset preset, const SlopeRingParams& p, const ToolContactChoice& choice,
                 const std::string& out) {
    preset.model.slopeRing = p;
    preset.model.slopeRingMethod = SlopeRingMethod::Coherent;
    if (const auto name = args.option("name")) preset.name = *name;
    if (const auto description = args.option("description")) preset.description = *description;
    TissueProperties tissue;
    tissue.youngsModulusKPa = choice.contact.material.youngsModulusNPerMm2 * 1000.0;
    tissue.poissonRatio = choice.contact.material.poissonRatio;
    tissue.toolRadiusMm = choice.contact.toolRadiusMm;
    tissue.source = args.option("source").value_or(choice.source);
    tissue.stiffeningExponent = choice.contact.stiffeningExponent;
    if (preset.tissue) tissue.stiffeningSource = preset.tissue->stiffeningSource;
    if (const auto s = args.option("stiffening-source")) tissue.stiffeningSource = *s;
    if (preset.tissue) {
        tissue.staticFriction = preset.tissue->staticFriction;
        tissue.dynamicFriction = preset.tissue->dynamicFriction;
    }
    preset.tissue = tissue;
    if (const std::string e = saveTissuePreset(preset, out); !e.empty()) {
        std::cerr << "palpate-cli calibrate: " << e << "\n";
        return false;
    }
    std::cerr << "wrote " << out << "\n";
    return true;
}

int calibrateCommand(const Given& args) {
    // No output may overwrite an input (docs/reliability.md).
    for (const char* output : {"out", "csv"})
        if (const auto out = args.option(output)) {
            std::vector<std::pair<std::string, std::string>> inputs;
            if (const auto preset = args.option("preset")) inputs.emplace_back(*preset, "preset");
            if (const auto mesh = args.option("mesh")) inputs.emplace_back(*mesh, "mesh");
            if (output == std::string("csv"))
                if (const auto preset = args.option("out")) inputs.emplace_back(*preset, "out");
            if (const std::string refused = outputIsAnInput(output, *out, inputs); !refused.empty()) {
                std::cerr << "palpate-cli calibrate: " << refused << "\n";
                return 2;
            }
        }
    const ToolContactChoice choice = toolContactFromArgs(args);
    if (!choice.error.empty()) {
        std::cerr << "palpate-cli calibrate: " << choice.error << "\n";
        return 2;
    }
    // A contact whose slopes a slope-ring cannot render is the user's value, not the slopes' fault:
    // name the option that set it (Young's modulus first, the usual culprit).
    if (const std::string problem = calibrationRangeProblem(choice.contact); !problem.empty()) {
        std::string culprit = "the tissue";
        for (const char* o : {"youngs-kpa", "tool-radius", "poisson"})
            if (const auto text = args.option(o); text && culprit == "the tissue") culprit = "--" + std::string(o) + " " + *text;
        if (culprit == "the tissue" && args.option("preset")) culprit = *args.option("preset") + ": tissue";
        std::cerr << "palpate-cli calibrate: " << culprit << " is out of range: " << problem << "\n";
        return 2;
    }
    TissuePreset preset;
    if (const auto path = args.option("preset")) preset = *loadTissuePreset(*path).preset;  // checked above
    // 1..kMaxRings, as defined (defineCalibrateCommand).
    if (const auto rings = args.option("rings")) preset.model.slopeRing.ringCount = int(*parsePositiveInt(*rings));
    const std::string meshPath = args.option("mesh").value_or(findResource(kDefaultMesh));
    std::string unitError;
    const auto meshUnit = meshUnitFromArgs(args, unitError);
    if (!meshUnit) {
        std::cerr << "palpate-cli calibrate: " << unitError << "\n";
        return 2;
    }
    auto loaded = loadMeshFile("palpate-cli calibrate: ", meshPath, *meshUnit);
    if (!loaded.mesh) {
        std::cerr << "palpate-cli calibrate: " << loaded.error() << "\n";
        return 1;
    }
    const TissueMesh& mesh = *loaded.mesh;
    VertexId touched = defaultTargetVertex(mesh);
    if (const auto vertex = args.option("vertex")) {
        const auto n = parsePositiveInt(*vertex);
        if (*vertex == "0") touched = 0;
        else if (!n || std::size_t(*n) >= mesh.vertexCount()) {
            std::cerr << "palpate-cli calibrate: --vertex: '" << *vertex << "' is not a vertex of " << meshPath << " (0.."
                      << mesh.vertexCount() - 1 << ")\n";
            return 2;
        } else touched = VertexId(*n);
    }

    // --fem: least squares against the reference FEM of this mesh (filled with tetrahedra);
    // otherwise the flat-punch formula at the rings' mean radii.
    const bool fem = args.flag("fem");
    std::vector<double> femField;
    const SlopeCalibration calibration =
        fem ? calibrateSlopesFromFem(mesh, touched, choice.contact, preset.model.slopeRing, 1.0, &femField)
            : calibrateSlopesFromPunch(mesh, touched, choice.contact, preset.model.slopeRing);
    const Octree octree(mesh, preset.octree);
    CoherentSlopeRing model(mesh, octree, calibration.params);
    const ModelError error = measureModelError(model, mesh, touched, choice.contact);
    const double femError =
        fem ? displacementErrorAgainstField(mesh, touched, normalDisplacementsMm(model, mesh, touched), femField,
                                            choice.contact.toolRadiusMm)
            : NAN;

    // --nonlinear: stiffening knots from the hyperelastic punch (docs/calibration.md, "Knots from the
    // hyperelastic reference"), fitted to this calibration's |m1|.
    std::optional<StiffeningCalibration> stiffening;
    SlopeCalibration calibrated = calibration;
    if (args.flag("nonlinear")) {
        StiffeningCalibrationDef def;
        def.material = hyperelasticMaterialOf(choice.contact);
        def.toolRadiusMm = choice.contact.toolRadiusMm;
        if (const auto text = args.option("nonlinear-depth")) {
            const auto mm = parseNumber(*text);
            if (!mm || !(*mm > 0.0 && *mm < 2.0 * def.toolRadiusMm)) {
                std::cerr << "palpate-cli calibrate: --nonlinear-depth: '" << *text << "' is not a depth in (0, "
                          << 2.0 * def.toolRadiusMm << ") mm (twice the tool radius)\n";
                return 2;
            }
            setStiffeningDepths(def, *mm / def.toolRadiusMm);
        }
        std::cerr << "calibrate: hyperelastic punch (" << hyperelasticLawName(def.material.law) << ", b = "
                  << def.material.stiffeningExponent << ") to " << def.depthsOverRadius.back() * def.toolRadiusMm
                  << " mm ...\n";
        try {
            const StiffeningCalibration reference = calibrateStiffening(def);
            StiffeningCalibration knots = knotsFromCurve(reference.curve, calibrated.params.slopeMagnitudeMmPerN[0]);
            knots.completed = reference.completed;
            knots.failure = reference.failure;
            knots.seconds = reference.seconds;
            knots.freeDofs = reference.freeDofs;
            knots.notes.insert(knots.notes.begin(), reference.notes.begin(), reference.notes.end());
            applyStiffening(knots, calibrated.params);
            stiffening = std::move(knots);
        } catch (const std::exception& e) {
            std::cerr << "palpate-cli calibrate: --nonlinear: " << e.what() << "\n";
            return 1;
        }
    }
    const SlopeRingParams& p = calibrated.params;
    // --csv FILE (with --nonlinear): the reference curve beside the linear and the knotted model.
    if (const auto csv = args.option("csv")) {
        if (!stiffening) {
            std::cerr << "palpate-cli calibrate: --csv goes with --nonlinear (it writes the stiffening curve)\n";
            return 2;
        }
        std::ostringstream text;
        text << "depth_mm,reference_force_n,ratio,linear_force_n,knot_force_n,fitted\n";
        for (const auto& c : stiffening->curve)
            text << c.depthMm << ',' << c.forceN << ',' << c.ratio << ',' << c.depthMm / p.slopeMagnitudeMmPerN[0] << ','
                 << knotForceAtDepthN(p, c.depthMm) << ',' << (c.knot ? 1 : 0) << '\n';
        std::ofstream out(*csv);
        out << text.str();
        if (!out) {
            std::cerr << "palpate-cli calibrate: " << *csv << ": cannot be written\n";
            return 1;
        }
    }
    const CalibrationReport report{meshPath, touched, choice, calibration, p, fem, error, femError, stiffening};
    if (args.flag("json")) printJson(report);
    else printText(report);
    if (const auto out = args.option("out"))
        if (!writePreset(args, preset, p, choice, *out)) return 1;
    return 0;
}

}  // namespace

void defineCalibrateCommand(CommandLine& cli) {
    CLI::App* calibrate = cli.command(cli.root(), "calibrate",
                                      "the slope-ring's slopes for a tissue, against the flat punch or this mesh's FEM "
                                      "(docs/calibration.md)",
                                      calibrateCommand);
    addValue(*calibrate, "mesh", "FILE", "the tissue mesh (default: the shipped one)");
    addMeshUnitOption(*calibrate);
    addValue(*calibrate, "rings", "N", "the ring count")->check(wholeNumberIn(1, kMaxRings));
    addValue(*calibrate, "vertex", "V", "the vertex pressed (default: the scene's target)");
    addFlag(*calibrate, "fem", "fit against this mesh's FEM instead of the flat punch");
    addFlag(*calibrate, "json", "print JSON");
    addValue(*calibrate, "out", "PRESET", "write the calibrated tissue preset");
    addValue(*calibrate, "name", "NAME", "the written preset's name");
    addValue(*calibrate, "description", "TEXT", "the written preset's description");
    addValue(*calibrate, "source", "TEXT", "where the tissue's values come from, kept in the preset");
    addFlag(*calibrate, "nonlinear", "also fit stiffening knots to the hyperelastic punch");
    addValue(*calibrate, "nonlinear-depth", "MM", "with --nonlinear: the deepest press, below twice the tool radius");
    addValue(*calibrate, "stiffening-source", "TEXT", "where the stiffening comes from, kept in the preset");
    addValue(*calibrate, "csv", "FILE", "with --nonlinear: write the stiffening curve as CSV");
    addToolContactOptions(*calibrate);
}

}  // namespace palpate::cli
