#pragma once
// Synthetic tick streams on a flat grid for scorer tests whose answers are worked out by hand: a
// 5 x 5 grid of vertices 10 mm apart in the plane z = 0 (vertex j * 5 + i at (10 i, 10 j, 0)),
// and samples at 1024 Hz, whose period (2^-10 s) makes every sum of tick lengths exact.

#include "engine/core/TissueMesh.h"
#include "engine/exercise/Exercise.h"
#include "engine/scoring/ScoreSample.h"

#include <glm/vec3.hpp>

#include <stdexcept>

namespace palpate::test {

inline constexpr double kTickS = 1.0 / 1024.0;

inline TissueMesh gridMesh() {
    std::vector<glm::vec3> p;
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i) p.emplace_back(10.0f * float(i), 10.0f * float(j), 0.0f);
    std::vector<std::array<VertexId, 3>> t;
    for (VertexId j = 0; j < 4; ++j)
        for (VertexId i = 0; i < 4; ++i) {
            const VertexId a = j * 5 + i, b = a + 1, c = a + 6, d = a + 5;
            t.push_back({a, b, c});
            t.push_back({a, c, d});
        }
    auto loaded = TissueMesh::fromTriangles(p, t, "grid", false);
    if (!loaded.mesh) throw std::runtime_error(loaded.error());
    return std::move(*loaded.mesh);
}

/// An exercise on the grid with nothing set but the type (callers fill in the rest).
inline Exercise gridExercise(ExerciseType type) {
    Exercise e;
    e.name = "grid";
    e.type = type;
    e.meshPath = "grid.off";
    e.tissuePresetPath = "preset.json";
    return e;
}

/// Tick `tick` at time tick * kTickS: the device read at `toolMm` with `buttons`, the force along +z.
inline ScoreSample sampleAt(std::uint64_t tick, glm::vec3 toolMm, VertexId touched, bool contact, float forceN,
                            std::uint32_t buttons = 0) {
    ScoreSample s;
    s.tick.tick = tick;
    s.tick.nowS = double(tick) * kTickS;
    s.tick.readOk = true;
    s.tick.sample.positionMm = toolMm;
    s.tick.sample.buttons = buttons;
    s.tick.sample.timeS = s.tick.nowS;
    s.tick.deviceState = DeviceState::Ready;
    s.tick.touched = touched;
    s.tick.contact = contact;
    s.tick.forceN = glm::vec3(0.0f, 0.0f, forceN);
    return s;
}

}  // namespace palpate::test
