#pragma once
// The kinds of exercise (ExerciseKind.h) and what their file sections share. Internal to
// engine/exercise: the registry (ExerciseKind.cpp) lists the kinds, the rest of the code asks it.

#include "engine/exercise/ExerciseKind.h"
#include "base/params/FieldTable.h"

#include <nlohmann/json.hpp>

#include <string>

namespace palpate {

const ExerciseKind& pressTargetsKind();
const ExerciseKind& findLumpKind();
const ExerciseKind& traceKind();
const ExerciseKind& detectLumpsKind();

/// The examination's numbers (the "coverage" section) the palpation kinds' editors show.
inline constexpr EditedNumber kCoverageMinForce{
    "coverage.min_force_n",
    PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Examined from:"),
    PALPATE_TRANSLATE_NOOP("palpate::Exercises",
                           "A contact lighter than this examines nothing (coverage.min_force_n): keep it "
                           "within the trainee's reach (the gauge shows it)."),
    "N",
    0.0,
    1000.0,
    3,
    0.01,
    [](const Exercise& e, std::size_t) { return e.coverage.minForceN; },
    [](Exercise& e, std::size_t, double v) { e.coverage.minForceN = v; }};
inline constexpr EditedNumber kCoverageRadius{
    "coverage.radius_mm",
    PALPATE_TRANSLATE_NOOP("palpate::Exercises", "Examined around:"),
    PALPATE_TRANSLATE_NOOP("palpate::Exercises",
                           "A contact examines the surface this close to it, mm (coverage.radius_mm)."),
    "mm",
    0.0,
    1000.0,
    2,
    0.5,
    [](const Exercise& e, std::size_t) { return e.coverage.radiusMm; },
    [](Exercise& e, std::size_t, double v) { e.coverage.radiusMm = v; }};

/// {"vertex": N} or {"point_mm": [x, y, z]} inside `j` (other keys are the caller's), at `path`.
void readSurfacePoint(JsonReader& reader, const Json& j, const std::string& path, SurfacePoint& out);
/// The point as its file writes it.
Json surfacePointJson(const SurfacePoint& point);
/// A demand's number in its text ("2.5"): three significant digits.
std::string demandNumber(double value);
/// The rest normal of a vertex of the geometry (zero for kNoVertex).
glm::vec3 normalOf(const ExerciseGeometry& geometry, VertexId vertex);

}  // namespace palpate
