#include "engine/lod/LodMeasure.h"

#include "engine/core/Octree.h"
#include "engine/core/Rings.h"
#include "engine/core/SceneTarget.h"
#include "engine/models/ModelRegistry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

namespace palpate {

namespace {

VertexId nearestVertex(const TissueMesh& mesh, const glm::vec3& pointMm) {
    VertexId best = 0;
    float bestD2 = std::numeric_limits<float>::infinity();
    const auto& rest = mesh.restPositionsMm();
    for (VertexId v = 0; v < rest.size(); ++v) {
        const glm::vec3 d = rest[v] - pointMm;
        const float d2 = glm::dot(d, d);
        if (d2 < bestD2) {
            bestD2 = d2;
            best = v;
        }
    }
    return best;
}

}  // namespace

Problems validateLodMeasureDef(const LodMeasureDef& def) {
    if (Problems e = validateToolContact(def.contact); !e.empty()) return e;
    if (def.ringCounts.empty()) return oneProblem("ringCounts", "ring counts: none given");
    for (int r : def.ringCounts)
        if (r < 1 || r > kMaxRings)
            return oneProblem("ringCounts",
                              "ring counts: " + std::to_string(r) + " is not in 1.." + std::to_string(kMaxRings));
    if (def.timing.repeats < 1) return oneProblem("timing.repeats", "timing repeats must be at least 1");
    if (!(def.timing.minMeasureMs >= 0.0))
        return oneProblem("timing.minMeasureMs", "timing min measure ms must be 0 or more");
    if (def.press.settleTicks < 1 || !(def.press.toolDepthMm > 0.0) || !(def.press.regionInRadii > 0.0))
        return oneProblem("press", "press: settle ticks, tool depth and region must be positive");
    return {};
}

LodMeasurement measureLodCandidates(const MeshLevels& levels, const LodMeasureDef& def, const LodProgressFn& progress,
                                    const std::atomic<bool>* cancel) {
    if (const std::string e = joinedMessages(validateLodMeasureDef(def)); !e.empty())
        throw std::invalid_argument("lod measure: " + e);
    if (levels.levels.empty()) throw std::invalid_argument("lod measure: no levels");
    const std::set<int> ringSet(def.ringCounts.begin(), def.ringCounts.end());
    const TissueMesh& fine = levels.levels.front().mesh;
    const glm::vec3 targetMm = fine.restPositionsMm()[defaultTargetVertex(fine)];
    const double total = double(levels.levels.size() * ringSet.size());

    LodMeasurement out;
    for (std::size_t L = 0; L < levels.levels.size(); ++L) {
        const TissueMesh& mesh = levels.levels[L].mesh;
        const Octree octree(mesh, OctreeDef{});
        // The same physical spot on every level: the level's vertex nearest the source's target,
        // and for the error, the source vertex under it (the same point: decimation keeps positions).
        const VertexId touched = nearestVertex(mesh, targetMm);
        const VertexId fineTouched = nearestVertex(fine, mesh.restPositionsMm()[touched]);
        const auto path = makePressAndStrokePath(mesh, def.path);
        for (int rings : ringSet) {
            if (cancel && cancel->load(std::memory_order_relaxed)) {
                out.cancelled = true;
                return out;
            }
            LodCandidate c;
            c.level = L;
            c.vertices = mesh.vertexCount();
            c.triangles = mesh.triangleCount();
            c.rings = rings;
            try {
                SlopeRingParams base = def.base;
                base.ringCount = rings;
                const SlopeCalibration calibration = calibrateSlopesFromPunch(mesh, touched, def.contact, base);
                ModelDef modelDef;
                modelDef.kind = ModelKind::SlopeRing;
                modelDef.slopeRingMethod = SlopeRingMethod::Coherent;
                modelDef.slopeRing = calibration.params;
                const auto model = makeModel(modelDef, mesh, octree);
                c.model = modelName(modelDef);
                const ModelError levelError = measureModelError(*model, mesh, touched, def.contact, def.press);
                c.levelErrorFraction = levelError.displacementError;
                c.forceErrorFraction = levelError.forceError;
                // measureModelError leaves the model pressed: carry that surface to the source.
                const std::vector<glm::vec3> shown = levels.toFine(L, model->positionsMm());
                const glm::dvec3 n(fine.restNormals()[fineTouched]);
                std::vector<double> normalDisplacementMm(fine.vertexCount());
                for (std::size_t v = 0; v < fine.vertexCount(); ++v)
                    normalDisplacementMm[v] = glm::dot(glm::dvec3(fine.restPositionsMm()[v]) - glm::dvec3(shown[v]), n);
                c.errorFraction = displacementErrorAgainstPunch(fine, fineTouched, normalDisplacementMm, def.contact.toolRadiusMm,
                                                                def.press.regionInRadii, &c.verticesCompared);
                c.tickUs = medianTickUs(*model, path, def.timing);
                if (c.verticesCompared < kMinVerticesCompared) {
                    std::ostringstream s;
                    s << "only " << c.verticesCompared << " source vertices within " << def.press.regionInRadii
                      << " tool radii of the contact: the mesh is too coarse for this tool to measure an error";
                    c.note = s.str();
                    c.errorFraction = std::nan("");
                }
            } catch (const std::exception& e) {
                c.errorFraction = c.levelErrorFraction = c.forceErrorFraction = c.tickUs = std::nan("");
                c.note = e.what();
            }
            out.candidates.push_back(c);
            if (progress) {
                std::ostringstream line;
                if (c.note.empty()) line << describeCandidate(c);
                else line << "level " << L << ", " << rings << " rings: not measured: " << c.note;
                progress(double(out.candidates.size()) / total, line.str());
            }
        }
    }
    return out;
}

}  // namespace palpate
