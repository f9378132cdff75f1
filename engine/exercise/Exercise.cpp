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

bool isLanguageCode(const std::string& code) {
    const auto lower = [&](std::size_t i) { return i < code.size() && code[i] >= 'a' && code[i] <= 'z'; };
    const auto upper = [&](std::size_t i) { return i < code.size() && code[i] >= 'A' && code[i] <= 'Z'; };
    const std::size_t letters = lower(0) && lower(1) ? (lower(2) ? 3 : 2) : 0;
    if (letters == 0) return false;
    if (code.size() == letters) return true;
    return code.size() == letters + 3 && code[letters] == '_' && upper(letters + 1) && upper(letters + 2);
}

ExerciseTextDef exerciseTextIn(const Exercise& e, const std::string& language) {
    ExerciseTextDef text{e.name, e.description};
    // The language itself first, then its base ("de_AT" -> "de").
    for (const std::string& code : {language, language.substr(0, language.find('_'))}) {
        const auto found = e.translations.find(code);
        if (found == e.translations.end()) continue;
        if (!found->second.name.empty()) text.name = found->second.name;
        if (!found->second.description.empty()) text.description = found->second.description;
        break;
    }
    return text;
}

Problems validateExercise(const Exercise& e) {
    Problems errors;
    ExerciseChecker c(errors);
    if (e.name.empty()) c.error("name", "must not be empty");
    for (const auto& [code, text] : e.translations) {
        if (!isLanguageCode(code))
            c.error("translations", "'" + code + "' is not a language code (use two letters such as de, or de_AT)");
        else if (text.name.empty() && text.description.empty())
            c.error("translations." + code, "gives neither a name nor a description");
    }
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
