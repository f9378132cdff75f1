#include "app/gui/SceneSimulation.h"

#include "engine/ToolPath.h"

#include <exception>

namespace palpate {

SceneSimulation::LoadOutcome SceneSimulation::load(const std::string& path) {
    LoadOutcome outcome;
    try {
        auto loaded = TissueMesh::load(path);
        if (!loaded.mesh) {
            for (const auto& e : loaded.report.errors) outcome.error += (outcome.error.empty() ? "" : "\n") + e;
            if (outcome.error.empty()) outcome.error = path + ": the mesh could not be loaded";
            return outcome;
        }
        outcome.simulation.reset(new SceneSimulation(path, std::move(*loaded.mesh)));
    } catch (const std::exception& e) {
        // Validated meshes should not throw; if the engine does, it is still no reason to crash the GUI.
        outcome.simulation.reset();
        outcome.error = path + ": " + e.what();
    }
    return outcome;
}

SceneSimulation::SceneSimulation(std::string path, TissueMesh mesh)
    : mPath(std::move(path)),
      mMesh(std::move(mesh)),
      mOctree(mMesh, OctreeDef{}),
      mDeformer(mMesh, mOctree, SlopeRingParams{}, SlopeRingMethod::Palpate),
      mToolPathMm(makePressAndStrokePath(mMesh)) {}

void SceneSimulation::advance(int ticks) {
    if (mToolPathMm.empty()) return;
    for (int i = 0; i < ticks; ++i) {
        mToolTipMm = mToolPathMm[mPathIndex];
        mLastTick = mDeformer.step(mToolTipMm, kTickS);
        mPathIndex = (mPathIndex + 1) % mToolPathMm.size();
        ++mTicksRun;
    }
}

void SceneSimulation::reset() {
    mDeformer.reset();
    mPathIndex = 0;
    mTicksRun = 0;
    mLastTick = TickResult{};
    mToolTipMm = glm::vec3(0.0f);
}

void SceneSimulation::fillSnapshot(SceneSnapshot& snapshot) const {
    const auto positions = mDeformer.positionsMm();
    snapshot.positionsMm.assign(positions.begin(), positions.end());
    snapshot.touched = mLastTick.touched;
    snapshot.contact = mLastTick.contact;
    snapshot.hasTool = mTicksRun > 0;
    snapshot.toolTipMm = mToolTipMm;
    snapshot.forceN = mLastTick.forceN;
}

}  // namespace palpate
