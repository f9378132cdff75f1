#pragma once
// Everything the haptic loop touches for one mesh: the mesh, its octree and the deformation
// model. Built off the haptic thread (it allocates), handed to the loop whole, retired whole.

#include "engine/models/DeformationModel.h"
#include "engine/core/Octree.h"
#include "engine/core/TissueMesh.h"
#include "engine/models/ModelRegistry.h"

#include <cstdint>
#include <memory>

namespace palpate {

struct TissuePreset;

class HapticScene {
public:
    /// A scene of any registry model (docs/models.md); volumetric-rings fills the surface with
    /// tetrahedra here. Not real-time: call it off the haptic thread. Throws std::invalid_argument
    /// naming the problem (parameters, octree, a surface the filler refuses).
    static std::unique_ptr<HapticScene> create(TissueMesh mesh, const ModelDef& model, const OctreeDef& octree = {});
    /// The preset's model (presetModelDef), parameters and octree.
    static std::unique_ptr<HapticScene> create(TissueMesh mesh, const TissuePreset& preset);

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
