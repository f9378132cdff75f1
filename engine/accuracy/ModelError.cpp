#include "engine/accuracy/ModelError.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace palpate {

namespace {

/// RMS over the loaded region (within regionInRadii tool radii of the contact, facing the same way:
/// the far side of a thin shape is not on this surface) of model - reference(v, r), over |peak|.
template <typename Reference>
double regionError(const TissueMesh& mesh, VertexId touched, const std::vector<double>& normalDisplacementMm,
                   double peakMm, double toolRadiusMm, double regionInRadii, int* verticesCompared, Reference reference) {
    const auto& rest = mesh.restPositionsMm();
    const auto& normals = mesh.restNormals();
    const glm::dvec3 centre(rest[touched]);
    const glm::dvec3 n(normals[touched]);
    const double regionMm = regionInRadii * toolRadiusMm;
    double sum2 = 0.0;
    int count = 0;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const glm::dvec3 d = glm::dvec3(rest[v]) - centre;
        if (glm::length(d) > regionMm || glm::dot(glm::dvec3(normals[v]), n) <= 0.0) continue;
        const double r = glm::length(d - glm::dot(d, n) * n);
        const double e = normalDisplacementMm[v] - reference(v, r);
        sum2 += e * e;
        ++count;
    }
    if (verticesCompared) *verticesCompared = count;
    if (count == 0 || !(std::abs(peakMm) > 0.0)) return NAN;
    return std::sqrt(sum2 / double(count)) / std::abs(peakMm);
}

}  // namespace

double displacementErrorAgainstPunch(const TissueMesh& mesh, VertexId touched, const std::vector<double>& normalDisplacementMm,
                                     double toolRadiusMm, double regionInRadii, int* verticesCompared) {
    const double peakMm = normalDisplacementMm[touched];
    return regionError(mesh, touched, normalDisplacementMm, peakMm, toolRadiusMm, regionInRadii, verticesCompared,
                       [&](std::size_t, double r) { return punchSurfaceDisplacementMm(toolRadiusMm, peakMm, r); });
}

double displacementErrorAgainstField(const TissueMesh& mesh, VertexId touched, const std::vector<double>& normalDisplacementMm,
                                     const std::vector<double>& referenceNormalDisplacementMm, double toolRadiusMm,
                                     double regionInRadii, int* verticesCompared) {
    // Compare shapes at equal indentation: the model's field scaled to the reference's peak.
    const double peakMm = referenceNormalDisplacementMm[touched];
    const double scale = normalDisplacementMm[touched] != 0.0 ? peakMm / normalDisplacementMm[touched] : 0.0;
    std::vector<double> scaled(normalDisplacementMm);
    for (double& x : scaled) x *= scale;
    return regionError(mesh, touched, scaled, peakMm, toolRadiusMm, regionInRadii, verticesCompared,
                       [&](std::size_t v, double) { return referenceNormalDisplacementMm[v]; });
}

std::vector<double> normalDisplacementsMm(const DeformationModel& model, const TissueMesh& mesh, VertexId touched) {
    const auto positions = model.positionsMm();
    const glm::dvec3 n(mesh.restNormals()[touched]);
    std::vector<double> out(mesh.vertexCount());
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
        out[v] = glm::dot(glm::dvec3(mesh.restPositionsMm()[v]) - glm::dvec3(positions[v]), n);
    return out;
}

ModelError measureModelError(DeformationModel& model, const TissueMesh& mesh, VertexId touched,
                             const ToolContact& contact, const PressDef& press) {
    if (touched >= mesh.vertexCount()) throw std::invalid_argument("touched vertex " + std::to_string(touched) + " is not in the mesh");
    const glm::vec3 rest = mesh.restPositionsMm()[touched];
    const glm::vec3 n = mesh.restNormals()[touched];
    const glm::vec3 tool = rest - float(press.toolDepthMm) * n;
    model.reset();
    TickResult last;
    for (int i = 0; i < press.settleTicks; ++i) last = model.step(tool, 0.001);
    if (!last.contact || last.touched != touched)
        throw std::runtime_error("pressing vertex " + std::to_string(touched) + " by " + std::to_string(press.toolDepthMm) +
                                 " mm gave " + (last.contact ? "contact on vertex " + std::to_string(last.touched) : std::string("no contact")));

    const std::vector<double> normalDisplacement = normalDisplacementsMm(model, mesh, touched);

    ModelError e;
    e.indentationMm = normalDisplacement[touched];
    e.displacementError = displacementErrorAgainstPunch(mesh, touched, normalDisplacement, contact.toolRadiusMm,
                                                        press.regionInRadii, &e.verticesCompared);
    e.forceN = glm::length(glm::dvec3(last.forceN));
    e.referenceForceN = punchForceN(contact.material, contact.toolRadiusMm, e.indentationMm);
    e.forceError = std::abs(e.forceN - e.referenceForceN) / e.referenceForceN;
    return e;
}

}  // namespace palpate
