// Trace a path (docs/scoring.md, "Trace"): follow a polyline on the surface keeping contact and
// the force inside a band.

#include "engine/exercise/kinds/Kinds.h"

#include "base/io/FileLimits.h"
#include "base/io/JsonReader.h"
#include "base/params/FieldTable.h"
#include "engine/exercise/ExerciseGeometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace palpate {

namespace {

double distance(const glm::vec3& a, const glm::vec3& b) { return glm::length(glm::dvec3(a) - glm::dvec3(b)); }

class TraceTask final : public ExerciseTask {
public:
    explicit TraceTask(std::shared_ptr<const ExerciseGeometry> geometry) : mGeometry(std::move(geometry)) {
        mCovered.assign(mGeometry->coverageSamplesMm().size(), 0);
    }

    void start(ScoreGuidance& g) override {
        g.forceMinN = mGeometry->exercise().trace.forceMinN;
        g.forceMaxN = mGeometry->exercise().trace.forceMaxN;
    }

    bool step(const TaskTick& t, ScoreGuidance& g) override {
        const TraceDef& def = mGeometry->exercise().trace;
        const double dist =
            t.haveContactPoint ? mGeometry->distanceToPathMm(t.contactPointMm) : std::numeric_limits<double>::infinity();
        g.distanceToPathMm = t.haveContactPoint ? dist : 0.0;
        if (t.contact) mTracing = true;  // tracing time starts at the first contact
        if (!mTracing) return false;
        mTracingS += t.dtS;
        if (t.contact) {
            mContactS += t.dtS;
            if (t.haveContactPoint) mPathDistanceSumMmS += dist * t.dtS;
            if (t.forceN >= def.forceMinN && t.forceN <= def.forceMaxN) mBandS += t.dtS;
            if (t.haveContactPoint && dist <= def.toleranceMm) {
                const auto& samples = mGeometry->coverageSamplesMm();
                const double tol2 = def.toleranceMm * def.toleranceMm;
                for (std::size_t i = 0; i < samples.size(); ++i) {
                    if (mCovered[i]) continue;
                    const glm::dvec3 d = glm::dvec3(samples[i]) - glm::dvec3(t.contactPointMm);
                    if (glm::dot(d, d) <= tol2) {
                        mCovered[i] = 1;
                        ++mCoveredCount;
                    }
                }
            }
        }
        g.pathCovered = mCovered.empty() ? 0.0 : double(mCoveredCount) / double(mCovered.size());
        return !mCovered.empty() && mCoveredCount == mCovered.size();
    }

    double completion(const ScoreGuidance&) const override {
        return mCovered.empty() ? 0.0 : double(mCoveredCount) / double(mCovered.size());
    }
    std::optional<double> idealPathMm(const glm::vec3& startMm) const override {
        if (mCoveredCount == 0) return std::nullopt;
        return distance(startMm, mGeometry->pathMm().front()) + completion({}) * mGeometry->pathLengthMm();
    }
    void report(ScoreReport&, MeasuredMetrics& metrics, bool) const override {
        metrics.put(Metric::ContactFraction, mTracingS > 0.0 ? mContactS / mTracingS : 0.0, mTracingS > 0.0);
        metrics.put(Metric::BandFraction, mTracingS > 0.0 ? mBandS / mTracingS : 0.0, mTracingS > 0.0);
        metrics.put(Metric::PathDistanceMm, mContactS > 0.0 ? mPathDistanceSumMmS / mContactS : 0.0, mContactS > 0.0);
    }

private:
    std::shared_ptr<const ExerciseGeometry> mGeometry;
    bool mTracing = false;
    double mTracingS = 0.0, mContactS = 0.0, mBandS = 0.0, mPathDistanceSumMmS = 0.0;
    std::vector<std::uint8_t> mCovered;
    std::size_t mCoveredCount = 0;
};

// What the editor edits: the path's points, in order, and the band.
constexpr EditedNumber kTraceNumbers[] = {
    {"trace.force_min_n", PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Band from:"),
     PALPATE_TRANSLATE_NOOP("palpate::Exercises", "The force band's lower end (trace.force_min_n)."), "N", 0.0, 1000.0,
     3, 0.05, [](const Exercise& e, std::size_t) { return e.trace.forceMinN; },
     [](Exercise& e, std::size_t, double v) { e.trace.forceMinN = v; }},
    {"trace.force_max_n", PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Band to:"),
     PALPATE_TRANSLATE_NOOP("palpate::Exercises", "The force band's upper end (trace.force_max_n)."), "N", 0.0, 1000.0,
     3, 0.05, [](const Exercise& e, std::size_t) { return e.trace.forceMaxN; },
     [](Exercise& e, std::size_t, double v) { e.trace.forceMaxN = v; }},
    {"trace.tolerance_mm", PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Tolerance:"),
     PALPATE_TRANSLATE_NOOP("palpate::Exercises",
                            "A path point is covered by contact this close to it (trace.tolerance_mm)."),
     "mm", 0.0, 1000.0, 2, 0.5, [](const Exercise& e, std::size_t) { return e.trace.toleranceMm; },
     [](Exercise& e, std::size_t, double v) { e.trace.toleranceMm = v; }},
};

const ExerciseEditing kEditing{
    PlacedItems{
        "trace.path",
        PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Path point %1"),
        PALPATE_TRANSLATE_NOOP(
            "palpate::Exercises",
            "While on, each click on the tissue appends a path point there; the first sets a band the tissue reaches "
            "with the mouse, if the band is still the default (Esc stops)."),
        false,
        true,
        [](const Exercise& e) { return e.trace.path.size(); },
        [](const Exercise& e, std::size_t i) -> const SurfacePoint& { return e.trace.path[i]; },
        [](Exercise& e, std::size_t i, const SurfacePoint& at) { e.trace.path[i] = at; },
        [](Exercise& e, const SurfacePoint& at) { e.trace.path.push_back(at); },
        [](Exercise& e, std::size_t i) { e.trace.path.erase(e.trace.path.begin() + std::ptrdiff_t(i)); },
        [](Exercise& e, std::size_t a, std::size_t b) { std::swap(e.trace.path[a], e.trace.path[b]); },
        {},
        [](Exercise& e, double minN, double maxN) {
            // Only a band still at its default: one the instructor chose stays.
            if (e.trace.forceMinN != TraceDef{}.forceMinN || e.trace.forceMaxN != TraceDef{}.forceMaxN) return;
            e.trace.forceMinN = minN;
            e.trace.forceMaxN = maxN;
        }},
    kTraceNumbers};

class TraceKind final : public ExerciseKind {
public:
    ExerciseType type() const override { return ExerciseType::Trace; }
    std::string_view key() const override { return "trace"; }
    const char* label() const override { return PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Trace a path"); }

    std::span<const Metric> ownMetrics() const override {
        static constexpr Metric kOwn[] = {Metric::Economy, Metric::ContactFraction, Metric::BandFraction,
                                          Metric::PathDistanceMm};
        return kOwn;
    }
    std::span<const MetricWeight> defaultWeights() const override {
        static constexpr MetricWeight kWeights[] = {
            {Metric::Completion, 30},      {Metric::PathDistanceMm, 15},        {Metric::ContactFraction, 15},
            {Metric::BandFraction, 20},    {Metric::TimeS, 5},                  {Metric::ExcessiveForceFraction, 5},
            {Metric::DamageTimeS, 10},
        };
        return kWeights;
    }

    std::vector<std::string> sectionKeys() const override { return {"path", "force_min_n", "force_max_n", "tolerance_mm"}; }
    void readSection(JsonReader& r, const Json& s, Exercise& e) const override {
        TraceDef& t = e.trace;
        r.number(s, "trace", "force_min_n", t.forceMinN, true);
        r.number(s, "trace", "force_max_n", t.forceMaxN, true);
        r.number(s, "trace", "tolerance_mm", t.toleranceMm);
        if (!s.contains("path")) {
            r.error("trace.path", "missing");
            return;
        }
        if (!s.at("path").is_array()) {
            r.error("trace.path", "must be an array of points");
            return;
        }
        const Json& a = s.at("path");
        for (std::size_t i = 0; i < a.size() && i <= std::size_t(kMaxTracePathPoints); ++i) {
            const std::string key = "trace.path[" + std::to_string(i) + "]";
            SurfacePoint p;
            if (r.object(a[i], key, {"vertex", "point_mm"})) readSurfacePoint(r, a[i], key, p);
            t.path.push_back(p);
        }
    }
    Json writeSection(const Exercise& e) const override {
        Json path = Json::array();
        for (const SurfacePoint& p : e.trace.path) path.push_back(surfacePointJson(p));
        return {{"path", path},
                {"force_min_n", e.trace.forceMinN},
                {"force_max_n", e.trace.forceMaxN},
                {"tolerance_mm", e.trace.toleranceMm}};
    }
    void validate(const Exercise& e, ExerciseChecker& c) const override {
        const TraceDef& t = e.trace;
        if (t.path.size() < 2) c.error("trace.path", "needs at least 2 points");
        if (t.path.size() > std::size_t(kMaxTracePathPoints))
            c.error("trace.path", "has more than " + std::to_string(kMaxTracePathPoints) + " points");
        for (std::size_t i = 0; i < t.path.size() && i < std::size_t(kMaxTracePathPoints); ++i)
            c.point("trace.path[" + std::to_string(i) + "]", t.path[i]);
        c.window("trace", t.forceMinN, t.forceMaxN, "force_min_n", "force_max_n");
        c.range("trace.tolerance_mm", t.toleranceMm, 0.0, 1000.0, true);
    }

    void place(const Exercise& e, GeometryPlacer& placer, PlacedGeometry& placed, std::string& error) const override {
        const auto& rest = placer.mesh().restPositionsMm();
        for (std::size_t i = 0; i < e.trace.path.size(); ++i) {
            const VertexId v = placer.place(e.trace.path[i], "trace.path[" + std::to_string(i) + "]");
            if (v != kNoVertex) {
                placed.pathMm.push_back(rest[v]);
                placed.pathVertices.push_back(v);
            }
        }
        if (!error.empty()) return;
        for (std::size_t i = 1; i < placed.pathMm.size(); ++i) {
            const glm::vec3 a = placed.pathMm[i - 1], b = placed.pathMm[i];
            const double length = glm::length(glm::dvec3(b) - glm::dvec3(a));
            placed.pathLengthMm += length;
            const int steps = std::max(1, int(std::ceil(length / 1.0)));
            for (int s = 0; s < steps; ++s)
                placed.coverageMm.push_back(glm::vec3(glm::dvec3(a) + (glm::dvec3(b) - glm::dvec3(a)) * (double(s) / steps)));
        }
        if (!placed.pathMm.empty()) placed.coverageMm.push_back(placed.pathMm.back());
        if (placed.pathLengthMm <= 0.0) error = "trace.path: its points all snap to one vertex: the path has no length";
    }
    std::vector<ExerciseDemand> demands(const Exercise& e) const override {
        return {{"the trace's band (up to " + demandNumber(e.trace.forceMaxN) + " N)", e.trace.forceMaxN, 0.0}};
    }
    std::unique_ptr<ExerciseTask> makeTask(std::shared_ptr<const ExerciseGeometry> geometry, double) const override {
        return std::make_unique<TraceTask>(std::move(geometry));
    }

    const ExerciseEditing& editing() const override { return kEditing; }

    ExerciseDrawing draw(const ExerciseGeometry& geometry, MarkerAudience, const ScoreGuidance*, int selected) const override {
        ExerciseDrawing out;
        out.pathMm = geometry.pathMm();
        const std::size_t points = geometry.exercise().trace.path.size();
        for (std::size_t i = 0; i < points && i < geometry.pathMm().size(); ++i) {
            SurfaceMarker m;
            m.kind = SurfaceMarkerKind::PathPoint;
            m.positionMm = geometry.pathMm()[i];
            const VertexId v = i < geometry.pathVertices().size() ? geometry.pathVertices()[i] : kNoVertex;
            m.normal = normalOf(geometry, v);
            if (i == 0) m.label = {PALPATE_TRANSLATE_NOOP("palpate::Exercises", "start")};
            else if (i + 1 == points) m.label = {PALPATE_TRANSLATE_NOOP("palpate::Exercises", "end")};
            m.selected = int(i) == selected;
            out.markers.push_back(m);
        }
        return out;
    }
    GuidanceView guidance(const Exercise&, const ScoreGuidance& g) const override {
        GuidanceView v;
        v.windowMinN = g.forceMinN;
        v.windowMaxN = g.forceMaxN;
        v.instruction =
            ViewText{PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Follow the line with %1")}.forceRange(g.forceMinN, g.forceMaxN);
        v.detail.push_back(g.contact ? ViewText{PALPATE_TRANSLATE_NOOP("palpate::Exercises", "%1 mm from the line")}.fixed(
                                           g.distanceToPathMm, 1)
                                     : ViewText{PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Not in contact")});
        v.progress = g.pathCovered;
        v.progressFormat = {PALPATE_TRANSLATE_NOOP("palpate::Exercises", "covered %p%")};
        return v;
    }
};

}  // namespace

const ExerciseKind& traceKind() {
    static const TraceKind kind;
    return kind;
}

}  // namespace palpate
