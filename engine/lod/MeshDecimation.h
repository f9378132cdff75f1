#pragma once
// Coarser copies of a surface by OpenMesh's Decimater: quadric error (ModQuadricT) orders the
// half-edge collapses; normal flipping (ModNormalFlippingT) and aspect ratio (ModAspectRatioT)
// veto collapses that would fold or sliver triangles. OpenMesh's collapse test keeps a closed
// manifold closed and manifold. A collapse keeps one end's position, so every coarse vertex sits
// exactly on a vertex of the finer surface.

#include "base/params/Problem.h"

#include "engine/core/TissueMesh.h"

#include <array>
#include <atomic>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace palpate {

/// The most triangles around one vertex the decimater takes: each collapse at a vertex re-ranks
/// every edge around it and checks every triangle around each, so a fan of k triangles costs k^2
/// per collapse (a 2000-triangle hub ran past a minute at 0 %). Remeshed or scanned surfaces have
/// 5-8; a CAD fan of a few dozen passes.
inline constexpr std::size_t kMaxDecimationValence = 128;

struct DecimationGuards {
    /// ModNormalFlippingT: a collapse may turn no triangle's normal by more than this (degrees).
    double maxNormalDeviationDeg = 60.0;
    /// ModAspectRatioT: a collapse may not make a triangle thinner than this (longest edge over height),
    /// unless it was already.
    double maxAspectRatio = 10.0;
};

/// "" when usable, else a message naming the field.
Problems validateDecimationGuards(const DecimationGuards& guards);

struct DecimatedSurface {
    std::size_t targetVertices = 0;
    std::vector<glm::vec3> positionsMm;
    std::vector<std::array<VertexId, 3>> triangles;
};

struct DecimationResult {
    std::vector<DecimatedSurface> surfaces;  ///< one per target reached or attempted, coarser each time
    bool cancelled = false;
    std::string error;                       ///< "" unless the source could not be handed to OpenMesh
};

/// Decimates `source` progressively to each of `targetVertices` (descending), taking a copy after
/// each, so that every level is a coarsening of the one before. A target the guards do not let it
/// reach gives a surface with more vertices (the caller reports it). `progress` receives the
/// fraction of all planned collapses done; `cancel` stops at a consistent state. A vertex with more
/// than kMaxDecimationValence triangles around it is an error naming it (remesh first).
DecimationResult decimateProgressively(const TissueMesh& source, std::span<const std::size_t> targetVertices,
                                       const DecimationGuards& guards,
                                       const std::function<void(double fraction)>& progress = {},
                                       const std::atomic<bool>* cancel = nullptr);

}  // namespace palpate
