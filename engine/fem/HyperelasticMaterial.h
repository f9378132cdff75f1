#pragma once
// Compressible hyperelastic laws of the reference FEM (docs/accuracy.md, "Hyperelastic reference"):
// the strain energy W(F) per unit reference volume, the first Piola-Kirchhoff stress P = dW/dF and
// the tangent A = dP/dF. Both laws share the small-strain constants (E, nu) of ElasticMaterial, so
// at small strain they are the linear FEM. Units: mm, N, N/mm^2.
//
// With psi = I1 - 3 - 2 ln J (>= 0, second order in the strain) and Lame constants (lambda, mu):
//   neo-Hookean:  W = mu/2 psi + lambda/2 (ln J)^2
//   exponential:  W = mu/(2b) (exp(b psi) - 1) + lambda/2 (ln J)^2   (b > 0 stiffens with strain;
//                 b -> 0 is the neo-Hookean law; Demiray's form on the compressible invariant)

#include "base/params/Problem.h"

#include "engine/fem/ClosedForms.h"

#include <glm/mat3x3.hpp>

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace palpate {

enum class HyperelasticLaw { NeoHookean, Exponential };

std::string_view hyperelasticLawName(HyperelasticLaw law);
/// "neo-hookean" or "exponential"; nullopt otherwise.
std::optional<HyperelasticLaw> parseHyperelasticLaw(std::string_view name);

struct HyperelasticMaterial {
    HyperelasticLaw law = HyperelasticLaw::NeoHookean;
    ElasticMaterial smallStrain{0.01, 0.45};  ///< E and nu of the small-strain limit
    /// b of the exponential law (dimensionless); ignored by the neo-Hookean law.
    double stiffeningExponent = 0.0;
};

/// "" when usable, else a message naming the field.
Problems validateHyperelasticMaterial(const HyperelasticMaterial& m);

/// The law evaluated at one deformation gradient; J <= 0 gives valid = false (energy +inf).
struct HyperelasticPoint {
    bool valid = false;
    double energyNPerMm2 = 0.0;  ///< W, N mm / mm^3
    glm::dmat3 stress{0.0};      ///< P (glm is column-major: stress[J][i] = P_iJ)
};

/// The law's two Lame constants and b, ready to evaluate many times.
class HyperelasticLawEvaluator {
public:
    explicit HyperelasticLawEvaluator(const HyperelasticMaterial& m);
    HyperelasticPoint evaluate(const glm::dmat3& deformationGradient) const;
    /// A_iJkL = dP_iJ / dF_kL flattened as tangent[(3 i + J) * 9 + 3 k + L]; false when J <= 0.
    bool tangent(const glm::dmat3& deformationGradient, std::array<double, 81>& tangent) const;
    /// The same law without its volume term lambda/2 (ln J)^2: what the nodal-pressure element
    /// evaluates per tet, the volume term going to the nodes (docs/accuracy.md, "Element").
    HyperelasticLawEvaluator withoutVolumeTerm() const;
    double lambdaNPerMm2() const { return mLambda; }

private:
    double mLambda, mMu, mB;
};

}  // namespace palpate
