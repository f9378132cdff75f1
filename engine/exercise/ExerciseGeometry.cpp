#include "engine/exercise/ExerciseGeometry.h"

#include "engine/scene/HapticScene.h"
#include "engine/models/slopering/CoherentSlopeRing.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace palpate {

namespace {

double segmentDistance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
    const glm::dvec3 pa = glm::dvec3(p) - glm::dvec3(a), ba = glm::dvec3(b) - glm::dvec3(a);
    const double len2 = glm::dot(ba, ba);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(pa, ba) / len2, 0.0, 1.0) : 0.0;
    return glm::length(pa - t * ba);
}

/// The distance from `origin` along the unit direction `dir` to the sphere (centre, radius): the
/// nearer crossing ahead, 0 when the origin is inside, negative when the ray misses it.
double rayToSphereMm(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& centre, double radius) {
    const glm::dvec3 oc = origin - centre;
    const double c = glm::dot(oc, oc) - radius * radius;
    if (c <= 0.0) return 0.0;
    const double b = glm::dot(oc, dir);
    const double disc = b * b - c;
    if (disc < 0.0 || b > 0.0) return -1.0;  // misses, or the sphere is behind
    return -b - std::sqrt(disc);
}

}  // namespace

VertexId ExerciseGeometry::snap(const SurfacePoint& point, const TissueMesh& mesh) {
    const std::size_t n = mesh.vertexCount();
    if (point.vertex) {
        // The file's numbering: find the engine vertex that came from it.
        const auto& original = mesh.originalIndex();
        for (VertexId v = 0; v < n; ++v)
            if ((original.empty() ? v : original[v]) == *point.vertex) return v;
        return kNoVertex;
    }
    VertexId best = kNoVertex;
    double best2 = std::numeric_limits<double>::infinity();
    const auto& rest = mesh.restPositionsMm();
    for (VertexId v = 0; v < n; ++v) {
        const glm::dvec3 d = glm::dvec3(rest[v]) - glm::dvec3(point.pointMm);
        const double d2 = glm::dot(d, d);
        if (d2 < best2) {
            best2 = d2;
            best = v;
        }
    }
    return best;
}

std::shared_ptr<const ExerciseGeometry> ExerciseGeometry::build(const Exercise& exercise, const TissueMesh& mesh,
                                                                std::string& error) {
    std::shared_ptr<ExerciseGeometry> g(new ExerciseGeometry());
    g->mExercise = exercise;
    g->mRubric = effectiveRubric(exercise);
    g->mRestMm = mesh.restPositionsMm();
    g->mNormals = mesh.restNormals();
    g->mNeighbourStart = mesh.neighbourStart();
    g->mNeighbours = mesh.neighbours();
    const std::size_t n = mesh.vertexCount();

    g->mVertexAreaMm2.assign(n, 0.0f);
    for (const auto& t : mesh.triangles()) {
        const glm::dvec3 a(g->mRestMm[t[0]]), b(g->mRestMm[t[1]]), c(g->mRestMm[t[2]]);
        const double third = glm::length(glm::cross(b - a, c - a)) / 6.0;
        for (VertexId v : t) g->mVertexAreaMm2[v] += float(third);
    }

    const std::string meshName = mesh.report().source.empty() ? "the mesh" : mesh.report().source;
    auto place = [&](const SurfacePoint& p, const std::string& key) -> VertexId {
        const VertexId v = snap(p, mesh);
        if (v == kNoVertex && error.empty())
            error = key + ": vertex " + std::to_string(p.vertex.value_or(0)) + " is not a vertex of " + meshName +
                    " (" + std::to_string(n) + " vertices)";
        return v;
    };
    switch (exercise.type) {
        case ExerciseType::PressTargets:
            for (std::size_t i = 0; i < exercise.pressTargets.targets.size(); ++i) {
                const PressTarget& t = exercise.pressTargets.targets[i];
                ResolvedTarget r;
                r.def = t;
                r.vertex = place(t.at, "press_targets.targets[" + std::to_string(i) + "]");
                if (r.vertex != kNoVertex) r.pointMm = g->mRestMm[r.vertex];
                g->mTargets.push_back(r);
            }
            break;
        case ExerciseType::FindLump: {
            const InclusionDef& inc = exercise.findLump.inclusion;
            g->mLumpVertex = place(inc.centre, "find_lump.inclusion.centre");
            if (g->mLumpVertex == kNoVertex) break;
            g->mLumpCentreMm = g->mRestMm[g->mLumpVertex];
            g->mCompliance.assign(n, 1.0f);
            const double r2 = inc.radiusMm * inc.radiusMm;
            for (VertexId v = 0; v < n; ++v) {
                const glm::dvec3 d = glm::dvec3(g->mRestMm[v]) - glm::dvec3(g->mLumpCentreMm);
                if (glm::dot(d, d) <= r2) {
                    g->mCompliance[v] = float(inc.stiffnessFactor);
                    ++g->mInclusionVertices;
                }
            }
            break;
        }
        case ExerciseType::DetectLumps: {
            // Each vertex looks straight in (along its rest normal): the first lump that ray meets
            // is the one under it, and how far in it lies is where pressing starts to meet it.
            g->mCompliance.assign(n, 1.0f);
            g->mEngageDepthMm.assign(n, 0.0f);
            g->mLumpOfVertex.assign(n, -1);
            std::vector<double> nearest(n, std::numeric_limits<double>::infinity());
            for (std::size_t k = 0; k < exercise.detectLumps.lumps.size(); ++k) {
                const LumpDef& def = exercise.detectLumps.lumps[k];
                ResolvedLump lump;
                lump.def = def;
                lump.vertex = place(def.at, "detect_lumps.lumps[" + std::to_string(k) + "]");
                if (lump.vertex == kNoVertex) break;
                lump.surfaceMm = g->mRestMm[lump.vertex];
                const glm::dvec3 centre = glm::dvec3(lump.surfaceMm) -
                                          (def.depthMm + def.radiusMm) * glm::dvec3(g->mNormals[lump.vertex]);
                lump.centreMm = glm::vec3(centre);
                for (VertexId v = 0; v < n; ++v) {
                    const double depth = rayToSphereMm(glm::dvec3(g->mRestMm[v]), -glm::dvec3(g->mNormals[v]), centre,
                                                       def.radiusMm);
                    // Met no deeper than the lump's centre lies under its own point: a ray that
                    // crosses the whole body to reach it from behind is not over it.
                    if (depth < 0.0 || depth > def.depthMm + def.radiusMm) continue;
                    const float c = float(1.0 / def.contrast);
                    // The nearest lump under a vertex is the one it meets; at equal depth the stiffer.
                    if (depth < nearest[v] || (depth == nearest[v] && c < g->mCompliance[v])) {
                        nearest[v] = depth;
                        g->mCompliance[v] = c;
                        g->mEngageDepthMm[v] = float(depth);
                        g->mLumpOfVertex[v] = std::int16_t(k);
                    }
                }
                g->mLumps.push_back(lump);
            }
            for (VertexId v = 0; v < n; ++v)
                if (g->mLumpOfVertex[v] >= 0 && std::size_t(g->mLumpOfVertex[v]) < g->mLumps.size()) {
                    ++g->mLumps[std::size_t(g->mLumpOfVertex[v])].footprintVertices;
                    ++g->mInclusionVertices;
                }
            break;
        }
        case ExerciseType::Trace: {
            for (std::size_t i = 0; i < exercise.trace.path.size(); ++i) {
                const VertexId v = place(exercise.trace.path[i], "trace.path[" + std::to_string(i) + "]");
                if (v != kNoVertex) {
                    g->mPathMm.push_back(g->mRestMm[v]);
                    g->mPathVertices.push_back(v);
                }
            }
            if (!error.empty()) break;
            for (std::size_t i = 1; i < g->mPathMm.size(); ++i) {
                const glm::vec3 a = g->mPathMm[i - 1], b = g->mPathMm[i];
                const double length = glm::length(glm::dvec3(b) - glm::dvec3(a));
                g->mPathLengthMm += length;
                const int steps = std::max(1, int(std::ceil(length / 1.0)));
                for (int s = 0; s < steps; ++s)
                    g->mCoverageMm.push_back(glm::vec3(glm::dvec3(a) + (glm::dvec3(b) - glm::dvec3(a)) * (double(s) / steps)));
            }
            if (!g->mPathMm.empty()) g->mCoverageMm.push_back(g->mPathMm.back());
            if (g->mPathLengthMm <= 0.0) error = "trace.path: its points all snap to one vertex: the path has no length";
            break;
        }
    }
    if (!error.empty()) return nullptr;
    return g;
}

double ExerciseGeometry::distanceToPathMm(const glm::vec3& p) const {
    if (mPathMm.empty()) return 0.0;
    if (mPathMm.size() == 1) return glm::length(glm::dvec3(p) - glm::dvec3(mPathMm[0]));
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 1; i < mPathMm.size(); ++i) best = std::min(best, segmentDistance(p, mPathMm[i - 1], mPathMm[i]));
    return best;
}

std::string applyExercisePhysics(const ExerciseGeometry& geometry, HapticScene& scene) {
    if (geometry.compliance().empty()) return {};
    if (scene.mesh().vertexCount() != geometry.vertexCount())
        return "the exercise's inclusion is for a mesh of " + std::to_string(geometry.vertexCount()) +
               " vertices, the scene has " + std::to_string(scene.mesh().vertexCount());
    auto* deformer = dynamic_cast<CoherentSlopeRing*>(&scene.model());
    if (!deformer)  // the paper's methods stay as published
        return "the exercise's lumps need the coherent slope-ring method (the scene runs " + scene.model().name() + ")";
    try {
        if (geometry.engageDepthMm().empty()) deformer->setCompliance(geometry.compliance());
        else deformer->setLumps(geometry.compliance(), geometry.engageDepthMm());
    } catch (const std::exception& e) {
        return std::string("the inclusion cannot be applied: ") + e.what();
    }
    return {};
}

}  // namespace palpate
