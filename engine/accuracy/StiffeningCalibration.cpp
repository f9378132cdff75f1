#include "engine/accuracy/StiffeningCalibration.h"

#include "engine/fem/GradedBlock.h"
#include "engine/fem/HyperelasticFem.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace palpate {

namespace {

bool ascendingPositive(const std::vector<double>& v) {
    for (std::size_t i = 0; i < v.size(); ++i)
        if (!(std::isfinite(v[i]) && v[i] > 0.0 && v[i] < 2.0) || (i > 0 && !(v[i] > v[i - 1]))) return false;
    return true;
}

}  // namespace

void setStiffeningDepths(StiffeningCalibrationDef& def, double deepestOverRadius, int knots) {
    def.depthsOverRadius = {0.01};
    def.checkDepthsOverRadius.clear();
    for (int k = 1; k <= knots; ++k) {
        def.depthsOverRadius.push_back(deepestOverRadius * k / knots);
        def.checkDepthsOverRadius.push_back(deepestOverRadius * (k - 0.5) / knots);
    }
}

Problems validateStiffeningCalibrationDef(const StiffeningCalibrationDef& def) {
    if (Problems e = validateHyperelasticMaterial(def.material); !e.empty()) return e;
    if (!(std::isfinite(def.toolRadiusMm) && def.toolRadiusMm > 0.0))
        return oneProblem("toolRadiusMm", "tool radius must be a positive number of mm");
    if (def.depthsOverRadius.size() < 2 || def.depthsOverRadius.size() > std::size_t(kMaxStiffeningKnots) + 1)
        return oneProblem("depthsOverRadius", "knot depths: 2.." + std::to_string(kMaxStiffeningKnots + 1) +
                                                  " depths are needed (the knots and the last piece's end)");
    if (!ascendingPositive(def.depthsOverRadius))
        return oneProblem("depthsOverRadius", "knot depths over the tool radius must rise within (0, 2)");
    for (double d : def.checkDepthsOverRadius)
        if (!(std::isfinite(d) && d > 0.0 && d < 2.0))
            return oneProblem("checkDepthsOverRadius", "check depths over the tool radius must lie within (0, 2)");
    if (def.aOverH < 1 || def.aOverH > 32) return oneProblem("aOverH", "cells across the tool radius must be in 1..32");
    if (!(std::isfinite(def.maxStepOverRadius) && def.maxStepOverRadius > 0.0 && def.maxStepOverRadius <= 0.5))
        return oneProblem("maxStepOverRadius", "load step over the tool radius must lie in (0, 0.5]");
    return {};
}

StiffeningCalibration calibrateStiffening(const StiffeningCalibrationDef& def) {
    const auto start = std::chrono::steady_clock::now();
    if (const std::string e = joinedMessages(validateStiffeningCalibrationDef(def)); !e.empty())
        throw std::invalid_argument(e);
    const double a = def.toolRadiusMm;
    const ElasticMaterial& small = def.material.smallStrain;
    const double firstSlope = 1.0 / (2.0 * a * planeStrainModulusNPerMm2(small));

    // Every depth, ascending, remembering which the knots go through.
    std::vector<std::pair<double, bool>> depths;
    for (double d : def.depthsOverRadius) depths.emplace_back(d, true);
    for (double d : def.checkDepthsOverRadius)
        if (d < def.depthsOverRadius.back()) depths.emplace_back(d, false);
    std::sort(depths.begin(), depths.end());
    depths.erase(std::unique(depths.begin(), depths.end(), [](auto& x, auto& y) { return x.first == y.first; }),
                 depths.end());

    // The quarter of the half-space under the punch (symmetry planes x = 0, y = 0; far faces held),
    // the punch's nodes carrying exactly its area (ContactEdgeNodes::HalfSpacing).
    GradedBlockDef blockDef;
    blockDef.contactRadiusMm = a;
    blockDef.contactRadiusOverSpacing = def.aOverH;
    const GradedBlock block = makeGradedBlock(blockDef);
    const TetMesh& mesh = block.mesh;
    std::vector<std::uint8_t> fixed(mesh.dofCount(), 0);
    std::vector<TetNodeId> punch;
    for (std::size_t k = 0; k < block.nz(); ++k)
        for (std::size_t j = 0; j < block.nx(); ++j)
            for (std::size_t i = 0; i < block.nx(); ++i) {
                const TetNodeId n = block.node(i, j, k);
                if (i == 0) fixed[3 * n + 0] = 1;
                if (j == 0) fixed[3 * n + 1] = 1;
                if (i + 1 == block.nx() || j + 1 == block.nx() || k + 1 == block.nz())
                    for (int c = 0; c < 3; ++c) fixed[3 * n + std::size_t(c)] = 1;
                else if (k == 0 && std::hypot(mesh.nodesMm[n].x, mesh.nodesMm[n].y) <= a * (1.0 + 1e-9)) {
                    fixed[3 * n + 2] = 1;  // frictionless: the punch prescribes the normal motion only
                    punch.push_back(n);
                }
            }
    const HyperelasticFem fem(mesh, def.material, fixed);
    const double deepestMm = depths.back().first * a;
    auto load = [&](double t) {
        HyperelasticLoad l;
        l.prescribedMm.assign(mesh.dofCount(), 0.0);
        for (TetNodeId n : punch) l.prescribedMm[3 * n + 2] = -t * deepestMm;
        return l;
    };
    std::vector<double> factors;
    for (const auto& d : depths) factors.push_back(d.first / depths.back().first);
    const LoadPathResult path = fem.solvePath(load, factors, def.maxStepOverRadius / depths.back().first);

    // rho relative to the first (linear) depth: the mesh's own small-strain error cancels.
    std::vector<StiffeningCurvePoint> curve;
    double linearStiffness = 0.0;
    for (std::size_t p = 0; p < path.states.size(); ++p) {
        double force = 0.0;
        for (TetNodeId n : punch) force -= 4.0 * path.states[p].reactionN[n].z;
        const double depthMm = depths[p].first * a;
        if (p == 0) linearStiffness = force / depthMm;
        StiffeningCurvePoint point;
        point.depthMm = depthMm;
        point.ratio = force / depthMm / linearStiffness;
        point.forceN = depthMm * point.ratio / firstSlope;
        point.knot = depths[p].second;
        curve.push_back(point);
    }
    StiffeningCalibration out;
    // A path that stopped early keeps what it reached; knots need two fitted depths.
    const auto fitted = std::count_if(curve.begin(), curve.end(), [](const StiffeningCurvePoint& p) { return p.knot; });
    if (fitted >= 2 && linearStiffness > 0.0) out = knotsFromCurve(curve, firstSlope);
    else out.curve = curve;
    out.completed = path.completed;
    out.failure = path.failure;
    if (!path.completed) {
        std::ostringstream s;
        s << "the hyperelastic punch stopped at " << (curve.empty() ? 0.0 : curve.back().depthMm) << " mm of "
          << deepestMm << " mm (" << path.failure << "); the last piece goes on from there";
        out.notes.push_back(s.str());
    }
    std::ostringstream s;
    s << "reference: " << hyperelasticLawName(def.material.law) << " (b = " << def.material.stiffeningExponent
      << "), flat punch a = " << a << " mm on the graded half-space, a/h = " << def.aOverH << ", "
      << fem.freeDofCount() << " free DOFs, " << path.steps << " load steps";
    out.notes.insert(out.notes.begin(), s.str());
    out.freeDofs = fem.freeDofCount();
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

StiffeningCalibration knotsFromCurve(std::vector<StiffeningCurvePoint> curve, double firstSlopeMmPerN) {
    if (!(std::isfinite(firstSlopeMmPerN) && firstSlopeMmPerN > 0.0))
        throw std::invalid_argument("first-ring slope must be a positive number of mm/N");
    for (std::size_t i = 0; i < curve.size(); ++i)
        if (!(std::isfinite(curve[i].depthMm) && curve[i].depthMm > 0.0 && std::isfinite(curve[i].ratio) &&
              curve[i].ratio > 0.0) ||
            (i > 0 && !(curve[i].depthMm > curve[i - 1].depthMm)))
            throw std::invalid_argument("stiffening curve: depths must rise and ratios be positive");
    for (auto& p : curve) p.forceN = p.depthMm * p.ratio / firstSlopeMmPerN;
    StiffeningCalibration out;
    std::vector<const StiffeningCurvePoint*> through;
    for (const auto& p : curve)
        if (p.knot) through.push_back(&p);
    if (through.size() < 2) throw std::invalid_argument("stiffening curve: fewer than 2 depths to fit the knots through");
    // Below the first knot E(F) = F: the curve must be linear there.
    if (std::abs(through.front()->ratio - 1.0) > 1e-9)
        throw std::invalid_argument("stiffening curve: the first fitted depth must be linear (ratio 1)");
    if (through.size() > std::size_t(kMaxStiffeningKnots) + 1) through.resize(std::size_t(kMaxStiffeningKnots) + 1);
    // E = depth / |m1|, F = depth rho / |m1|; piece i from through[i] to through[i + 1] has
    // compliance dE / dF. Clamped to (0, 1] and to not rising (validation requires both).
    double previous = 1.0;
    for (std::size_t i = 0; i + 1 < through.size(); ++i) {
        const double d0 = through[i]->depthMm, d1 = through[i + 1]->depthMm;
        const double f0 = d0 * through[i]->ratio / firstSlopeMmPerN, f1 = d1 * through[i + 1]->ratio / firstSlopeMmPerN;
        if (!(f1 > f0)) throw std::invalid_argument("stiffening curve: the reference force does not rise with depth");
        double q = (d1 - d0) / firstSlopeMmPerN / (f1 - f0);
        if (q > previous) {
            std::ostringstream s;
            s << "between " << d0 << " and " << d1 << " mm the reference softens (compliance " << q
              << "); the piece keeps " << previous << " (the model only stiffens)";
            out.notes.push_back(s.str());
            q = previous;
        }
        q = std::max(q, 1e-6);
        out.knotForceN.push_back(i == 0 ? d0 / firstSlopeMmPerN : f0);
        out.knotCompliance.push_back(q);
        previous = q;
    }
    out.knots = int(out.knotForceN.size());
    // Knot forces must rise strictly; the first knot is where E(F) = F ends (rho = 1 there).
    for (std::size_t i = 1; i < out.knotForceN.size(); ++i)
        out.knotForceN[i] = std::max(out.knotForceN[i], std::nextafter(out.knotForceN[i - 1], INFINITY));
    SlopeRingParams params;
    params.slopeMagnitudeMmPerN[0] = firstSlopeMmPerN;
    applyStiffening(out, params);
    for (const auto& p : curve) {
        const double model = knotForceAtDepthN(params, p.depthMm);
        out.worstKnotErrorFraction = std::max(out.worstKnotErrorFraction, std::abs(model - p.forceN) / p.forceN);
    }
    out.curve = std::move(curve);
    out.completed = true;
    return out;
}

void applyStiffening(const StiffeningCalibration& calibration, SlopeRingParams& params) {
    params.stiffeningKnots = std::clamp(calibration.knots, 0, kMaxStiffeningKnots);
    for (int k = 0; k < params.stiffeningKnots; ++k) {
        params.stiffeningForceN[std::size_t(k)] = calibration.knotForceN[std::size_t(k)];
        params.stiffeningCompliance[std::size_t(k)] = calibration.knotCompliance[std::size_t(k)];
    }
}

double knotForceAtDepthN(const SlopeRingParams& params, double depthMm) {
    const double m1 = params.slopeMagnitudeMmPerN[0];
    const double effective = depthMm / m1;
    const int knots = std::clamp(params.stiffeningKnots, 0, kMaxStiffeningKnots);
    if (knots == 0 || effective <= params.stiffeningForceN[0]) return effective;
    // Walk E(F) = E_k + q_k (F - F_k) piece by piece (docs/method.md, "Tissue that stiffens with depth").
    double eK = params.stiffeningForceN[0];
    int k = 0;
    while (k + 1 < knots) {
        const double eNext = eK + params.stiffeningCompliance[std::size_t(k)] *
                                      (params.stiffeningForceN[std::size_t(k + 1)] - params.stiffeningForceN[std::size_t(k)]);
        if (effective <= eNext) break;
        eK = eNext;
        ++k;
    }
    return params.stiffeningForceN[std::size_t(k)] + (effective - eK) / params.stiffeningCompliance[std::size_t(k)];
}

double curveForceAtDepthN(const std::vector<StiffeningCurvePoint>& curve, double depthMm, double firstSlopeMmPerN) {
    if (curve.empty()) return depthMm / firstSlopeMmPerN;
    if (depthMm <= curve.front().depthMm) return depthMm / firstSlopeMmPerN * curve.front().ratio;
    for (std::size_t i = 1; i < curve.size(); ++i)
        if (depthMm <= curve[i].depthMm) {
            const double t = (depthMm - curve[i - 1].depthMm) / (curve[i].depthMm - curve[i - 1].depthMm);
            return curve[i - 1].forceN + t * (curve[i].forceN - curve[i - 1].forceN);
        }
    // Beyond the last point: its last segment goes on, as the knots' last piece does.
    if (curve.size() < 2) return depthMm / firstSlopeMmPerN * curve.back().ratio;
    const auto& p = curve[curve.size() - 2];
    const auto& q = curve.back();
    return q.forceN + (depthMm - q.depthMm) * (q.forceN - p.forceN) / (q.depthMm - p.depthMm);
}

}  // namespace palpate
