#include "engine/scene/HapticScene.h"

#include "engine/scene/TissuePreset.h"

#include <atomic>

namespace palpate {

namespace {
std::atomic<std::uint64_t> gNextSceneId{1};
}

HapticScene::HapticScene(TissueMesh mesh, const OctreeDef& octree)
    : mMesh(std::move(mesh)), mOctree(mMesh, octree), mId(gNextSceneId.fetch_add(1)) {}

std::unique_ptr<HapticScene> HapticScene::create(TissueMesh mesh, const ModelDef& model, const OctreeDef& octree) {
    std::unique_ptr<HapticScene> scene(new HapticScene(std::move(mesh), octree));
    scene->mModel = makeModel(model, scene->mMesh, scene->mOctree);
    return scene;
}

std::unique_ptr<HapticScene> HapticScene::create(TissueMesh mesh, const TissuePreset& preset) {
    return create(std::move(mesh), presetModelDef(preset), preset.octree);
}

}  // namespace palpate
