#include "engine/exercise/Metric.h"

namespace palpate {

namespace {

struct MetricInfo {
    std::string_view name, unit, description;
    bool press, lump, trace, detect;
};

constexpr std::array<MetricInfo, kMetricCount> kInfo{{
    {"completion", "", "share of the task done: targets achieved, lump marked, path covered, examination finished (else the surface examined)", true, true, true, true},
    {"time_s", "s", "exercise time until the task was complete (all of it if it was not)", true, true, true, true},
    {"target_error_mm", "mm", "mean distance from the target while pressing inside its force window", true, false, false, false},
    {"hold_in_window_fraction", "", "time inside the force window / time on a target in contact", true, false, false, false},
    {"peak_force_n", "N", "largest force rendered", true, true, true, true},
    {"mean_force_n", "N", "mean force magnitude while in contact", true, true, true, true},
    {"impulse_ns", "N s", "integral of the force magnitude over time", true, true, true, true},
    {"excessive_force_events", "events", "times the force rose above the excessive force", true, true, true, true},
    {"excessive_force_fraction", "", "time above the excessive force / time in contact", true, true, true, true},
    {"damage_time_s", "s", "time with tissue displaced beyond the displacement limit", true, true, true, true},
    {"damage_area_mm2", "mm^2", "largest surface area displaced beyond the limit at one time", true, true, true, true},
    {"max_displacement_mm", "mm", "largest displacement of any vertex from rest", true, true, true, true},
    {"path_length_mm", "mm", "distance travelled by the tool tip", true, true, true, true},
    {"economy", "", "ideal path length / path length (1 = no wasted motion)", true, true, true, false},
    {"lump_error_mm", "mm", "distance from the contact point at the mark to the inclusion centre", false, true, false, false},
    {"contact_fraction", "", "time in contact / tracing time", false, false, true, false},
    {"band_fraction", "", "time in contact with the force in the band / tracing time", false, false, true, false},
    {"path_distance_mm", "mm", "mean distance of the contact point from the path while in contact", false, false, true, false},
    {"sensitivity", "", "lumps found / lumps hidden", false, false, false, true},
    {"positive_predictive_value", "", "findings on a lump / findings", false, false, false, true},
    {"false_alarms", "findings", "findings matched to no lump", false, false, false, true},
    {"localisation_mm", "mm", "mean distance from a found lump's centre to the finding on it", false, false, false, true},
    {"coverage_fraction", "", "surface area examined with at least the coverage force / surface area", false, true, false, true},
}};

}  // namespace

std::string_view metricName(Metric metric) { return kInfo[std::size_t(metric)].name; }
std::string_view metricUnit(Metric metric) { return kInfo[std::size_t(metric)].unit; }
std::string_view metricDescription(Metric metric) { return kInfo[std::size_t(metric)].description; }

std::optional<Metric> parseMetric(std::string_view name) {
    for (std::size_t i = 0; i < kMetricCount; ++i)
        if (kInfo[i].name == name) return Metric(i);
    return std::nullopt;
}

bool metricApplies(Metric metric, ExerciseType type) {
    const MetricInfo& info = kInfo[std::size_t(metric)];
    switch (type) {
        case ExerciseType::PressTargets: return info.press;
        case ExerciseType::FindLump: return info.lump;
        case ExerciseType::Trace: return info.trace;
        case ExerciseType::DetectLumps: return info.detect;
    }
    return false;
}

std::string_view exerciseTypeName(ExerciseType type) {
    switch (type) {
        case ExerciseType::PressTargets: return "press_targets";
        case ExerciseType::FindLump: return "find_lump";
        case ExerciseType::Trace: return "trace";
        case ExerciseType::DetectLumps: return "detect_lumps";
    }
    return "?";
}

std::optional<ExerciseType> parseExerciseType(std::string_view name) {
    for (ExerciseType t : {ExerciseType::PressTargets, ExerciseType::FindLump, ExerciseType::Trace, ExerciseType::DetectLumps})
        if (exerciseTypeName(t) == name) return t;
    return std::nullopt;
}

}  // namespace palpate
