#include "engine/exercise/PalpationCoverage.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace palpate {

PalpationCoverage::PalpationCoverage(const TissueMesh& mesh, const CoverageDef& def)
    : mRestMm(mesh.restPositionsMm()), mNeighbourStart(mesh.neighbourStart()), mNeighbours(mesh.neighbours()),
      mDef(def), mVertexAreaMm2(mesh.vertexCount(), 0.0) {
    // A vertex stands for a third of each triangle around it.
    const auto& rest = mesh.restPositionsMm();
    for (const auto& t : mesh.triangles()) {
        const double third = 0.5 * glm::length(glm::cross(glm::dvec3(rest[t[1]] - rest[t[0]]), glm::dvec3(rest[t[2]] - rest[t[0]]))) / 3.0;
        for (VertexId v : t) mVertexAreaMm2[v] += third;
        mTotalAreaMm2 += 3.0 * third;
    }
    reserveWork();
}

PalpationCoverage::PalpationCoverage(const ExerciseGeometry& geometry, const CoverageDef& def)
    : mRestMm(geometry.restMm()), mNeighbourStart(geometry.neighbourStart()), mNeighbours(geometry.neighbours()),
      mDef(def), mVertexAreaMm2(geometry.vertexAreasMm2().begin(), geometry.vertexAreasMm2().end()) {
    for (double a : mVertexAreaMm2) mTotalAreaMm2 += a;
    reserveWork();
}

void PalpationCoverage::reserveWork() {
    mPeakForceN.assign(mRestMm.size(), 0.0f);
    mStamp.assign(mRestMm.size(), 0);
    mQueue.reserve(mRestMm.size());
}

void PalpationCoverage::add(VertexId touched, const glm::vec3& contactMm, double forceN) {
    if (forceN < mDef.minForceN || touched >= mRestMm.size() || mNeighbourStart.size() != mRestMm.size() + 1) return;
    const auto& rest = mRestMm;
    const auto& start = mNeighbourStart;
    const auto& neighbours = mNeighbours;
    const double radius2 = mDef.radiusMm * mDef.radiusMm;
    auto within = [&](VertexId v) {
        const glm::dvec3 d = glm::dvec3(rest[v]) - glm::dvec3(contactMm);
        return glm::dot(d, d) <= radius2;
    };
    ++mGeneration;
    mQueue.clear();
    // The walk starts at the touched vertex even when it lies just outside the radius (a coarse
    // mesh under a small tool): its neighbours may still be inside.
    mQueue.push_back(touched);
    mStamp[touched] = mGeneration;
    for (std::size_t head = 0; head < mQueue.size(); ++head) {
        const VertexId v = mQueue[head];
        if (within(v)) {
            if (mPeakForceN[v] == 0.0f) mCoveredAreaMm2 += mVertexAreaMm2[v];
            mPeakForceN[v] = std::max(mPeakForceN[v], float(forceN));
        } else if (v != touched) {
            continue;  // outside: the walk does not go on through it
        }
        for (std::uint32_t i = start[v]; i < start[v + 1]; ++i) {
            const VertexId w = neighbours[i];
            if (mStamp[w] == mGeneration) continue;
            mStamp[w] = mGeneration;
            mQueue.push_back(w);
        }
    }
}

double PalpationCoverage::coveredFraction() const {
    return mTotalAreaMm2 > 0.0 ? std::min(1.0, mCoveredAreaMm2 / mTotalAreaMm2) : 0.0;
}

}  // namespace palpate
