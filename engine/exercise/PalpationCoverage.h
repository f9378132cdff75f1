#pragma once
// How much of the surface was examined firmly enough (docs/scoring.md, "Coverage"): every contact
// at or above a force covers the vertices within a radius of its point; the covered fraction is
// by area, and the largest force seen at each vertex is the heat map.

#include "engine/core/TissueMesh.h"
#include "engine/exercise/ExerciseGeometry.h"
#include "engine/exercise/PalpationResult.h"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace palpate {

class PalpationCoverage {
public:
    PalpationCoverage(const TissueMesh& mesh, const CoverageDef& def);
    /// On an exercise's copy of the mesh (the scorer's: it keeps no mesh).
    PalpationCoverage(const ExerciseGeometry& geometry, const CoverageDef& def);

    /// One contact sample: the touched vertex (where the walk starts), the contact point and the
    /// force's magnitude. Covers the vertices within the radius that the surface connects to the
    /// touched vertex, so that a press does not reach through a thin wall.
    void add(VertexId touched, const glm::vec3& contactMm, double forceN);

    /// Covered area over the whole surface's area, in [0, 1].
    double coveredFraction() const;
    /// The largest force that covered each vertex, N (0 where none did): the heat map.
    const std::vector<float>& peakForceN() const { return mPeakForceN; }

private:
    void reserveWork();

    // The surface: views of the mesh's or the geometry's arrays, which outlive this.
    std::span<const glm::vec3> mRestMm;
    std::span<const std::uint32_t> mNeighbourStart;
    std::span<const VertexId> mNeighbours;
    CoverageDef mDef;
    std::vector<double> mVertexAreaMm2;
    double mTotalAreaMm2 = 0.0;
    double mCoveredAreaMm2 = 0.0;
    std::vector<float> mPeakForceN;
    std::vector<std::uint32_t> mStamp;
    std::uint32_t mGeneration = 0;
    std::vector<VertexId> mQueue;
};

}  // namespace palpate
