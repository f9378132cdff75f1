// Find the lump (docs/scoring.md, "Find the lump"): a stiffer region of the tissue, found by
// palpation and marked.

#include "engine/exercise/kinds/Kinds.h"

#include "base/io/JsonReader.h"
#include "base/params/FieldTable.h"
#include "engine/exercise/ExerciseGeometry.h"
#include "engine/exercise/PalpationExamination.h"

#include <glm/geometric.hpp>

namespace palpate {

namespace {

double distance(const glm::vec3& a, const glm::vec3& b) { return glm::length(glm::dvec3(a) - glm::dvec3(b)); }

class FindLumpTask final : public ExerciseTask {
public:
    FindLumpTask(std::shared_ptr<const ExerciseGeometry> geometry, double periodS)
        : mGeometry(geometry), mExamination(std::move(geometry), periodS) {}

    bool step(const TaskTick& t, ScoreGuidance& g) override {
        mExamination.add(t, g);
        if (!t.mark || mMarked) return false;
        mMarked = true;
        g.marked = true;
        if (t.haveContactPoint) {
            mLumpErrorMm = distance(t.contactPointMm, mGeometry->lumpCentreMm());
            mMarkMeasured = true;
        }
        return true;
    }
    double completion(const ScoreGuidance&) const override { return mMarked ? 1.0 : 0.0; }
    std::optional<double> idealPathMm(const glm::vec3& startMm) const override {
        if (!mMarked) return std::nullopt;
        return distance(startMm, mGeometry->lumpCentreMm());
    }
    void report(ScoreReport& r, MeasuredMetrics& metrics, bool detail) const override {
        metrics.put(Metric::LumpErrorMm, mLumpErrorMm, mMarkMeasured);
        r.palpation = mExamination.summary(detail);
        mExamination.addCommonFeedback(*r.palpation, true);
        metrics.put(Metric::CoverageFraction, r.palpation->coverageFraction);
    }

private:
    std::shared_ptr<const ExerciseGeometry> mGeometry;
    PalpationExamination mExamination;
    bool mMarked = false, mMarkMeasured = false;
    double mLumpErrorMm = 0.0;
};

// What the editor edits: the inclusion (one), its radius and stiffness; the examination's force.
constexpr EditedNumber kInclusionNumbers[] = {
    {"radius_mm", PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Radius"),
     PALPATE_TRANSLATE_NOOP("palpate::Exercises",
                            "Vertices this close to the centre are in the inclusion (find_lump.inclusion.radius_mm)."),
     "mm", 0.0, 1000.0, 2, 0.5, [](const Exercise& e, std::size_t) { return e.findLump.inclusion.radiusMm; },
     [](Exercise& e, std::size_t, double v) { e.findLump.inclusion.radiusMm = v; }},
    {"stiffness_factor", PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Stiffness"),
     PALPATE_TRANSLATE_NOOP("palpate::Exercises",
                            "The inclusion's slopes are multiplied by this, in (0, 1]: smaller is stiffer "
                            "(find_lump.inclusion.stiffness_factor)."),
     "", 0.0, 1.0, 3, 0.05, [](const Exercise& e, std::size_t) { return e.findLump.inclusion.stiffnessFactor; },
     [](Exercise& e, std::size_t, double v) { e.findLump.inclusion.stiffnessFactor = v; }},
};
constexpr EditedNumber kFindLumpNumbers[] = {kCoverageMinForce, kCoverageRadius};

const ExerciseEditing kEditing{
    PlacedItems{"find_lump.inclusion", PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Inclusion"),
                PALPATE_TRANSLATE_NOOP("palpate::Exercises",
                                       "The next click on the mesh puts the inclusion's centre there."),
                true, false, [](const Exercise&) { return std::size_t(1); },
                [](const Exercise& e, std::size_t) -> const SurfacePoint& { return e.findLump.inclusion.centre; },
                [](Exercise& e, std::size_t, const SurfacePoint& at) { e.findLump.inclusion.centre = at; },
                [](Exercise& e, const SurfacePoint& at) { e.findLump.inclusion.centre = at; },
                [](Exercise&, std::size_t) {}, [](Exercise&, std::size_t, std::size_t) {}, kInclusionNumbers, nullptr},
    kFindLumpNumbers};

class FindLumpKind final : public ExerciseKind {
public:
    ExerciseType type() const override { return ExerciseType::FindLump; }
    std::string_view key() const override { return "find_lump"; }
    const char* label() const override { return PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Find the lump"); }
    bool palpation() const override { return true; }
    bool changesTissue() const override { return true; }

    std::span<const Metric> ownMetrics() const override {
        static constexpr Metric kOwn[] = {Metric::Economy, Metric::LumpErrorMm, Metric::CoverageFraction};
        return kOwn;
    }
    std::span<const MetricWeight> defaultWeights() const override {
        static constexpr MetricWeight kWeights[] = {
            {Metric::Completion, 20},           {Metric::LumpErrorMm, 40},
            {Metric::TimeS, 10},                {Metric::ExcessiveForceEvents, 5},
            {Metric::ExcessiveForceFraction, 10}, {Metric::DamageTimeS, 15},
        };
        return kWeights;
    }

    std::vector<std::string> sectionKeys() const override { return {"inclusion"}; }
    void readSection(JsonReader& r, const Json& s, Exercise& e) const override {
        if (!s.contains("inclusion")) {
            r.error("find_lump.inclusion", "missing");
            return;
        }
        const Json& inc = s.at("inclusion");
        const std::string path = "find_lump.inclusion";
        if (!r.object(inc, path, {"centre", "radius_mm", "stiffness_factor"})) return;
        InclusionDef& d = e.findLump.inclusion;
        if (!inc.contains("centre")) r.error(path + ".centre", "missing");
        else if (r.object(inc.at("centre"), path + ".centre", {"vertex", "point_mm"}))
            readSurfacePoint(r, inc.at("centre"), path + ".centre", d.centre);
        r.number(inc, path, "radius_mm", d.radiusMm, true);
        r.number(inc, path, "stiffness_factor", d.stiffnessFactor, true);
    }
    Json writeSection(const Exercise& e) const override {
        const InclusionDef& d = e.findLump.inclusion;
        return {{"inclusion",
                 {{"centre", surfacePointJson(d.centre)}, {"radius_mm", d.radiusMm}, {"stiffness_factor", d.stiffnessFactor}}}};
    }
    void validate(const Exercise& e, ExerciseChecker& c) const override {
        const InclusionDef& inc = e.findLump.inclusion;
        c.point("find_lump.inclusion.centre", inc.centre);
        c.range("find_lump.inclusion.radius_mm", inc.radiusMm, 0.0, 1000.0, true);
        c.range("find_lump.inclusion.stiffness_factor", inc.stiffnessFactor, 0.0, 1.0, true);
    }

    void place(const Exercise& e, GeometryPlacer& placer, PlacedGeometry& placed, std::string&) const override {
        const InclusionDef& inc = e.findLump.inclusion;
        placed.lumpVertex = placer.place(inc.centre, "find_lump.inclusion.centre");
        if (placed.lumpVertex == kNoVertex) return;
        const auto& rest = placer.mesh().restPositionsMm();
        const std::size_t n = rest.size();
        placed.lumpCentreMm = rest[placed.lumpVertex];
        placed.compliance.assign(n, 1.0f);
        const double r2 = inc.radiusMm * inc.radiusMm;
        for (VertexId v = 0; v < n; ++v) {
            const glm::dvec3 d = glm::dvec3(rest[v]) - glm::dvec3(placed.lumpCentreMm);
            if (glm::dot(d, d) <= r2) {
                placed.compliance[v] = float(inc.stiffnessFactor);
                ++placed.inclusionVertices;
            }
        }
    }
    std::vector<ExerciseDemand> demands(const Exercise& e) const override {
        return {{"the firmest press allowed (" + demandNumber(e.excessiveForceN) + " N)", e.excessiveForceN, 0.0}};
    }
    std::unique_ptr<ExerciseTask> makeTask(std::shared_ptr<const ExerciseGeometry> geometry, double periodS) const override {
        return std::make_unique<FindLumpTask>(std::move(geometry), periodS);
    }

    // The inclusion is shown to the instructor who places it, never to the trainee who must find it.
    const ExerciseEditing& editing() const override { return kEditing; }

    ExerciseDrawing draw(const ExerciseGeometry& geometry, MarkerAudience audience, const ScoreGuidance*,
                         int selected) const override {
        ExerciseDrawing out;
        if (audience != MarkerAudience::Instructor || geometry.lumpVertex() == kNoVertex) return out;
        SurfaceMarker m;
        m.kind = SurfaceMarkerKind::Inclusion;
        m.positionMm = geometry.lumpCentreMm();
        m.normal = normalOf(geometry, geometry.lumpVertex());
        m.radiusMm = geometry.exercise().findLump.inclusion.radiusMm;
        m.label = {PALPATE_TRANSLATE_NOOP("palpate::Exercises", "lump")};
        m.selected = selected == 0;
        out.markers.push_back(m);
        return out;
    }
    GuidanceView guidance(const Exercise&, const ScoreGuidance& g) const override {
        GuidanceView v;
        v.instruction = {g.marked ? PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Marked. Mark again to correct, or Stop to finish.")
                                  : PALPATE_TRANSLATE_NOOP("palpate::Exercises",
                                                           "Palpate gently; press Mark (M) while you press on the lump")};
        v.detail.push_back({g.contact ? PALPATE_TRANSLATE_NOOP("palpate::Exercises", "In contact")
                                      : PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Not in contact")});
        v.progress = g.marked ? 1.0 : 0.0;
        v.progressFormat = {g.marked ? PALPATE_TRANSLATE_NOOP("palpate::Exercises", "marked")
                                     : PALPATE_TRANSLATE_NOOP("palpate::Exercises", "not marked yet")};
        return v;
    }
};

}  // namespace

const ExerciseKind& findLumpKind() {
    static const FindLumpKind kind;
    return kind;
}

}  // namespace palpate
