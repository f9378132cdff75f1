// Press targets (docs/scoring.md, "Press targets"): press a sequence of surface targets, each with
// the force inside its window, and hold it there.

#include "engine/exercise/kinds/Kinds.h"

#include "base/io/FileLimits.h"
#include "base/io/JsonReader.h"
#include "base/params/FieldTable.h"
#include "engine/exercise/ExerciseGeometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace palpate {

namespace {

/// Slack on the hold time: the clock's sum of 1 ms steps is not exact.
constexpr double kHoldSlackS = 1e-9;

double distance(const glm::vec3& a, const glm::vec3& b) { return glm::length(glm::dvec3(a) - glm::dvec3(b)); }

class PressTargetsTask final : public ExerciseTask {
public:
    explicit PressTargetsTask(std::shared_ptr<const ExerciseGeometry> geometry) : mGeometry(std::move(geometry)) {
        const std::size_t n = mGeometry->targets().size();
        mTargets.assign(n, TargetResult{});
        mErrorSumMmS.assign(n, 0.0);
        mErrorS.assign(n, 0.0);
    }

    void start(ScoreGuidance& g) override {
        const auto& targets = mGeometry->targets();
        if (targets.empty()) return;
        g.targetIndex = 0;
        g.targetCount = int(targets.size());
        g.forceMinN = targets[0].def.forceMinN;
        g.forceMaxN = targets[0].def.forceMaxN;
    }

    bool step(const TaskTick& t, ScoreGuidance& g) override {
        const auto& targets = mGeometry->targets();
        if (mTarget >= targets.size()) return false;
        const ResolvedTarget& target = targets[mTarget];
        const double dist = t.haveContactPoint ? distance(t.contactPointMm, target.pointMm) : std::numeric_limits<double>::infinity();
        const bool inWindow = t.contact && t.forceN >= target.def.forceMinN && t.forceN <= target.def.forceMaxN;
        const bool onTarget = t.contact && t.haveContactPoint && dist <= target.def.toleranceMm;
        TargetResult& result = mTargets[mTarget];
        // The press that achieved the previous target is not one for this target: it counts from
        // the first tick the force leaves the window.
        if (!inWindow) mCarriedPress = false;
        if (inWindow && t.haveContactPoint && !mCarriedPress) {
            mErrorSumMmS[mTarget] += dist * t.dtS;
            mErrorS[mTarget] += t.dtS;
        }
        // The hold time on a target runs from the first time the force is inside its window there
        // (pressing in to the window is not holding).
        if (onTarget && inWindow) mHoldStarted = true;
        if (onTarget && mHoldStarted) result.onTargetS += t.dtS;
        if (onTarget && inWindow) {
            result.inWindowS += t.dtS;
            mHoldS += t.dtS;
        } else {
            mHoldS = 0.0;
        }
        g.onTarget = onTarget;
        g.distanceToTargetMm = t.haveContactPoint ? dist : 0.0;
        g.holdProgress = target.def.holdS > 0.0 ? std::min(1.0, mHoldS / target.def.holdS) : 0.0;
        if (!(onTarget && inWindow && mHoldS >= target.def.holdS - kHoldSlackS)) return false;
        result.achieved = true;
        result.achievedAtS = t.elapsedS;
        ++mTarget;
        mHoldS = 0.0;
        mHoldStarted = false;
        mCarriedPress = true;
        g.holdProgress = 0.0;
        g.onTarget = false;
        if (mTarget == targets.size()) {
            g.targetIndex = -1;
            return true;
        }
        g.targetIndex = int(mTarget);
        g.forceMinN = targets[mTarget].def.forceMinN;
        g.forceMaxN = targets[mTarget].def.forceMaxN;
        return false;
    }

    double completion(const ScoreGuidance&) const override {
        const auto& targets = mGeometry->targets();
        return targets.empty() ? 0.0 : double(mTarget) / double(targets.size());
    }

    std::optional<double> idealPathMm(const glm::vec3& startMm) const override {
        if (mTarget == 0) return std::nullopt;
        const auto& targets = mGeometry->targets();
        double idealMm = distance(startMm, targets[0].pointMm);
        for (std::size_t i = 1; i < mTarget; ++i) idealMm += distance(targets[i].pointMm, targets[i - 1].pointMm);
        return idealMm;
    }

    void report(ScoreReport& r, MeasuredMetrics& metrics, bool) const override {
        r.targets = mTargets;
        for (std::size_t i = 0; i < r.targets.size(); ++i) {
            r.targets[i].errorMeasured = mErrorS[i] > 0.0;
            r.targets[i].errorMm = r.targets[i].errorMeasured ? mErrorSumMmS[i] / mErrorS[i] : 0.0;
        }
        double sum = 0.0;
        int n = 0;
        for (const TargetResult& t : r.targets)
            if (t.errorMeasured) {
                sum += t.errorMm;
                ++n;
            }
        metrics.put(Metric::TargetErrorMm, n > 0 ? sum / n : 0.0, n > 0);
        double on = 0.0, in = 0.0;
        for (const TargetResult& t : r.targets) {
            on += t.onTargetS;
            in += t.inWindowS;
        }
        metrics.put(Metric::HoldInWindowFraction, on > 0.0 ? in / on : 0.0, on > 0.0);
    }

private:
    std::shared_ptr<const ExerciseGeometry> mGeometry;
    std::size_t mTarget = 0;
    double mHoldS = 0.0;
    bool mHoldStarted = false;   // the force was inside the current target's window on it
    bool mCarriedPress = false;  // the press that achieved the previous target goes on
    std::vector<TargetResult> mTargets;
    std::vector<double> mErrorSumMmS, mErrorS;
};

// What the editor edits: the targets, each with its window, hold and tolerance.
PressTarget& targetOf(Exercise& e, std::size_t i) { return e.pressTargets.targets[i]; }
const PressTarget& targetOf(const Exercise& e, std::size_t i) { return e.pressTargets.targets[i]; }

constexpr EditedNumber kTargetNumbers[] = {
    {"force_min_n", PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Fmin"),
     PALPATE_TRANSLATE_NOOP("palpate::Exercises", "The force window's lower end, N (force_min_n)."), "N", 0.0, 1000.0,
     3, 0.05, [](const Exercise& e, std::size_t i) { return targetOf(e, i).forceMinN; },
     [](Exercise& e, std::size_t i, double v) { targetOf(e, i).forceMinN = v; }},
    {"force_max_n", PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Fmax"),
     PALPATE_TRANSLATE_NOOP("palpate::Exercises", "The force window's upper end, N (force_max_n)."), "N", 0.0, 1000.0,
     3, 0.05, [](const Exercise& e, std::size_t i) { return targetOf(e, i).forceMaxN; },
     [](Exercise& e, std::size_t i, double v) { targetOf(e, i).forceMaxN = v; }},
    {"hold_s", PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Hold"),
     PALPATE_TRANSLATE_NOOP("palpate::Exercises",
                            "How long the force must stay in the window without a break, s (hold_s)."),
     "s", 0.0, 600.0, 3, 0.1, [](const Exercise& e, std::size_t i) { return targetOf(e, i).holdS; },
     [](Exercise& e, std::size_t i, double v) { targetOf(e, i).holdS = v; }},
    {"tolerance_mm", PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Tol."),
     PALPATE_TRANSLATE_NOOP("palpate::Exercises", "How close to the target the contact must be, mm (tolerance_mm)."),
     "mm", 0.0, 1000.0, 3, 0.5, [](const Exercise& e, std::size_t i) { return targetOf(e, i).toleranceMm; },
     [](Exercise& e, std::size_t i, double v) { targetOf(e, i).toleranceMm = v; }},
};

const ExerciseEditing kEditing{
    PlacedItems{
        "press_targets.targets", PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Target %1"),
        PALPATE_TRANSLATE_NOOP(
            "palpate::Exercises",
            "While on, each click on the tissue appends a target there, with the last target's window, hold and "
            "tolerance; the first gets a window the tissue reaches with the mouse (Esc stops)."),
        false, true, [](const Exercise& e) { return e.pressTargets.targets.size(); },
        [](const Exercise& e, std::size_t i) -> const SurfacePoint& { return targetOf(e, i).at; },
        [](Exercise& e, std::size_t i, const SurfacePoint& at) { targetOf(e, i).at = at; },
        [](Exercise& e, const SurfacePoint& at) {
            PressTarget t = e.pressTargets.targets.empty() ? PressTarget{} : e.pressTargets.targets.back();
            t.at = at;
            e.pressTargets.targets.push_back(t);
        },
        [](Exercise& e, std::size_t i) {
            e.pressTargets.targets.erase(e.pressTargets.targets.begin() + std::ptrdiff_t(i));
        },
        [](Exercise& e, std::size_t a, std::size_t b) { std::swap(targetOf(e, a), targetOf(e, b)); }, kTargetNumbers,
        [](Exercise& e, double minN, double maxN) {
            PressTarget& t = e.pressTargets.targets.front();
            t.forceMinN = minN;
            t.forceMaxN = maxN;
        }},
    {}};

class PressTargetsKind final : public ExerciseKind {
public:
    ExerciseType type() const override { return ExerciseType::PressTargets; }
    std::string_view key() const override { return "press_targets"; }
    const char* label() const override { return PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Press targets"); }

    std::span<const Metric> ownMetrics() const override {
        static constexpr Metric kOwn[] = {Metric::TargetErrorMm, Metric::HoldInWindowFraction, Metric::Economy};
        return kOwn;
    }
    std::span<const MetricWeight> defaultWeights() const override {
        static constexpr MetricWeight kWeights[] = {
            {Metric::Completion, 40},           {Metric::TimeS, 10},
            {Metric::TargetErrorMm, 10},        {Metric::HoldInWindowFraction, 15},
            {Metric::ExcessiveForceEvents, 5},  {Metric::ExcessiveForceFraction, 5},
            {Metric::DamageTimeS, 10},          {Metric::Economy, 5},
        };
        return kWeights;
    }

    std::vector<std::string> sectionKeys() const override {
        return {"targets", "force_min_n", "force_max_n", "hold_s", "tolerance_mm"};
    }
    void readSection(JsonReader& r, const Json& s, Exercise& e) const override {
        const std::string path = "press_targets";
        PressTarget defaults;
        r.number(s, path, "force_min_n", defaults.forceMinN);
        r.number(s, path, "force_max_n", defaults.forceMaxN);
        r.number(s, path, "hold_s", defaults.holdS);
        r.number(s, path, "tolerance_mm", defaults.toleranceMm);
        if (!s.contains("targets")) {
            r.error("press_targets.targets", "missing");
            return;
        }
        if (!s.at("targets").is_array()) {
            r.error("press_targets.targets", "must be an array of targets");
            return;
        }
        const Json& a = s.at("targets");
        for (std::size_t i = 0; i < a.size() && i <= std::size_t(kMaxPressTargets); ++i) {
            const std::string key = "press_targets.targets[" + std::to_string(i) + "]";
            PressTarget t = defaults;
            if (r.object(a[i], key, {"vertex", "point_mm", "force_min_n", "force_max_n", "hold_s", "tolerance_mm"})) {
                readSurfacePoint(r, a[i], key, t.at);
                r.number(a[i], key, "force_min_n", t.forceMinN);
                r.number(a[i], key, "force_max_n", t.forceMaxN);
                r.number(a[i], key, "hold_s", t.holdS);
                r.number(a[i], key, "tolerance_mm", t.toleranceMm);
            }
            e.pressTargets.targets.push_back(t);
        }
    }
    Json writeSection(const Exercise& e) const override {
        Json targets = Json::array();
        for (const PressTarget& t : e.pressTargets.targets) {
            Json o = surfacePointJson(t.at);
            o["force_min_n"] = t.forceMinN;
            o["force_max_n"] = t.forceMaxN;
            o["hold_s"] = t.holdS;
            o["tolerance_mm"] = t.toleranceMm;
            targets.push_back(o);
        }
        return {{"targets", targets}};
    }
    void validate(const Exercise& e, ExerciseChecker& c) const override {
        const auto& targets = e.pressTargets.targets;
        if (targets.empty()) c.error("press_targets.targets", "needs at least one target");
        if (targets.size() > std::size_t(kMaxPressTargets))
            c.error("press_targets.targets", "has more than " + std::to_string(kMaxPressTargets) + " targets");
        for (std::size_t i = 0; i < targets.size() && i < std::size_t(kMaxPressTargets); ++i) {
            const PressTarget& t = targets[i];
            const std::string key = "press_targets.targets[" + std::to_string(i) + "]";
            c.point(key, t.at);
            c.window(key, t.forceMinN, t.forceMaxN, "force_min_n", "force_max_n");
            c.range(key + ".hold_s", t.holdS, 0.0, 600.0);
            c.range(key + ".tolerance_mm", t.toleranceMm, 0.0, 1000.0, true);
            if (t.forceMinN >= e.excessiveForceN)
                c.error(key + ".force_min_n", ExerciseChecker::text(t.forceMinN) + " N is not below force.excessive_n " +
                                                  ExerciseChecker::text(e.excessiveForceN) +
                                                  " N: the target cannot be met safely");
        }
    }

    void place(const Exercise& e, GeometryPlacer& placer, PlacedGeometry& placed, std::string&) const override {
        const auto& rest = placer.mesh().restPositionsMm();
        for (std::size_t i = 0; i < e.pressTargets.targets.size(); ++i) {
            const PressTarget& t = e.pressTargets.targets[i];
            ResolvedTarget r;
            r.def = t;
            r.vertex = placer.place(t.at, "press_targets.targets[" + std::to_string(i) + "]");
            if (r.vertex != kNoVertex) r.pointMm = rest[r.vertex];
            placed.targets.push_back(r);
        }
    }
    std::vector<ExerciseDemand> demands(const Exercise& e) const override {
        std::vector<ExerciseDemand> out;
        for (std::size_t i = 0; i < e.pressTargets.targets.size(); ++i) {
            const double f = e.pressTargets.targets[i].forceMaxN;
            out.push_back({"press target " + std::to_string(i + 1) + " (up to " + demandNumber(f) + " N)", f, 0.0});
        }
        return out;
    }
    std::unique_ptr<ExerciseTask> makeTask(std::shared_ptr<const ExerciseGeometry> geometry, double) const override {
        return std::make_unique<PressTargetsTask>(std::move(geometry));
    }

    const ExerciseEditing& editing() const override { return kEditing; }

    ExerciseDrawing draw(const ExerciseGeometry& geometry, MarkerAudience, const ScoreGuidance* guidance,
                         int selected) const override {
        ExerciseDrawing out;
        const auto& targets = geometry.targets();
        for (std::size_t i = 0; i < targets.size(); ++i) {
            SurfaceMarker m;
            m.kind = SurfaceMarkerKind::Target;
            if (guidance && guidance->targetIndex >= 0) {
                if (int(i) < guidance->targetIndex) m.kind = SurfaceMarkerKind::DoneTarget;
                else if (int(i) == guidance->targetIndex) m.kind = SurfaceMarkerKind::CurrentTarget;
            } else if (guidance && guidance->completed) {
                m.kind = SurfaceMarkerKind::DoneTarget;
            }
            m.positionMm = targets[i].pointMm;
            m.normal = normalOf(geometry, targets[i].vertex);
            m.label = ViewText{"%1"}.whole(double(i + 1));
            // The tolerance circle helps the instructor place targets and the trainee aim.
            m.radiusMm = targets[i].def.toleranceMm;
            m.selected = int(i) == selected;
            out.markers.push_back(m);
        }
        return out;
    }
    GuidanceView guidance(const Exercise&, const ScoreGuidance& g) const override {
        GuidanceView v;
        v.windowMinN = g.forceMinN;
        v.windowMaxN = g.forceMaxN;
        if (g.targetIndex >= 0) {
            v.instruction = ViewText{PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Target %1 of %2: press with %3 and hold")}
                                .whole(g.targetIndex + 1)
                                .whole(g.targetCount)
                                .forceRange(g.forceMinN, g.forceMaxN);
            v.detail.push_back(g.onTarget ? ViewText{PALPATE_TRANSLATE_NOOP("palpate::Exercises", "On target")}
                                          : ViewText{PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Move to the blue marker (%1 mm away)")}
                                                .fixed(g.distanceToTargetMm, 0));
            v.progress = g.holdProgress;
            v.progressFormat = {PALPATE_TRANSLATE_NOOP("palpate::Exercises", "hold %p%")};
        } else {
            v.instruction = {g.completed ? PALPATE_TRANSLATE_NOOP("palpate::Exercises", "All targets done")
                                         : PALPATE_TRANSLATE_NOOP("palpate::Exercises", "No target left")};
            v.progress = 1.0;
            v.progressFormat = {PALPATE_TRANSLATE_NOOP("palpate::Exercises", "hold %p%")};
        }
        return v;
    }
};

}  // namespace

const ExerciseKind& pressTargetsKind() {
    static const PressTargetsKind kind;
    return kind;
}

}  // namespace palpate
