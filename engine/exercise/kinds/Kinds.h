#pragma once
// The kinds of exercise (ExerciseKind.h) and what their file sections share. Internal to
// engine/exercise: the registry (ExerciseKind.cpp) lists the kinds, the rest of the code asks it.

#include "engine/exercise/ExerciseKind.h"

#include <nlohmann/json.hpp>

#include <string>

namespace palpate {

const ExerciseKind& pressTargetsKind();
const ExerciseKind& findLumpKind();
const ExerciseKind& traceKind();
const ExerciseKind& detectLumpsKind();

/// {"vertex": N} or {"point_mm": [x, y, z]} inside `j` (other keys are the caller's), at `path`.
void readSurfacePoint(JsonReader& reader, const Json& j, const std::string& path, SurfacePoint& out);
/// The point as its file writes it.
Json surfacePointJson(const SurfacePoint& point);
/// A demand's number in its text ("2.5"): three significant digits.
std::string demandNumber(double value);
/// The rest normal of a vertex of the geometry (zero for kNoVertex).
glm::vec3 normalOf(const ExerciseGeometry& geometry, VertexId vertex);

}  // namespace palpate
