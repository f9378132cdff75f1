#pragma once
// What a scored session measures. Each metric has a stable name (the key in exercise rubrics and
// in `palpate-cli score --json`), a unit, and the exercise types it applies to; docs/scoring.md
// defines each one exactly.

#include <array>
#include <cstddef>
#include <optional>
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

/// The rubric key: "completion", "time_s", ...
std::string_view metricName(Metric metric);
/// Unit as shown ("", "s", "mm", "N", "N s", "mm^2", "events").
std::string_view metricUnit(Metric metric);
/// One line for people (the breakdown, the GUI's score card tooltips).
std::string_view metricDescription(Metric metric);
std::optional<Metric> parseMetric(std::string_view name);
/// Whether an exercise of this type measures the metric.
bool metricApplies(Metric metric, ExerciseType type);

std::string_view exerciseTypeName(ExerciseType type);  ///< "press_targets", "find_lump", "trace", "detect_lumps"
std::optional<ExerciseType> parseExerciseType(std::string_view name);

}  // namespace palpate
