#include "engine/lod/MeshLevels.h"

#include "engine/core/MeshHash.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace palpate {

Problems validateLevelDef(const LevelDef& o) {
    if (!std::isfinite(o.vertexRatio) || o.vertexRatio <= 0.05 || o.vertexRatio >= 0.95)
        return oneProblem("vertexRatio", "levels: vertex ratio must be in (0.05, 0.95)");
    if (o.minVertices < 8) return oneProblem("minVertices", "levels: min vertices must be at least 8");
    if (o.maxCoarseLevels < 0 || o.maxCoarseLevels > 20)
        return oneProblem("maxCoarseLevels", "levels: max coarse levels must be in 0..20");
    if (Problems guards = validateDecimationGuards(o.guards); !guards.empty()) {
        for (Problem& p : guards) p.message = "levels: " + p.message;
        return guards;
    }
    return {};
}

std::vector<std::size_t> levelTargets(std::size_t sourceVertices, const LevelDef& o) {
    std::vector<std::size_t> targets;
    double n = double(sourceVertices);
    for (int k = 0; k < o.maxCoarseLevels; ++k) {
        n *= o.vertexRatio;
        const auto target = std::size_t(std::llround(n));
        if (target < o.minVertices) break;
        targets.push_back(target);
    }
    return targets;
}

bool mapLevelToSource(const TissueMesh& source, MeshLevel& level, const std::atomic<bool>* cancel) {
    level.fineOnLevel = embedPoints(source.restPositionsMm(), level.mesh, cancel);
    if (cancel && cancel->load()) return false;
    level.levelOnFine = embedPoints(level.mesh.restPositionsMm(), source, cancel);
    return !(cancel && cancel->load());
}

std::string levelTopologyProblem(const TissueMesh& source, const TissueMesh& level) {
    const MeshReport& r = level.report();
    std::ostringstream s;
    if (!r.valid()) s << r.errors.front();
    else if (r.nonManifoldEdgeCount || r.nonManifoldVertexCount)
        s << r.nonManifoldEdgeCount << " non-manifold edges, " << r.nonManifoldVertexCount << " non-manifold vertices";
    else if (source.report().boundaryEdgeCount == 0 && r.boundaryEdgeCount > 0)
        s << "the source is closed but the level has " << r.boundaryEdgeCount << " boundary edges";
    return s.str();
}

MeshLevels generateLevels(const TissueMesh& source, const LevelDef& options, const LodProgressFn& progress,
                          const std::atomic<bool>* cancel) {
    if (const std::string e = joinedMessages(validateLevelDef(options)); !e.empty()) throw std::invalid_argument(e);
    using Clock = std::chrono::steady_clock;
    auto say = [&](double fraction, const std::string& stage) {
        if (progress) progress(std::clamp(fraction, 0.0, 1.0), stage);
    };
    MeshLevels out;
    out.sourceHash = meshHash(source);
    MeshLevel fine;
    fine.mesh = source;
    fine.targetVertices = source.vertexCount();
    out.levels.push_back(std::move(fine));

    const std::vector<std::size_t> targets = levelTargets(source.vertexCount(), options);
    if (targets.empty()) {
        out.notes.push_back(source.report().source + ": " + std::to_string(source.vertexCount()) +
                            " vertices: no coarser level above the minimum of " + std::to_string(options.minVertices));
        say(1.0, "done");
        return out;
    }
    // Decimation is the first half of the work, the mappings the second.
    say(0.0, "decimating");
    const auto start = Clock::now();
    DecimationResult decimated = decimateProgressively(
        source, targets, options.guards, [&](double f) { say(0.5 * f, "decimating"); }, cancel);
    if (!decimated.error.empty()) throw std::runtime_error(decimated.error);
    const double decimationSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    out.cancelled = decimated.cancelled;

    for (std::size_t k = 0; k < decimated.surfaces.size(); ++k) {
        if (cancel && cancel->load()) {
            out.cancelled = true;
            break;
        }
        const auto levelStart = Clock::now();
        DecimatedSurface& s = decimated.surfaces[k];
        const std::string name = source.report().source + " level " + std::to_string(k + 1);
        const std::size_t reached = s.positionsMm.size();
        if (reached >= out.levels.back().mesh.vertexCount()) {
            // The guards allowed no collapse since the last level: a copy would only cost memory.
            out.notes.push_back(name + ": the guards allowed no further collapse below " + std::to_string(reached) +
                                " vertices (target " + std::to_string(s.targetVertices) + "); no more levels");
            break;
        }
        auto built = TissueMesh::fromTriangles(std::move(s.positionsMm), s.triangles, name);
        if (!built.mesh) throw std::runtime_error(name + ": decimation gave an unusable mesh: " + built.error());
        MeshLevel level;
        level.mesh = std::move(*built.mesh);
        level.targetVertices = s.targetVertices;
        if (const std::string problem = levelTopologyProblem(source, level.mesh); !problem.empty())
            throw std::runtime_error(name + ": decimation broke the surface: " + problem);
        if (reached > s.targetVertices)
            out.notes.push_back(name + ": the guards stopped the decimater at " + std::to_string(reached) +
                                " vertices (target " + std::to_string(s.targetVertices) + ")");
        say(0.5 + 0.5 * double(k) / double(decimated.surfaces.size()), "mapping level " + std::to_string(k + 1));
        if (!mapLevelToSource(source, level, cancel)) {
            out.cancelled = true;
            break;
        }
        level.seconds = std::chrono::duration<double>(Clock::now() - levelStart).count() +
                        decimationSeconds / double(decimated.surfaces.size());
        out.levels.push_back(std::move(level));
    }
    if (!out.cancelled) say(1.0, "done");
    return out;
}

std::vector<glm::vec3> MeshLevels::toFine(std::size_t level, std::span<const glm::vec3> levelPositionsMm) const {
    if (level == 0) return {levelPositionsMm.begin(), levelPositionsMm.end()};
    const MeshLevel& l = levels.at(level);
    std::vector<glm::vec3> out(l.fineOnLevel.size());
    placeEmbeddedPoints(l.fineOnLevel, l.mesh, levelPositionsMm, out);
    return out;
}

std::vector<glm::vec3> MeshLevels::fromFine(std::size_t level, std::span<const glm::vec3> finePositionsMm) const {
    if (level == 0) return {finePositionsMm.begin(), finePositionsMm.end()};
    const MeshLevel& l = levels.at(level);
    std::vector<glm::vec3> out(l.levelOnFine.size());
    placeEmbeddedPoints(l.levelOnFine, levels.front().mesh, finePositionsMm, out);
    return out;
}

std::vector<glm::vec3> MeshLevels::transfer(std::size_t fromLevel, std::size_t toLevel,
                                            std::span<const glm::vec3> positionsMm) const {
    if (fromLevel == toLevel) return {positionsMm.begin(), positionsMm.end()};
    const std::vector<glm::vec3> fine = toFine(fromLevel, positionsMm);
    return fromFine(toLevel, fine);
}

}  // namespace palpate
