#pragma once
// Parameters of the mass-spring model (docs/models.md): a lumped mass per vertex, springs along
// the mesh edges, an anchor spring from each vertex to its rest position, a penalty contact on the
// touched vertex. Stiffnesses are per spring (N/mm), as in the classic models, so the same numbers
// give a dimple the same number of edges wide at every resolution (see docs/models.md).

#include "base/params/FieldTable.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace palpate {

enum class MassSpringIntegrator {
    SymplecticEuler,  ///< velocity then position; explicit, conserves a nearby energy; dt < 2 / omega_max
    Rk4,              ///< classic Runge-Kutta 4; explicit, slightly dissipative; dt < 2.78 / omega_max
    BackwardEuler,    ///< Baraff-Witkin implicit step solved by conjugate gradients; any dt, dissipative
};

std::string_view integratorName(MassSpringIntegrator integrator);
std::optional<MassSpringIntegrator> parseIntegrator(std::string_view name);

struct MassSpringParams {
    /// Lumped mass per vertex, kg (the slope-ring model's relaxation uses the same 1 g).
    double vertexMassKg = 0.001;
    /// Spring from each vertex to its rest position, N/mm: what holds the surface in shape.
    double anchorStiffnessNPerMm = 0.1;
    /// Spring along each mesh edge, N/mm, acting on the difference of its two vertices'
    /// displacements (a pre-tensioned edge in the small-displacement limit): it spreads the dent to
    /// the neighbours. 5x the anchor: the dent shrinks to ~0.6 of itself per ring (measured,
    /// docs/models.md), a few rings wide like the slope-ring model's default.
    double edgeStiffnessNPerMm = 0.5;
    /// Penalty stiffness between the tool tip and the touched vertex, N/mm (the slope-ring default).
    double contactStiffnessNPerMm = 1.0;
    /// Velocity damping of every vertex as a fraction of the critical damping of its anchor spring
    /// alone (1: the slowest mode does not ring; 0: no damping, energy is conserved).
    double dampingRatio = 1.0;
    /// Explicit integrators: sub-steps per tick; 0 = the fewest that keep h * omega_max inside the
    /// integrator's stability bound (with a 10 % margin), omega_max from Gershgorin's bound.
    int substeps = 0;
    /// Cap on automatic sub-steps (bounded work per tick; above it the step may be unstable).
    int maxSubsteps = 256;
    /// Backward Euler: conjugate-gradient iteration cap and relative residual tolerance.
    int cgMaxIterations = 100;
    double cgTolerance = 1e-6;
    /// Local variant: rings of the touched vertex that are simulated (everything else is pinned
    /// at rest, except vertices that left the rings and are still moving).
    int localRingCount = 6;
    /// Local variant's integrator (the whole-model variants are named by theirs).
    MassSpringIntegrator localIntegrator = MassSpringIntegrator::BackwardEuler;
    /// A vertex outside the active rings closer than this to rest and moving less than this per
    /// tick snaps to rest and stops being simulated (local variant), mm.
    double restEpsilonMm = 1e-4;
};

/// The fields of MassSpringParams in file order (base/params/FieldTable.h).
FieldTable<MassSpringParams> massSpringFields();

/// Every problem found, each naming the field; empty when valid.
Problems validateMassSpringParams(const MassSpringParams& params);

}  // namespace palpate
