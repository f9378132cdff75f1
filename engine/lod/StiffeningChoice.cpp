#include "engine/lod/StiffeningChoice.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace palpate {

double stiffeningReferenceDepthOverRadius(double deepestMm, double toolRadiusMm) {
    return std::clamp(1.05 * deepestMm / toolRadiusMm, 0.6, 1.5);
}

double curveDepthAtForceMm(const std::vector<StiffeningCurvePoint>& curve, double forceN, double firstSlopeMmPerN) {
    if (!(forceN > 0.0)) return 0.0;
    if (curve.empty()) return forceN * firstSlopeMmPerN;
    if (forceN <= curve.front().forceN) return forceN * firstSlopeMmPerN / curve.front().ratio;
    for (std::size_t i = 1; i < curve.size(); ++i)
        if (forceN <= curve[i].forceN) {
            const double t = (forceN - curve[i - 1].forceN) / (curve[i].forceN - curve[i - 1].forceN);
            return curve[i - 1].depthMm + t * (curve[i].depthMm - curve[i - 1].depthMm);
        }
    if (curve.size() < 2) return forceN * firstSlopeMmPerN / curve.back().ratio;
    const auto& p = curve[curve.size() - 2];
    const auto& q = curve.back();
    return q.depthMm + (forceN - q.forceN) * (q.depthMm - p.depthMm) / (q.forceN - p.forceN);
}

StiffeningChoice chooseStiffening(const StiffeningCalibration& reference, const SlopeRingParams& knotted,
                                  const std::vector<SceneDepth>& depths, const LodNeeds& needs) {
    StiffeningChoice c;
    if (reference.curve.empty()) {
        c.error = "no hyperelastic reference curve to judge the linear model by";
        return c;
    }
    if (const auto problems = validateLodNeeds(needs); !problems.empty()) {
        c.error = problems.front().message;
        return c;
    }
    if (depths.empty()) {
        c.error = "the scene presses to no depth";
        return c;
    }
    const double m1 = knotted.slopeMagnitudeMmPerN[0];
    for (const SceneDepth& d : depths) {
        if (!(d.depthMm > 0.0)) continue;
        // Beyond the reference nothing is known: judge there at its deepest point.
        // A press passes every shallower depth on its way: the worst up to it counts.
        const double at = std::min(d.depthMm, reference.curve.back().depthMm);
        double linear = 0.0, nonlinear = 0.0;
        const auto judge = [&](double depthMm) {
            const double ref = curveForceAtDepthN(reference.curve, depthMm, m1);
            linear = std::max(linear, std::abs(depthMm / m1 - ref) / ref);
            nonlinear = std::max(nonlinear, std::abs(knotForceAtDepthN(knotted, depthMm) - ref) / ref);
        };
        for (const StiffeningCurvePoint& p : reference.curve)
            if (p.depthMm < at) judge(p.depthMm);
        judge(at);
        if (linear > c.linearErrorFraction || c.worstDepthWhat.empty()) {
            c.linearErrorFraction = std::max(c.linearErrorFraction, linear);
            c.worstDepthWhat = d.what;
            c.worstDepthMm = d.depthMm;
        }
        c.nonlinearErrorFraction = std::max(c.nonlinearErrorFraction, nonlinear);
    }
    const double target = needs.maxErrorFraction;
    const double deepestCurveMm = reference.curve.back().depthMm;
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(1);
    const auto pct = [](double f) { return 100.0 * f; };
    if (c.linearErrorFraction <= target) {
        c.feasible = true;
        s << "Linear tissue (no stiffening knots): at its deepest press (" << c.worstDepthWhat << ", "
          << c.worstDepthMm << " mm) the linear force is " << pct(c.linearErrorFraction)
          << " % off the hyperelastic reference, within the " << pct(target) << " % allowed; the knots would cost a "
          << "walk over " << reference.knots << " pieces per tick for no gain the scene asks for.";
    } else {
        c.nonlinear = true;
        c.knots = reference.knots;
        c.feasible = c.nonlinearErrorFraction <= target;
        s << "Stiffening tissue (" << reference.knots << " knots): the linear force is " << pct(c.linearErrorFraction)
          << " % off the hyperelastic reference at " << c.worstDepthWhat << " (" << c.worstDepthMm << " mm), above the "
          << pct(target) << " % allowed; with the knots it is " << pct(c.nonlinearErrorFraction) << " %"
          << (c.feasible ? "." : ", still above the target.");
    }
    for (const SceneDepth& d : depths)
        if (d.depthMm > deepestCurveMm * 1.0001) {
            s << " " << d.what << " (" << d.depthMm << " mm) lies beyond the reference's deepest point (" << deepestCurveMm
              << " mm), so it is judged there; deeper, neither model has been checked.";
            break;
        }
    c.reason = s.str();
    return c;
}

}  // namespace palpate
