#include "engine/bench/SlidePath.h"

#include "engine/core/SceneTarget.h"
#include "engine/lod/NearestTriangle.h"
#include "engine/core/HapticRate.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace palpate {

namespace {

struct SurfacePoint {
    glm::dvec3 pointMm{0.0};
    glm::dvec3 normal{0.0, 0.0, 1.0};
};

/// The nearest point of the rest surface to `p`, with the vertex normals interpolated there.
SurfacePoint project(const TissueMesh& mesh, NearestTriangle& nearest, const glm::dvec3& p) {
    const auto& rest = mesh.restPositionsMm();
    const auto& normals = mesh.restNormals();
    const auto& tri = mesh.triangles()[nearest.nearest(p).triangle];
    const glm::dvec3 a(rest[tri[0]]), b(rest[tri[1]]), c(rest[tri[2]]);
    const glm::dvec3 q = closestPointOnTriangle(p, a, b, c);
    // Barycentric weights of q (on the triangle, so all >= 0 up to rounding).
    const glm::dvec3 v0 = b - a, v1 = c - a, v2 = q - a;
    const double d00 = glm::dot(v0, v0), d01 = glm::dot(v0, v1), d11 = glm::dot(v1, v1);
    const double d20 = glm::dot(v2, v0), d21 = glm::dot(v2, v1);
    const double denom = d00 * d11 - d01 * d01;
    double wb = denom > 0.0 ? (d11 * d20 - d01 * d21) / denom : 0.0;
    double wc = denom > 0.0 ? (d00 * d21 - d01 * d20) / denom : 0.0;
    wb = std::clamp(wb, 0.0, 1.0);
    wc = std::clamp(wc, 0.0, 1.0 - wb);
    const double wa = 1.0 - wb - wc;
    const glm::dvec3 n = wa * glm::dvec3(normals[tri[0]]) + wb * glm::dvec3(normals[tri[1]]) +
                         wc * glm::dvec3(normals[tri[2]]);
    const double length = glm::length(n);
    return {q, length > 0.0 ? n / length : glm::dvec3(glm::cross(v0, v1) / std::sqrt(std::max(denom, 1e-300)))};
}

std::size_t ticksOf(double seconds, double rateHz) { return std::size_t(std::llround(seconds * rateHz)); }

}  // namespace

Problems validateSlideDef(const SlideDef& def) {
    Problems problems;
    auto positive = [&](double value, const char* field, const char* unit) {
        if (!(std::isfinite(value) && value > 0.0))
            problems.push_back({field, -1, -1,
                                std::string(field) + " = " + std::to_string(value) + " " + unit +
                                    " must be a positive finite number"});
    };
    auto nonNegative = [&](double value, const char* field, const char* unit) {
        if (!(std::isfinite(value) && value >= 0.0))
            problems.push_back({field, -1, -1,
                                std::string(field) + " = " + std::to_string(value) + " " + unit +
                                    " must be a finite number >= 0"});
    };
    positive(def.depthMm, "depthMm", "mm");
    positive(def.speedMmPerS, "speedMmPerS", "mm/s");
    positive(def.slideS, "slideS", "s");
    positive(def.approachS, "approachS", "s");
    nonNegative(def.settleS, "settleS", "s");
    nonNegative(def.breakawayS, "breakawayS", "s");
    positive(def.liftS, "liftS", "s");
    nonNegative(def.approachHeightMm, "approachHeightMm", "mm");
    if (!hapticRateInRange(def.rateHz))
        problems.push_back({"rateHz", -1, -1, "rateHz = " + std::to_string(def.rateHz) + " Hz must be in 10..10000"});
    if (problems.empty() && ticksOf(def.slideS - def.breakawayS, def.rateHz) < 2)
        problems.push_back({"breakawayS", -1, -1,
                            "breakawayS = " + std::to_string(def.breakawayS) +
                                " s leaves fewer than 2 ticks of the slide for the statistics (slideS = " +
                                std::to_string(def.slideS) + " s)"});
    return problems;
}

SlidePath makeSlidePath(const TissueMesh& mesh, double toolRadiusMm, const SlideDef& def) {
    if (const Problems problems = validateSlideDef(def); !problems.empty())
        throw std::invalid_argument("slide: " + joinedMessages(problems));
    if (!(std::isfinite(toolRadiusMm) && toolRadiusMm >= 0.0))
        throw std::invalid_argument("slide: the tool radius " + std::to_string(toolRadiusMm) + " mm must be >= 0");
    if (mesh.vertexCount() == 0 || mesh.triangleCount() == 0) throw std::invalid_argument("slide: the mesh is empty");

    NearestTriangle nearest(mesh);
    const VertexId start = defaultTargetVertex(mesh);
    const glm::dvec3 origin(mesh.restPositionsMm()[start]);
    const glm::dvec3 startNormal(mesh.restNormals()[start]);
    // The +y tangent at the target, as the benchmark's stroke (engine/core/ToolPath.h).
    glm::dvec3 tangent = glm::dvec3(0, 1, 0) - glm::dot(glm::dvec3(0, 1, 0), startNormal) * startNormal;
    if (glm::length(tangent) < 1e-3) tangent = glm::dvec3(0, 0, 1);
    tangent = glm::normalize(tangent);

    const double step = def.speedMmPerS / def.rateHz;  // along the surface, per tick
    const std::size_t slideTicks = ticksOf(def.slideS, def.rateHz);
    const double length = step * double(slideTicks - 1);

    // The section of the surface by the plane through the target, its normal and the tangent: walked
    // from the target both ways in steps of a quarter tick's length, each step taken along the
    // section in the local tangent plane and projected back onto the triangles (a point that close
    // to the surface has one nearest point, so the walk neither stalls at vertices nor jumps).
    const glm::dvec3 planeNormal = glm::normalize(glm::cross(startNormal, tangent));
    const double substep = 0.25 * step;
    const std::size_t substeps = std::size_t(std::ceil((0.5 * length + 2.0 * step) / substep));
    auto walk = [&](glm::dvec3 direction) {
        std::vector<SurfacePoint> points{project(mesh, nearest, origin)};
        for (std::size_t k = 0; k < substeps; ++k) {
            const SurfacePoint& at = points.back();
            glm::dvec3 along = glm::cross(planeNormal, at.normal);
            if (glm::length(along) < 1e-9) along = direction;
            along = glm::normalize(glm::dot(along, direction) < 0.0 ? -along : along);
            const SurfacePoint next = project(mesh, nearest, at.pointMm + substep * along);
            if (glm::length(next.pointMm - at.pointMm) > 4.0 * substep)
                throw std::invalid_argument("slide: the surface folds back near the target (the walk jumped)");
            points.push_back(next);
            direction = along;
        }
        return points;
    };
    const std::vector<SurfacePoint> forward = walk(tangent), backward = walk(-tangent);
    std::vector<SurfacePoint> fine(backward.rbegin(), backward.rend() - 1);  // without the target twice
    fine.insert(fine.end(), forward.begin(), forward.end());
    std::vector<double> arc(fine.size(), 0.0);
    for (std::size_t i = 1; i < fine.size(); ++i)
        arc[i] = arc[i - 1] + glm::length(fine[i].pointMm - fine[i - 1].pointMm);
    const double centreArc = arc[backward.size() - 1];
    if (centreArc < 0.5 * length || arc.back() - centreArc < 0.5 * length)
        throw std::invalid_argument("slide: a slide of " + std::to_string(length) + " mm does not fit on the surface");

    SlidePath path;
    path.toolRadiusMm = toolRadiusMm;
    path.depthMm = def.depthMm;
    path.lengthMm = length;
    path.rateHz = def.rateHz;
    const double offset = toolRadiusMm - def.depthMm;  // along the normal, from the surface point
    auto add = [&](const SurfacePoint& s, double heightMm) {
        path.surfaceMm.push_back(glm::vec3(s.pointMm));
        path.normal.push_back(glm::vec3(s.normal));
        path.toolMm.push_back(glm::vec3(s.pointMm + (offset + heightMm) * s.normal));
    };

    // One point per tick at constant arc length, between two walked points, projected (exactly on
    // the surface again).
    std::vector<SurfacePoint> slide(slideTicks);
    for (std::size_t k = 0; k < slideTicks; ++k) {
        const double target = centreArc - 0.5 * length + double(k) * step;
        std::size_t i = std::size_t(std::upper_bound(arc.begin(), arc.end(), target) - arc.begin());
        i = std::clamp<std::size_t>(i, 1, arc.size() - 1);
        const double segment = arc[i] - arc[i - 1];
        const double t = segment > 0.0 ? std::clamp((target - arc[i - 1]) / segment, 0.0, 1.0) : 0.0;
        slide[k] = project(mesh, nearest, fine[i - 1].pointMm + t * (fine[i].pointMm - fine[i - 1].pointMm));
    }

    const std::size_t approachTicks = ticksOf(def.approachS, def.rateHz);
    const std::size_t settleTicks = ticksOf(def.settleS, def.rateHz);
    const std::size_t liftTicks = ticksOf(def.liftS, def.rateHz);
    const double drop = def.approachHeightMm + def.depthMm;  // from the approach height to the depth
    for (std::size_t i = 0; i < approachTicks; ++i)
        add(slide.front(), drop * (1.0 - double(i) / double(approachTicks)));
    for (std::size_t i = 0; i < settleTicks; ++i) add(slide.front(), 0.0);
    path.slideBegin = path.toolMm.size();
    path.statsBegin = path.slideBegin + ticksOf(def.breakawayS, def.rateHz);
    for (const SurfacePoint& s : slide) add(s, 0.0);
    path.slideEnd = path.toolMm.size();
    for (std::size_t i = 0; i < liftTicks; ++i) add(slide.back(), drop * double(i + 1) / double(liftTicks));
    return path;
}

}  // namespace palpate
