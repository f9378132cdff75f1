#include "engine/exercise/Exercise.h"

#include "engine/exercise/ExerciseChecker.h"
#include "engine/exercise/ExerciseKind.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace palpate {

RubricItem defaultRubricItem(const Exercise& e, Metric m) {
    RubricItem item;
    item.weight = exerciseKind(e.type).defaultWeight(e, m);
    metricRow(m).thresholds(e, item.fullMarks, item.zeroMarks);
    return item;
}

Rubric effectiveRubric(const Exercise& e) {
    const ExerciseKind& kind = exerciseKind(e.type);
    Rubric rubric{};
    for (std::size_t i = 0; i < kMetricCount; ++i) {
        const Metric m = Metric(i);
        rubric[i] = e.rubric[i] ? *e.rubric[i] : defaultRubricItem(e, m);
        if (!kind.measures(m) || !kind.counts(e, m)) rubric[i].weight = 0.0;
    }
    return rubric;
}

Problems validateExercise(const Exercise& e) {
    Problems errors;
    ExerciseChecker c(errors);
    if (e.name.empty()) c.error("name", "must not be empty");
    if (e.meshPath.empty()) c.error("mesh", "must name a mesh file");
    c.range("mesh_unit", e.meshUnit.mmPerUnit, kMinMmPerUnit, kMaxMmPerUnit);
    if (e.tissuePresetPath.empty()) c.error("tissue_preset", "must name a tissue preset file");
    c.range("time_limit_s", e.timeLimitS, 0.0, 3600.0, true);
    c.range("damage.displacement_limit_mm", e.displacementLimitMm, 0.0, 1000.0, true);
    c.range("force.excessive_n", e.excessiveForceN, 0.0, 1000.0, true);

    const ExerciseKind& kind = exerciseKind(e.type);
    kind.validate(e, c);
    if (kind.palpation()) {
        c.range("coverage.min_force_n", e.coverage.minForceN, 0.0, 1000.0);
        c.range("coverage.radius_mm", e.coverage.radiusMm, 0.0, 1000.0, true);
    }

    double weights = 0.0;
    const Rubric rubric = effectiveRubric(e);
    for (std::size_t i = 0; i < kMetricCount; ++i) {
        const Metric m = Metric(i);
        const std::string key = "rubric." + std::string(metricName(m));
        if (e.rubric[i] && !kind.measures(m)) {
            c.error(key, "is not measured by " + std::string(kind.key()) + " exercises");
            continue;
        }
        if (!kind.measures(m)) continue;
        const RubricItem& item = rubric[i];
        c.range(key + ".weight", item.weight, 0.0, 1000.0);
        const bool full = std::isfinite(item.fullMarks);
        const bool zero = std::isfinite(item.zeroMarks);
        if (!full) c.error(key + ".full", "must be a finite number");
        if (!zero) c.error(key + ".zero", "must be a finite number");
        if (full && zero && item.fullMarks == item.zeroMarks)
            c.error(key + ".zero", "equals full (" + ExerciseChecker::text(item.fullMarks) + "): the sub-score would be a step");
        if (std::isfinite(item.weight)) weights += std::max(0.0, item.weight);
    }
    if (weights <= 0.0) c.error("rubric", "every weight is 0: nothing would be scored");
    return errors;
}

}  // namespace palpate
