#pragma once
// Every deformation model by a stable name, and one function that builds any of them, so that
// scenes, presets, the GUI's selector, the sweep and the stability maps can offer them all without
// knowing each class. Names: mass-spring-symplectic, mass-spring-rk4, mass-spring-implicit,
// mass-spring-local, radius-of-influence, ffd, volumetric-rings, and the slope-ring methods by
// their SlopeRingMethod names (coherent, proposed, hybrid, previous; "palpate" is read as
// coherent, as files written before named it). See docs/models.md.

#include "engine/models/DeformationModel.h"
#include "engine/core/Octree.h"
#include "engine/models/slopering/SlopeRingMethod.h"
#include "engine/models/slopering/SlopeRingParams.h"
#include "engine/core/TissueMesh.h"
#include "engine/fem/TetMesh.h"
#include "engine/models/FfdParams.h"
#include "engine/models/MassSpringParams.h"
#include "engine/models/RadiusOfInfluenceParams.h"
#include "engine/models/ContactDef.h"
#include "engine/models/VolumetricRingsParams.h"

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace palpate {

enum class ModelKind {
    SlopeRing,             ///< the method in ModelDef::slopeRingMethod (engine/models/slopering)
    MassSpringSymplectic,  ///< whole model, symplectic Euler
    MassSpringRk4,         ///< whole model, RK4
    MassSpringImplicit,    ///< whole model, backward Euler (conjugate gradients)
    MassSpringLocal,       ///< the touched vertex's rings only, MassSpringParams::localIntegrator
    RadiusOfInfluence,
    Ffd,
    VolumetricRings,
};

/// Which model, and every model's parameters (only the kind's are used). Trivially copyable: the
/// haptic loop queues it to the haptic thread (HapticLoop::setModelParams).
struct ModelDef {
    ModelKind kind = ModelKind::SlopeRing;
    SlopeRingMethod slopeRingMethod = SlopeRingMethod::Coherent;
    /// Slopes, springs and rings: of the slope-ring methods and of volumetric-rings (whose rings are
    /// the tet graph's).
    SlopeRingParams slopeRing;
    MassSpringParams massSpring;
    RadiusOfInfluenceParams radiusOfInfluence;
    FfdParams ffd;
    /// The tool and friction (used by the coherent slope-ring method; the others touch with a point).
    ContactDef contact;
};

/// How a model's stability is judged (docs/stability.md), said in the model's own terms: which
/// bound limits it and what it renders per unit tool displacement. engine/stability holds the
/// arithmetic of each rule, so a new model that fits an existing rule touches only its descriptor.
struct ModelStability {
    enum class Bound {
        LoopGain,        ///< the slope-ring update's alpha (1 + |m1| k_c) < 2 (slopeRing parameters)
        IntegratorStep,  ///< an integrator's step h omega_max < its bound (massSpring parameters)
        None,            ///< nothing: the dent follows the tool, not the force
    };
    enum class Rendered {
        SlopeRing,       ///< k_s |m1| F in closed form (slopeRing parameters)
        PureSpring,      ///< a spring of springStiffnessNPerMm
        MeasuredOnMesh,  ///< measured on the real model pressed on the mesh (needs the mesh)
    };
    Bound bound = Bound::None;
    Rendered rendered = Rendered::PureSpring;
    MassSpringIntegrator integrator = MassSpringIntegrator::SymplecticEuler;  ///< of IntegratorStep
    double springStiffnessNPerMm = 0.0;                                       ///< of PureSpring
    bool rendersFrictionProxy = false;  ///< also renders the friction proxy's stick spring
};

/// The translation context of the models' labels and descriptions, the engine's own.
inline constexpr const char* kModelTextContext = "palpate::Models";

/// Everything said about one model of the selector, once (docs/models.md, "Adding a model"): its
/// stable name, its kind (and slope-ring method), its label and description for people (English;
/// translated in kModelTextContext), the preset file's section holding its own parameters, and
/// how it is checked and built.
struct ModelDescriptor {
    const char* name;                 ///< "coherent", "mass-spring-rk4", ...
    ModelKind kind;
    SlopeRingMethod slopeRingMethod;  ///< the method of a SlopeRing kind; Coherent for the others
    const char* label;                ///< "Coherent rings (ours)"
    const char* description;          ///< what it is and what a tick costs
    const char* section;              ///< "slope_ring", "mass_spring", "radius_of_influence", "ffd"
    /// Every problem of the definition's parameters for this model, each naming the field.
    Problems (*validate)(const ModelDef& def);
    /// Builds it from valid parameters; `tets` is the surface's tetrahedral fill (volumetric-rings).
    std::unique_ptr<DeformationModel> (*make)(const ModelDef& def, const TissueMesh& mesh, const Octree& octree,
                                              const TetMesh& tets);
    /// Its stability rules for this definition (ModelStability).
    ModelStability (*stability)(const ModelDef& def);
    bool needsTets = false;           ///< it runs on a tetrahedral fill of the surface
};

/// Every model, in modelNames()'s order (the registry models, then the slope-ring methods).
std::span<const ModelDescriptor> modelDescriptors();
/// The descriptor of a name; nullptr for an unknown one ("palpate" is read as coherent).
const ModelDescriptor* findModelDescriptor(std::string_view name);
/// The descriptor of a definition's kind (and method).
const ModelDescriptor& modelDescriptor(const ModelDef& def);

/// A slope-ring method's definition with these parameters.
ModelDef slopeRingModelDef(const SlopeRingParams& params, SlopeRingMethod method = SlopeRingMethod::Coherent);

/// The stable names, in the order a selector lists them.
std::vector<std::string> modelNames();
/// The definition with default parameters for a name; nullopt for an unknown one.
std::optional<ModelDef> modelDefForName(std::string_view name);
/// The stable name of a definition (the model's name() says the same).
std::string modelName(const ModelDef& def);
/// The radius of the tool the definition's model touches with (DeformationModel::toolRadiusMm):
/// def.contact's for ours (the coherent slope-ring method), 0 (a point) for the others.
double modelToolRadiusMm(const ModelDef& def);
/// Every problem of the kind's parameters, each naming the field; empty when valid.
Problems validateModelDef(const ModelDef& def);
/// The slope-ring parameters the kind uses (the slope-ring methods' and volumetric rings'), or
/// nullptr for a kind made of others: what a recording stores of a parameter change.
const SlopeRingParams* slopeRingParamsOf(const ModelDef& def);
SlopeRingParams* slopeRingParamsOf(ModelDef& def);

/// Builds the model. `mesh` and `octree` must outlive it. volumetric-rings fills the surface with
/// tetrahedra first (not real-time). Throws std::invalid_argument naming the problem (invalid
/// parameters, or a surface that cannot be filled).
std::unique_ptr<DeformationModel> makeModel(const ModelDef& def, const TissueMesh& mesh, const Octree& octree);
/// As above, with the tet mesh for volumetric-rings given (its first nodes the surface's vertices).
std::unique_ptr<DeformationModel> makeModel(const ModelDef& def, const TissueMesh& mesh, const Octree& octree,
                                            const TetMesh& tets);

}  // namespace palpate
