#include "engine/models/ModelRegistry.h"

#include "engine/models/FfdModel.h"
#include "engine/models/MassSpringModel.h"
#include "engine/models/RadiusOfInfluenceModel.h"
#include "engine/models/VolumetricFill.h"
#include "engine/models/VolumetricRingsModel.h"
#include "engine/models/slopering/SlopeRingModel.h"

#include "base/params/FieldTable.h"

#include <stdexcept>

namespace palpate {

namespace {

Problems validateSlopeRing(const ModelDef& def) {
    Problems problems = validateSlopeRingParams(def.slopeRing);
    const Problems contact = validateContactDef(def.contact);
    problems.insert(problems.end(), contact.begin(), contact.end());
    return problems;
}
Problems validateMassSpring(const ModelDef& def) { return validateMassSpringParams(def.massSpring); }
Problems validateRadiusOfInfluence(const ModelDef& def) { return validateRadiusOfInfluenceParams(def.radiusOfInfluence); }
Problems validateFfd(const ModelDef& def) { return validateFfdParams(def.ffd); }
Problems validateVolumetricRings(const ModelDef& def) { return validateVolumetricRingsParams({def.slopeRing}); }

std::unique_ptr<DeformationModel> makeSlopeRingModel(const ModelDef& def, const TissueMesh& mesh,
                                                     const Octree& octree, const TetMesh&) {
    auto model = makeSlopeRing(mesh, octree, def.slopeRing, def.slopeRingMethod);
    model->setContact(def.contact);
    return model;
}
template <MassSpringIntegrator Integrator>
std::unique_ptr<DeformationModel> makeWholeMassSpring(const ModelDef& def, const TissueMesh& mesh,
                                                      const Octree& octree, const TetMesh&) {
    return std::make_unique<MassSpringModel>(mesh, octree, def.massSpring, Integrator, MassSpringScope::Whole);
}
std::unique_ptr<DeformationModel> makeLocalMassSpring(const ModelDef& def, const TissueMesh& mesh,
                                                      const Octree& octree, const TetMesh&) {
    return std::make_unique<MassSpringModel>(mesh, octree, def.massSpring, def.massSpring.localIntegrator,
                                             MassSpringScope::Local);
}
std::unique_ptr<DeformationModel> makeRadiusOfInfluence(const ModelDef& def, const TissueMesh& mesh,
                                                        const Octree& octree, const TetMesh&) {
    return std::make_unique<RadiusOfInfluenceModel>(mesh, octree, def.radiusOfInfluence);
}
std::unique_ptr<DeformationModel> makeFfd(const ModelDef& def, const TissueMesh& mesh, const Octree& octree,
                                          const TetMesh&) {
    return std::make_unique<FfdModel>(mesh, octree, def.ffd);
}
std::unique_ptr<DeformationModel> makeVolumetricRings(const ModelDef& def, const TissueMesh& mesh,
                                                      const Octree& octree, const TetMesh& tets) {
    if (tets.nodeCount() == 0) throw std::invalid_argument("volumetric-rings: the tet mesh is empty");
    return std::make_unique<VolumetricRingsModel>(mesh, octree, tets, VolumetricRingsParams{def.slopeRing});
}

ModelStability slopeRingStability(const ModelDef& def) {
    // Only the coherent method renders friction, and only with a friction coefficient.
    return {.bound = ModelStability::Bound::LoopGain,
            .rendered = ModelStability::Rendered::SlopeRing,
            .rendersFrictionProxy = def.slopeRingMethod == SlopeRingMethod::Coherent &&
                                    def.contact.staticFriction > 0.0};
}
ModelStability volumetricRingsStability(const ModelDef&) {
    return {.bound = ModelStability::Bound::LoopGain, .rendered = ModelStability::Rendered::SlopeRing};
}
template <MassSpringIntegrator Integrator>
ModelStability wholeMassSpringStability(const ModelDef&) {
    return {.bound = ModelStability::Bound::IntegratorStep,
            .rendered = ModelStability::Rendered::MeasuredOnMesh,
            .integrator = Integrator};
}
ModelStability localMassSpringStability(const ModelDef& def) {
    return {.bound = ModelStability::Bound::IntegratorStep,
            .rendered = ModelStability::Rendered::MeasuredOnMesh,
            .integrator = def.massSpring.localIntegrator};
}
ModelStability radiusOfInfluenceStability(const ModelDef& def) {
    return {.rendered = ModelStability::Rendered::PureSpring,
            .springStiffnessNPerMm = def.radiusOfInfluence.stiffnessNPerMm};
}
ModelStability ffdStability(const ModelDef& def) {
    return {.rendered = ModelStability::Rendered::PureSpring, .springStiffnessNPerMm = def.ffd.stiffnessNPerMm};
}

// A constant table: no allocation and no initialisation on first use, so that the haptic thread
// may read it (slopeRingParamsOf when a parameter change is recorded).
constexpr ModelDescriptor slopeRing(const char* name, SlopeRingMethod method, const char* label,
                                    const char* description) {
    return {.name = name,
            .kind = ModelKind::SlopeRing,
            .slopeRingMethod = method,
            .label = label,
            .description = description,
            .section = "slope_ring",
            .validate = validateSlopeRing,
            .make = makeSlopeRingModel,
            .stability = slopeRingStability};
}

constexpr ModelDescriptor other(const char* name, ModelKind kind, const char* label, const char* description,
                                const char* section, Problems (*validate)(const ModelDef&),
                                std::unique_ptr<DeformationModel> (*make)(const ModelDef&, const TissueMesh&,
                                                                          const Octree&, const TetMesh&),
                                ModelStability (*stability)(const ModelDef&)) {
    return {.name = name,
            .kind = kind,
            .slopeRingMethod = SlopeRingMethod::Coherent,
            .label = label,
            .description = description,
            .section = section,
            .validate = validate,
            .make = make,
            .stability = stability,
            .needsTets = kind == ModelKind::VolumetricRings};
}

constexpr ModelDescriptor kDescriptors[] = {
    other("mass-spring-symplectic", ModelKind::MassSpringSymplectic,
          PALPATE_TRANSLATE_NOOP("palpate::Models", "Mass-spring, symplectic Euler"),
          PALPATE_TRANSLATE_NOOP(
              "palpate::Models",
              "Masses on the vertices, edge and anchor springs, penalty contact; explicit symplectic Euler "
              "with automatic sub-steps. Cost: every vertex per sub-step, O(n)."),
          "mass_spring", validateMassSpring, makeWholeMassSpring<MassSpringIntegrator::SymplecticEuler>,
          wholeMassSpringStability<MassSpringIntegrator::SymplecticEuler>),
    other("mass-spring-rk4", ModelKind::MassSpringRk4, PALPATE_TRANSLATE_NOOP("palpate::Models", "Mass-spring, RK4"),
          PALPATE_TRANSLATE_NOOP(
              "palpate::Models",
              "The mass-spring model with classic Runge-Kutta 4 (four stages per sub-step). Cost: every "
              "vertex, four times per sub-step, O(n): over 1 ms from a few thousand vertices."),
          "mass_spring", validateMassSpring, makeWholeMassSpring<MassSpringIntegrator::Rk4>,
          wholeMassSpringStability<MassSpringIntegrator::Rk4>),
    other("mass-spring-implicit", ModelKind::MassSpringImplicit,
          PALPATE_TRANSLATE_NOOP("palpate::Models", "Mass-spring, backward Euler"),
          PALPATE_TRANSLATE_NOOP("palpate::Models",
                                 "The mass-spring model with the implicit backward Euler step (conjugate gradients): "
                                 "unconditionally stable, dissipative. Cost: every vertex per CG iteration, O(n)."),
          "mass_spring", validateMassSpring, makeWholeMassSpring<MassSpringIntegrator::BackwardEuler>,
          wholeMassSpringStability<MassSpringIntegrator::BackwardEuler>),
    other("mass-spring-local", ModelKind::MassSpringLocal,
          PALPATE_TRANSLATE_NOOP("palpate::Models", "Mass-spring, local rings"),
          PALPATE_TRANSLATE_NOOP(
              "palpate::Models",
              "The mass-spring model on the touched vertex's rings only (and what still moves); the rest "
              "is pinned at rest. Cost: the rings, about the same at every mesh size."),
          "mass_spring", validateMassSpring, makeLocalMassSpring, localMassSpringStability),
    other("radius-of-influence", ModelKind::RadiusOfInfluence,
          PALPATE_TRANSLATE_NOOP("palpate::Models", "Radius of influence (Basdogan)"),
          PALPATE_TRANSLATE_NOOP(
              "palpate::Models",
              "Geometric: every vertex within a radius follows the tool by a polynomial profile of its "
              "distance; force k_s × depth. Cost: the vertices within the radius."),
          "radius_of_influence", validateRadiusOfInfluence, makeRadiusOfInfluence, radiusOfInfluenceStability),
    other("ffd", ModelKind::Ffd, PALPATE_TRANSLATE_NOOP("palpate::Models", "Free-form deformation (FFD)"),
          PALPATE_TRANSLATE_NOOP(
              "palpate::Models",
              "Geometric: the mesh embedded in a Bernstein lattice whose control points near the contact "
              "move; force k_s × depth. Cost: every vertex per tick, O(n)."),
          "ffd", validateFfd, makeFfd, ffdStability),
    other("volumetric-rings", ModelKind::VolumetricRings,
          PALPATE_TRANSLATE_NOOP("palpate::Models", "Volumetric slope-rings"),
          PALPATE_TRANSLATE_NOOP(
              "palpate::Models",
              "The slope-ring update on rings of a tetrahedral fill of the surface (the paper's future "
              "work); uses the slopes and springs below. Cost: the rings of the tet graph."),
          "slope_ring", validateVolumetricRings, makeVolumetricRings, volumetricRingsStability),
    slopeRing(
        "coherent", SlopeRingMethod::Coherent, PALPATE_TRANSLATE_NOOP("palpate::Models", "Coherent rings (ours)"),
        PALPATE_TRANSLATE_NOOP("palpate::Models",
                               "Ours: exact warm-started nearest-vertex search, only the rings processed, incremental "
                               "work per tick. Cost: the rings of the touched vertex.")),
    slopeRing(
        "proposed", SlopeRingMethod::Proposed, PALPATE_TRANSLATE_NOOP("palpate::Models", "Proposed (paper)"),
        PALPATE_TRANSLATE_NOOP("palpate::Models",
                               "The paper's method: its octree searchNode (faithful, can miss the nearest vertex) and "
                               "only the rings. Cost: the rings of the touched vertex.")),
    slopeRing(
        "hybrid", SlopeRingMethod::Hybrid, PALPATE_TRANSLATE_NOOP("palpate::Models", "Hybrid (paper)"),
        PALPATE_TRANSLATE_NOOP("palpate::Models",
                               "The paper's hybrid: its octree searchNode, and the whole model processed every tick. "
                               "Cost: every vertex per tick, O(n).")),
    slopeRing("previous", SlopeRingMethod::Previous, PALPATE_TRANSLATE_NOOP("palpate::Models", "Previous (paper)"),
              PALPATE_TRANSLATE_NOOP(
                  "palpate::Models",
                  "The paper's baseline: linear nearest-vertex search, and the whole model processed every "
                  "tick. Cost: every vertex per tick, O(n).")),
};

void throwIfInvalid(const ModelDef& def) {
    const auto errors = validateModelDef(def);
    if (errors.empty()) return;
    std::string text = "invalid " + modelName(def) + " parameters:";
    for (const auto& e : errors) text += "\n  " + e.message;
    throw std::invalid_argument(text);
}

}  // namespace

std::span<const ModelDescriptor> modelDescriptors() { return kDescriptors; }

const ModelDescriptor* findModelDescriptor(std::string_view name) {
    for (const ModelDescriptor& d : modelDescriptors())
        if (name == d.name) return &d;
    // Other spellings of the slope-ring methods ("palpate", as files written before named coherent).
    if (const auto method = parseMethod(name))
        for (const ModelDescriptor& d : modelDescriptors())
            if (d.kind == ModelKind::SlopeRing && d.slopeRingMethod == *method) return &d;
    return nullptr;
}

const ModelDescriptor& modelDescriptor(const ModelDef& def) {
    for (const ModelDescriptor& d : modelDescriptors())
        if (d.kind == def.kind && (d.kind != ModelKind::SlopeRing || d.slopeRingMethod == def.slopeRingMethod)) return d;
    throw std::invalid_argument("unknown model kind " + std::to_string(int(def.kind)));
}

ModelDef slopeRingModelDef(const SlopeRingParams& params, SlopeRingMethod method) {
    ModelDef def;
    def.kind = ModelKind::SlopeRing;
    def.slopeRingMethod = method;
    def.slopeRing = params;
    return def;
}

std::vector<std::string> modelNames() {
    std::vector<std::string> names;
    for (const ModelDescriptor& d : modelDescriptors()) names.emplace_back(d.name);
    return names;
}

std::optional<ModelDef> modelDefForName(std::string_view name) {
    const ModelDescriptor* d = findModelDescriptor(name);
    if (!d) return std::nullopt;
    ModelDef def;
    def.kind = d->kind;
    def.slopeRingMethod = d->slopeRingMethod;
    return def;
}

std::string modelName(const ModelDef& def) {
    for (const ModelDescriptor& d : modelDescriptors())
        if (d.kind == def.kind && (d.kind != ModelKind::SlopeRing || d.slopeRingMethod == def.slopeRingMethod))
            return d.name;
    return "unknown";
}

double modelToolRadiusMm(const ModelDef& def) {
    return def.kind == ModelKind::SlopeRing && def.slopeRingMethod == SlopeRingMethod::Coherent
               ? def.contact.toolRadiusMm
               : 0.0;
}

Problems validateModelDef(const ModelDef& def) {
    for (const ModelDescriptor& d : modelDescriptors())
        if (d.kind == def.kind) return d.validate(def);
    return {{"kind", -1, -1, "kind: unknown model kind " + std::to_string(int(def.kind))}};
}

const SlopeRingParams* slopeRingParamsOf(const ModelDef& def) {
    return modelDescriptor(def).section == std::string_view("slope_ring") ? &def.slopeRing : nullptr;
}

SlopeRingParams* slopeRingParamsOf(ModelDef& def) {
    return const_cast<SlopeRingParams*>(slopeRingParamsOf(static_cast<const ModelDef&>(def)));
}

std::unique_ptr<DeformationModel> makeModel(const ModelDef& def, const TissueMesh& mesh, const Octree& octree) {
    if (modelDescriptor(def).needsTets) {
        throwIfInvalid(def);
        const TetMesh tets = fillSurfaceWithTets(mesh);  // throws std::invalid_argument naming the problem
        return makeModel(def, mesh, octree, tets);
    }
    return makeModel(def, mesh, octree, TetMesh{});
}

std::unique_ptr<DeformationModel> makeModel(const ModelDef& def, const TissueMesh& mesh, const Octree& octree,
                                            const TetMesh& tets) {
    throwIfInvalid(def);
    return modelDescriptor(def).make(def, mesh, octree, tets);
}

}  // namespace palpate
