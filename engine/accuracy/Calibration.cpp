#include "engine/accuracy/Calibration.h"

#include "engine/core/Rings.h"
#include "engine/fem/SurfaceFill.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace palpate {

namespace {

RingSet ringsOf(const TissueMesh& mesh, VertexId touched, int ringCount) {
    if (touched >= mesh.vertexCount()) throw std::invalid_argument("touched vertex " + std::to_string(touched) + " is not in the mesh");
    if (ringCount < 0 || ringCount > kMaxRings)
        throw std::invalid_argument("ring count " + std::to_string(ringCount) + " is outside 0.." + std::to_string(kMaxRings));
    RingFinder finder(mesh);
    RingSet rings = finder.makeRingSet();
    finder.find(touched, ringCount, rings);
    return rings;
}

double tangentDistanceMm(const TissueMesh& mesh, VertexId touched, VertexId v) {
    const glm::dvec3 n = glm::dvec3(mesh.restNormals()[touched]);
    const glm::dvec3 d = glm::dvec3(mesh.restPositionsMm()[v]) - glm::dvec3(mesh.restPositionsMm()[touched]);
    return glm::length(d - glm::dot(d, n) * n);
}

/// Keeps |m_0| > |m_1| > ... (validation requires it), noting each ring that had to be lowered.
void enforceDecrease(SlopeCalibration& c, const char* why) {
    auto& m = c.params.slopeMagnitudeMmPerN;
    for (int r = 1; r <= c.params.ringCount; ++r) {
        if (m[std::size_t(r)] < m[std::size_t(r - 1)] && m[std::size_t(r)] > 0.0) continue;
        m[std::size_t(r)] = std::max(m[std::size_t(r - 1)] * 0.999, kMinCalibratedSlopeMmPerN);
        c.notes.push_back("ring " + std::to_string(r) + " " + why + "; its slope is set just below ring " +
                          std::to_string(r - 1) + "'s so the slopes still decrease");
    }
}

void finish(SlopeCalibration& c) {
    auto& p = c.params;
    const double m1 = p.slopeMagnitudeMmPerN[0];
    p.springStiffnessNPerMm = 1.0 / m1;
    p.slopeLimitMmPerN = std::max(1.0, m1 * 1.0001);
    c.outsidePaperRange = m1 >= 1.0;
    if (c.outsidePaperRange) {
        std::ostringstream s;
        s << "|m1| = " << m1 << " mm/N is outside the paper's range (0, 1) mm/N (soft tissue or a small tool); "
          << "the contact update stays stable (loop gain " << p.loopGain() << ", relaxation solved exactly)";
        c.notes.push_back(s.str());
    }
}

}  // namespace

Problems validateToolContact(const ToolContact& contact) {
    if (Problems e = validateElasticMaterial(contact.material); !e.empty()) return e;
    if (!std::isfinite(contact.toolRadiusMm) || contact.toolRadiusMm <= 0.0)
        return oneProblem("toolRadiusMm", "tool radius must be a positive number of mm");
    if (!(contact.stiffeningExponent >= 0.0 && contact.stiffeningExponent <= 100.0))
        return oneProblem("stiffeningExponent", "stiffening exponent must be a number in 0..100");
    return {};
}

bool sameToolContact(const ToolContact& a, const ToolContact& b) {
    return a.material.youngsModulusNPerMm2 == b.material.youngsModulusNPerMm2 &&
           a.material.poissonRatio == b.material.poissonRatio && a.toolRadiusMm == b.toolRadiusMm &&
           a.stiffeningExponent == b.stiffeningExponent;
}

HyperelasticMaterial hyperelasticMaterialOf(const ToolContact& contact) {
    HyperelasticMaterial m;
    m.law = contact.stiffeningExponent > 0.0 ? HyperelasticLaw::Exponential : HyperelasticLaw::NeoHookean;
    m.smallStrain = contact.material;
    m.stiffeningExponent = contact.stiffeningExponent;
    return m;
}

double punchFirstSlopeMmPerN(const ToolContact& contact) {
    return 1.0 / (2.0 * contact.toolRadiusMm * planeStrainModulusNPerMm2(contact.material));
}

std::string calibrationRangeProblem(const ToolContact& contact) {
    if (std::string e = joinedMessages(validateToolContact(contact)); !e.empty()) return e;
    // finish() sets the slope limit just above |m1|; the limit's own range bounds |m1|.
    const FieldDef<SlopeRingParams>* limit = findField(slopeRingFields(), "slopeLimitMmPerN");
    const double maxSlope = (limit ? limit->spec.hi : 100.0) / 1.0001;
    const double m1 = punchFirstSlopeMmPerN(contact);
    if (std::isfinite(m1) && m1 >= kMinCalibratedSlopeMmPerN && m1 <= maxSlope) return {};
    const double a = contact.toolRadiusMm;
    const double nu = contact.material.poissonRatio;
    // E (kPa) between which |m1| = 1 / (2 a E / (1 - nu^2)) stays in [min, max] for this tool.
    const double loKPa = (1.0 - nu * nu) / (2.0 * a * maxSlope) * 1000.0;
    const double hiKPa = (1.0 - nu * nu) / (2.0 * a * kMinCalibratedSlopeMmPerN) * 1000.0;
    const double eStar = planeStrainModulusNPerMm2(contact.material);
    const double loMm = 1.0 / (2.0 * eStar * maxSlope), hiMm = 1.0 / (2.0 * eStar * kMinCalibratedSlopeMmPerN);
    std::ostringstream s;
    s << "Young's modulus " << contact.material.youngsModulusNPerMm2 * 1000.0 << " kPa with a " << a
      << " mm tool gives a first-ring slope of " << m1 << " mm/N, "
      << (std::isfinite(m1) && m1 < kMinCalibratedSlopeMmPerN ? "below the smallest" : "above the largest")
      << " a slope-ring renders (" << kMinCalibratedSlopeMmPerN << " to " << maxSlope
      << " mm/N): for this tool and Poisson's ratio, Young's modulus must be " << loKPa << " to " << hiKPa
      << " kPa; for this material, the tool radius " << loMm << " to " << hiMm << " mm";
    return s.str();
}

std::vector<double> ringMeanRadiiMm(const TissueMesh& mesh, VertexId touched, int ringCount) {
    const RingSet rings = ringsOf(mesh, touched, ringCount);
    std::vector<double> radii;
    for (int r = 1; r <= rings.ringCount; ++r) {
        double sum = 0.0;
        const auto ring = rings.ring(r);
        for (VertexId v : ring) sum += tangentDistanceMm(mesh, touched, v);
        radii.push_back(ring.empty() ? 0.0 : sum / double(ring.size()));
    }
    return radii;
}

SlopeCalibration calibrateSlopesFromPunch(const TissueMesh& mesh, VertexId touched, const ToolContact& contact,
                                          const SlopeRingParams& base) {
    if (const std::string e = calibrationRangeProblem(contact); !e.empty()) throw std::invalid_argument(e);
    SlopeCalibration c;
    c.params = base;
    c.ringRadiiMm = ringMeanRadiiMm(mesh, touched, base.ringCount);
    const double a = contact.toolRadiusMm;
    const double m1 = 1.0 / (2.0 * a * planeStrainModulusNPerMm2(contact.material));
    auto& m = c.params.slopeMagnitudeMmPerN;
    m[0] = m1;
    for (int r = 1; r <= base.ringCount; ++r) {
        const double rk = c.ringRadiiMm[std::size_t(r - 1)];
        // punchSurfaceDisplacementMm(a, 1, r) is the displacement per unit indentation: 1 inside the tool.
        m[std::size_t(r)] = m1 * punchSurfaceDisplacementMm(a, 1.0, rk);
    }
    enforceDecrease(c, "lies inside the tool radius (the punch moves it as far as the touched vertex)");
    finish(c);
    return c;
}

SlopeCalibration calibrateSlopesFromDisplacements(const TissueMesh& mesh, VertexId touched,
                                                  const std::vector<double>& normalDisplacementMm, double forceN,
                                                  const SlopeRingParams& base) {
    if (normalDisplacementMm.size() != mesh.vertexCount())
        throw std::invalid_argument("reference displacements: " + std::to_string(normalDisplacementMm.size()) +
                                    " values for " + std::to_string(mesh.vertexCount()) + " vertices");
    if (!std::isfinite(forceN) || forceN <= 0.0) throw std::invalid_argument("reference force must be positive");
    SlopeCalibration c;
    c.params = base;
    c.ringRadiiMm = ringMeanRadiiMm(mesh, touched, base.ringCount);
    const RingSet rings = ringsOf(mesh, touched, base.ringCount);
    auto& m = c.params.slopeMagnitudeMmPerN;
    for (int r = 0; r <= base.ringCount; ++r) {
        // Least squares of u_v = m F over the ring: m = sum(u_v F) / sum(F^2) = mean(u_v) / F.
        double sum = 0.0;
        const auto ring = rings.ring(r);
        for (VertexId v : ring) sum += normalDisplacementMm[v];
        m[std::size_t(r)] = ring.empty() ? 0.0 : sum / double(ring.size()) / forceN;
    }
    if (!(m[0] > 0.0)) throw std::invalid_argument("reference displacement of the touched vertex is not into the tissue");
    enforceDecrease(c, "moves as far as the ring inside it in the reference");
    finish(c);
    return c;
}

SlopeCalibration calibrateSlopesFromFem(const TissueMesh& mesh, VertexId touched, const ToolContact& contact,
                                        const SlopeRingParams& base, double indentationMm,
                                        std::vector<double>* referenceNormalDisplacementMm) {
    if (const std::string e = joinedMessages(validateToolContact(contact)); !e.empty()) throw std::invalid_argument(e);
    if (touched >= mesh.vertexCount()) throw std::invalid_argument("touched vertex " + std::to_string(touched) + " is not in the mesh");
    const SurfaceIndentation fem = indentSurface(mesh, touched, contact.toolRadiusMm, indentationMm, contact.material);
    const glm::dvec3 n(mesh.restNormals()[touched]);
    std::vector<double> normal(mesh.vertexCount());
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) normal[v] = -glm::dot(fem.displacementMm[v], n);
    SlopeCalibration c = calibrateSlopesFromDisplacements(mesh, touched, normal, fem.reactionForceN, base);
    std::ostringstream s;
    s << "FEM reference: " << fem.nodes << " nodes, " << fem.tets << " tets, tissue " << fem.thicknessMm
      << " mm thick over a rigid core, " << fem.prescribedVertexCount << " vertices under the tool, reaction "
      << fem.reactionForceN << " N at " << indentationMm << " mm";
    c.notes.insert(c.notes.begin(), s.str());
    if (referenceNormalDisplacementMm) *referenceNormalDisplacementMm = std::move(normal);
    return c;
}

}  // namespace palpate
