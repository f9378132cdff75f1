#pragma once
// How round the rings are: the slope model moves ring k as one (docs/method.md), which assumes
// ring k lies at about the same distance from the touched vertex in every direction. Slivers and
// uneven edges break that; this measures it (docs/meshes.md, "Ring roundness").

#include "engine/core/Rings.h"
#include "engine/core/TissueMesh.h"

#include <cstddef>

namespace palpate {

struct RingRoundness {
    int ringCount = 0;
    /// For ring k (1..ringCount): the mean over sampled centres of the coefficient of variation
    /// (standard deviation / mean) of the distances from the centre to the vertices of ring k.
    /// 0 = a perfect circle; a regular mesh gives about 0.1 at ring 2.
    double ringDistanceCv[kMaxRings + 1] = {};
    double edgeLengthCv = 0.0;     ///< of all edges
    double meanEdgeMm = 0.0;
    double minEdgeMm = 0.0;
    double maxEdgeMm = 0.0;
    std::size_t sampledCentres = 0;
    /// The worst ring's CV (the one the panel and `mesh check` lead with).
    double worstRingCv() const;
};

/// Measures rings 1..ringCount around up to `maxCentres` vertices spread over the mesh (every
/// vertex when the mesh has fewer); boundary vertices are skipped, their rings are cut off.
RingRoundness measureRingRoundness(const TissueMesh& mesh, int ringCount = 3, std::size_t maxCentres = 2000);

}  // namespace palpate
