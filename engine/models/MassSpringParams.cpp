#include "engine/models/MassSpringParams.h"

#include "engine/core/Rings.h"

namespace palpate {

namespace {

// Indexed by MassSpringIntegrator.
constexpr const char* kIntegratorNames[] = {"symplectic", "rk4", "implicit"};
constexpr const char* kIntegratorLabels[] = {PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Symplectic Euler"),
                                             PALPATE_TRANSLATE_NOOP("palpate::Parameters", "RK4"),
                                             PALPATE_TRANSLATE_NOOP("palpate::Parameters",
                                                                    "Backward Euler (implicit)")};

constexpr FieldDef<MassSpringParams> kFields[] = {
    field<&MassSpringParams::vertexMassKg>(
        {.key = "vertexMassKg",
         .jsonKey = "vertex_mass_kg",
         .unit = "kg",
         .lo = 0,
         .hi = kNoLimit,
         .lower = Bound::Open,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Vertex mass m:"),
         .tip = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Lumped mass per vertex, kg."),
         .decimals = 7,
         .step = 0.0005}),
    field<&MassSpringParams::anchorStiffnessNPerMm>(
        {.key = "anchorStiffnessNPerMm",
         .jsonKey = "anchor_stiffness_n_per_mm",
         .unit = "N/mm",
         .lo = 0,
         .hi = kNoLimit,
         .lower = Bound::Open,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Anchor stiffness k_a:"),
         .tip = PALPATE_TRANSLATE_NOOP("palpate::Parameters",
                                       "Spring from each vertex to its rest position, N/mm: what holds the shape."),
         .decimals = 6,
         .step = 0.01}),
    field<&MassSpringParams::edgeStiffnessNPerMm>(
        {.key = "edgeStiffnessNPerMm",
         .jsonKey = "edge_stiffness_n_per_mm",
         .unit = "N/mm",
         .lo = 0,
         .hi = kNoLimit,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Edge stiffness k_e:"),
         .tip = PALPATE_TRANSLATE_NOOP("palpate::Parameters",
                                       "Spring along each mesh edge, N/mm: spreads the dent to the neighbours."),
         .decimals = 6,
         .step = 0.05}),
    field<&MassSpringParams::contactStiffnessNPerMm>(
        {.key = "contactStiffnessNPerMm",
         .jsonKey = "contact_stiffness_n_per_mm",
         .unit = "N/mm",
         .lo = 0,
         .hi = kNoLimit,
         .lower = Bound::Open,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Contact stiffness k_c:"),
         .tip = PALPATE_TRANSLATE_NOOP("palpate::Parameters",
                                       "Penalty stiffness between the tool tip and the touched vertex, N/mm."),
         .decimals = 6,
         .step = 0.1}),
    field<&MassSpringParams::dampingRatio>(
        {.key = "dampingRatio",
         .jsonKey = "damping_ratio",
         .lo = 0,
         .hi = 100,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Damping ratio ζ:"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "Velocity damping as a fraction of the anchor spring's critical damping (0..100)."),
         .decimals = 3,
         .step = 0.1}),
    field<&MassSpringParams::substeps>(
        {.key = "substeps",
         .jsonKey = "substeps",
         .lo = 0,
         .hi = 100000,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Sub-steps:"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "Explicit integrators: sub-steps per tick; 0 = automatic (inside the stability bound); at most the "
             "max sub-steps.")}),
    field<&MassSpringParams::maxSubsteps>(
        {.key = "maxSubsteps",
         .jsonKey = "max_substeps",
         .lo = 1,
         .hi = 100000,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Max sub-steps:"),
         .tip = PALPATE_TRANSLATE_NOOP("palpate::Parameters",
                                       "Cap on automatic sub-steps (bounded work per tick).")}),
    field<&MassSpringParams::cgMaxIterations>(
        {.key = "cgMaxIterations",
         .jsonKey = "cg_max_iterations",
         .lo = 1,
         .hi = 100000,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "CG iterations (max):"),
         .tip = PALPATE_TRANSLATE_NOOP("palpate::Parameters",
                                       "Backward Euler: conjugate-gradient iteration cap.")}),
    field<&MassSpringParams::cgTolerance>(
        {.key = "cgTolerance",
         .jsonKey = "cg_tolerance",
         .lo = 0,
         .hi = 1,
         .lower = Bound::Open,
         .upper = Bound::Open,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "CG tolerance:"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "Backward Euler: relative residual at which conjugate gradients stop, in (0, 1)."),
         .decimals = 12,
         .step = 1e-6}),
    field<&MassSpringParams::localRingCount>(
        {.key = "localRingCount",
         .jsonKey = "local_ring_count",
         .lo = 1,
         .hi = kMaxRings,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Simulated rings:"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "Rings of the touched vertex that are simulated; everything else is pinned at rest."),
         .onlyFor = "mass-spring-local"}),
    field<&MassSpringParams::localIntegrator>(
        {.key = "localIntegrator",
         .jsonKey = "local_integrator",
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Integrator:"),
         .tip = PALPATE_TRANSLATE_NOOP("palpate::Parameters",
                                       "The local variant's integrator: symplectic Euler, RK4 or backward Euler."),
         .choices = kIntegratorNames,
         .choiceLabels = kIntegratorLabels,
         .choiceNoun = "integrator",
         .onlyFor = "mass-spring-local"}),
    field<&MassSpringParams::restEpsilonMm>(
        {.key = "restEpsilonMm",
         .jsonKey = "rest_epsilon_mm",
         .unit = "mm",
         .lo = 0,
         .hi = kNoLimit,
         .lower = Bound::Open,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Rest tolerance:"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "A vertex outside the rings this close to rest and moving less than this per tick stops being "
             "simulated, mm."),
         .decimals = 9,
         .step = 1e-4,
         .onlyFor = "mass-spring-local"}),
};

}  // namespace

std::string_view integratorName(MassSpringIntegrator integrator) {
    const int i = int(integrator);
    return i >= 0 && i < int(std::size(kIntegratorNames)) ? kIntegratorNames[i] : "?";
}

std::optional<MassSpringIntegrator> parseIntegrator(std::string_view name) {
    for (int i = 0; i < int(std::size(kIntegratorNames)); ++i)
        if (name == kIntegratorNames[i]) return MassSpringIntegrator(i);
    return std::nullopt;
}

FieldTable<MassSpringParams> massSpringFields() { return kFields; }

Problems validateMassSpringParams(const MassSpringParams& p) {
    Problems problems;
    checkFields(massSpringFields(), p, problems);
    if (!hasProblem(problems, "substeps") && !hasProblem(problems, "maxSubsteps") && p.substeps > p.maxSubsteps)
        problems.push_back({"substeps", -1, -1,
                            "substeps = " + std::to_string(p.substeps) +
                                " must be at most maxSubsteps = " + std::to_string(p.maxSubsteps)});
    return problems;
}

}  // namespace palpate
