#include "engine/exercise/ScoreReport.h"

#include "engine/exercise/ExerciseKind.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <sstream>

namespace palpate {

const MetricResult* ScoreReport::find(Metric metric) const {
    for (const MetricResult& m : metrics)
        if (m.metric == metric) return &m;
    return nullptr;
}

std::string scoreReportToJson(const ScoreReport& r, int indent) {
    using Json = nlohmann::ordered_json;
    Json metrics = Json::object(), rubric = Json::object();
    for (const MetricResult& m : r.metrics) {
        const std::string name(metricName(m.metric));
        metrics[name] = m.measured ? Json(m.value) : Json(nullptr);
        rubric[name] = {{"value", m.measured ? Json(m.value) : Json(nullptr)},
                        {"sub_score", m.subScore},
                        {"weight", m.weight},
                        {"contribution", m.contribution},
                        {"full", m.fullMarks},
                        {"zero", m.zeroMarks}};
    }
    Json j{{"score", r.score},
           {"work_done", r.workDone},
           {"metrics", metrics},
           {"rubric", rubric},
           {"exercise", r.exerciseName},
           {"type", std::string(exerciseTypeName(r.type))},
           {"completed", r.guidance.completed},
           {"time_up", r.guidance.timeUp},
           {"ticks_scored", r.ticksScored},
           {"ticks_after_end", r.ticksAfterEnd},
           {"first_tick", r.firstTick},
           {"last_tick", r.lastTick},
           {"marks", r.marks}};
    if (!r.targets.empty()) {  // press targets
        Json targets = Json::array();
        for (const TargetResult& t : r.targets)
            targets.push_back({{"achieved", t.achieved},
                               {"achieved_at_s", t.achieved ? Json(t.achievedAtS) : Json(nullptr)},
                               {"error_mm", t.errorMeasured ? Json(t.errorMm) : Json(nullptr)},
                               {"on_target_s", t.onTargetS},
                               {"in_window_s", t.inWindowS}});
        j["targets"] = targets;
    }
    if (r.palpation) {
        const PalpationSummary& p = *r.palpation;
        auto maybe = [](const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); };
        if (const auto& d = p.detection) {
            Json lumps = Json::array();
            for (std::size_t k = 0; k < d->findingOfLump.size(); ++k)
                lumps.push_back({{"hit", d->findingOfLump[k] >= 0},
                                 {"finding", d->findingOfLump[k] >= 0 ? Json(d->findingOfLump[k]) : Json(nullptr)},
                                 {"localisation_mm", d->findingOfLump[k] >= 0 ? Json(d->localisationMm[k]) : Json(nullptr)}});
            // Sensitivity, predictive value, false alarms and localisation are metrics: "metrics" holds them.
            j["detection"] = {{"hits", d->hits}, {"misses", d->misses}, {"lumps", lumps}};
            Json findings = Json::array();
            for (const glm::dvec3& f : p.findingsMm) findings.push_back({f.x, f.y, f.z});
            j["findings_mm"] = findings;
        }
        j["coverage"] = {{"min_force_n", p.coverage.minForceN}, {"radius_mm", p.coverage.radiusMm}};
        auto phase = [](const std::optional<ForcePercentiles>& f) {
            if (!f) return Json(nullptr);
            return Json{{"samples", f->samples}, {"p10_n", f->p10N}, {"p50_n", f->p50N}, {"p90_n", f->p90N}, {"max_n", f->maxN}};
        };
        j["force_by_phase"] = {{"search", phase(p.forceByPhase.search)},
                               {"palpation", phase(p.forceByPhase.palpation)},
                               {"palpation_over_search", maybe(p.forceByPhase.palpationOverSearch)}};
        j["deepest_lump_reach_force_n"] = maybe(p.deepestLumpReachForceN);
        Json feedback = Json::array();
        for (const PalpationFeedback& f : p.feedback) feedback.push_back({{"key", f.key}, {"text", f.text}});
        j["feedback"] = feedback;
    }
    if (!r.aids.empty()) {
        Json aids = Json::array();
        for (const GuidanceAid& a : r.aids) aids.push_back({{"name", a.name}, {"level", a.level}});
        j["aids"] = aids;
    }
    j["warnings"] = r.warnings;
    return indent < 0 ? j.dump() : j.dump(indent);
}

std::string scoreReportToText(const ScoreReport& r) {
    std::ostringstream out;
    char line[256];
    std::snprintf(line, sizeof(line), "%s (%s): score %.1f / 100%s\n", r.exerciseName.c_str(),
                  std::string(exerciseTypeName(r.type)).c_str(), r.score,
                  r.guidance.completed ? ", completed" : (r.guidance.timeUp ? ", time up" : ", not completed"));
    out << line;
    if (r.workDone < 1.0) {
        std::snprintf(line, sizeof(line), "  work done %.0f %%: the lines that count errors earn that share of their points\n",
                      100.0 * r.workDone);
        out << line;
    }
    std::snprintf(line, sizeof(line), "  %-26s %14s %6s %7s %8s  %s\n", "metric", "value", "sub", "weight", "points",
                  "full .. zero");
    out << line;
    for (const MetricResult& m : r.metrics) {
        const std::string value = m.measured ? metricValueText(m.metric, m.value) : "-";
        const std::string range = metricValueText(m.metric, m.fullMarks) + " .. " + metricValueText(m.metric, m.zeroMarks);
        std::snprintf(line, sizeof(line), "  %-26s %14s %6.2f %7.1f %8.2f  %s\n", std::string(metricName(m.metric)).c_str(),
                      value.c_str(), m.subScore, m.weight, m.contribution, range.c_str());
        out << line;
    }
    for (std::size_t i = 0; i < r.targets.size(); ++i) {
        const TargetResult& t = r.targets[i];
        std::snprintf(line, sizeof(line), "  target %zu: %s", i + 1, t.achieved ? "achieved" : "not achieved");
        out << line;
        if (t.achieved) {
            std::snprintf(line, sizeof(line), " at %.2f s", t.achievedAtS);
            out << line;
        }
        if (t.errorMeasured) {
            std::snprintf(line, sizeof(line), ", error %.2f mm", t.errorMm);
            out << line;
        }
        std::snprintf(line, sizeof(line), ", %.2f s in window of %.2f s on target\n", t.inWindowS, t.onTargetS);
        out << line;
    }
    std::snprintf(line, sizeof(line), "  ticks scored %llu (ticks %llu..%llu), after the end %llu, marks %llu\n",
                  static_cast<unsigned long long>(r.ticksScored), static_cast<unsigned long long>(r.firstTick),
                  static_cast<unsigned long long>(r.lastTick), static_cast<unsigned long long>(r.ticksAfterEnd),
                  static_cast<unsigned long long>(r.marks));
    out << line;
    if (r.palpation) {
        const PalpationSummary& p = *r.palpation;
        if (const auto& d = p.detection) {
            std::snprintf(line, sizeof(line), "  lumps: %zu hit, %zu missed, %zu false alarms\n", d->hits, d->misses,
                          d->falseAlarms);
            out << line;
        }
        std::snprintf(line, sizeof(line), "  coverage %.1f %% of the surface at %.1f N or more\n",
                      100.0 * p.coverageFraction, p.coverage.minForceN);
        out << line;
        auto phase = [&](const char* name, const std::optional<ForcePercentiles>& f) {
            if (!f) return;
            std::snprintf(line, sizeof(line), "  %s force: median %.2f N, 90th percentile %.2f N (%zu ticks)\n", name,
                          f->p50N, f->p90N, f->samples);
            out << line;
        };
        phase("search", p.forceByPhase.search);
        phase("palpation", p.forceByPhase.palpation);
        for (const PalpationFeedback& f : p.feedback) out << "  feedback: " << f.text << "\n";
    }
    for (const std::string& w : r.warnings) out << "  warning: " << w << "\n";
    return out.str();
}

}  // namespace palpate
