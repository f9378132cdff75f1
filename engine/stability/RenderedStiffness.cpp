#include "engine/stability/RenderedStiffness.h"

#include "engine/core/Octree.h"
#include "engine/stability/StabilityBounds.h"
#include "engine/stability/TransferProbe.h"

#include <cmath>
#include <cstdio>

namespace palpate {

namespace {

std::string format(const char* pattern, double value) {
    char buffer[200];
    std::snprintf(buffer, sizeof buffer, pattern, value);
    return buffer;
}

RenderedStiffnessLine slopeRingNormal(const SlopeRingParams& p) {
    RenderedStiffnessLine line;
    line.what = "normal";
    line.staticNPerMm = p.renderedStiffnessNPerMm();
    const PassivitySweep sweep = sweepPassivity(slopeRingTransfer(p));
    line.passiveEquivalentNPerMm = sweep.passiveEquivalentNPerMm;
    line.worstThetaRad = sweep.worstThetaRad;
    const double lambda = slopeRingRelaxationPole(p);
    if (lambda > 1e-9) line.why = format("with the relaxation lag, lambda = %.3g", lambda);
    else if (lambda < -1e-9) line.why = format("with the relaxation's alternation, lambda = %.3g", lambda);
    line.lower = "lower springStiffness (k_s), |m1| or contactStiffness (k_c)";
    if (std::abs(lambda) > 1e-9) line.lower += ", or set forceRelaxation to 0 (automatic: no lag)";
    return line;
}

/// The coherent method's friction proxy: in the stick phase a pure spring of the normal rendered
/// stiffness K_r between the tool and the proxy, tangentially (docs/stability.md).
RenderedStiffnessLine frictionProxy(const SlopeRingParams& p) {
    RenderedStiffnessLine line;
    line.what = "proxy (friction, stick)";
    line.staticNPerMm = p.renderedStiffnessNPerMm();
    const double k = line.staticNPerMm;
    const PassivitySweep sweep = sweepPassivity([k](double) { return std::complex<double>(k, 0.0); });
    line.passiveEquivalentNPerMm = sweep.passiveEquivalentNPerMm;
    line.worstThetaRad = sweep.worstThetaRad;
    line.why = "a pure spring";
    line.lower = "lower springStiffness (k_s), |m1| or contactStiffness (k_c)";
    return line;
}

RenderedStiffnessLine pureSpring(double stiffnessNPerMm) {
    RenderedStiffnessLine line;
    line.what = "normal";
    line.staticNPerMm = stiffnessNPerMm;
    const PassivitySweep sweep = sweepPassivity([stiffnessNPerMm](double) {
        return std::complex<double>(stiffnessNPerMm, 0.0);
    });
    line.passiveEquivalentNPerMm = sweep.passiveEquivalentNPerMm;
    line.worstThetaRad = sweep.worstThetaRad;
    line.lower = "lower stiffness (k_s) or raise the haptic rate";
    return line;
}

RenderedStiffnessLine massSpring(const ModelDef& def, const TissueMesh& mesh, double periodS) {
    RenderedStiffnessLine line;
    line.what = "normal";
    // Above the tissue's frequencies the touched vertex's mass cannot follow the tool and the
    // contact spring alone pushes back: K_eq approaches k_c, whatever the damping (docs/stability.md).
    line.lower = "lower contactStiffness (k_c) or raise the haptic rate";
    if (!validateModelDef(def).empty()) {
        line.staticNPerMm = std::nan("");
        line.passiveEquivalentNPerMm = kNoBound;
        line.why = "not measured: the parameters are invalid";
        return line;
    }
    const Octree octree(mesh, OctreeDef{});
    const auto model = makeModel(def, mesh, octree);
    const MeasuredTransfer measured = measureRenderedTransfer(*model, mesh, highestValenceVertex(mesh), periodS);
    if (!measured.ok) {
        line.staticNPerMm = std::nan("");
        line.passiveEquivalentNPerMm = kNoBound;
        line.why = "not measured: " + measured.problem;
        return line;
    }
    line.staticNPerMm = measured.staticNPerMm;
    const PassivitySweep sweep = sweepPassivity(measured.transfer());
    line.passiveEquivalentNPerMm = sweep.passiveEquivalentNPerMm;
    line.worstThetaRad = sweep.worstThetaRad;
    line.why = "measured: the tissue's dynamics behind the contact";
    return line;
}

}  // namespace

double slopeRingRelaxationPole(const SlopeRingParams& p) {
    return 1.0 - p.effectiveRelaxation() * (1.0 + p.loopGain());
}

RenderedTransfer slopeRingTransfer(const SlopeRingParams& p) {
    const double numerator = p.springStiffnessNPerMm * p.slopeMagnitudeMmPerN[0] * p.effectiveRelaxation() *
                             p.contactStiffnessNPerMm;
    const double lambda = slopeRingRelaxationPole(p);
    return [numerator, lambda](double theta) { return numerator / (1.0 - lambda * std::polar(1.0, -theta)); };
}

double slopeRingPassiveEquivalentNPerMm(const SlopeRingParams& p) {
    const double lambda = std::abs(slopeRingRelaxationPole(p));
    if (!(lambda < 1.0)) return kNoBound;
    return p.renderedStiffnessNPerMm() * (1.0 + lambda) / (1.0 - lambda);
}

bool renderedStiffnessNeedsMesh(const ModelDef& def) {
    return modelDescriptor(def).stability(def).rendered == ModelStability::Rendered::MeasuredOnMesh;
}

std::optional<RenderedStiffness> renderedStiffness(const ModelDef& def, const TissueMesh* mesh, double periodS) {
    const ModelStability rules = modelDescriptor(def).stability(def);
    if (rules.rendered == ModelStability::Rendered::MeasuredOnMesh && !mesh) return std::nullopt;
    RenderedStiffness out;
    switch (rules.rendered) {
        case ModelStability::Rendered::SlopeRing: out.lines.push_back(slopeRingNormal(def.slopeRing)); break;
        case ModelStability::Rendered::PureSpring: out.lines.push_back(pureSpring(rules.springStiffnessNPerMm)); break;
        case ModelStability::Rendered::MeasuredOnMesh: out.lines.push_back(massSpring(def, *mesh, periodS)); break;
    }
    if (rules.rendersFrictionProxy) out.lines.push_back(frictionProxy(def.slopeRing));
    return out;
}

}  // namespace palpate
