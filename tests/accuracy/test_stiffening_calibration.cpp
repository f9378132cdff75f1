// Stiffening knots from the hyperelastic reference (docs/calibration.md, "Knots from the
// hyperelastic reference") and the linear-or-nonlinear choice (docs/lod.md).

#include "engine/accuracy/Calibration.h"
#include "engine/accuracy/StiffeningCalibration.h"
#include "engine/exercise/ExerciseDemands.h"
#include "engine/exercise/ExerciseFile.h"
#include "engine/lod/StiffeningChoice.h"
#include "engine/models/slopering/SlopeRingParams.h"

#include <gtest/gtest.h>

#include <cmath>

namespace palpate {
namespace {

/// rho(d) = 1 + c (d^2 - d_0^2) at the given depths (1 at the first, as a calibration has it), all fitted.
std::vector<StiffeningCurvePoint> quadraticCurve(const std::vector<double>& depthsMm, double c, double m1) {
    std::vector<StiffeningCurvePoint> curve;
    for (double d : depthsMm) {
        StiffeningCurvePoint p;
        p.depthMm = d;
        p.ratio = 1.0 + c * (d * d - depthsMm[0] * depthsMm[0]);
        p.forceN = d * p.ratio / m1;
        p.knot = true;
        curve.push_back(p);
    }
    return curve;
}

TEST(StiffeningKnots, PassThroughTheFittedDepthsAndStiffen) {
    const double m1 = 2.0;
    const auto curve = quadraticCurve({0.05, 1.0, 2.0, 3.0, 4.0}, 0.05, m1);
    const StiffeningCalibration k = knotsFromCurve(curve, m1);
    ASSERT_EQ(k.knots, 4);
    EXPECT_DOUBLE_EQ(k.knotForceN[0], 0.05 / m1);  // where E(F) = F ends
    for (int i = 1; i < k.knots; ++i) {
        EXPECT_GT(k.knotForceN[std::size_t(i)], k.knotForceN[std::size_t(i - 1)]);
        EXPECT_LE(k.knotCompliance[std::size_t(i)], k.knotCompliance[std::size_t(i - 1)]);
    }
    for (double q : k.knotCompliance) {
        EXPECT_GT(q, 0.0);
        EXPECT_LE(q, 1.0);
    }
    SlopeRingParams p;
    p.slopeMagnitudeMmPerN[0] = m1;
    p.slopeLimitMmPerN = 2.5;
    applyStiffening(k, p);
    for (const Problem& problem : validateSlopeRingParams(p)) ADD_FAILURE() << problem.message;
    for (const auto& point : curve) EXPECT_NEAR(knotForceAtDepthN(p, point.depthMm), point.forceN, 1e-12 * point.forceN);
    EXPECT_LT(k.worstKnotErrorFraction, 1e-12);
    // Between knots the chord is stiffer than the convex curve's ... and below the first knot linear.
    EXPECT_DOUBLE_EQ(knotForceAtDepthN(p, 0.01), 0.01 / m1);
    // Beyond the last depth the last piece goes on, and so does the curve: they agree.
    EXPECT_NEAR(knotForceAtDepthN(p, 6.0), curveForceAtDepthN(curve, 6.0, m1), 1e-9);
}

TEST(StiffeningKnots, ASofteningStretchIsHeldAndNoted) {
    const double m1 = 1.0;
    std::vector<StiffeningCurvePoint> curve = quadraticCurve({0.05, 1.0, 2.0, 3.0}, 0.1, m1);
    curve[3].ratio = curve[2].ratio * 0.9;  // softer again: the model cannot follow
    const StiffeningCalibration k = knotsFromCurve(curve, m1);
    ASSERT_EQ(k.knots, 3);
    EXPECT_DOUBLE_EQ(k.knotCompliance[2], k.knotCompliance[1]);
    ASSERT_FALSE(k.notes.empty());
    EXPECT_NE(k.notes.front().find("softens"), std::string::npos);
}

TEST(StiffeningKnots, BadCurvesAreRefused) {
    EXPECT_THROW(knotsFromCurve({}, 1.0), std::invalid_argument);
    auto curve = quadraticCurve({0.05, 1.0}, 0.1, 1.0);
    EXPECT_THROW(knotsFromCurve(curve, 0.0), std::invalid_argument);
    curve[1].depthMm = 0.01;
    EXPECT_THROW(knotsFromCurve(curve, 1.0), std::invalid_argument);
    StiffeningCalibrationDef def;
    def.depthsOverRadius = {0.3, 0.2};
    EXPECT_FALSE(validateStiffeningCalibrationDef(def).empty());
    def = {};
    def.material.smallStrain.poissonRatio = 0.6;
    EXPECT_FALSE(validateStiffeningCalibrationDef(def).empty());
    def = {};
    def.toolRadiusMm = -1.0;
    EXPECT_THROW(calibrateStiffening(def), std::invalid_argument);
}

// The hyperelastic punch on a coarse block: the first ratio is 1 by construction, neo-Hookean
// tissue stiffens a little with depth and the exponential law much more.
TEST(StiffeningReference, ExponentialTissueStiffensMoreThanNeoHookean) {
    StiffeningCalibrationDef def;
    def.material.smallStrain = {4.34e-3, 0.45};
    def.toolRadiusMm = 5.0;
    def.aOverH = 2;
    def.depthsOverRadius = {0.01, 0.2, 0.4, 0.6};
    def.checkDepthsOverRadius = {0.3};
    def.maxStepOverRadius = 0.05;
    const StiffeningCalibration neo = calibrateStiffening(def);
    def.material.law = HyperelasticLaw::Exponential;
    def.material.stiffeningExponent = 5.0;
    const StiffeningCalibration expo = calibrateStiffening(def);
    for (const auto* c : {&neo, &expo}) {
        ASSERT_TRUE(c->completed) << c->failure;
        ASSERT_EQ(c->curve.size(), 5u);
        EXPECT_DOUBLE_EQ(c->curve.front().ratio, 1.0);
        EXPECT_EQ(c->knots, 3);
        for (std::size_t i = 1; i < c->curve.size(); ++i) EXPECT_GT(c->curve[i].ratio, c->curve[i - 1].ratio);
        EXPECT_LT(c->worstKnotErrorFraction, 0.02);
    }
    EXPECT_LT(neo.curve.back().ratio, 1.1);
    EXPECT_GT(expo.curve.back().ratio, neo.curve.back().ratio + 0.1);
    // The curve's forces are the punch formula times rho.
    const double m1 = 1.0 / (2.0 * 5.0 * planeStrainModulusNPerMm2(def.material.smallStrain));
    for (const auto& p : expo.curve) EXPECT_NEAR(p.forceN, p.depthMm * p.ratio / m1, 1e-12 * p.forceN);
}

TEST(StiffeningChoiceTest, LinearWhileItMeetsTheTargetElseTheKnots) {
    const double m1 = 2.0;
    const StiffeningCalibration k = knotsFromCurve(quadraticCurve({0.05, 1.0, 2.0, 3.0, 4.0}, 0.05, m1), m1);
    SlopeRingParams p;
    p.slopeMagnitudeMmPerN[0] = m1;
    applyStiffening(k, p);
    // rho(1) ~ 1.05: linear error 1 - 1/1.05 = 4.8 %; rho(3) ~ 1.45: 31 % (d_0^2 = 0.0025 aside).
    const LodNeeds tenPercent{0.1, 100.0};
    const StiffeningChoice shallow = chooseStiffening(k, p, {{"a light press", 1.0}}, tenPercent);
    EXPECT_TRUE(shallow.error.empty()) << shallow.error;
    EXPECT_FALSE(shallow.nonlinear);
    EXPECT_TRUE(shallow.feasible);
    EXPECT_NEAR(shallow.linearErrorFraction, 1.0 - 1.0 / (1.05 - 0.05 * 0.0025), 1e-9);
    EXPECT_NE(shallow.reason.find("a light press"), std::string::npos);

    const StiffeningChoice deep = chooseStiffening(k, p, {{"a light press", 1.0}, {"a firm press", 3.0}}, tenPercent);
    EXPECT_TRUE(deep.nonlinear);
    EXPECT_TRUE(deep.feasible);
    EXPECT_EQ(deep.knots, 4);
    EXPECT_EQ(deep.worstDepthWhat, "a firm press");
    EXPECT_NEAR(deep.linearErrorFraction, 1.0 - 1.0 / (1.45 - 0.05 * 0.0025), 1e-9);
    EXPECT_LT(deep.nonlinearErrorFraction, 1e-9);

    // Beyond the reference: judged at its deepest point, and said.
    const StiffeningChoice beyond = chooseStiffening(k, p, {{"a very firm press", 9.0}}, tenPercent);
    EXPECT_NEAR(beyond.linearErrorFraction, 1.0 - 1.0 / (1.8 - 0.05 * 0.0025), 1e-9);
    EXPECT_NE(beyond.reason.find("beyond the reference"), std::string::npos) << beyond.reason;

    EXPECT_FALSE(chooseStiffening(k, p, {}, tenPercent).error.empty());
    EXPECT_FALSE(chooseStiffening(k, p, {{"x", 1.0}}, LodNeeds{-1.0, 100.0}).error.empty());
    EXPECT_FALSE(chooseStiffening(StiffeningCalibration{}, p, {{"x", 1.0}}, tenPercent).error.empty());
    // Depth at force inverts the curve.
    EXPECT_NEAR(curveDepthAtForceMm(k.curve, curveForceAtDepthN(k.curve, 2.5, m1), m1), 2.5, 1e-9);
}

TEST(ExerciseDemandsTest, ShippedExercisesNameTheirPresses) {
    const std::string dir = std::string(PALPATE_SOURCE_DIR) + "/resources/exercises/";
    for (const char* name : {"press_targets", "trace", "find_lump", "detect_lumps", "no_lump"}) {
        const ExerciseLoadResult ex = loadExercise(dir + name + ".json");
        ASSERT_TRUE(ex.exercise) << ex.error();
        const auto demands = exerciseDemands(*ex.exercise);
        ASSERT_FALSE(demands.empty()) << name;
        for (const ExerciseDemand& d : demands) {
            EXPECT_FALSE(d.what.empty());
            EXPECT_TRUE((d.forceN > 0.0) != (d.depthMm > 0.0)) << name << ": " << d.what;
        }
    }
    const ExerciseLoadResult press = loadExercise(dir + "press_targets.json");
    const auto demands = exerciseDemands(*press.exercise);
    ASSERT_EQ(demands.size(), press.exercise->pressTargets.targets.size());
    EXPECT_EQ(demands[0].forceN, press.exercise->pressTargets.targets[0].forceMaxN);
    const ExerciseLoadResult lumps = loadExercise(dir + "detect_lumps.json");
    double deepest = 0.0;
    for (const LumpDef& l : lumps.exercise->detectLumps.lumps) deepest = std::max(deepest, l.depthMm);
    EXPECT_EQ(exerciseDemands(*lumps.exercise)[0].depthMm, deepest);
}

}  // namespace
}  // namespace palpate
