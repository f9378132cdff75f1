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

bool renderedStiffnessNeedsMesh(ModelKind kind) {
    return kind == ModelKind::MassSpringSymplectic || kind == ModelKind::MassSpringRk4 ||
           kind == ModelKind::MassSpringImplicit || kind == ModelKind::MassSpringLocal;
}

std::optional<RenderedStiffness> renderedStiffness(const ModelDef& def, const TissueMesh* mesh, double periodS) {
    if (renderedStiffnessNeedsMesh(def.kind) && !mesh) return std::nullopt;
    RenderedStiffness out;
    switch (def.kind) {
        case ModelKind::SlopeRing:
            out.lines.push_back(slopeRingNormal(def.slopeRing));
            // Only the coherent method renders friction, and only with a friction coefficient.
            if (def.slopeRingMethod == SlopeRingMethod::Coherent && def.contact.staticFriction > 0.0)
                out.lines.push_back(frictionProxy(def.slopeRing));
            break;
        case ModelKind::VolumetricRings: out.lines.push_back(slopeRingNormal(def.slopeRing)); break;
        case ModelKind::RadiusOfInfluence:
            out.lines.push_back(pureSpring(def.radiusOfInfluence.stiffnessNPerMm));
            break;
        case ModelKind::Ffd: out.lines.push_back(pureSpring(def.ffd.stiffnessNPerMm)); break;
        case ModelKind::MassSpringSymplectic:
        case ModelKind::MassSpringRk4:
        case ModelKind::MassSpringImplicit:
        case ModelKind::MassSpringLocal: out.lines.push_back(massSpring(def, *mesh, periodS)); break;
    }
    return out;
}

}  // namespace palpate
