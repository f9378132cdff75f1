#include "engine/exercise/ExerciseGeometry.h"

#include "engine/exercise/ExerciseKind.h"

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

VertexId GeometryPlacer::place(const SurfacePoint& point, const std::string& key) {
    const VertexId v = ExerciseGeometry::snap(point, mMesh);
    if (v == kNoVertex && mError.empty()) {
        const std::string meshName = mMesh.report().source.empty() ? "the mesh" : mMesh.report().source;
        mError = key + ": vertex " + std::to_string(point.vertex.value_or(0)) + " is not a vertex of " + meshName +
                 " (" + std::to_string(mMesh.vertexCount()) + " vertices)";
    }
    return v;
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

    GeometryPlacer placer(mesh, error);
    exerciseKind(exercise.type).place(exercise, placer, g->mPlaced, error);
    if (!error.empty()) return nullptr;
    return g;
}

double ExerciseGeometry::distanceToPathMm(const glm::vec3& p) const {
    const auto& path = mPlaced.pathMm;
    if (path.empty()) return 0.0;
    if (path.size() == 1) return glm::length(glm::dvec3(p) - glm::dvec3(path[0]));
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 1; i < path.size(); ++i) best = std::min(best, segmentDistance(p, path[i - 1], path[i]));
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
