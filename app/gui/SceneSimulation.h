#pragma once
// The default scene running on the GUI thread: a mesh, its octree, the slope-ring deformer and the
// scripted press-and-stroke tool path, looped. Qt-free. A stand-in until the haptic thread (a later
// issue) owns the deformer and the GUI only reads its snapshots.

#include "engine/DeformationModel.h"
#include "engine/Octree.h"
#include "engine/SlopeRingDeformer.h"
#include "engine/TissueMesh.h"
#include "widgets/SceneSnapshot.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace palpate {

class SceneSimulation {
public:
    static constexpr double kTickS = 0.001;  ///< the tool path has one position per 1 ms tick

    struct LoadOutcome {
        std::unique_ptr<SceneSimulation> simulation;  ///< null on failure
        std::string error;                            ///< every problem, each naming the file
    };
    /// Loads and validates the mesh and builds the scene. Never throws.
    static LoadOutcome load(const std::string& path);

    SceneSimulation(const SceneSimulation&) = delete;
    SceneSimulation& operator=(const SceneSimulation&) = delete;

    const std::string& path() const { return mPath; }
    const TissueMesh& mesh() const { return mMesh; }

    /// Steps the deformer `ticks` times along the tool path, starting it over at its end.
    void advance(int ticks);
    /// Rest shape, tool back at the start of the path.
    void reset();

    const TickResult& lastTick() const { return mLastTick; }
    std::uint64_t ticksRun() const { return mTicksRun; }
    /// Copies the current state into `snapshot` (reusing its storage).
    void fillSnapshot(SceneSnapshot& snapshot) const;

private:
    SceneSimulation(std::string path, TissueMesh mesh);

    std::string mPath;
    TissueMesh mMesh;  // the octree and the deformer refer to it: this object never moves (no copy, no move)
    Octree mOctree;
    SlopeRingDeformer mDeformer;
    std::vector<glm::vec3> mToolPathMm;
    std::size_t mPathIndex = 0;
    std::uint64_t mTicksRun = 0;
    TickResult mLastTick;
    glm::vec3 mToolTipMm{0.0f};
};

}  // namespace palpate
