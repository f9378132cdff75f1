#pragma once
// What a scored session measures. One row per metric (MetricRow): its stable name (the key in
// exercise rubrics and in `palpate-cli score --json`), its text for people, unit, display and
// default thresholds; the kinds of exercise say which they measure and weigh (ExerciseKind.h).
// docs/scoring.md defines each one exactly.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace palpate {

enum class ExerciseType { PressTargets, FindLump, Trace, DetectLumps };

enum class Metric {
    Completion,              ///< 0..1: targets achieved, lump marked, path covered
    TimeS,                   ///< exercise time to completion (or all of it, if not completed)
    TargetErrorMm,           ///< press targets: distance from the target while pressing in its window
    HoldInWindowFraction,    ///< press targets: time in the force window / time on target in contact
    PeakForceN,
    MeanForceN,              ///< mean |F| over the time in contact
    ImpulseNs,               ///< integral of |F| dt
    ExcessiveForceEvents,    ///< times |F| rose above the exercise's excessive force
    ExcessiveForceFraction,  ///< time above it / time in contact
    DamageTimeS,             ///< time with some vertex displaced beyond the displacement limit
    DamageAreaMm2,           ///< largest surface area displaced beyond the limit at one time
    MaxDisplacementMm,       ///< largest displacement of any vertex
    PathLengthMm,            ///< distance the tool tip travelled
    Economy,                 ///< ideal path length / path length, at most 1
    LumpErrorMm,             ///< find the lump: contact point at the mark to the inclusion centre
    ContactFraction,         ///< trace: time in contact / tracing time
    BandFraction,            ///< trace: time in contact with |F| in the band / tracing time
    PathDistanceMm,          ///< trace: mean distance of the contact point from the path
    Sensitivity,             ///< detect lumps: hits / lumps
    PositivePredictiveValue, ///< detect lumps: hits / findings
    FalseAlarms,             ///< detect lumps: findings matched to no lump
    LocalisationMm,          ///< detect lumps: mean distance of a hit's finding from its lump's centre
    CoverageFraction,        ///< find the lump, detect lumps: surface area examined firmly enough / all
    Count
};

inline constexpr std::size_t kMetricCount = std::size_t(Metric::Count);

struct Exercise;

/// How a metric's value is shown to people (docs/scoring.md, "Metrics").
enum class MetricDisplay {
    Percent,  ///< a fraction 0..1 shown as a percentage ("85 %")
    Number,   ///< a quantity with its unit and `decimals` ("3.2 mm")
    Count,    ///< a whole number of events or findings
};

/// Everything said about one metric, once: the rubric's key, its name and description for people
/// (English; translated in the context kMetricTextContext), its unit, how it is shown, which way is
/// better, whether every kind of exercise measures it (else the kinds that do say so,
/// ExerciseKind::ownMetrics), whether it counts errors, and its default rubric thresholds.
struct MetricRow {
    Metric metric;
    std::string_view key;          ///< "completion", "time_s", ...
    const char* name;              ///< "Completion"
    const char* description;       ///< one line
    const char* unit;              ///< "", "s", "mm", "N", "N s", "mm^2", "events", "findings"
    MetricDisplay display;
    int decimals;                  ///< Number: decimals shown
    bool everyKind;                ///< every kind of exercise measures it
    /// It grades the absence of errors or waste (force, damage, time, false alarms), which is
    /// worth nothing without the work: its sub-score is weighted by the work done.
    bool countsErrors;
    /// Count: none. Else its sub-score is multiplied by that metric's value when measured (found
    /// lumps count in proportion to how many findings were lumps: marking everywhere finds all).
    Metric creditTimes;
    /// The default full and zero marks for this exercise (full better than zero).
    void (*thresholds)(const Exercise& exercise, double& fullMarks, double& zeroMarks);
    /// Whether a larger value is better (from the default thresholds' order).
    bool higherIsBetter() const;
};

/// The translation context of the metric rows' names and descriptions, the engine's own.
inline constexpr const char* kMetricTextContext = "palpate::Metrics";

/// The row of a metric.
const MetricRow& metricRow(Metric metric);
/// The rubric key: "completion", "time_s", ...
std::string_view metricName(Metric metric);
/// Unit as shown ("", "s", "mm", "N", "N s", "mm^2", "events").
std::string_view metricUnit(Metric metric);
/// One line for people (the breakdown, the GUI's score card tooltips).
std::string_view metricDescription(Metric metric);
std::optional<Metric> parseMetric(std::string_view name);

/// A value as people read it, from its row's display (docs/scoring.md, "Metrics"): the number to
/// print, its decimals and what follows it ("%" for a fraction shown as a percentage, else the
/// unit, possibly empty). Every surface (score card, PDF, text, learning curve) formats from this.
struct MetricShown {
    double number;
    int decimals;
    std::string_view unit;
};
MetricShown metricShown(Metric metric, double value);
/// The value as text in the C locale: "85 %", "3.20 mm", "2 findings" (the CLI's text report).
std::string metricValueText(Metric metric, double value);

}  // namespace palpate
