#pragma once
// Everything the haptic loop touches for one mesh: the mesh, its octree and the deformation
// model. Built off the haptic thread (it allocates), handed to the loop whole, retired whole.

#include "engine/DeformationModel.h"
#include "engine/Octree.h"
#include "engine/SlopeRingMethod.h"
#include "engine/SlopeRingParams.h"
#include "engine/TissueMesh.h"

#include <cstdint>
#include <memory>

namespace palpate {

class HapticScene {
public:
    /// A slope-ring scene. Throws std::invalid_argument on invalid parameters or octree definition.
    static std::unique_ptr<HapticScene> createSlopeRing(TissueMesh mesh, const SlopeRingParams& params,
                                                        SlopeRingMethod method = SlopeRingMethod::Palpate,
                                                        const OctreeDef& octree = {});

    const TissueMesh& mesh() const { return mMesh; }
    const Octree& octree() const { return mOctree; }
    DeformationModel& model() { return *mModel; }
    const DeformationModel& model() const { return *mModel; }
    /// Unique per scene in this process, so observers can tell scenes apart.
    std::uint64_t id() const { return mId; }

private:
    HapticScene(TissueMesh mesh, const OctreeDef& octree);

    TissueMesh mMesh;
    Octree mOctree;
    std::unique_ptr<DeformationModel> mModel;
    std::uint64_t mId;
};

}  // namespace palpate
