// A metric's value reads the same way everywhere because every surface formats it from its row
// (engine/exercise/Metric.h): a fraction as a percentage, a quantity with its unit and decimals, a
// count as a whole number of its unit.
#include "engine/exercise/Exercise.h"
#include "engine/exercise/Metric.h"
#include "engine/exercise/ScoreReport.h"

#include <gtest/gtest.h>

namespace palpate {
namespace {

TEST(MetricText, AFractionReadsAsAPercentage) {
    EXPECT_EQ(metricValueText(Metric::Completion, 0.853), "85 %");
    EXPECT_EQ(metricValueText(Metric::CoverageFraction, 1.0), "100 %");
    const MetricShown shown = metricShown(Metric::Sensitivity, 2.0 / 3.0);
    EXPECT_NEAR(shown.number, 66.67, 0.01);
    EXPECT_EQ(shown.unit, "%");
}

TEST(MetricText, AQuantityCarriesItsUnitAndTheRowsDecimals) {
    EXPECT_EQ(metricValueText(Metric::PeakForceN, 3.2), "3.20 N");
    EXPECT_EQ(metricValueText(Metric::DamageAreaMm2, 12.0), "12.00 mm^2");
    EXPECT_EQ(metricValueText(Metric::ImpulseNs, 0.126), "0.13 N s");
}

TEST(MetricText, ACountIsAWholeNumberOfItsUnit) {
    EXPECT_EQ(metricValueText(Metric::FalseAlarms, 2.0), "2 findings");
    EXPECT_EQ(metricValueText(Metric::ExcessiveForceEvents, 3.0), "3 events");
}

// A row shown as a percentage is a fraction: its default marks lie in 0..1 (a quantity filed as a
// percentage would print "5000 %").
TEST(MetricText, RowsShownAsPercentagesAreFractions) {
    Exercise exercise;
    for (std::size_t i = 0; i < kMetricCount; ++i) {
        const MetricRow& row = metricRow(Metric(i));
        double full = 0.0, zero = 0.0;
        row.thresholds(exercise, full, zero);
        if (row.display == MetricDisplay::Percent) {
            EXPECT_TRUE(full >= 0.0 && full <= 1.0 && zero >= 0.0 && zero <= 1.0) << row.key;
            EXPECT_STREQ(row.unit, "") << row.key;
        } else {
            EXPECT_FALSE(std::string_view(row.key).ends_with("_fraction")) << row.key;
        }
    }
}

// The CLI's text says the value and the marks the way the window does.
TEST(MetricText, TheTextReportShowsValuesAndMarksFromTheRows) {
    ScoreReport report;
    report.exerciseName = "press";
    MetricResult completion;
    completion.metric = Metric::Completion;
    completion.measured = true;
    completion.value = 0.5;
    completion.fullMarks = 1.0;
    completion.zeroMarks = 0.0;
    MetricResult peak;
    peak.metric = Metric::PeakForceN;
    peak.measured = true;
    peak.value = 2.5;
    peak.fullMarks = 3.0;
    peak.zeroMarks = 6.0;
    report.metrics = {completion, peak};
    const std::string text = scoreReportToText(report);
    EXPECT_NE(text.find("50 %"), std::string::npos) << text;
    EXPECT_NE(text.find("100 % .. 0 %"), std::string::npos) << text;
    EXPECT_NE(text.find("2.50 N"), std::string::npos) << text;
    EXPECT_NE(text.find("3.00 N .. 6.00 N"), std::string::npos) << text;
}

}  // namespace
}  // namespace palpate
