#include "engine/exercise/Metric.h"

#include "base/params/FieldTable.h"
#include "engine/exercise/Exercise.h"

#include <cmath>
#include <cstdio>

namespace palpate {

namespace {

double meanTargetToleranceMm(const Exercise& e) {
    if (e.pressTargets.targets.empty()) return 3.0;
    double sum = 0.0;
    for (const PressTarget& t : e.pressTargets.targets) sum += t.toleranceMm;
    return sum / double(e.pressTargets.targets.size());
}

double meanLumpRadiusMm(const Exercise& e) {
    if (e.detectLumps.lumps.empty()) return 6.0;
    double sum = 0.0;
    for (const LumpDef& l : e.detectLumps.lumps) sum += l.radiusMm;
    return sum / double(e.detectLumps.lumps.size());
}

/// Fixed thresholds, the same for every exercise.
template <int FullMilli, int ZeroMilli>
void fixed(const Exercise&, double& full, double& zero) {
    full = FullMilli / 1000.0;
    zero = ZeroMilli / 1000.0;
}


constexpr Metric kNoCredit = Metric::Count;
constexpr MetricDisplay kPercent = MetricDisplay::Percent, kNumber = MetricDisplay::Number, kCount = MetricDisplay::Count;

constexpr MetricRow kRows[kMetricCount] = {
    {Metric::Completion, "completion", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "completion"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "share of the task done: targets achieved, lump marked, path covered, examination finished (else the surface examined)"),
     "", kPercent, 0, true, false, kNoCredit, fixed<1000, 0>},
    {Metric::TimeS, "time_s", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "time"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "exercise time until the task was complete (all of it if it was not)"), "s", kNumber, 2, true, true, kNoCredit,
     [](const Exercise& e, double& full, double& zero) {
         full = 0.5 * e.timeLimitS;
         zero = e.timeLimitS;
     }},
    {Metric::TargetErrorMm, "target_error_mm", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "target error"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "mean distance from the target while pressing inside its force window"), "mm", kNumber, 2, false, false, kNoCredit,
     [](const Exercise& e, double& full, double& zero) {
         full = 0.25 * meanTargetToleranceMm(e);
         zero = 1.5 * meanTargetToleranceMm(e);
     }},
    {Metric::HoldInWindowFraction, "hold_in_window_fraction", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "hold in window fraction"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "time inside the force window / time on a target in contact"), "", kPercent, 0, false, false, kNoCredit,
     fixed<900, 300>},
    {Metric::PeakForceN, "peak_force_n", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "peak force"), PALPATE_TRANSLATE_NOOP("palpate::Metrics", "largest force rendered"),
     "N", kNumber, 2, true, true, kNoCredit,
     [](const Exercise& e, double& full, double& zero) {
         full = 0.75 * e.excessiveForceN;
         zero = 1.5 * e.excessiveForceN;
     }},
    {Metric::MeanForceN, "mean_force_n", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "mean force"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "mean force magnitude while in contact"), "N", kNumber, 2, true, true, kNoCredit,
     [](const Exercise& e, double& full, double& zero) {
         full = 0.5 * e.excessiveForceN;
         zero = e.excessiveForceN;
     }},
    {Metric::ImpulseNs, "impulse_ns", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "impulse"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "integral of the force magnitude over time"), "N s", kNumber, 2, true, true, kNoCredit,
     [](const Exercise& e, double& full, double& zero) {
         full = 0.0;
         zero = 0.5 * e.excessiveForceN * e.timeLimitS;
     }},
    {Metric::ExcessiveForceEvents, "excessive_force_events", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "excessive force events"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "times the force rose above the excessive force"), PALPATE_TRANSLATE_NOOP("palpate::Metrics", "events"), kCount, 0, true, true, kNoCredit, fixed<0, 5000>},
    {Metric::ExcessiveForceFraction, "excessive_force_fraction", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "excessive force fraction"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "time above the excessive force / time in contact"), "", kPercent, 0, true, true, kNoCredit, fixed<0, 200>},
    {Metric::DamageTimeS, "damage_time_s", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "damage time"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "time with tissue displaced beyond the displacement limit"), "s", kNumber, 2, true, true, kNoCredit, fixed<0, 2000>},
    {Metric::DamageAreaMm2, "damage_area_mm2", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "damage area"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "largest surface area displaced beyond the limit at one time"), "mm^2", kNumber, 2, true, true, kNoCredit,
     fixed<0, 200000>},
    {Metric::MaxDisplacementMm, "max_displacement_mm", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "max displacement"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "largest displacement of any vertex from rest"), "mm", kNumber, 2, true, true, kNoCredit,
     [](const Exercise& e, double& full, double& zero) {
         full = 0.5 * e.displacementLimitMm;
         zero = 1.5 * e.displacementLimitMm;
     }},
    {Metric::PathLengthMm, "path_length_mm", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "path length"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "distance travelled by the tool tip"), "mm", kNumber, 2, true, true, kNoCredit, fixed<0, 10000000>},
    {Metric::Economy, "economy", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "economy"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "ideal path length / path length (1 = no wasted motion)"), "", kPercent, 0, false, false, kNoCredit, fixed<500, 100>},
    {Metric::LumpErrorMm, "lump_error_mm", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "lump error"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "distance from the contact point at the mark to the inclusion centre"), "mm", kNumber, 2, false, false, kNoCredit,
     [](const Exercise& e, double& full, double& zero) {
         full = 0.5 * e.findLump.inclusion.radiusMm;
         zero = 3.0 * e.findLump.inclusion.radiusMm;
     }},
    {Metric::ContactFraction, "contact_fraction", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "contact fraction"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "time in contact / tracing time"), "", kPercent, 0, false, false, kNoCredit, fixed<950, 500>},
    {Metric::BandFraction, "band_fraction", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "band fraction"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "time in contact with the force in the band / tracing time"), "", kPercent, 0, false, false, kNoCredit,
     fixed<800, 200>},
    {Metric::PathDistanceMm, "path_distance_mm", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "path distance"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "mean distance of the contact point from the path while in contact"), "mm", kNumber, 2, false, false, kNoCredit,
     [](const Exercise& e, double& full, double& zero) {
         full = 0.5 * e.trace.toleranceMm;
         zero = 2.0 * e.trace.toleranceMm;
     }},
    {Metric::Sensitivity, "sensitivity", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "sensitivity"), PALPATE_TRANSLATE_NOOP("palpate::Metrics", "lumps found / lumps hidden"),
     "", kPercent, 0, false, false, Metric::PositivePredictiveValue, fixed<1000, 0>},
    {Metric::PositivePredictiveValue, "positive_predictive_value", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "positive predictive value"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "findings on a lump / findings"), "", kPercent, 0, false, false, kNoCredit, fixed<1000, 0>},
    {Metric::FalseAlarms, "false_alarms", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "false alarms"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "findings matched to no lump"), PALPATE_TRANSLATE_NOOP("palpate::Metrics", "findings"), kCount, 0, false, true, kNoCredit, fixed<0, 3000>},
    // A hit lies at most radius + tolerance from its lump's centre: that is zero marks.
    {Metric::LocalisationMm, "localisation_mm", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "localisation"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "mean distance from a found lump's centre to the finding on it"), "mm", kNumber, 2, false, false, kNoCredit,
     [](const Exercise& e, double& full, double& zero) {
         full = 0.5 * meanLumpRadiusMm(e);
         zero = meanLumpRadiusMm(e) + e.detectLumps.toleranceMm;
     }},
    {Metric::CoverageFraction, "coverage_fraction", PALPATE_TRANSLATE_NOOP("palpate::Metrics", "coverage fraction"),
     PALPATE_TRANSLATE_NOOP("palpate::Metrics", "surface area examined with at least the coverage force / surface area"), "", kPercent, 0, false, false, kNoCredit,
     fixed<800, 200>},
};

constexpr bool rowsInMetricOrder() {
    for (std::size_t i = 0; i < kMetricCount; ++i)
        if (std::size_t(kRows[i].metric) != i) return false;
    return true;
}
static_assert(rowsInMetricOrder(), "one row per metric, in the enum's order");

}  // namespace

bool MetricRow::higherIsBetter() const {
    double full = 0.0, zero = 0.0;
    thresholds(Exercise{}, full, zero);
    return full > zero;
}

const MetricRow& metricRow(Metric metric) { return kRows[std::size_t(metric)]; }
std::string_view metricName(Metric metric) { return metricRow(metric).key; }
std::string_view metricUnit(Metric metric) { return metricRow(metric).unit; }
std::string_view metricDescription(Metric metric) { return metricRow(metric).description; }

std::optional<Metric> parseMetric(std::string_view name) {
    for (const MetricRow& row : kRows)
        if (row.key == name) return row.metric;
    return std::nullopt;
}

MetricShown metricShown(Metric metric, double value) {
    const MetricRow& row = metricRow(metric);
    switch (row.display) {
    case MetricDisplay::Percent: return {100.0 * value, row.decimals, "%"};
    case MetricDisplay::Count: return {std::round(value), 0, row.unit};
    case MetricDisplay::Number: break;
    }
    return {value, row.decimals, row.unit};
}

std::string metricValueText(Metric metric, double value) {
    const MetricShown shown = metricShown(metric, value);
    char text[64];
    std::snprintf(text, sizeof(text), "%.*f", shown.decimals, shown.number);
    std::string out = text;
    if (!shown.unit.empty()) out.append(" ").append(shown.unit);
    return out;
}

}  // namespace palpate
