#pragma once
// Can a press target's force window be reached by pressing with the mouse (docs/scoring.md,
// "Reachable targets")? In touch mode the tool's lowest point goes a depth below the touched
// vertex's rest position along its rest normal, the depth set by the wheel in steps up to a
// maximum (the viewport defines both). The force a target is judged on is the one rendered to the
// device after the safety filter, so the probe runs the real thing: the exercise's scene (its
// mesh, tissue preset and physics) in a stepped haptic loop with a mouse device, the tool pressed
// in step by step, each depth held until the force settles.
//
//   TouchReach touch{Viewport::kMaxTouchDepthMm, Viewport::kTouchDepthStepMm};
//   auto probe = TouchForceProbe::create(mesh, preset, geometry.get(), touch, error);
//   TargetReach reach = judgeTarget(target.def, probe->forcesN(target.vertex), touch);

#include "engine/scoring/ExerciseSession.h"

#include <glm/vec3.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

class HapticLoop;
class MouseDevice;

/// How deep the mouse can press: depths 0, step, 2 step, ... up to maxDepthMm (which is one of
/// them even when it is not a whole number of steps). A step <= 0 means one depth, the maximum.
struct TouchReach {
    double maxDepthMm = 0.0;
    double depthStepMm = 0.0;
    /// The press a touch starts with before the wheel deepens it (0: not known).
    double defaultDepthMm = 0.0;
    /// The depths the force is probed at, shallowest first.
    std::vector<double> depthsMm() const;
};

/// Where touch mode puts the tool for a press `depthMm` deep at a surface point: its lowest point
/// that far below `restMm` along the outward `normal`; a sphere's centre is its radius above that.
glm::vec3 touchToolPositionMm(const glm::vec3& restMm, const glm::vec3& normal, float toolRadiusMm, float depthMm);

/// What pressing at one vertex gives at each of TouchReach::depthsMm(): the force rendered and how
/// far the vertex has sunk along its rest normal (less than the depth: the contact gives too).
struct TouchPresses {
    std::vector<double> forcesN;
    std::vector<double> sinksMm;
};

/// The rendered force at each touch depth at a vertex of one scene. Not real-time: it builds a
/// scene and runs a stepped loop (a few thousand ticks a vertex).
class TouchForceProbe {
public:
    /// `physics` (may be null) is applied to the scene as a session does (find the lump's
    /// inclusion). Null with `error` when the scene cannot be built or `touch` is unusable.
    static std::unique_ptr<TouchForceProbe> create(const TissueMesh& mesh, const TissuePreset& preset,
                                                   const ExerciseGeometry* physics, const TouchReach& touch,
                                                   std::string& error);
    ~TouchForceProbe();
    TouchForceProbe(const TouchForceProbe&) = delete;
    TouchForceProbe& operator=(const TouchForceProbe&) = delete;

    const TouchReach& touch() const { return mTouch; }
    /// |F| rendered (N) with the tool held at each of touch().depthsMm() at vertex `v` (engine
    /// numbering), the tissue at rest before the press; empty for a vertex not on the mesh.
    std::vector<double> forcesN(VertexId v) { return presses(v).forcesN; }
    /// The same presses with how far the vertex has sunk under the tool at each depth.
    TouchPresses presses(VertexId v);

private:
    TouchForceProbe() = default;
    /// Steps until |F| stops changing (or a time cap), returns the last |F|.
    double settle();

    TouchReach mTouch;
    std::vector<double> mDepthsMm;
    std::vector<glm::vec3> mRestMm, mNormals;
    float mToolRadiusMm = 0.0f;
    std::unique_ptr<HapticLoop> mLoop;
    MouseDevice* mMouse = nullptr;  // owned by mLoop
    int mMaxSettleTicks = 0;
};

/// Whether a target's window can be met at one of the probed depths.
struct TargetReach {
    bool reachable = false;
    double maxForceN = 0.0;          ///< the largest force of any probed depth (the deepest, for a monotone tissue)
    double maxDepthMm = 0.0;         ///< the deepest probed depth
    std::optional<double> depthMm;   ///< the shallowest depth whose force is inside the window
    /// When the window lies between two depths' forces (too narrow for the wheel's step): the
    /// forces either side of it and their depths.
    std::optional<double> belowForceN, aboveForceN, belowDepthMm, aboveDepthMm;
};

/// Judges `target`'s window against forces probed at touch.depthsMm() (TouchForceProbe::forcesN).
TargetReach judgeTarget(const PressTarget& target, const std::vector<double>& forcesN, const TouchReach& touch);

/// A force window a trainee meets pressing between a third and two thirds of the deepest touch,
/// and at least two wheel steps deeper than the default press, so that a touch left at its
/// default is clearly short of it and reaching it is a deliberate press (forces probed at
/// touch.depthsMm(), interpolated), its ends rounded inwards to two significant digits: the
/// editor's window for a first target. nullopt when the tissue gives no force there.
struct ForceWindow {
    double minN = 0.0;
    double maxN = 0.0;
};
std::optional<ForceWindow> comfortableWindow(const std::vector<double>& forcesN, const TouchReach& touch);

/// Whether a lump hidden under the surface (docs/scoring.md, "Lumps under the surface") can be
/// felt: pressing above it is soft until the surface has sunk to the lump's top, so it is felt
/// one wheel step past the press that sinks the surface that far (the difference between two
/// steps is what the trainee feels).
struct LumpReach {
    double engageDepthMm = 0.0;   ///< the press that sinks the surface to the lump's top
    double feelDepthMm = 0.0;     ///< that press and one wheel step
    bool mouseFeels = false;      ///< the mouse's deepest press goes that deep
    double mouseDeepestMm = 0.0;  ///< the mouse's deepest press
    double deepestFeltMm = 0.0;   ///< the deepest lump top the mouse feels there (0: none)
    /// The force a press that deep gives on the tissue as it is (interpolated between the probed
    /// depths, extrapolated from the deepest two beyond them); nullopt when the tissue gives none.
    std::optional<double> forceN;
};

/// Judges a lump at its surface point against presses probed there at touch.depthsMm() (on the
/// tissue without the lump). Beyond the deepest press the sink and the force are extrapolated
/// from the deepest two (the slope-ring tissue's grow in proportion to the press).
LumpReach judgeLump(const LumpDef& lump, const TouchPresses& presses, const TouchReach& touch);

/// How firmly the mouse examines a surface (coverage.min_force_n, docs/scoring.md "Reachable
/// targets"): the force of its default press (before the wheel turns), rounded down to two
/// digits, and the force of its deepest press; each the middle of its values over a few points
/// spread over the surface.
struct ExamineReach {
    double defaultPressN = 0.0;
    double deepestN = 0.0;
};

/// The points the examining force is probed at: the vertices farthest out along -x, +x, -y, +y,
/// -z and +z (without repeats).
std::vector<VertexId> examinePoints(const std::vector<glm::vec3>& restMm);

/// Judges the forces probed at examinePoints() at touch.depthsMm(), the default press
/// `defaultDepthMm` deep; nullopt when none gives a force.
std::optional<ExamineReach> judgeExamining(const std::vector<std::vector<double>>& forcesPerPointN,
                                           const TouchReach& touch, double defaultDepthMm);

/// What to change, in English ("" when reachable): for the CLI and logs; the editor says it in
/// the user's language from the same figures.
std::string reachAdvice(const PressTarget& target, const TargetReach& reach);

/// Every press target of the exercise (others: none), in order. Empty with `error` when the
/// scene cannot be built.
std::vector<TargetReach> checkTargetReachability(const ExerciseAssets& assets, const TouchReach& touch,
                                                 std::string& error);

}  // namespace palpate
