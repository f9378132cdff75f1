#include "engine/fem/HyperelasticMaterial.h"

#include "engine/fem/LinearElasticFem.h"

#include <glm/matrix.hpp>

#include <cmath>

namespace palpate {

namespace {

/// Component (i, J) of a glm matrix (column-major: m[column][row]).
inline double at(const glm::dmat3& m, int i, int j) { return m[j][i]; }

}  // namespace

std::string_view hyperelasticLawName(HyperelasticLaw law) {
    return law == HyperelasticLaw::NeoHookean ? "neo-hookean" : "exponential";
}

std::optional<HyperelasticLaw> parseHyperelasticLaw(std::string_view name) {
    if (name == "neo-hookean") return HyperelasticLaw::NeoHookean;
    if (name == "exponential") return HyperelasticLaw::Exponential;
    return std::nullopt;
}

Problems validateHyperelasticMaterial(const HyperelasticMaterial& m) {
    if (Problems e = validateElasticMaterial(m.smallStrain); !e.empty()) return e;
    if (m.law == HyperelasticLaw::Exponential && !(m.stiffeningExponent >= 0.0 && m.stiffeningExponent <= 100.0))
        return oneProblem("stiffeningExponent", "stiffening exponent b must be a number in [0, 100]");
    return {};
}

HyperelasticLawEvaluator::HyperelasticLawEvaluator(const HyperelasticMaterial& m) {
    const auto [lambda, mu] = lameConstantsNPerMm2(m.smallStrain);
    mLambda = lambda;
    mMu = mu;
    mB = m.law == HyperelasticLaw::Exponential ? m.stiffeningExponent : 0.0;
}

HyperelasticLawEvaluator HyperelasticLawEvaluator::withoutVolumeTerm() const {
    HyperelasticLawEvaluator out = *this;
    out.mLambda = 0.0;
    return out;
}

/// J - 1 and psi = I1 - 3 - 2 ln J from H = F - I without the cancellation of the plain formulas
/// (at small strain psi is O(H^2) while I1 - 3 and 2 ln J are O(H)): J - 1 = tr H + (principal 2x2
/// minors) + det H, ln J = log1p(J - 1).
struct Invariants {
    double jMinus1, lnJ, psi;
};

Invariants invariants(const glm::dmat3& f) {
    glm::dmat3 h = f;
    for (int c = 0; c < 3; ++c) h[c][c] -= 1.0;
    const double tr = h[0][0] + h[1][1] + h[2][2];
    const double minors = h[0][0] * h[1][1] - h[1][0] * h[0][1] + h[0][0] * h[2][2] - h[2][0] * h[0][2] +
                          h[1][1] * h[2][2] - h[2][1] * h[1][2];
    Invariants v;
    v.jMinus1 = tr + minors + glm::determinant(h);
    v.lnJ = v.jMinus1 > -1.0 ? std::log1p(v.jMinus1) : -INFINITY;
    double squares = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) squares += h[c][r] * h[c][r];
    // I1 - 3 = 2 tr H + |H|^2; 2 (tr H - ln J) is computed as one difference of two close numbers
    // of size tr H, so its error is eps |tr H|, not eps.
    v.psi = squares + 2.0 * (tr - v.lnJ);
    return v;
}

/// F - F^-T from H = F - I as H + (F^-1 H)^T (since I - F^-T = (F^-1 H)^T): its error is then eps |H|,
/// not eps, which matters where the strain is tiny (far from a contact, in the small-strain check).
glm::dmat3 differenceFromInverseTranspose(const glm::dmat3& f) {
    glm::dmat3 h = f;
    for (int c = 0; c < 3; ++c) h[c][c] -= 1.0;
    return h + glm::transpose(glm::inverse(f) * h);
}

// P = w1 (F - F^-T) + lambda ln J F^-T with w1 = mu exp(b psi) (mu for neo-Hookean).
HyperelasticPoint HyperelasticLawEvaluator::evaluate(const glm::dmat3& f) const {
    HyperelasticPoint out;
    const Invariants v = invariants(f);
    if (!(v.jMinus1 > -1.0) || !std::isfinite(v.jMinus1)) return out;
    const double lnJ = v.lnJ, psi = v.psi;
    const glm::dmat3 g = glm::transpose(glm::inverse(f));  // F^-T
    double w1 = mMu;
    if (mB > 0.0) {
        const double bPsi = mB * psi;
        w1 = mMu * std::exp(bPsi);
        out.energyNPerMm2 = mMu / (2.0 * mB) * std::expm1(bPsi) + 0.5 * mLambda * lnJ * lnJ;
    } else {
        out.energyNPerMm2 = 0.5 * mMu * psi + 0.5 * mLambda * lnJ * lnJ;
    }
    out.stress = w1 * differenceFromInverseTranspose(f) + (mLambda * lnJ) * g;
    out.valid = std::isfinite(out.energyNPerMm2);
    return out;
}

// dP = w1 [dF + G dF^T G] + 2 b w1 D (D : dF) + lambda (G : dF) G - lambda ln J G dF^T G,
// G = F^-T, D = F - G: A_iJkL = (w1 - lambda ln J) G_iL G_kJ + w1 d_ik d_JL + 2 b w1 D_iJ D_kL
// + lambda G_iJ G_kL (docs/accuracy.md).
bool HyperelasticLawEvaluator::tangent(const glm::dmat3& f, std::array<double, 81>& a) const {
    const Invariants v = invariants(f);
    if (!(v.jMinus1 > -1.0) || !std::isfinite(v.jMinus1)) return false;
    const double lnJ = v.lnJ;
    const glm::dmat3 g = glm::transpose(glm::inverse(f));
    const double w1 = mB > 0.0 ? mMu * std::exp(mB * v.psi) : mMu;
    const glm::dmat3 d = differenceFromInverseTranspose(f);
    const double geometric = w1 - mLambda * lnJ;
    for (int i = 0; i < 3; ++i)
        for (int jj = 0; jj < 3; ++jj)
            for (int k = 0; k < 3; ++k)
                for (int l = 0; l < 3; ++l) {
                    double v = geometric * at(g, i, l) * at(g, k, jj) + mLambda * at(g, i, jj) * at(g, k, l);
                    if (i == k && jj == l) v += w1;
                    if (mB > 0.0) v += 2.0 * mB * w1 * at(d, i, jj) * at(d, k, l);
                    a[std::size_t((3 * i + jj) * 9 + 3 * k + l)] = v;
                }
    return std::isfinite(w1);
}

}  // namespace palpate
