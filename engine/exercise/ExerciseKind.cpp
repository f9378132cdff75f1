#include "engine/exercise/ExerciseKind.h"

#include "base/io/JsonReader.h"
#include "engine/exercise/ExerciseGeometry.h"
#include "engine/exercise/kinds/Kinds.h"

#include <algorithm>
#include <array>
#include <sstream>

namespace palpate {

std::span<const ExerciseKind* const> exerciseKinds() {
    // The one list of kinds; ExerciseType's values index it.
    static const std::array<const ExerciseKind*, 4> kKinds{&pressTargetsKind(), &findLumpKind(), &traceKind(),
                                                            &detectLumpsKind()};
    return kKinds;
}

const ExerciseKind& exerciseKind(ExerciseType type) {
    for (const ExerciseKind* kind : exerciseKinds())
        if (kind->type() == type) return *kind;
    return *exerciseKinds().front();  // unreachable for a valid type
}

const ExerciseKind* findExerciseKind(std::string_view key) {
    for (const ExerciseKind* kind : exerciseKinds())
        if (kind->key() == key) return kind;
    return nullptr;
}

std::string_view exerciseTypeName(ExerciseType type) { return exerciseKind(type).key(); }

std::optional<ExerciseType> parseExerciseType(std::string_view name) {
    const ExerciseKind* kind = findExerciseKind(name);
    return kind ? std::optional<ExerciseType>(kind->type()) : std::nullopt;
}

bool ExerciseKind::measures(Metric metric) const {
    if (metric == Metric::Count) return false;
    if (metricRow(metric).everyKind) return true;
    const auto own = ownMetrics();
    return std::find(own.begin(), own.end(), metric) != own.end();
}

double ExerciseKind::defaultWeight(Metric metric) const {
    if (!measures(metric)) return 0.0;
    for (const MetricWeight& w : defaultWeights())
        if (w.metric == metric) return w.weight;
    return 0.0;
}

void readSurfacePoint(JsonReader& r, const Json& j, const std::string& path, SurfacePoint& out) {
    const bool hasVertex = j.contains("vertex"), hasPoint = j.contains("point_mm");
    if (hasVertex == hasPoint) {
        r.error(path, hasVertex ? "give vertex or point_mm, not both" : "needs vertex or point_mm");
        return;
    }
    if (hasVertex) {
        const Json& v = j.at("vertex");
        if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > 0xFFFFFFFELL)
            r.error(JsonReader::join(path, "vertex"), "must be a vertex number (0 or more) of the mesh file");
        else out.vertex = std::uint32_t(v.get<long long>());
        return;
    }
    const Json& p = j.at("point_mm");
    if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() || !p[2].is_number()) {
        r.error(JsonReader::join(path, "point_mm"), "must be an array of three numbers (x, y, z in mm)");
        return;
    }
    out.pointMm = glm::vec3(float(p[0].get<double>()), float(p[1].get<double>()), float(p[2].get<double>()));
}

Json surfacePointJson(const SurfacePoint& p) {
    Json j = Json::object();
    if (p.vertex) j["vertex"] = *p.vertex;
    else j["point_mm"] = {double(p.pointMm.x), double(p.pointMm.y), double(p.pointMm.z)};
    return j;
}

glm::vec3 normalOf(const ExerciseGeometry& geometry, VertexId v) {
    return v < geometry.normals().size() ? geometry.normals()[v] : glm::vec3(0.0f);
}

std::string demandNumber(double v) {
    std::ostringstream s;
    s.precision(3);
    s << v;
    return s.str();
}

bool showsLiveScore(const Exercise& exercise) {
    return exercise.showLiveScore.value_or(exerciseKind(exercise.type).showsLiveScore());
}

}  // namespace palpate
