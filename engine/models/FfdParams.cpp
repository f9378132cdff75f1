#include "engine/models/FfdParams.h"

namespace palpate {

namespace {

constexpr FieldDef<FfdParams> kFields[] = {
    field<&FfdParams::controlPointsPerAxis>(
        {.key = "controlPointsPerAxis",
         .jsonKey = "control_points_per_axis",
         .lo = 2,
         .hi = kMaxFfdPointsPerAxis,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Control points per axis:"),
         .tip = PALPATE_TRANSLATE_NOOP("palpate::Parameters",
                                       "Lattice resolution: control points per axis, Bernstein degree + 1 (2..16).")}),
    field<&FfdParams::movedPerAxis>(
        {.key = "movedPerAxis",
         .jsonKey = "moved_per_axis",
         .lo = 1,
         .hi = kMaxFfdPointsPerAxis,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Moved per axis:"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "Control points moved per axis: the block nearest the contact (1..control points).")}),
    field<&FfdParams::marginFraction>(
        {.key = "marginFraction",
         .jsonKey = "margin_fraction",
         .lo = 0,
         .hi = 1,
         .lower = Bound::Open,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Lattice margin:"),
         .tip = PALPATE_TRANSLATE_NOOP(
             "palpate::Parameters",
             "The lattice is the mesh's bounding box grown by this fraction of its diagonal, in (0, 1]."),
         .decimals = 4,
         .step = 0.01}),
    field<&FfdParams::stiffnessNPerMm>(
        {.key = "stiffnessNPerMm",
         .jsonKey = "stiffness_n_per_mm",
         .unit = "N/mm",
         .lo = 0,
         .hi = kNoLimit,
         .lower = Bound::Open,
         .label = PALPATE_TRANSLATE_NOOP("palpate::Parameters", "Stiffness k_s:"),
         .tip = PALPATE_TRANSLATE_NOOP("palpate::Parameters",
                                       "The rendered force is k_s times the touched vertex's displacement, N/mm."),
         .decimals = 6,
         .step = 0.01}),
};

}  // namespace

FieldTable<FfdParams> ffdFields() { return kFields; }

Problems validateFfdParams(const FfdParams& p) {
    Problems problems;
    checkFields(ffdFields(), p, problems);
    if (!hasProblem(problems, "controlPointsPerAxis") && !hasProblem(problems, "movedPerAxis") &&
        p.movedPerAxis > p.controlPointsPerAxis)
        problems.push_back({"movedPerAxis", -1, -1,
                            "movedPerAxis = " + std::to_string(p.movedPerAxis) +
                                " must be at most controlPointsPerAxis = " + std::to_string(p.controlPointsPerAxis)});
    return problems;
}

}  // namespace palpate
