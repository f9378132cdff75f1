#pragma once
// What the GUI shows of the simulation at one instant. The GUI's snapshot observer fills it from the
// haptic loop's newest HapticSnapshot (DESIGN.md section 2): the GUI never steps the model itself.

#include "engine/TissueMesh.h"

#include <glm/vec3.hpp>

#include <vector>

namespace palpate {

struct SceneSnapshot {
    std::vector<glm::vec3> positionsMm;  ///< current vertex positions, in the mesh's vertex order
    VertexId touched = kNoVertex;        ///< vertex nearest to the tool tip
    bool contact = false;                ///< the tool tip is pressing the touched vertex
    bool hasTool = false;                ///< false until the first tick: then there is no tool to draw
    glm::vec3 toolTipMm{0.0f};
    glm::vec3 forceN{0.0f};              ///< force rendered to the user (outward reaction)
};

}  // namespace palpate
