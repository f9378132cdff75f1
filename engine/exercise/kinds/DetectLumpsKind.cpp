// Detect lumps (docs/scoring.md, "Detect lumps"): examine the surface for zero or more lumps
// hidden under it, mark each, and say when done.

#include "engine/exercise/kinds/Kinds.h"

#include "base/io/FileLimits.h"
#include "base/io/JsonReader.h"
#include "base/params/FieldTable.h"
#include "engine/exercise/ExerciseGeometry.h"
#include "engine/exercise/LumpDetection.h"
#include "engine/exercise/PalpationExamination.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace palpate {

namespace {

/// Below this covered share the examination was not systematic enough (feedback).
constexpr double kLowCoverageFraction = 0.6;

constexpr const char* kStaircaseParameters[] = {"contrast", "depth_mm"};

/// The distance from `origin` along the unit direction `dir` to the sphere (centre, radius): the
/// nearer crossing ahead, 0 when the origin is inside, negative when the ray misses it.
double rayToSphereMm(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& centre, double radius) {
    const glm::dvec3 oc = origin - centre;
    const double c = glm::dot(oc, oc) - radius * radius;
    if (c <= 0.0) return 0.0;
    const double b = glm::dot(oc, dir);
    const double disc = b * b - c;
    if (disc < 0.0 || b > 0.0) return -1.0;  // misses, or the sphere is behind
    return -b - std::sqrt(disc);
}

void readStaircase(JsonReader& r, const Json& j, const std::string& path, StaircaseDef& out) {
    if (!r.object(j, path, {"parameter", "start", "step", "easiest", "hardest", "down", "up"})) return;
    std::string parameter;
    if (r.text(j, path, "parameter", parameter, true)) {
        if (parameter == kStaircaseParameters[0]) out.parameter = StaircaseDef::Parameter::Contrast;
        else if (parameter == kStaircaseParameters[1]) out.parameter = StaircaseDef::Parameter::DepthMm;
        else r.error(JsonReader::join(path, "parameter"), "unknown parameter '" + parameter + "' (use contrast or depth_mm)");
    }
    r.number(j, path, "start", out.start, true);
    r.number(j, path, "step", out.step, true);
    r.number(j, path, "easiest", out.easiest, true);
    r.number(j, path, "hardest", out.hardest, true);
    double down = out.down, up = out.up;
    if (r.number(j, path, "down", down)) {
        if (down != std::floor(down) || down < 1 || down > 10)
            r.error(JsonReader::join(path, "down"), "must be a whole number from 1 to 10");
        else out.down = int(down);
    }
    if (r.number(j, path, "up", up)) {
        if (up != std::floor(up) || up < 1 || up > 10) r.error(JsonReader::join(path, "up"), "must be a whole number from 1 to 10");
        else out.up = int(up);
    }
}

void validateStaircase(ExerciseChecker& c, const StaircaseDef& s) {
    const auto text = ExerciseChecker::text;
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

class DetectLumpsTask final : public ExerciseTask {
public:
    DetectLumpsTask(std::shared_ptr<const ExerciseGeometry> geometry, double periodS)
        : mGeometry(geometry), mExamination(std::move(geometry), periodS) {
        mFindingsMm.reserve(64);
    }

    bool step(const TaskTick& t, ScoreGuidance& g) override {
        mExamination.add(t, g);
        if (t.mark && t.haveContactPoint) mFindingsMm.push_back(glm::dvec3(t.contactPointMm));
        g.findings = int(mFindingsMm.size());
        return t.done;
    }
    // Finished by the trainee: done; cut off by the time limit: as far as the surface was
    // examined (only an examination that touched nothing is nothing done).
    double completion(const ScoreGuidance& g) const override {
        return g.completed ? 1.0 : mExamination.coveredFraction();
    }
    // The work of an examination is the surface examined firmly enough: finishing at once is no
    // examination. Covering the coverage line's full-marks share is all of it.
    double workDone(const ScoreGuidance&) const override {
        const double fullShare = mGeometry->rubric()[std::size_t(Metric::CoverageFraction)].fullMarks;
        return fullShare > 0.0 ? std::min(1.0, mExamination.coveredFraction() / fullShare) : 1.0;
    }
    void report(ScoreReport& r, MeasuredMetrics& metrics, bool detail) const override {
        const Exercise& e = mGeometry->exercise();
        PalpationSummary p = mExamination.summary(detail);
        p.findingsMm = mFindingsMm;
        const auto& lumps = mGeometry->lumps();
        std::vector<HiddenLump> hidden;
        for (const ResolvedLump& l : lumps) hidden.push_back({glm::dvec3(l.surfaceMm), l.def.radiusMm});
        p.detection = scoreDetection(hidden, mFindingsMm, {e.detectLumps.toleranceMm});
        // The deepest lump, and whether the surface over it ever sank as deep as its top.
        std::size_t deepest = lumps.size();
        for (std::size_t k = 0; k < lumps.size(); ++k)
            if (deepest == lumps.size() || lumps[k].def.depthMm > lumps[deepest].def.depthMm) deepest = k;
        const double forcePerMm = mExamination.forcePerMm().value_or(0.0);
        if (deepest < lumps.size()) {
            const double depthMm = lumps[deepest].def.depthMm;
            if (forcePerMm > 0.0) p.deepestLumpReachForceN = depthMm * forcePerMm;
            const double sunkMm = mExamination.lumpMaxSinkMm()[deepest];
            const bool missed = p.detection->findingOfLump[deepest] < 0;
            if (missed && sunkMm < depthMm) {
                std::string text = "Pressed too lightly to reach the deepest lump: it lies " + oneDecimal(depthMm) +
                                   " mm under the surface, and over it the surface sank " + oneDecimal(sunkMm) +
                                   " mm at most.";
                std::vector<double> numbers{depthMm, sunkMm};
                if (p.deepestLumpReachForceN) {
                    text += " Press to about " + oneDecimal(*p.deepestLumpReachForceN) + " N or more to feel it.";
                    numbers.push_back(*p.deepestLumpReachForceN);
                }
                p.feedback.push_back({"pressed_too_lightly", text, numbers});
            }
        }
        if (p.detection->falseAlarms > 0)
            p.feedback.push_back({"false_alarms",
                                  std::to_string(p.detection->falseAlarms) +
                                      (p.detection->falseAlarms == 1 ? " finding was" : " findings were") +
                                      " on no lump: mark only where the tissue resists more than around it.",
                                  {double(p.detection->falseAlarms)}});
        // Only an examination of the whole surface is judged on how much of it was covered (find
        // the lump may go straight to it).
        if (p.coverageFraction < kLowCoverageFraction)
            p.feedback.push_back({"low_coverage",
                                  "Examined " + oneDecimal(100.0 * p.coverageFraction) + " % of the surface at " +
                                      demandNumber(e.coverage.minForceN) +
                                      " N or more: cover all of it, in overlapping rows.",
                                  {100.0 * p.coverageFraction, e.coverage.minForceN}});
        mExamination.addCommonFeedback(p, !e.detectLumps.lumps.empty());
        const DetectionResult& d = *p.detection;
        metrics.put(Metric::Sensitivity, d.sensitivity.value_or(0.0), d.sensitivity.has_value());
        metrics.put(Metric::PositivePredictiveValue, d.positivePredictive.value_or(0.0), d.positivePredictive.has_value());
        metrics.put(Metric::FalseAlarms, double(d.falseAlarms));
        const auto localisation = d.meanLocalisationMm();
        metrics.put(Metric::LocalisationMm, localisation.value_or(0.0), localisation.has_value());
        metrics.put(Metric::CoverageFraction, p.coverageFraction);
        r.palpation = std::move(p);
    }

private:
    std::shared_ptr<const ExerciseGeometry> mGeometry;
    PalpationExamination mExamination;
    std::vector<glm::dvec3> mFindingsMm;
};

// What the editor edits: the lumps, each with its radius, depth and contrast; how near a mark
// must be; the examination's force.
LumpDef& lumpOf(Exercise& e, std::size_t i) { return e.detectLumps.lumps[i]; }
const LumpDef& lumpOf(const Exercise& e, std::size_t i) { return e.detectLumps.lumps[i]; }

constexpr EditedNumber kLumpNumbers[] = {
    {"radius_mm", PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Radius"),
     PALPATE_TRANSLATE_NOOP("palpate::Exercises", "The lump's radius, mm (radius_mm)."), "mm", 0.0, 100.0, 2, 0.5,
     [](const Exercise& e, std::size_t i) { return lumpOf(e, i).radiusMm; },
     [](Exercise& e, std::size_t i, double v) { lumpOf(e, i).radiusMm = v; }},
    {"depth_mm", PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Depth"),
     PALPATE_TRANSLATE_NOOP("palpate::Exercises",
                            "From the surface to the lump's top, mm (depth_mm): a deeper lump needs a firmer "
                            "press to be felt."),
     "mm", 0.0, 100.0, 2, 0.5, [](const Exercise& e, std::size_t i) { return lumpOf(e, i).depthMm; },
     [](Exercise& e, std::size_t i, double v) { lumpOf(e, i).depthMm = v; }},
    {"contrast", PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Contrast"),
     PALPATE_TRANSLATE_NOOP("palpate::Exercises",
                            "How many times stiffer than the tissue the lump is (contrast), above 1: lower is "
                            "harder to feel."),
     "", 1.0, 100.0, 2, 0.5, [](const Exercise& e, std::size_t i) { return lumpOf(e, i).contrast; },
     [](Exercise& e, std::size_t i, double v) { lumpOf(e, i).contrast = v; }},
};
constexpr EditedNumber kDetectNumbers[] = {
    {"detect_lumps.tolerance_mm", PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Mark within:"),
     PALPATE_TRANSLATE_NOOP("palpate::Exercises",
                            "A mark this far outside a lump's radius still finds it, mm (detect_lumps.tolerance_mm)."),
     "mm", 0.0, 1000.0, 2, 0.5, [](const Exercise& e, std::size_t) { return e.detectLumps.toleranceMm; },
     [](Exercise& e, std::size_t, double v) { e.detectLumps.toleranceMm = v; }},
    kCoverageMinForce,
    kCoverageRadius,
};

const ExerciseEditing kEditing{
    PlacedItems{"detect_lumps.lumps", PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Lump %1"),
                PALPATE_TRANSLATE_NOOP(
                    "palpate::Exercises",
                    "While on, each click on the tissue hides a lump under it, with the last lump's radius, depth and "
                    "contrast (Esc stops). No lumps: healthy tissue, where reporting nothing is the finding."),
                false, false, [](const Exercise& e) { return e.detectLumps.lumps.size(); },
                [](const Exercise& e, std::size_t i) -> const SurfacePoint& { return lumpOf(e, i).at; },
                [](Exercise& e, std::size_t i, const SurfacePoint& at) { lumpOf(e, i).at = at; },
                [](Exercise& e, const SurfacePoint& at) {
                    LumpDef l = e.detectLumps.lumps.empty() ? LumpDef{} : e.detectLumps.lumps.back();
                    l.at = at;
                    e.detectLumps.lumps.push_back(l);
                },
                [](Exercise& e, std::size_t i) {
                    e.detectLumps.lumps.erase(e.detectLumps.lumps.begin() + std::ptrdiff_t(i));
                },
                [](Exercise& e, std::size_t a, std::size_t b) { std::swap(lumpOf(e, a), lumpOf(e, b)); }, kLumpNumbers,
                nullptr},
    kDetectNumbers};

class DetectLumpsKind final : public ExerciseKind {
public:
    ExerciseType type() const override { return ExerciseType::DetectLumps; }
    std::string_view key() const override { return "detect_lumps"; }
    const char* label() const override { return PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Detect lumps"); }
    bool palpation() const override { return true; }
    bool changesTissue() const override { return true; }
    bool finishedByTrainee() const override { return true; }
    bool adaptive() const override { return true; }

    std::span<const Metric> ownMetrics() const override {
        static constexpr Metric kOwn[] = {Metric::Sensitivity, Metric::PositivePredictiveValue, Metric::FalseAlarms,
                                          Metric::LocalisationMm, Metric::CoverageFraction};
        return kOwn;
    }
    std::span<const MetricWeight> defaultWeights() const override {
        static constexpr MetricWeight kWeights[] = {
            {Metric::Sensitivity, 35},   {Metric::FalseAlarms, 20},           {Metric::LocalisationMm, 10},
            {Metric::CoverageFraction, 15}, {Metric::TimeS, 5},               {Metric::ExcessiveForceFraction, 5},
            {Metric::DamageTimeS, 10},
        };
        return kWeights;
    }
    // The score so far rises with a hit and falls with a false alarm: it would tell which marks
    // hit. Shown at Finish.
    bool showsLiveScore() const override { return false; }
    // Without lumps, reporting nothing is the finding: the weight of finding and localising lumps
    // goes to the false-alarm line (an examination that marks healthy tissue has failed).
    double defaultWeight(const Exercise& e, Metric m) const override {
        if (!e.detectLumps.lumps.empty()) return ExerciseKind::defaultWeight(m);
        if (m == Metric::FalseAlarms)
            return ExerciseKind::defaultWeight(Metric::FalseAlarms) + ExerciseKind::defaultWeight(Metric::Sensitivity) +
                   ExerciseKind::defaultWeight(Metric::LocalisationMm);
        return ExerciseKind::defaultWeight(m);
    }
    // Without lumps there is nothing to find or to localise: those lines do not count.
    bool counts(const Exercise& e, Metric m) const override {
        return !(e.detectLumps.lumps.empty() && (m == Metric::Sensitivity || m == Metric::LocalisationMm));
    }

    std::vector<std::string> sectionKeys() const override { return {"lumps", "tolerance_mm", "staircase"}; }
    void readSection(JsonReader& r, const Json& s, Exercise& e) const override {
        DetectLumpsDef& out = e.detectLumps;
        const std::string path = "detect_lumps";
        r.number(s, path, "tolerance_mm", out.toleranceMm);
        if (!s.contains("lumps")) {
            r.error("detect_lumps.lumps", "missing (an exercise without lumps says \"lumps\": [])");
        } else if (!s.at("lumps").is_array()) {
            r.error("detect_lumps.lumps", "must be an array of lumps");
        } else {
            const Json& a = s.at("lumps");
            for (std::size_t i = 0; i < a.size() && i <= std::size_t(kMaxLumps); ++i) {
                const std::string key = "detect_lumps.lumps[" + std::to_string(i) + "]";
                LumpDef lump;
                if (r.object(a[i], key, {"vertex", "point_mm", "radius_mm", "depth_mm", "contrast"})) {
                    readSurfacePoint(r, a[i], key, lump.at);
                    r.number(a[i], key, "radius_mm", lump.radiusMm, true);
                    r.number(a[i], key, "depth_mm", lump.depthMm, true);
                    r.number(a[i], key, "contrast", lump.contrast, true);
                }
                out.lumps.push_back(lump);
            }
        }
        if (s.contains("staircase")) {
            StaircaseDef staircase;
            readStaircase(r, s.at("staircase"), "detect_lumps.staircase", staircase);
            out.staircase = staircase;
        }
    }
    Json writeSection(const Exercise& e) const override {
        Json lumps = Json::array();
        for (const LumpDef& l : e.detectLumps.lumps) {
            Json o = surfacePointJson(l.at);
            o["radius_mm"] = l.radiusMm;
            o["depth_mm"] = l.depthMm;
            o["contrast"] = l.contrast;
            lumps.push_back(o);
        }
        Json d = {{"lumps", lumps}, {"tolerance_mm", e.detectLumps.toleranceMm}};
        if (const auto& st = e.detectLumps.staircase)
            d["staircase"] = {{"parameter", kStaircaseParameters[int(st->parameter)]},
                              {"start", st->start},
                              {"step", st->step},
                              {"easiest", st->easiest},
                              {"hardest", st->hardest},
                              {"down", st->down},
                              {"up", st->up}};
        return d;
    }
    void validate(const Exercise& e, ExerciseChecker& c) const override {
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
    }

    void place(const Exercise& exercise, GeometryPlacer& placer, PlacedGeometry& placed, std::string&) const override {
        const auto& rest = placer.mesh().restPositionsMm();
        const auto& normals = placer.mesh().restNormals();
        const std::size_t n = rest.size();
        // Each vertex looks straight in (along its rest normal): the first lump that ray meets is
        // the one under it, and how far in it lies is where pressing starts to meet it.
        placed.compliance.assign(n, 1.0f);
        placed.engageDepthMm.assign(n, 0.0f);
        placed.lumpOfVertex.assign(n, -1);
        std::vector<double> nearest(n, std::numeric_limits<double>::infinity());
        for (std::size_t k = 0; k < exercise.detectLumps.lumps.size(); ++k) {
            const LumpDef& def = exercise.detectLumps.lumps[k];
            ResolvedLump lump;
            lump.def = def;
            lump.vertex = placer.place(def.at, "detect_lumps.lumps[" + std::to_string(k) + "]");
            if (lump.vertex == kNoVertex) break;
            lump.surfaceMm = rest[lump.vertex];
            const glm::dvec3 centre =
                glm::dvec3(lump.surfaceMm) - (def.depthMm + def.radiusMm) * glm::dvec3(normals[lump.vertex]);
            lump.centreMm = glm::vec3(centre);
            for (VertexId v = 0; v < n; ++v) {
                const double depth = rayToSphereMm(glm::dvec3(rest[v]), -glm::dvec3(normals[v]), centre, def.radiusMm);
                // Met no deeper than the lump's centre lies under its own point: a ray that
                // crosses the whole body to reach it from behind is not over it.
                if (depth < 0.0 || depth > def.depthMm + def.radiusMm) continue;
                const float c = float(1.0 / def.contrast);
                // The nearest lump under a vertex is the one it meets; at equal depth the stiffer.
                if (depth < nearest[v] || (depth == nearest[v] && c < placed.compliance[v])) {
                    nearest[v] = depth;
                    placed.compliance[v] = c;
                    placed.engageDepthMm[v] = float(depth);
                    placed.lumpOfVertex[v] = std::int16_t(k);
                }
            }
            placed.lumps.push_back(lump);
        }
        for (VertexId v = 0; v < n; ++v)
            if (placed.lumpOfVertex[v] >= 0 && std::size_t(placed.lumpOfVertex[v]) < placed.lumps.size()) {
                ++placed.lumps[std::size_t(placed.lumpOfVertex[v])].footprintVertices;
                ++placed.inclusionVertices;
            }
    }
    std::vector<ExerciseDemand> demands(const Exercise& e) const override {
        double deepest = 0.0;
        for (const LumpDef& lump : e.detectLumps.lumps) deepest = std::max(deepest, lump.depthMm);
        if (deepest > 0.0) return {{"the deepest lump (" + demandNumber(deepest) + " mm down)", 0.0, deepest}};
        return {{"the firmest press allowed (" + demandNumber(e.excessiveForceN) + " N)", e.excessiveForceN, 0.0}};
    }
    std::unique_ptr<ExerciseTask> makeTask(std::shared_ptr<const ExerciseGeometry> geometry, double periodS) const override {
        return std::make_unique<DetectLumpsTask>(std::move(geometry), periodS);
    }

    // Hidden from the trainee until the examination is over: then where they were.
    const ExerciseEditing& editing() const override { return kEditing; }

    ExerciseDrawing draw(const ExerciseGeometry& geometry, MarkerAudience audience, const ScoreGuidance* guidance,
                         int selected) const override {
        ExerciseDrawing out;
        if (audience != MarkerAudience::Instructor && !(guidance && guidance->over())) return out;
        const auto& lumps = geometry.lumps();
        for (std::size_t i = 0; i < lumps.size(); ++i) {
            SurfaceMarker m;
            m.kind = SurfaceMarkerKind::Inclusion;
            m.positionMm = lumps[i].surfaceMm;
            m.normal = normalOf(geometry, lumps[i].vertex);
            m.radiusMm = lumps[i].def.radiusMm;
            m.bodyRadiusMm = lumps[i].def.radiusMm;
            m.bodyCentreMm = lumps[i].centreMm;
            m.label = ViewText{PALPATE_TRANSLATE_NOOP("palpate::Exercises", "lump %1, %2 mm deep")}
                          .whole(double(i + 1))
                          .fixed(lumps[i].def.depthMm, 1);
            m.selected = int(i) == selected;
            out.markers.push_back(m);
        }
        return out;
    }
    GuidanceView guidance(const Exercise& e, const ScoreGuidance& g) const override {
        GuidanceView v;
        v.examineAtN = e.coverage.minForceN;
        v.markTip = {PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Mark a lump where the tool presses now (M)")};
        v.instruction = {PALPATE_TRANSLATE_NOOP("palpate::Exercises",
                                                "Search the whole surface, press in where it feels different, Mark (M) each "
                                                "lump; Finish (F7) when done")};
        ViewText findings{PALPATE_TRANSLATE_N_NOOP("palpate::Exercises", "%n finding(s) marked")};
        findings.count = g.findings;
        v.detail.push_back(findings);
        v.detail.push_back({g.contact ? PALPATE_TRANSLATE_NOOP("palpate::Exercises", "in contact")
                                      : PALPATE_TRANSLATE_NOOP("palpate::Exercises", "not in contact")});
        // A stroke lighter than the coverage force examines nothing: say so while it happens.
        if (g.contact && g.forceN < e.coverage.minForceN)
            v.detail.push_back(ViewText{PALPATE_TRANSLATE_NOOP("palpate::Exercises",
                                                               "lighter than %1 N counts as not examined: press deeper "
                                                               "(with the mouse: scroll the wheel)")}
                                   .fixed(e.coverage.minForceN, 1));
        v.progress = g.coverageFraction;
        v.progressFormat = {PALPATE_TRANSLATE_NOOP("palpate::Exercises", "surface examined %p%")};
        return v;
    }
};

}  // namespace

const ExerciseKind& detectLumpsKind() {
    static const DetectLumpsKind kind;
    return kind;
}

}  // namespace palpate
