#include "engine/models/slopering/SlopeRingModel.h"

#include "engine/models/ModelRegistry.h"
#include "engine/models/slopering/CoherentSlopeRing.h"
#include "engine/models/slopering/PaperSlopeRing.h"

#include <stdexcept>

namespace palpate {

SlopeRingModel::SlopeRingModel(const TissueMesh& mesh, const Octree& octree, SlopeRingMethod method)
    : mMesh(mesh),
      mOctree(octree),
      mMethod(method),
      mRingFinder(mesh),
      mPositions(mesh.restPositionsMm()),
      mVelocitiesMmPerS(mesh.vertexCount(), glm::vec3(0.0f)) {}

std::string SlopeRingModel::name() const { return "slope-ring/" + std::string(methodName(mMethod)); }

void SlopeRingModel::setParams(const SlopeRingParams& params) {
    const auto errors = validateSlopeRingParams(params);
    if (!errors.empty()) {
        std::string text = "invalid slope-ring parameters:";
        for (const auto& e : errors) text += "\n  " + e.message;
        throw std::invalid_argument(text);
    }
    const bool ringsChanged = params.ringCount != mParams.ringCount;
    mParams = params;
    updateHotConstants();
    paramsReplaced(ringsChanged);
}

bool SlopeRingModel::applyModelParams(const ModelDef& def) {
    if (def.kind != ModelKind::SlopeRing || def.slopeRingMethod != mMethod) return false;
    if (!canTakeParams(def.slopeRing)) return false;
    const bool ringsChanged = def.slopeRing.ringCount != mParams.ringCount;
    mParams = def.slopeRing;
    updateHotConstants();
    paramsReplaced(ringsChanged);
    setContact(def.contact);
    return true;
}

void SlopeRingModel::updateHotConstants() {
    mHot = slopeRingConstants(mParams);
    mRelaxDtS = -1.0;
}

void SlopeRingModel::resetShared() {
    mPositions = mMesh.restPositionsMm();
    std::fill(mVelocitiesMmPerS.begin(), mVelocitiesMmPerS.end(), glm::vec3(0.0f));
    mTouched = kNoVertex;
    mContactForceN = 0.0f;
    mContact = false;
}

std::unique_ptr<SlopeRingModel> makeSlopeRing(const TissueMesh& mesh, const Octree& octree,
                                              const SlopeRingParams& params, SlopeRingMethod method,
                                              bool eagerPositions) {
    if (method == SlopeRingMethod::Coherent)
        return std::make_unique<CoherentSlopeRing>(mesh, octree, params, eagerPositions);
    return std::make_unique<PaperSlopeRing>(mesh, octree, params, method);
}

}  // namespace palpate
