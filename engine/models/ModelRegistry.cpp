#include "engine/models/ModelRegistry.h"

#include "engine/models/FfdModel.h"
#include "engine/models/MassSpringModel.h"
#include "engine/models/RadiusOfInfluenceModel.h"
#include "engine/models/VolumetricFill.h"
#include "engine/models/VolumetricRingsModel.h"
#include "engine/models/slopering/SlopeRingModel.h"

#include <stdexcept>

namespace palpate {

namespace {

struct Named {
    const char* name;
    ModelKind kind;
};
constexpr Named kModels[] = {
    {"mass-spring-symplectic", ModelKind::MassSpringSymplectic},
    {"mass-spring-rk4", ModelKind::MassSpringRk4},
    {"mass-spring-implicit", ModelKind::MassSpringImplicit},
    {"mass-spring-local", ModelKind::MassSpringLocal},
    {"radius-of-influence", ModelKind::RadiusOfInfluence},
    {"ffd", ModelKind::Ffd},
    {"volumetric-rings", ModelKind::VolumetricRings},
};
constexpr SlopeRingMethod kSlopeRingMethods[] = {SlopeRingMethod::Coherent, SlopeRingMethod::Proposed,
                                                 SlopeRingMethod::Hybrid, SlopeRingMethod::Previous};

void throwIfInvalid(const ModelDef& def) {
    const auto errors = validateModelDef(def);
    if (errors.empty()) return;
    std::string text = "invalid " + modelName(def) + " parameters:";
    for (const auto& e : errors) text += "\n  " + e.message;
    throw std::invalid_argument(text);
}

}  // namespace

ModelDef slopeRingModelDef(const SlopeRingParams& params, SlopeRingMethod method) {
    ModelDef def;
    def.kind = ModelKind::SlopeRing;
    def.slopeRingMethod = method;
    def.slopeRing = params;
    return def;
}

std::vector<std::string> modelNames() {
    std::vector<std::string> names;
    for (const Named& m : kModels) names.emplace_back(m.name);
    for (SlopeRingMethod method : kSlopeRingMethods) names.emplace_back(methodName(method));
    return names;
}

std::optional<ModelDef> modelDefForName(std::string_view name) {
    ModelDef def;
    for (const Named& m : kModels)
        if (name == m.name) {
            def.kind = m.kind;
            return def;
        }
    if (const auto method = parseMethod(name)) {
        def.kind = ModelKind::SlopeRing;
        def.slopeRingMethod = *method;
        return def;
    }
    return std::nullopt;
}

std::string modelName(const ModelDef& def) {
    if (def.kind == ModelKind::SlopeRing) return std::string(methodName(def.slopeRingMethod));
    for (const Named& m : kModels)
        if (m.kind == def.kind) return m.name;
    return "unknown";
}

double modelToolRadiusMm(const ModelDef& def) {
    return def.kind == ModelKind::SlopeRing && def.slopeRingMethod == SlopeRingMethod::Coherent
               ? def.contact.toolRadiusMm
               : 0.0;
}

Problems validateModelDef(const ModelDef& def) {
    switch (def.kind) {
        case ModelKind::SlopeRing: {
            Problems problems = validateSlopeRingParams(def.slopeRing);
            const Problems contact = validateContactDef(def.contact);
            problems.insert(problems.end(), contact.begin(), contact.end());
            return problems;
        }
        case ModelKind::MassSpringSymplectic:
        case ModelKind::MassSpringRk4:
        case ModelKind::MassSpringImplicit:
        case ModelKind::MassSpringLocal: return validateMassSpringParams(def.massSpring);
        case ModelKind::RadiusOfInfluence: return validateRadiusOfInfluenceParams(def.radiusOfInfluence);
        case ModelKind::Ffd: return validateFfdParams(def.ffd);
        case ModelKind::VolumetricRings: return validateVolumetricRingsParams(def.volumetricRings);
    }
    return {{"kind", -1, -1, "kind: unknown model kind " + std::to_string(int(def.kind))}};
}

const SlopeRingParams* slopeRingParamsOf(const ModelDef& def) {
    switch (def.kind) {
        case ModelKind::SlopeRing: return &def.slopeRing;
        case ModelKind::VolumetricRings: return &def.volumetricRings.slopeRing;
        default: return nullptr;
    }
}

SlopeRingParams* slopeRingParamsOf(ModelDef& def) {
    return const_cast<SlopeRingParams*>(slopeRingParamsOf(static_cast<const ModelDef&>(def)));
}

std::unique_ptr<DeformationModel> makeModel(const ModelDef& def, const TissueMesh& mesh, const Octree& octree) {
    if (def.kind == ModelKind::VolumetricRings) {
        throwIfInvalid(def);
        const TetMesh tets = fillSurfaceWithTets(mesh);  // throws std::invalid_argument naming the problem
        return makeModel(def, mesh, octree, tets);
    }
    return makeModel(def, mesh, octree, TetMesh{});
}

std::unique_ptr<DeformationModel> makeModel(const ModelDef& def, const TissueMesh& mesh, const Octree& octree,
                                            const TetMesh& tets) {
    throwIfInvalid(def);
    switch (def.kind) {
        case ModelKind::SlopeRing: {
            auto model = makeSlopeRing(mesh, octree, def.slopeRing, def.slopeRingMethod);
            model->setContact(def.contact);
            return model;
        }
        case ModelKind::MassSpringSymplectic:
            return std::make_unique<MassSpringModel>(mesh, octree, def.massSpring,
                                                     MassSpringIntegrator::SymplecticEuler, MassSpringScope::Whole);
        case ModelKind::MassSpringRk4:
            return std::make_unique<MassSpringModel>(mesh, octree, def.massSpring, MassSpringIntegrator::Rk4,
                                                     MassSpringScope::Whole);
        case ModelKind::MassSpringImplicit:
            return std::make_unique<MassSpringModel>(mesh, octree, def.massSpring, MassSpringIntegrator::BackwardEuler,
                                                     MassSpringScope::Whole);
        case ModelKind::MassSpringLocal:
            return std::make_unique<MassSpringModel>(mesh, octree, def.massSpring, def.massSpring.localIntegrator,
                                                     MassSpringScope::Local);
        case ModelKind::RadiusOfInfluence:
            return std::make_unique<RadiusOfInfluenceModel>(mesh, octree, def.radiusOfInfluence);
        case ModelKind::Ffd: return std::make_unique<FfdModel>(mesh, octree, def.ffd);
        case ModelKind::VolumetricRings:
            if (tets.nodeCount() == 0) throw std::invalid_argument("volumetric-rings: the tet mesh is empty");
            return std::make_unique<VolumetricRingsModel>(mesh, octree, tets, def.volumetricRings);
    }
    throw std::invalid_argument("makeModel: unknown model kind " + std::to_string(int(def.kind)));
}

}  // namespace palpate
