#include "engine/exercise/Exercise.h"

#include "base/io/FileLimits.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace palpate {

namespace {

std::string text(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

/// Range checks that name the key.
class Checker {
public:
    explicit Checker(std::vector<std::string>& errors) : mErrors(errors) {}

    void error(const std::string& key, const std::string& problem) { mErrors.push_back(key + ": " + problem); }

    /// lo < v <= hi (openLow) or lo <= v <= hi.
    bool range(const std::string& key, double v, double lo, double hi, bool openLow = false) {
        const bool ok = std::isfinite(v) && (openLow ? v > lo : v >= lo) && v <= hi;
        if (!ok) error(key, text(v) + " is out of range " + (openLow ? "(" : "[") + text(lo) + ", " + text(hi) + "]");
        return ok;
    }

    void point(const std::string& key, const SurfacePoint& p) {
        if (p.vertex) return;
        for (int i = 0; i < 3; ++i)
            if (!std::isfinite(p.pointMm[i]) || std::fabs(p.pointMm[i]) > 1e6f) {
                error(key + ".point_mm", "must be three finite coordinates in mm");
                return;
            }
    }

    void window(const std::string& key, double minN, double maxN, const char* minKey, const char* maxKey) {
        const bool a = range(key + "." + minKey, minN, 0.0, 1000.0);
        const bool b = range(key + "." + maxKey, maxN, 0.0, 1000.0, true);
        if (a && b && !(maxN > minN)) error(key + "." + maxKey, text(maxN) + " must be greater than " + minKey + " " + text(minN));
    }

private:
    std::vector<std::string>& mErrors;
};

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

double defaultWeight(ExerciseType type, Metric m) {
    switch (type) {
        case ExerciseType::PressTargets:
            switch (m) {
                case Metric::Completion: return 40;
                case Metric::TimeS: return 10;
                case Metric::TargetErrorMm: return 10;
                case Metric::HoldInWindowFraction: return 15;
                case Metric::ExcessiveForceEvents: return 5;
                case Metric::ExcessiveForceFraction: return 5;
                case Metric::DamageTimeS: return 10;
                case Metric::Economy: return 5;
                default: return 0;
            }
        case ExerciseType::FindLump:
            switch (m) {
                case Metric::Completion: return 20;
                case Metric::LumpErrorMm: return 40;
                case Metric::TimeS: return 10;
                case Metric::ExcessiveForceEvents: return 5;
                case Metric::ExcessiveForceFraction: return 10;
                case Metric::DamageTimeS: return 15;
                default: return 0;
            }
        case ExerciseType::Trace:
            switch (m) {
                case Metric::Completion: return 30;
                case Metric::PathDistanceMm: return 15;
                case Metric::ContactFraction: return 15;
                case Metric::BandFraction: return 20;
                case Metric::TimeS: return 5;
                case Metric::ExcessiveForceFraction: return 5;
                case Metric::DamageTimeS: return 10;
                default: return 0;
            }
        case ExerciseType::DetectLumps:
            switch (m) {
                case Metric::Sensitivity: return 35;
                case Metric::FalseAlarms: return 20;
                case Metric::LocalisationMm: return 10;
                case Metric::CoverageFraction: return 15;
                case Metric::TimeS: return 5;
                case Metric::ExcessiveForceFraction: return 5;
                case Metric::DamageTimeS: return 10;
                default: return 0;
            }
    }
    return 0;
}

void validateStaircase(Checker& c, const StaircaseDef& s) {
    const std::string key = "detect_lumps.staircase";
    const bool contrast = s.parameter == StaircaseDef::Parameter::Contrast;
    // The levels a lump can take: a contrast above 1 (1 is no lump), a depth of 0 or more.
    const double lo = contrast ? 1.0 : 0.0, hi = 100.0;
    bool ok = c.range(key + ".easiest", s.easiest, lo, hi, contrast);
    ok = c.range(key + ".hardest", s.hardest, lo, hi, contrast) && ok;
    if (ok && s.easiest == s.hardest) c.error(key + ".hardest", "equals easiest: the staircase could not move");
    if (ok && contrast && s.easiest < s.hardest)
        c.error(key + ".easiest", text(s.easiest) + " is below hardest " + text(s.hardest) +
                                      ": a higher contrast is easier to feel");
    if (ok && !contrast && s.easiest > s.hardest)
        c.error(key + ".easiest", text(s.easiest) + " mm is deeper than hardest " + text(s.hardest) +
                                      " mm: a shallower lump is easier to feel");
    if (ok) c.range(key + ".start", s.start, std::min(s.easiest, s.hardest), std::max(s.easiest, s.hardest));
    if (ok) c.range(key + ".step", s.step, 0.0, std::fabs(s.easiest - s.hardest), true);
    c.range(key + ".down", s.down, 1, 10);
    c.range(key + ".up", s.up, 1, 10);
}

}  // namespace

RubricItem defaultRubricItem(const Exercise& e, Metric m) {
    RubricItem item;
    item.weight = metricApplies(m, e.type) ? defaultWeight(e.type, m) : 0.0;
    auto set = [&](double full, double zero) {
        item.fullMarks = full;
        item.zeroMarks = zero;
    };
    const double excessive = e.excessiveForceN;
    switch (m) {
        case Metric::Completion: set(1.0, 0.0); break;
        case Metric::TimeS: set(0.5 * e.timeLimitS, e.timeLimitS); break;
        case Metric::TargetErrorMm: set(0.25 * meanTargetToleranceMm(e), 1.5 * meanTargetToleranceMm(e)); break;
        case Metric::HoldInWindowFraction: set(0.9, 0.3); break;
        case Metric::PeakForceN: set(0.75 * excessive, 1.5 * excessive); break;
        case Metric::MeanForceN: set(0.5 * excessive, excessive); break;
        case Metric::ImpulseNs: set(0.0, 0.5 * excessive * e.timeLimitS); break;
        case Metric::ExcessiveForceEvents: set(0.0, 5.0); break;
        case Metric::ExcessiveForceFraction: set(0.0, 0.2); break;
        case Metric::DamageTimeS: set(0.0, 2.0); break;
        case Metric::DamageAreaMm2: set(0.0, 200.0); break;
        case Metric::MaxDisplacementMm: set(0.5 * e.displacementLimitMm, 1.5 * e.displacementLimitMm); break;
        case Metric::PathLengthMm: set(0.0, 10000.0); break;
        case Metric::Economy: set(0.5, 0.1); break;
        case Metric::LumpErrorMm: set(0.5 * e.findLump.inclusion.radiusMm, 3.0 * e.findLump.inclusion.radiusMm); break;
        case Metric::ContactFraction: set(0.95, 0.5); break;
        case Metric::BandFraction: set(0.8, 0.2); break;
        case Metric::PathDistanceMm: set(0.5 * e.trace.toleranceMm, 2.0 * e.trace.toleranceMm); break;
        case Metric::Sensitivity: set(1.0, 0.0); break;
        case Metric::PositivePredictiveValue: set(1.0, 0.0); break;
        case Metric::FalseAlarms: set(0.0, 3.0); break;
        // A hit lies at most radius + tolerance from its lump's centre: that is zero marks.
        case Metric::LocalisationMm: set(0.5 * meanLumpRadiusMm(e), meanLumpRadiusMm(e) + e.detectLumps.toleranceMm); break;
        case Metric::CoverageFraction: set(0.8, 0.2); break;
        case Metric::Count: break;
    }
    return item;
}

Rubric effectiveRubric(const Exercise& e) {
    Rubric rubric{};
    for (std::size_t i = 0; i < kMetricCount; ++i) {
        const Metric m = Metric(i);
        rubric[i] = e.rubric[i] ? *e.rubric[i] : defaultRubricItem(e, m);
        if (!metricApplies(m, e.type)) rubric[i].weight = 0.0;
        // Without lumps there is nothing to find or to localise: those lines do not count.
        if (e.type == ExerciseType::DetectLumps && e.detectLumps.lumps.empty() &&
            (m == Metric::Sensitivity || m == Metric::LocalisationMm))
            rubric[i].weight = 0.0;
    }
    return rubric;
}

std::vector<std::string> validateExercise(const Exercise& e) {
    std::vector<std::string> errors;
    Checker c(errors);
    if (e.name.empty()) c.error("name", "must not be empty");
    if (e.meshPath.empty()) c.error("mesh", "must name a mesh file");
    c.range("mesh_unit", e.meshUnit.mmPerUnit, kMinMmPerUnit, kMaxMmPerUnit);
    if (e.tissuePresetPath.empty()) c.error("tissue_preset", "must name a tissue preset file");
    c.range("time_limit_s", e.timeLimitS, 0.0, 3600.0, true);
    c.range("damage.displacement_limit_mm", e.displacementLimitMm, 0.0, 1000.0, true);
    c.range("force.excessive_n", e.excessiveForceN, 0.0, 1000.0, true);

    switch (e.type) {
        case ExerciseType::PressTargets: {
            const auto& targets = e.pressTargets.targets;
            if (targets.empty()) c.error("press_targets.targets", "needs at least one target");
            if (targets.size() > std::size_t(kMaxPressTargets))
                c.error("press_targets.targets", "has more than " + std::to_string(kMaxPressTargets) + " targets");
            for (std::size_t i = 0; i < targets.size() && i < std::size_t(kMaxPressTargets); ++i) {
                const PressTarget& t = targets[i];
                const std::string key = "press_targets.targets[" + std::to_string(i) + "]";
                c.point(key, t.at);
                c.window(key, t.forceMinN, t.forceMaxN, "force_min_n", "force_max_n");
                c.range(key + ".hold_s", t.holdS, 0.0, 600.0);
                c.range(key + ".tolerance_mm", t.toleranceMm, 0.0, 1000.0, true);
                if (t.forceMinN >= e.excessiveForceN)
                    c.error(key + ".force_min_n", text(t.forceMinN) + " N is not below force.excessive_n " +
                                                      text(e.excessiveForceN) + " N: the target cannot be met safely");
            }
            break;
        }
        case ExerciseType::FindLump: {
            const InclusionDef& inc = e.findLump.inclusion;
            c.point("find_lump.inclusion.centre", inc.centre);
            c.range("find_lump.inclusion.radius_mm", inc.radiusMm, 0.0, 1000.0, true);
            c.range("find_lump.inclusion.stiffness_factor", inc.stiffnessFactor, 0.0, 1.0, true);
            break;
        }
        case ExerciseType::Trace: {
            const TraceDef& t = e.trace;
            if (t.path.size() < 2) c.error("trace.path", "needs at least 2 points");
            if (t.path.size() > std::size_t(kMaxTracePathPoints))
                c.error("trace.path", "has more than " + std::to_string(kMaxTracePathPoints) + " points");
            for (std::size_t i = 0; i < t.path.size() && i < std::size_t(kMaxTracePathPoints); ++i)
                c.point("trace.path[" + std::to_string(i) + "]", t.path[i]);
            c.window("trace", t.forceMinN, t.forceMaxN, "force_min_n", "force_max_n");
            c.range("trace.tolerance_mm", t.toleranceMm, 0.0, 1000.0, true);
            break;
        }
        case ExerciseType::DetectLumps: {
            const DetectLumpsDef& d = e.detectLumps;
            if (d.lumps.size() > std::size_t(kMaxLumps))
                c.error("detect_lumps.lumps", "has more than " + std::to_string(kMaxLumps) + " lumps");
            for (std::size_t i = 0; i < d.lumps.size() && i < std::size_t(kMaxLumps); ++i) {
                const LumpDef& l = d.lumps[i];
                const std::string key = "detect_lumps.lumps[" + std::to_string(i) + "]";
                c.point(key, l.at);
                c.range(key + ".radius_mm", l.radiusMm, 0.0, 100.0, true);
                c.range(key + ".depth_mm", l.depthMm, 0.0, 100.0);
                c.range(key + ".contrast", l.contrast, 1.0, 100.0, true);
            }
            c.range("detect_lumps.tolerance_mm", d.toleranceMm, 0.0, 1000.0, true);
            if (d.staircase) validateStaircase(c, *d.staircase);
            break;
        }
    }
    if (e.type == ExerciseType::FindLump || e.type == ExerciseType::DetectLumps) {
        c.range("coverage.min_force_n", e.coverage.minForceN, 0.0, 1000.0);
        c.range("coverage.radius_mm", e.coverage.radiusMm, 0.0, 1000.0, true);
    }

    double weights = 0.0;
    const Rubric rubric = effectiveRubric(e);
    for (std::size_t i = 0; i < kMetricCount; ++i) {
        const Metric m = Metric(i);
        const std::string key = "rubric." + std::string(metricName(m));
        if (e.rubric[i] && !metricApplies(m, e.type)) {
            c.error(key, "is not measured by " + std::string(exerciseTypeName(e.type)) + " exercises");
            continue;
        }
        if (!metricApplies(m, e.type)) continue;
        const RubricItem& item = rubric[i];
        c.range(key + ".weight", item.weight, 0.0, 1000.0);
        const bool full = std::isfinite(item.fullMarks);
        const bool zero = std::isfinite(item.zeroMarks);
        if (!full) c.error(key + ".full", "must be a finite number");
        if (!zero) c.error(key + ".zero", "must be a finite number");
        if (full && zero && item.fullMarks == item.zeroMarks)
            c.error(key + ".zero", "equals full (" + text(item.fullMarks) + "): the sub-score would be a step");
        if (std::isfinite(item.weight)) weights += std::max(0.0, item.weight);
    }
    if (weights <= 0.0) c.error("rubric", "every weight is 0: nothing would be scored");
    return errors;
}

}  // namespace palpate
