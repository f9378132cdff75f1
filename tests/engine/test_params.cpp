// Slope-ring parameters: every way to get them wrong is rejected with a message naming the
// parameter; the defaults and the stable side of the loop-gain bound are accepted.

#include "engine/core/MeshGenerator.h"
#include "engine/core/Octree.h"
#include "engine/models/slopering/SlopeRingModel.h"
#include "engine/models/slopering/SlopeRingParams.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace palpate {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string joined(const std::vector<std::string>& errors) {
    std::string out;
    for (const auto& e : errors) out += e + "\n";
    return out;
}

bool anyMentions(const std::vector<std::string>& errors, const std::string& a, const std::string& b = "") {
    for (const auto& e : errors)
        if (e.find(a) != std::string::npos && (b.empty() || e.find(b) != std::string::npos)) return true;
    return false;
}

/// Strictly decreasing magnitudes below 1 for rings 0..ringCount: 0.9, 0.8, ...
SlopeRingParams validFor(int ringCount) {
    SlopeRingParams p;
    p.ringCount = ringCount;
    for (int r = 0; r <= kMaxRings; ++r) p.slopeMagnitudeMmPerN[std::size_t(r)] = 0.9 - 0.1 * r;
    return p;
}

std::string slopeName(int r) { return "|m" + std::to_string(r + 1) + "|"; }

TEST(SlopeRingParams, DefaultsAreValid) {
    const SlopeRingParams defaults;
    EXPECT_TRUE(messagesOf(validateSlopeRingParams(defaults)).empty()) << joined(messagesOf(validateSlopeRingParams(defaults)));
    for (int n = 0; n <= kMaxRings; ++n)
        EXPECT_TRUE(messagesOf(validateSlopeRingParams(validFor(n))).empty()) << "ringCount " << n << "\n"
                                                                  << joined(messagesOf(validateSlopeRingParams(validFor(n))));
}

TEST(SlopeRingParams, RejectsEveryWrongOrdering) {
    for (int ringCount = 1; ringCount <= kMaxRings; ++ringCount) {
        for (int r = 1; r <= ringCount; ++r) {
            for (double delta : {0.0, 0.01, 0.05}) {  // equal, slightly and clearly increasing
                SlopeRingParams p = validFor(ringCount);
                p.slopeMagnitudeMmPerN[std::size_t(r)] = p.slopeMagnitudeMmPerN[std::size_t(r - 1)] + delta;
                const auto errors = messagesOf(validateSlopeRingParams(p));
                ASSERT_FALSE(errors.empty()) << "ringCount " << ringCount << ", " << slopeName(r - 1) << " vs "
                                             << slopeName(r) << " delta " << delta;
                EXPECT_TRUE(anyMentions(errors, slopeName(r - 1), slopeName(r)))
                    << "no message names both " << slopeName(r - 1) << " and " << slopeName(r) << ":\n"
                    << joined(errors);
            }
        }
        // Slopes beyond the used rings are ignored, whatever their order.
        SlopeRingParams p = validFor(ringCount);
        if (ringCount < kMaxRings) {
            p.slopeMagnitudeMmPerN[std::size_t(ringCount + 1)] = 0.95;
            EXPECT_TRUE(messagesOf(validateSlopeRingParams(p)).empty()) << joined(messagesOf(validateSlopeRingParams(p)));
        }
    }
}

TEST(SlopeRingParams, RejectsZeroNegativeNonFiniteAndTooLargeSlopes) {
    for (int ringCount = 0; ringCount <= kMaxRings; ++ringCount) {
        for (int r = 0; r <= ringCount; ++r) {
            for (double bad : {0.0, -0.1, -1.0, kNaN, kInf, -kInf}) {
                SlopeRingParams p = validFor(ringCount);
                p.slopeMagnitudeMmPerN[std::size_t(r)] = bad;
                const auto errors = messagesOf(validateSlopeRingParams(p));
                ASSERT_FALSE(errors.empty()) << slopeName(r) << " = " << bad;
                EXPECT_TRUE(anyMentions(errors, slopeName(r))) << slopeName(r) << " = " << bad << ":\n"
                                                               << joined(errors);
            }
        }
    }
    // At or above the limit (the paper's (0, 1) by default, or a raised limit).
    for (double m1 : {1.0, 1.0000001, 2.0, 50.0}) {
        SlopeRingParams p = validFor(2);
        p.slopeMagnitudeMmPerN[0] = m1;
        const auto errors = messagesOf(validateSlopeRingParams(p));
        ASSERT_FALSE(errors.empty()) << "|m1| = " << m1;
        EXPECT_TRUE(anyMentions(errors, "|m1|")) << joined(errors);
    }
    {
        SlopeRingParams p = validFor(2);
        p.slopeLimitMmPerN = 0.5;  // |m1| = 0.9 and |m2| = 0.8 and |m3| = 0.7 are now too large
        const auto errors = messagesOf(validateSlopeRingParams(p));
        EXPECT_TRUE(anyMentions(errors, "|m1|")) << joined(errors);
        EXPECT_TRUE(anyMentions(errors, "|m2|")) << joined(errors);
        EXPECT_TRUE(anyMentions(errors, "|m3|")) << joined(errors);
        p.slopeMagnitudeMmPerN = {0.4, 0.3, 0.2};
        EXPECT_TRUE(messagesOf(validateSlopeRingParams(p)).empty()) << joined(messagesOf(validateSlopeRingParams(p)));
    }
    for (double limit : {0.0, -1.0, kNaN, kInf, 1000.0}) {
        SlopeRingParams p = validFor(2);
        p.slopeLimitMmPerN = limit;
        const auto errors = messagesOf(validateSlopeRingParams(p));
        ASSERT_FALSE(errors.empty()) << "slopeLimit " << limit;
        EXPECT_TRUE(anyMentions(errors, "slopeLimit")) << joined(errors);
    }
}

TEST(SlopeRingParams, RejectsBadRingCount) {
    for (int n : {-1, -100, kMaxRings + 1, 1000}) {
        SlopeRingParams p;
        p.ringCount = n;
        const auto errors = messagesOf(validateSlopeRingParams(p));
        ASSERT_FALSE(errors.empty()) << "ringCount " << n;
        EXPECT_TRUE(anyMentions(errors, "ringCount")) << joined(errors);
    }
}

TEST(SlopeRingParams, RejectsBadStiffnessMassDampingRelaxation) {
    struct Field {
        const char* name;
        double SlopeRingParams::*member;
        std::vector<double> bad;
        std::vector<double> good;
    };
    const Field fields[] = {
        {"contactStiffness", &SlopeRingParams::contactStiffnessNPerMm, {0.0, -1.0, kNaN, kInf}, {0.01, 1.0}},
        {"springStiffness", &SlopeRingParams::springStiffnessNPerMm, {0.0, -1.5, kNaN, kInf}, {0.1, 10.0}},
        {"vertexMass", &SlopeRingParams::vertexMassKg, {0.0, -0.001, kNaN, kInf}, {1e-6, 0.5}},
        {"dampingRatio", &SlopeRingParams::dampingRatio, {-0.1, kNaN, kInf, 101.0}, {0.0, 0.5, 1.0, 3.0}},
        {"forceRelaxation", &SlopeRingParams::forceRelaxation, {-0.1, 1.01, kNaN, kInf}, {0.0, 0.3, 1.0}},
    };
    for (const Field& f : fields) {
        for (double v : f.bad) {
            SlopeRingParams p;
            p.*f.member = v;
            const auto errors = messagesOf(validateSlopeRingParams(p));
            ASSERT_FALSE(errors.empty()) << f.name << " = " << v;
            EXPECT_TRUE(anyMentions(errors, f.name)) << f.name << " = " << v << ":\n" << joined(errors);
        }
        for (double v : f.good) {
            SlopeRingParams p;
            p.*f.member = v;
            EXPECT_TRUE(messagesOf(validateSlopeRingParams(p)).empty()) << f.name << " = " << v << ":\n"
                                                            << joined(messagesOf(validateSlopeRingParams(p)));
        }
    }
}

TEST(SlopeRingParams, LoopGainBoundBothSides) {
    // gain g = |m1| k_c; with relaxation alpha the force iteration is stable iff alpha (1 + g) < 2.
    SlopeRingParams p;
    p.slopeLimitMmPerN = 100.0;
    p.slopeMagnitudeMmPerN = {40.0, 20.0, 10.0};
    p.contactStiffnessNPerMm = 1.0;  // g = 40
    p.forceRelaxation = 1.0;         // alpha (1 + g) = 41: unstable
    auto errors = messagesOf(validateSlopeRingParams(p));
    ASSERT_FALSE(errors.empty());
    EXPECT_TRUE(anyMentions(errors, "forceRelaxation") || anyMentions(errors, "contactStiffness"))
        << joined(errors);
    EXPECT_TRUE(anyMentions(errors, "gain")) << joined(errors);

    p.forceRelaxation = 1.9 / 41.0;  // inside the bound
    EXPECT_TRUE(messagesOf(validateSlopeRingParams(p)).empty()) << joined(messagesOf(validateSlopeRingParams(p)));
    p.forceRelaxation = 0.0;  // automatic: alpha = 1 / (1 + g), the one-tick solve
    EXPECT_TRUE(messagesOf(validateSlopeRingParams(p)).empty()) << joined(messagesOf(validateSlopeRingParams(p)));
    EXPECT_DOUBLE_EQ(p.effectiveRelaxation(), 1.0 / 41.0);
    EXPECT_DOUBLE_EQ(p.loopGain(), 40.0);

    {
        // Exactly on the bound (all values exact in binary): g = 3, alpha = 0.5 -> 0.5 * 4 = 2.
        SlopeRingParams e;
        e.slopeLimitMmPerN = 100.0;
        e.slopeMagnitudeMmPerN = {3.0, 2.0, 1.0};
        e.contactStiffnessNPerMm = 1.0;
        e.forceRelaxation = 0.5;
        EXPECT_FALSE(messagesOf(validateSlopeRingParams(e)).empty());
        e.forceRelaxation = 0.4375;  // 0.4375 * 4 = 1.75
        EXPECT_TRUE(messagesOf(validateSlopeRingParams(e)).empty()) << joined(messagesOf(validateSlopeRingParams(e)));
    }

    // In the paper's range with full relaxation: g = 0.9 -> 1.9 < 2 is stable, g = 1 is not.
    SlopeRingParams q;
    q.slopeMagnitudeMmPerN = {0.9, 0.5, 0.2};
    q.forceRelaxation = 1.0;
    q.contactStiffnessNPerMm = 1.0;
    EXPECT_TRUE(messagesOf(validateSlopeRingParams(q)).empty()) << joined(messagesOf(validateSlopeRingParams(q)));
    q.contactStiffnessNPerMm = 1.0 / 0.9;
    EXPECT_FALSE(messagesOf(validateSlopeRingParams(q)).empty());
    q.contactStiffnessNPerMm = 2.0;
    EXPECT_FALSE(messagesOf(validateSlopeRingParams(q)).empty());
}

TEST(SlopeRingParams, DeformerConstructorAndSetParamsThrowOnInvalid) {
    auto loaded = generateMesh(GeneratedShape::Sphere, 100);
    ASSERT_TRUE(loaded.mesh) << loaded.error();
    const Octree tree(*loaded.mesh, OctreeDef{});
    SlopeRingParams bad;
    bad.slopeMagnitudeMmPerN[1] = bad.slopeMagnitudeMmPerN[0];
    for (SlopeRingMethod m : {SlopeRingMethod::Previous, SlopeRingMethod::Hybrid, SlopeRingMethod::Proposed,
                              SlopeRingMethod::Coherent}) {
        EXPECT_THROW(makeSlopeRing(*loaded.mesh, tree, bad, m), std::invalid_argument);
        try {
            const auto d = makeSlopeRing(*loaded.mesh, tree, bad, m);
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("|m1|"), std::string::npos) << e.what();
        }
        const auto ok = makeSlopeRing(*loaded.mesh, tree, SlopeRingParams{}, m);
        EXPECT_THROW(ok->setParams(bad), std::invalid_argument);
        SlopeRingParams nan;
        nan.contactStiffnessNPerMm = kNaN;
        EXPECT_THROW(ok->setParams(nan), std::invalid_argument);
        EXPECT_THROW(makeSlopeRing(*loaded.mesh, tree, nan, m), std::invalid_argument);
        // A rejected setParams keeps the old parameters.
        EXPECT_EQ(ok->params().contactStiffnessNPerMm, SlopeRingParams{}.contactStiffnessNPerMm);
    }
}

}  // namespace
}  // namespace palpate
