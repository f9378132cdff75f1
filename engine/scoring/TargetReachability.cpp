#include "engine/scoring/TargetReachability.h"

#include "device/MouseDevice.h"
#include "engine/loop/HapticLoop.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace palpate {

namespace {

/// A depth is held until |F| changes by less than this from one tick to the next, kSettledTicks in
/// a row: well below what a window of the editor (3 decimals) can tell.
constexpr double kSettledForceChangeN = 1e-5;
constexpr int kSettledTicks = 10;
/// At most this long per depth: a tissue that still creeps then is judged where it is.
constexpr double kMaxSettleS = 0.5;
/// The tool's height above the surface before and between presses (no contact).
constexpr float kLiftMm = 20.0f;

std::string newtons(double forceN) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g N", forceN);
    return text;
}

std::string millimetres(double mm) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g mm", mm);
    return text;
}

}  // namespace

std::vector<double> TouchReach::depthsMm() const {
    std::vector<double> out;
    if (!(maxDepthMm >= 0.0) || !std::isfinite(maxDepthMm)) return out;
    if (depthStepMm > 0.0 && std::isfinite(depthStepMm))
        for (int k = 0; double(k) * depthStepMm < maxDepthMm - 1e-9; ++k) out.push_back(double(k) * depthStepMm);
    out.push_back(maxDepthMm);
    return out;
}

glm::vec3 touchToolPositionMm(const glm::vec3& restMm, const glm::vec3& normal, float toolRadiusMm, float depthMm) {
    return restMm + (toolRadiusMm - depthMm) * normal;
}

std::unique_ptr<TouchForceProbe> TouchForceProbe::create(const TissueMesh& mesh, const TissuePreset& preset,
                                                         const ExerciseGeometry* physics, const TouchReach& touch,
                                                         std::string& error) {
    std::unique_ptr<TouchForceProbe> probe(new TouchForceProbe);
    probe->mTouch = touch;
    probe->mDepthsMm = touch.depthsMm();
    if (probe->mDepthsMm.empty()) {
        error = "the touch depth must be a number >= 0 mm";
        return nullptr;
    }
    std::unique_ptr<HapticScene> scene;
    try {
        scene = HapticScene::create(mesh, preset);
    } catch (const std::exception& e) {
        error = std::string("the scene cannot be built: ") + e.what();
        return nullptr;
    }
    if (physics && !(error = applyExercisePhysics(*physics, *scene)).empty()) return nullptr;
    probe->mRestMm = scene->mesh().restPositionsMm();
    probe->mNormals = scene->mesh().restNormals();
    probe->mToolRadiusMm = scene->model().toolRadiusMm();
    // The device touch mode steers, with its spec: the safety filter shapes (and caps) the force as
    // it does in the window.
    auto mouse = std::make_unique<MouseDevice>();
    mouse->open();
    probe->mMouse = mouse.get();
    HapticLoopDef def;
    def.rateHz = preset.hapticRateHz;
    try {
        probe->mLoop = std::make_unique<HapticLoop>(def, std::move(scene), std::move(mouse));
    } catch (const std::exception& e) {
        error = std::string("the haptic loop cannot be made: ") + e.what();
        return nullptr;
    }
    probe->mMaxSettleTicks = std::max(kSettledTicks, int(std::ceil(kMaxSettleS * def.rateHz)));
    // Off the surface until the safety filter has armed and ramped in (as a fresh device does).
    if (!probe->mRestMm.empty()) probe->mMouse->setTargetMm(probe->mRestMm[0] + kLiftMm * probe->mNormals[0]);
    const int armTicks = int(std::ceil((def.safety.rampTimeS + 0.01) * def.rateHz));
    for (int i = 0; i < armTicks; ++i) probe->mLoop->stepOnce();
    return probe;
}

TouchForceProbe::~TouchForceProbe() = default;

double TouchForceProbe::settle() {
    double last = -1.0;
    int quiet = 0;
    for (int i = 0; i < mMaxSettleTicks; ++i) {
        mLoop->stepOnce();
        const double f = double(glm::length(mMouse->lastForceN()));
        quiet = std::abs(f - last) < kSettledForceChangeN ? quiet + 1 : 0;
        last = f;
        if (quiet >= kSettledTicks) break;
    }
    return last;
}

TouchPresses TouchForceProbe::presses(VertexId v) {
    TouchPresses out;
    if (v >= mRestMm.size() || v >= mNormals.size()) return out;
    // From rest, above the vertex, then in as the wheel presses: one step at a time.
    DeformationModel& model = mLoop->scene().model();
    model.reset();
    mMouse->setTargetMm(touchToolPositionMm(mRestMm[v], mNormals[v], mToolRadiusMm, -kLiftMm));
    settle();
    out.forcesN.reserve(mDepthsMm.size());
    out.sinksMm.reserve(mDepthsMm.size());
    for (const double depthMm : mDepthsMm) {
        mMouse->setTargetMm(touchToolPositionMm(mRestMm[v], mNormals[v], mToolRadiusMm, float(depthMm)));
        out.forcesN.push_back(settle());
        const auto positions = model.positionsMm();
        out.sinksMm.push_back(v < positions.size() ? double(glm::dot(mRestMm[v] - positions[v], mNormals[v])) : 0.0);
    }
    mMouse->setTargetMm(touchToolPositionMm(mRestMm[v], mNormals[v], mToolRadiusMm, -kLiftMm));
    settle();
    return out;
}

TargetReach judgeTarget(const PressTarget& target, const std::vector<double>& forcesN, const TouchReach& touch) {
    TargetReach r;
    const std::vector<double> depths = touch.depthsMm();
    const std::size_t n = std::min(depths.size(), forcesN.size());
    if (n == 0) return r;
    r.maxDepthMm = depths[n - 1];
    for (std::size_t i = 0; i < n; ++i) {
        r.maxForceN = std::max(r.maxForceN, forcesN[i]);
        if (!r.depthMm && forcesN[i] >= target.forceMinN && forcesN[i] <= target.forceMaxN) r.depthMm = depths[i];
    }
    r.reachable = r.depthMm.has_value();
    if (!r.reachable && r.maxForceN > target.forceMaxN)
        // Reached and passed: the window lies between two neighbouring depths' forces.
        for (std::size_t i = 0; i + 1 < n; ++i)
            if (forcesN[i] < target.forceMinN && forcesN[i + 1] > target.forceMaxN) {
                r.belowForceN = forcesN[i];
                r.aboveForceN = forcesN[i + 1];
                r.belowDepthMm = depths[i];
                r.aboveDepthMm = depths[i + 1];
                break;
            }
    return r;
}

namespace {

/// The force at `depthMm`, linear between the probed depths.
double forceAt(const std::vector<double>& forcesN, const std::vector<double>& depthsMm, double depthMm) {
    const std::size_t n = std::min(forcesN.size(), depthsMm.size());
    if (n == 0) return 0.0;
    if (depthMm <= depthsMm[0]) return forcesN[0];
    for (std::size_t i = 1; i < n; ++i)
        if (depthMm <= depthsMm[i]) {
            const double t = (depthMm - depthsMm[i - 1]) / (depthsMm[i] - depthsMm[i - 1]);
            return forcesN[i - 1] + t * (forcesN[i] - forcesN[i - 1]);
        }
    return forcesN[n - 1];
}

/// `value` rounded to two significant digits, up or down.
double roundTwoDigits(double value, bool up) {
    if (!(value > 0.0)) return value;
    const double unit = std::pow(10.0, std::floor(std::log10(value)) - 1.0);
    return (up ? std::ceil(value / unit - 1e-9) : std::floor(value / unit + 1e-9)) * unit;
}

}  // namespace

std::optional<ForceWindow> comfortableWindow(const std::vector<double>& forcesN, const TouchReach& touch) {
    const std::vector<double> depths = touch.depthsMm();
    const double loDepthMm = std::max(touch.maxDepthMm / 3.0, touch.defaultDepthMm + 2.0 * touch.depthStepMm);
    const double hiDepthMm = std::min(touch.maxDepthMm,
                                      std::max(2.0 * touch.maxDepthMm / 3.0, loDepthMm + 2.0 * touch.depthStepMm));
    if (!(hiDepthMm > loDepthMm)) return std::nullopt;
    const double lo = forceAt(forcesN, depths, loDepthMm);
    const double hi = forceAt(forcesN, depths, hiDepthMm);
    // Below a millinewton nothing is felt, and the editor's three decimals cannot hold it.
    if (!(lo >= 1e-3) || !(hi > lo)) return std::nullopt;
    ForceWindow w{roundTwoDigits(lo, true), roundTwoDigits(hi, false)};
    if (!(w.maxN > w.minN)) w = ForceWindow{lo, hi};
    return w;
}

std::vector<VertexId> examinePoints(const std::vector<glm::vec3>& restMm) {
    std::vector<VertexId> out;
    if (restMm.empty()) return out;
    for (int axis = 0; axis < 3; ++axis)
        for (const float sign : {-1.0f, 1.0f}) {
            VertexId best = 0;
            for (VertexId v = 1; v < restMm.size(); ++v)
                if (sign * restMm[v][axis] > sign * restMm[best][axis]) best = v;
            if (std::find(out.begin(), out.end(), best) == out.end()) out.push_back(best);
        }
    return out;
}

std::optional<ExamineReach> judgeExamining(const std::vector<std::vector<double>>& forcesPerPointN,
                                           const TouchReach& touch, double defaultDepthMm) {
    std::vector<double> defaultPress, deepest;
    const std::vector<double> depths = touch.depthsMm();
    for (const std::vector<double>& forces : forcesPerPointN) {
        if (forces.empty()) continue;
        defaultPress.push_back(forceAt(forces, depths, defaultDepthMm));
        deepest.push_back(forces.back());
    }
    if (deepest.empty()) return std::nullopt;
    const auto middle = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        const std::size_t n = v.size();
        return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    };
    ExamineReach out;
    out.deepestN = middle(deepest);
    out.defaultPressN = roundTwoDigits(middle(defaultPress), false);
    if (!(out.deepestN > 1e-6)) return std::nullopt;
    return out;
}

namespace {

/// y at x along the polyline (xs ascending), extrapolated from the last two points beyond it;
/// nullopt with fewer than two points beyond the first.
std::optional<double> alongOrBeyond(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
    const std::size_t n = std::min(xs.size(), ys.size());
    if (n == 0) return std::nullopt;
    if (x <= xs[n - 1]) return forceAt(ys, xs, x);  // along: the probe's own interpolation
    if (n == 1) return std::nullopt;
    const double span = xs[n - 1] - xs[n - 2];
    if (!(span > 0.0)) return ys[n - 1];
    return ys[n - 2] + (ys[n - 1] - ys[n - 2]) * (x - xs[n - 2]) / span;
}

/// The smallest x at which y (ascending in the main) reaches `level`, along or beyond the
/// polyline; nullopt when it never does (y flat or falling at the end).
std::optional<double> whereReaches(const std::vector<double>& xs, const std::vector<double>& ys, double level) {
    const std::size_t n = std::min(xs.size(), ys.size());
    for (std::size_t i = 0; i < n; ++i) {
        if (ys[i] < level) continue;
        if (i == 0) return xs[0];
        const double rise = ys[i] - ys[i - 1];
        return rise > 0.0 ? xs[i - 1] + (xs[i] - xs[i - 1]) * (level - ys[i - 1]) / rise : xs[i];
    }
    if (n < 2) return std::nullopt;
    const double slope = (ys[n - 1] - ys[n - 2]) / (xs[n - 1] - xs[n - 2]);
    if (!(slope > 1e-9)) return std::nullopt;
    return xs[n - 1] + (level - ys[n - 1]) / slope;
}

}  // namespace

LumpReach judgeLump(const LumpDef& lump, const TouchPresses& presses, const TouchReach& touch) {
    LumpReach out;
    const std::vector<double> depths = touch.depthsMm();
    // Without a wheel step (one depth), half a millimetre past.
    const double stepMm = touch.depthStepMm > 0.0 ? touch.depthStepMm : 0.5;
    out.mouseDeepestMm = touch.maxDepthMm;
    const std::optional<double> engage = whereReaches(depths, presses.sinksMm, lump.depthMm);
    // A tissue that does not sink with the press never brings the lump within reach.
    out.engageDepthMm = engage ? std::max(*engage, lump.depthMm) : std::numeric_limits<double>::infinity();
    out.feelDepthMm = out.engageDepthMm + stepMm;
    out.mouseFeels = touch.maxDepthMm + 1e-9 >= out.feelDepthMm;
    if (const auto sink = alongOrBeyond(depths, presses.sinksMm, touch.maxDepthMm - stepMm))
        out.deepestFeltMm = std::max(0.0, *sink);
    if (engage) {
        const std::optional<double> forceN = alongOrBeyond(depths, presses.forcesN, out.feelDepthMm);
        if (forceN && *forceN > 1e-6 && std::isfinite(*forceN)) out.forceN = *forceN;
    }
    return out;
}

std::string reachAdvice(const PressTarget& target, const TargetReach& reach) {
    if (reach.reachable) return {};
    const std::string window = newtons(target.forceMinN) + " to " + newtons(target.forceMaxN);
    if (reach.belowForceN)
        return "the window " + window + " lies between the force at " + millimetres(*reach.belowDepthMm) + " (" +
               newtons(*reach.belowForceN) + ") and at " + millimetres(*reach.aboveDepthMm) + " (" +
               newtons(*reach.aboveForceN) + "): widen it to take in one of them";
    return "the window " + window + " cannot be reached with the mouse: pressing " + millimetres(reach.maxDepthMm) +
           " deep (the deepest) gives " + newtons(reach.maxForceN) + "; lower force_min_n to at most " +
           newtons(reach.maxForceN) + ", or choose a stiffer tissue preset";
}

std::vector<TargetReach> checkTargetReachability(const ExerciseAssets& assets, const TouchReach& touch,
                                                 std::string& error) {
    std::vector<TargetReach> out;
    if (!assets.mesh || !assets.geometry || assets.geometry->targets().empty()) return out;
    auto probe = TouchForceProbe::create(*assets.mesh, assets.preset, assets.geometry.get(), touch, error);
    if (!probe) return out;
    for (const ResolvedTarget& t : assets.geometry->targets())
        out.push_back(judgeTarget(t.def, probe->forcesN(t.vertex), touch));
    return out;
}

}  // namespace palpate
