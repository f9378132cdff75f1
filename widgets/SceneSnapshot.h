#pragma once
// What the GUI shows of the simulation at one instant. The GUI's snapshot observer fills it from the
// haptic loop's newest HapticSnapshot (docs/architecture.md): the GUI never steps the model itself.

#include "engine/core/TissueMesh.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace palpate {

/// Ring value of a vertex in no ring: at rest, or relaxing back to it (the engine's kRelaxingRing
/// has the same value).
inline constexpr std::uint8_t kNoRing = 0xff;

struct SceneSnapshot {
    std::vector<glm::vec3> positionsMm;  ///< current vertex positions, in the mesh's vertex order
    /// Per vertex: the ring of the touched vertex it is in (0 = the touched vertex), else kNoRing.
    /// Empty means no vertex is in a ring.
    std::vector<std::uint8_t> rings;
    /// Increases by one with every change of positionsMm or rings (0: unversioned, e.g. built by
    /// hand). When a viewport last saw version - 1 of the same mesh, only `changed` need be read.
    std::uint64_t version = 0;
    /// The vertices whose position or ring differs from version - 1 (each once, any order).
    std::vector<VertexId> changed;
    VertexId touched = kNoVertex;        ///< vertex nearest to the tool tip
    bool contact = false;                ///< the tool tip is pressing the touched vertex
    bool hasTool = false;                ///< false until the first tick: then there is no tool to draw
    glm::vec3 toolTipMm{0.0f};           ///< the device's position (a sphere tool's centre)
    float toolRadiusMm = 0.0f;           ///< 0: a point tool
    glm::vec3 proxyMm{0.0f};             ///< where the tool is held on the tissue (the tip otherwise)
    glm::vec3 forceN{0.0f};              ///< force rendered to the user (outward reaction)
};

}  // namespace palpate
