// The sweep CSV reader (Qt-free, engine/accuracy/SweepCsv): what sweepToCsv writes reads back to
// the same points, and a malformed file is refused with the line, column and problem named.
#include "engine/accuracy/SweepCsv.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace palpate;

namespace {

std::vector<SweepPoint> points() {
    std::vector<SweepPoint> out;
    int i = 0;
    for (GeneratedShape shape : {GeneratedShape::Sphere, GeneratedShape::Stomach})
        for (const char* model : {"coherent", "proposed", "mass-spring-rk4"}) {
            SweepPoint p;
            p.model = model;
            p.rings = 2 + i % 3;
            p.series = p.model == "coherent"   ? "slope-ring " + std::to_string(p.rings) + " rings"
                       : p.model == "proposed" ? "proposed (paper)"
                                               : p.model;
            p.shape = shape;
            p.vertices = 1442 + 1000 * std::size_t(i);
            p.tickUs = 0.0251234 * (i + 1);
            p.error.displacementError = 0.137 + 0.01 * i;
            p.error.forceError = 1.5e-7 * i;
            p.error.indentationMm = 2.75;
            p.error.forceN = 0.0534;
            p.error.referenceForceN = 0.0535;
            p.error.verticesCompared = 80 + i;
            p.pareto = i % 2 == 0;
            out.push_back(p);
            ++i;
        }
    return out;
}

}  // namespace

TEST(SweepCsv, RoundTripsSweepToCsv) {
    const std::vector<SweepPoint> original = points();
    const std::string csv = sweepToCsv(original);
    std::string error = "stale";
    const std::vector<SweepPoint> parsed = parseSweepCsv(csv, &error);
    EXPECT_TRUE(error.empty()) << error;
    ASSERT_EQ(parsed.size(), original.size());
    for (std::size_t i = 0; i < parsed.size(); ++i) {
        const SweepPoint& a = parsed[i];
        const SweepPoint& b = original[i];
        EXPECT_EQ(a.series, b.series);
        EXPECT_EQ(a.model, b.model);
        EXPECT_EQ(a.rings, b.rings);
        EXPECT_EQ(a.shape, b.shape);
        EXPECT_EQ(a.vertices, b.vertices);
        EXPECT_NEAR(a.tickUs, b.tickUs, 1e-5 * b.tickUs);  // the CSV keeps 6 significant digits
        EXPECT_NEAR(a.error.displacementError, b.error.displacementError, 1e-6);
        EXPECT_NEAR(a.error.forceError, b.error.forceError, 1e-12);
        EXPECT_EQ(a.error.verticesCompared, b.error.verticesCompared);
        EXPECT_EQ(a.pareto, b.pareto);
    }
    // Written again, the text is the same; CRLF line ends and blank lines are accepted.
    EXPECT_EQ(sweepToCsv(parsed), csv);
    std::string crlf;
    for (char c : csv) crlf += c == '\n' ? std::string("\r\n\r\n") : std::string(1, c);
    EXPECT_EQ(parseSweepCsv(crlf, &error).size(), original.size()) << error;
}

TEST(SweepCsv, RejectsAMalformedLineNamingTheLineAndColumn) {
    const std::string csv = sweepToCsv(points());
    std::string error;

    // Line 3 (the second point): a tick cost that is not a number.
    std::string bad = csv;
    const std::size_t line3 = bad.find('\n', bad.find('\n') + 1) + 1;
    const std::size_t field6 = [&] {
        std::size_t at = line3;
        for (int i = 0; i < 5; ++i) at = bad.find(',', at) + 1;
        return at;
    }();
    bad.replace(field6, bad.find(',', field6) - field6, "fast");
    EXPECT_TRUE(parseSweepCsv(bad, &error).empty());
    EXPECT_EQ(error.rfind("line 3, column 6 (tick_us): 'fast' is not a number", 0), 0u) << error;

    EXPECT_TRUE(parseSweepCsv(csv + "sphere,1442,x\n", &error).empty());
    EXPECT_NE(error.find("line 8: 3 fields, the header has 16"), std::string::npos) << error;

    EXPECT_TRUE(parseSweepCsv(csv + "cube,1442,s,palpate,1,0.1,0.1,0,0,0,0,0,1,,,\n", &error).empty());
    EXPECT_NE(error.find("line 8, column 1 (shape)"), std::string::npos) << error;

    EXPECT_TRUE(parseSweepCsv(csv + "sphere,1442,s,palpate,1,0.1,0.1,0,0,0,0,0,yes,,,\n", &error).empty());
    EXPECT_NE(error.find("line 8, column 13 (pareto): 'yes' is not 0 or 1"), std::string::npos) << error;

    EXPECT_TRUE(parseSweepCsv("shape,vertices,speed\n", &error).empty());
    EXPECT_NE(error.find("line 1, column 3 (speed): unknown column"), std::string::npos) << error;

    EXPECT_TRUE(parseSweepCsv("", &error).empty());
    EXPECT_NE(error.find("line 1"), std::string::npos) << error;
}

// A sweep written before the organ sweep's columns existed still reads: no site, nothing measured
// against the hyperelastic FEM.
TEST(SweepCsv, ACsvWithoutTheOrganColumnsStillReads) {
    SweepPoint p;
    p.series = "slope-ring 1 ring";
    p.model = "coherent";
    p.rings = 1;
    p.vertices = 1442;
    p.tickUs = 0.1;
    p.error.displacementError = 0.2;
    std::string text = sweepToCsv({p});
    // Drop the last three columns of every line.
    std::string old;
    for (std::size_t start = 0; start < text.size();) {
        std::size_t end = text.find('\n', start);
        std::string line = text.substr(start, end - start);
        for (int i = 0; i < 3; ++i) line = line.substr(0, line.rfind(','));
        old += line + "\n";
        start = end + 1;
    }
    std::string error;
    const auto points = parseSweepCsv(old, &error);
    ASSERT_TRUE(error.empty()) << error;
    ASSERT_EQ(points.size(), 1u);
    EXPECT_TRUE(points[0].site.empty());
    EXPECT_TRUE(std::isnan(points[0].hyperelasticDisplacementError));
    EXPECT_DOUBLE_EQ(points[0].error.displacementError, 0.2);
}

