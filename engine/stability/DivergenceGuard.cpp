#include "engine/stability/DivergenceGuard.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace palpate {

void DivergenceGuard::reset() {
    mWindowTick = 0;
    mWindowPeak = 0.0;
    mPreviousPeak = -1.0;
    mGrowingWindows = 0;
    mLastForce = glm::vec3(0.0f);
    mLastDelta = glm::vec3(0.0f);
    mAlternatingTicks = 0;
    mFirstSwing = 0.0f;
    mLastTouched = kNoVertex;
    mFanTrianglesOf = kNoVertex;  // the next mesh may number its vertices otherwise
}

namespace {
bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
}  // namespace

// The fan's inversion test over any source of current positions (positionOf(v)).
template <typename PositionOf>
bool fanInvertedWith(const TissueMesh& mesh, const PositionOf& positionOf, VertexId v) {
    if (v >= mesh.vertexCount()) return false;
    const auto& start = mesh.fanStart();
    const auto& fan = mesh.fanTriangles();
    const auto& rest = mesh.restPositionsMm();
    for (std::uint32_t i = start[v]; i < start[v + 1]; ++i) {
        const auto& t = mesh.triangles()[fan[i]];
        const glm::vec3 restNormal = glm::cross(rest[t[1]] - rest[t[0]], rest[t[2]] - rest[t[0]]);
        const glm::vec3 p0 = positionOf(t[0]);
        const glm::vec3 nowNormal = glm::cross(positionOf(t[1]) - p0, positionOf(t[2]) - p0);
        if (glm::dot(restNormal, nowNormal) <= 0.0f) return true;
    }
    return false;
}

bool DivergenceGuard::fanInverted(const TissueMesh& mesh, std::span<const glm::vec3> positions, VertexId v) {
    if (positions.size() != mesh.vertexCount()) return false;
    return fanInvertedWith(mesh, [&](VertexId u) { return positions[u]; }, v);
}

DivergenceVerdict DivergenceGuard::check(const TissueMesh& mesh, std::span<const glm::vec3> positions,
                                         const TickResult& result) {
    const std::size_t n = std::min(positions.size(), mesh.vertexCount());
    const auto sample = [&](std::size_t first, int count, glm::vec3* out) {
        std::size_t v = first;
        for (int k = 0; k < count; ++k) {
            out[k] = positions[v];
            if (++v == n) v = 0;
        }
    };
    const bool whole = positions.size() == mesh.vertexCount();
    const auto positionOf = [&](VertexId v) { return positions[v]; };
    const auto inverted = [&](VertexId t) { return fanInvertedWith(mesh, positionOf, t); };
    return checkWith(mesh, n, sample, whole, inverted, [&](int, VertexId v) { return positions[v]; }, result);
}

DivergenceVerdict DivergenceGuard::check(const TissueMesh& mesh, const DeformationModel& model,
                                         const TickResult& result) {
    const std::size_t n = mesh.vertexCount();
    const auto sample = [&](std::size_t first, int count, glm::vec3* out) {
        VertexId ids[kMaxSampled];
        std::size_t v = first;  // wraps without a division per vertex (the tick's budget is ~100 ns)
        for (int k = 0; k < count; ++k) {
            ids[k] = VertexId(v);
            if (++v == n) v = 0;
        }
        model.copyPositionsMm({ids, std::size_t(count)}, out);
    };
    // The fan (the touched vertex and its neighbours) read once; a vertex outside it (none, for
    // the tests below) is read alone.
    if (result.touched != kNoVertex) mLastTouched = result.touched;
    mFanCount = 0;
    if (mLastTouched != kNoVertex && mLastTouched < n) {
        const auto& start = mesh.neighbourStart();
        const auto& nb = mesh.neighbours();
        mFanIds[mFanCount++] = mLastTouched;
        for (std::uint32_t i = start[mLastTouched]; i < start[mLastTouched + 1] && mFanCount < kMaxFan; ++i)
            mFanIds[mFanCount++] = nb[i];
        model.copyPositionsMm({mFanIds, std::size_t(mFanCount)}, mFanPositions);
    }
    const auto positionOf = [&](VertexId v) {
        // The touched vertex first, then its neighbours, sorted (the mesh keeps them so).
        if (mFanCount > 0 && mFanIds[0] == v) return mFanPositions[0];
        const VertexId* begin = mFanIds + 1;
        const VertexId* end = mFanIds + std::max(mFanCount, 1);
        const VertexId* found = std::lower_bound(begin, end, v);
        if (found != end && *found == v) return mFanPositions[found - mFanIds];
        glm::vec3 p;
        model.copyPositionsMm({&v, 1}, &p);
        return p;
    };
    // A model that moves only the vertices it lists has nothing to sample elsewhere.
    const auto fanAt = [&](int i, VertexId v) { return i < mFanCount ? mFanPositions[i] : positionOf(v); };
    // The fan's triangles as indices into the fan read above, with their rest normals, taken again
    // only when the touched vertex changes: the test is then a cross product per triangle.
    if (mLastTouched != mFanTrianglesOf && mLastTouched != kNoVertex && mLastTouched < n) {
        mFanTrianglesOf = mLastTouched;
        mFanTriangleCount = 0;
        const auto& start = mesh.fanStart();
        const auto& rest = mesh.restPositionsMm();
        for (std::uint32_t i = start[mLastTouched]; i < start[mLastTouched + 1]; ++i) {
            const auto& tri = mesh.triangles()[mesh.fanTriangles()[i]];
            FanTriangle f;
            bool complete = mFanTriangleCount < kMaxFan;
            for (int k = 0; k < 3 && complete; ++k) {
                const VertexId* first = mFanIds + 1;
                const VertexId* end = mFanIds + mFanCount;
                const VertexId v = tri[std::size_t(k)];
                const VertexId* found = v == mFanIds[0] ? mFanIds : std::lower_bound(first, end, v);
                complete = found != end && *found == v;
                if (complete) f.corner[k] = std::uint8_t(found - mFanIds);
            }
            if (!complete) {  // a fan beyond kMaxFan: the generic test below
                mFanTriangleCount = -1;
                break;
            }
            f.restNormal = glm::cross(rest[tri[1]] - rest[tri[0]], rest[tri[2]] - rest[tri[0]]);
            mFanTriangles[mFanTriangleCount++] = f;
        }
    }
    const auto inverted = [&](VertexId t) {
        if (mFanTriangleCount < 0 || t != mFanTrianglesOf) return fanInvertedWith(mesh, positionOf, t);
        for (int i = 0; i < mFanTriangleCount; ++i) {
            const FanTriangle& f = mFanTriangles[i];
            const glm::vec3 p0 = mFanPositions[f.corner[0]];
            const glm::vec3 now = glm::cross(mFanPositions[f.corner[1]] - p0, mFanPositions[f.corner[2]] - p0);
            if (glm::dot(f.restNormal, now) <= 0.0f) return true;
        }
        return false;
    };
    return checkWith(mesh, model.movesOnlyDisplaced() ? 0 : n, sample, true, inverted, fanAt, result);
}

template <typename Sample, typename Inverted, typename FanAt>
DivergenceVerdict DivergenceGuard::checkWith(const TissueMesh& mesh, std::size_t n, const Sample& sample,
                                             bool whole, const Inverted& inverted, const FanAt& fanAt,
                                             const TickResult& result) {
    const glm::vec3 force = result.forceN;
    if (!finite(force)) return {DivergenceKind::NonFinite};

    // The touched vertex's fan: finite positions, its displacement for the activity.
    double displacement2 = 0.0;
    // Round robin over the mesh: a non-finite vertex anywhere (a mode blowing up far from the tool
    // stops the search from finding any vertex, so the fan alone would never see it).
    if (n > 0) {
        const int count = std::min(mDef.sampledVerticesPerTick, kMaxSampled);
        glm::vec3 sampled[kMaxSampled];
        if (mSampleCursor >= n) mSampleCursor = 0;
        sample(mSampleCursor, count, sampled);
        mSampleCursor += std::size_t(count);
        if (mSampleCursor >= n) mSampleCursor %= n;
        for (int k = 0; k < count; ++k)
            if (!finite(sampled[k])) return {DivergenceKind::NonFinite};
    }
    if (result.touched != kNoVertex) mLastTouched = result.touched;
    const VertexId t = mLastTouched;
    const bool fan = t != kNoVertex && t < mesh.vertexCount() && whole;
    if (fan) {
        const auto& start = mesh.neighbourStart();
        const auto& nb = mesh.neighbours();
        const auto& rest = mesh.restPositionsMm();
        // The fan in order: the touched vertex, then its neighbours (fanAt(i, v) is the i-th).
        float largest2 = 0.0f;
        bool allFinite = true;
        auto visit = [&](int i, VertexId v) {
            const glm::vec3 p = fanAt(i, v);
            allFinite = allFinite && finite(p);
            const glm::vec3 u = p - rest[v];
            largest2 = std::max(largest2, glm::dot(u, u));
        };
        visit(0, t);
        for (std::uint32_t i = start[t]; i < start[t + 1]; ++i) visit(int(i - start[t]) + 1, nb[i]);
        if (!allFinite || !std::isfinite(largest2)) return {DivergenceKind::NonFinite};
        displacement2 = double(largest2);
    }
    // Energy growth: the peak activity of each window against the previous window's.
    const double activity = double(glm::dot(force, force)) + displacement2;
    mWindowPeak = std::max(mWindowPeak, activity);
    if (++mWindowTick >= mDef.windowTicks) {
        if (mPreviousPeak >= 0.0 && mWindowPeak > mDef.activityFloor &&
            mWindowPeak > mDef.energyGrowthPerWindow * std::max(mPreviousPeak, mDef.activityFloor))
            ++mGrowingWindows;
        else
            mGrowingWindows = 0;
        mPreviousPeak = mWindowPeak;
        mWindowPeak = 0.0;
        mWindowTick = 0;
        if (mGrowingWindows >= mDef.growthWindows) return {DivergenceKind::EnergyGrowth};
    }

    // Oscillation: the force's change reverses every tick with a swing that is not noise.
    // (Compared squared: no square root per tick.)
    const glm::vec3 delta = force - mLastForce;
    const float size2 = std::max(glm::dot(force, force), glm::dot(mLastForce, mLastForce));
    const float fraction = float(mDef.oscillationFraction);
    const float delta2 = glm::dot(delta, delta);
    const bool swing = delta2 > fraction * fraction * size2 && size2 > 1e-8f;
    mAlternatingTicks = swing && glm::dot(delta, mLastDelta) < 0.0f ? mAlternatingTicks + 1 : 0;
    if (mAlternatingTicks == 1) mFirstSwing = std::sqrt(delta2);
    mLastForce = force;
    mLastDelta = delta;
    if (mAlternatingTicks >= mDef.oscillationTicks && delta2 >= 0.25f * mFirstSwing * mFirstSwing)
        return {DivergenceKind::Oscillation};

    // A fan whose vertices all moved less than a quarter of its smallest rest height cannot have
    // turned over: a corner would have to cross its opposite edge's line (distance >= h, changed by
    // at most the two displacements), or the triangle turn rigidly by 90 degrees (its corners
    // moving by about its height or more). The test is skipped then (docs/stability.md, "Guards").
    const double height = fan ? double(mesh.fanMinHeightMm()[t]) : 0.0;
    const bool couldInvert = fan && 16.0 * displacement2 >= height * height;
    if (mDef.checkInversion && couldInvert && inverted(t)) return {DivergenceKind::Inversion};
    return {};
}

}  // namespace palpate
