#pragma once
// The run-time divergence detector (docs/stability.md, "Guards"): run once per tick after the
// model's step, before the force is sent. It looks at what any DeformationModel exposes (the force
// and the positions of the touched vertex's fan) and says whether the model has left its stable
// range: a non-finite force or position, activity (force^2 + fan displacement^2) growing by orders
// of magnitude window after window, a contact force that alternates every tick (the slope model
// beyond alpha (1 + g) = 2), or a triangle of the touched vertex's fan inverted against its rest
// orientation; and a few vertices per tick, round robin, for NaN anywhere (not for a model that
// moves only the vertices it lists, DeformationModel::movesOnlyDisplaced). Real-time safe: no
// allocation, O(valence^2 + sampled) work, messages are static strings.

#include "engine/models/DeformationModel.h"
#include "engine/core/TissueMesh.h"
#include "engine/stability/DivergenceKind.h"

#include <cstdint>
#include <span>

namespace palpate {

struct DivergenceGuardDef {
    /// Ticks per energy window.
    int windowTicks = 16;
    /// Factor by which a window's peak activity must exceed the previous window's...
    double energyGrowthPerWindow = 100.0;
    /// ...in this many consecutive windows (with the defaults: x10^6 in 48 ticks, far beyond any
    /// hand: a press from 0.01 N to 10 N in 48 ms).
    int growthWindows = 3;
    /// Activity below this (N^2 + mm^2) is noise, not growth.
    double activityFloor = 1e-6;
    /// Consecutive ticks of a force whose tick-to-tick change flips sign with a swing above
    /// oscillationFraction of its size, and has not decayed to half its first swing over them
    /// (a stable slope-ring set near its bound rings down; |lambda|^64 > 0.5 flags within 0.5 %).
    int oscillationTicks = 64;
    double oscillationFraction = 0.05;
    /// Vertices checked for NaN per tick, round robin over the mesh (a mode that blows up away
    /// from the tool is seen within vertexCount / this ticks of overflowing).
    int sampledVerticesPerTick = 32;
    bool checkInversion = true;
};

struct DivergenceVerdict {
    DivergenceKind kind = DivergenceKind::None;
    explicit operator bool() const { return kind != DivergenceKind::None; }
    const char* name() const { return divergenceKindName(kind); }
    const char* advice() const { return divergenceAdvice(kind); }
};

class DivergenceGuard {
public:
    explicit DivergenceGuard(const DivergenceGuardDef& def = {}) : mDef(def) {}

    /// One tick: `result` from the model's step, `positionsMm` its current positions (only the
    /// touched vertex's fan is read). Real-time safe.
    DivergenceVerdict check(const TissueMesh& mesh, std::span<const glm::vec3> positionsMm, const TickResult& result);
    /// The same, reading only the few positions it needs from the model (copyPositionsMm): what
    /// the haptic loop calls, so that a model writing its positions when read keeps that saving.
    DivergenceVerdict check(const TissueMesh& mesh, const DeformationModel& model, const TickResult& result);
    /// Forgets the history (after the model was reset, or a scene change).
    void reset();

    /// True when a triangle (t, j, k) of v's fan has turned over: its normal from the current
    /// positions points against the one from the rest positions (orientation-free: the same vertex
    /// order on both sides). The fan is the mesh's triangles around v. Real-time safe.
    static bool fanInverted(const TissueMesh& mesh, std::span<const glm::vec3> positionsMm, VertexId v);

    const DivergenceGuardDef& def() const { return mDef; }

private:
    static constexpr int kMaxSampled = 256;  // sampledVerticesPerTick is capped at this
    static constexpr int kMaxFan = 64;       // fan vertices read at once (more are read one by one)
    template <typename Sample, typename Inverted, typename FanAt>
    DivergenceVerdict checkWith(const TissueMesh& mesh, std::size_t n, const Sample& sample, bool whole,
                                const Inverted& inverted, const FanAt& fanAt, const TickResult& result);

    DivergenceGuardDef mDef;
    VertexId mFanIds[kMaxFan] = {};
    glm::vec3 mFanPositions[kMaxFan] = {};
    int mFanCount = 0;
    struct FanTriangle {
        std::uint8_t corner[3] = {};  // indices into mFanIds / mFanPositions
        glm::vec3 restNormal{0.0f};
    };
    FanTriangle mFanTriangles[kMaxFan];
    int mFanTriangleCount = 0;              // -1: the fan does not fit (the generic test runs)
    VertexId mFanTrianglesOf = kNoVertex;   // the touched vertex they belong to
    int mWindowTick = 0;
    double mWindowPeak = 0.0;
    double mPreviousPeak = -1.0;  // < 0: no completed window yet
    int mGrowingWindows = 0;
    glm::vec3 mLastForce{0.0f};
    glm::vec3 mLastDelta{0.0f};
    float mFirstSwing = 0.0f;
    int mAlternatingTicks = 0;
    VertexId mLastTouched = kNoVertex;  // the fan watched while the search finds no vertex
    std::size_t mSampleCursor = 0;
};

}  // namespace palpate
