#pragma once
// What the divergence guard can find (DivergenceGuard.h), with its name and the advice for the
// user, header-only: the recorder's reader names the events without linking the guard.

#include <cstdint>

namespace palpate {

enum class DivergenceKind : std::uint8_t {
    None = 0,
    NonFinite,    ///< NaN or infinity in the force or the fan's positions
    EnergyGrowth, ///< activity grew by energyGrowthPerWindow for growthWindows windows in a row
    Oscillation,  ///< the contact force changed direction every tick for oscillationTicks ticks
    Inversion,    ///< a triangle of the touched vertex's fan flipped against its rest normal
};

/// A short name for logs and the snapshot ("non-finite", "energy growth", ...).
inline const char* divergenceKindName(DivergenceKind kind) {
    switch (kind) {
        case DivergenceKind::None: return "none";
        case DivergenceKind::NonFinite: return "non-finite";
        case DivergenceKind::EnergyGrowth: return "energy growth";
        case DivergenceKind::Oscillation: return "force oscillation";
        case DivergenceKind::Inversion: return "triangle inversion";
    }
    return "unknown";
}

/// What happened and which parameter to change, for the user (static text).
inline const char* divergenceAdvice(DivergenceKind kind) {
    switch (kind) {
        case DivergenceKind::None: return "";
        case DivergenceKind::NonFinite:
            return "the model produced a non-finite force or position; force zeroed and tissue reset. Lower the "
                   "stiffnesses (k, contactStiffness) or the time step: raise the loop rate or the mass-spring "
                   "substeps, or use backward Euler";
        case DivergenceKind::EnergyGrowth:
            return "the tissue's energy grew without bound (the integrator is beyond dt < 2 / omega_max); force "
                   "zeroed and tissue reset. Raise substeps, lower the stiffnesses (k, contactStiffness) or raise "
                   "vertexMass, or use backward Euler";
        case DivergenceKind::Oscillation:
            return "the contact force flips every tick (the slope model beyond alpha (1 + |m1| k_c) < 2); force "
                   "zeroed and tissue reset. Lower forceRelaxation (0 = automatic), |m1| or contactStiffness";
        case DivergenceKind::Inversion:
            return "a triangle at the tool turned inside out (|m1 - m2| |F_t| beyond the vertex's height over the "
                   "opposite edge); force zeroed and tissue reset. Lower |m1| - |m2| or contactStiffness";
    }
    return "";
}

}  // namespace palpate
