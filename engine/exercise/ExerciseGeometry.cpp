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
        return "the find-the-lump inclusion needs the coherent slope-ring method (the scene runs " + scene.model().name() + ")";
    try {
        deformer->setCompliance(geometry.compliance());
    } catch (const std::exception& e) {
        return std::string("the inclusion cannot be applied: ") + e.what();
    }
    return {};
}

}  // namespace palpate
