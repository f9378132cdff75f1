#include "engine/stability/StabilityBounds.h"

#include "engine/models/slopering/SlopeRingParams.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace palpate {

double slopeRingMaxGain(double alpha) { return alpha > 0.0 ? kLoopProductLimit / alpha - 1.0 : kNoBound; }

double slopeRingMaxRelaxation(double gain) { return kLoopProductLimit / (1.0 + gain); }

double slopeRingMargin(double alpha, double gain) { return 1.0 - alpha * (1.0 + gain) / kLoopProductLimit; }

double symplecticEulerMaxStepS(double omega, double gamma) {
    // The step matrix of (u, w) has trace 1 + c - c h^2 omega^2 and determinant c = 1 / (1 + h gamma);
    // Jury's conditions leave 1 + trace + det > 0, i.e. h^2 omega^2 < 4 + 2 h gamma. Solved for h.
    if (!(omega > 0.0)) return kNoBound;
    return (gamma + std::sqrt(gamma * gamma + 4.0 * omega * omega)) / (omega * omega);
}

double rk4MaxStepS(double omega) { return omega > 0.0 ? 2.0 * std::sqrt(2.0) / omega : kNoBound; }

double forwardEulerMaxStepS(double omega, double gamma) {
    if (!(omega > 0.0)) return gamma > 0.0 ? 2.0 / gamma : kNoBound;
    const double disc = gamma * gamma / 4.0 - omega * omega;
    if (disc <= 0.0) return gamma / (omega * omega);  // complex pair: |lambda|^2 = omega^2
    // Two real negative eigenvalues: the faster one limits, h < 2 / |lambda_fast|.
    return 2.0 / (gamma / 2.0 + std::sqrt(disc));
}

double massSpringOmegaMaxRadPerS(const TissueMesh& mesh, const MassSpringParams& p, VertexId touched) {
    return massSpringOmegaMaxRadPerS(mesh, p, touched, std::vector<std::uint8_t>(mesh.vertexCount(), 1));
}

double massSpringOmegaMaxRadPerS(const TissueMesh& mesh, const MassSpringParams& p, VertexId touched,
                                 const std::vector<std::uint8_t>& simulated) {
    // The stiffness is isotropic except the contact's k_c n n^T on the touched vertex, so the top
    // eigenvalue is that of the scalar n x n matrix k_a I + k_e L + k_c e_t e_t^T (L the graph
    // Laplacian). Power iteration; the Rayleigh quotient converges with the square of the vector.
    const std::size_t n = mesh.vertexCount();
    const auto& start = mesh.neighbourStart();
    const auto& nb = mesh.neighbours();
    std::vector<double> x(n), y(n);
    // Pinned vertices (simulated[i] == 0) stay at zero: the iteration runs on the simulated block,
    // whose rows keep every edge (a pinned neighbour's spring still pulls).
    for (std::size_t i = 0; i < n; ++i)
        x[i] = simulated[i] ? ((i * 2654435761u) % 1000) / 1000.0 - 0.5 + (i % 2 ? 0.3 : -0.3) : 0.0;
    double lambda = 0.0;
    for (int iteration = 0; iteration < 20000; ++iteration) {
        double norm = 0.0;
        for (std::size_t i = 0; i < n; ++i) norm += x[i] * x[i];
        norm = std::sqrt(norm);
        for (double& v : x) v /= norm;
        double rayleigh = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            if (!simulated[i]) {
                y[i] = 0.0;
                continue;
            }
            double s = p.anchorStiffnessNPerMm * x[i];
            for (std::uint32_t k = start[i]; k < start[i + 1]; ++k) s += p.edgeStiffnessNPerMm * (x[i] - x[nb[k]]);
            if (i == touched) s += p.contactStiffnessNPerMm * x[i];
            y[i] = s;
            rayleigh += s * x[i];
        }
        std::swap(x, y);
        if (iteration > 50 && std::abs(rayleigh - lambda) <= 1e-13 * rayleigh) {
            lambda = rayleigh;
            break;
        }
        lambda = rayleigh;
    }
    return std::sqrt(1000.0 * lambda / p.vertexMassKg);
}

double massSpringOmegaGershgorinRadPerS(const TissueMesh& mesh, const MassSpringParams& p) {
    const auto& start = mesh.neighbourStart();
    double row = 0.0;
    for (std::size_t i = 0; i + 1 < start.size(); ++i)
        row = std::max(row, p.anchorStiffnessNPerMm + 2.0 * p.edgeStiffnessNPerMm * double(start[i + 1] - start[i]) +
                                p.contactStiffnessNPerMm);
    return std::sqrt(1000.0 * row / p.vertexMassKg);
}

double passiveMaxStiffnessNPerMm(double b, double periodS, double virtualDamping) {
    const double slack = b - std::abs(virtualDamping);
    return slack > 0.0 && periodS > 0.0 ? 2.0 * slack / periodS : 0.0;
}

double sampledWallMaxStiffnessNPerMm(double m, double b, double T) {
    if (!(m > 0.0) || !(b > 0.0) || !(T > 0.0)) return 0.0;
    const double tau = m / b;
    const double oneMinusDelta = -std::expm1(-T / tau);  // 1 - delta without cancellation
    const double delta = 1.0 - oneMinusDelta;
    // tau (1 - delta) - delta T = T^2 / (2 tau) - T^3 / (3 tau^2) + ...: series when T / tau is small.
    const double e = T / tau;
    const double determinantDenominator =
        e < 1e-3 ? T * (e / 2.0 - e * e / 3.0 + e * e * e / 8.0) : tau * oneMinusDelta - delta * T;
    const double fromDeterminant = b * oneMinusDelta / determinantDenominator;
    const double massDenominator = T * (1.0 + delta) - 2.0 * tau * oneMinusDelta;
    const double fromMass = massDenominator > 0.0 ? 2.0 * b * (1.0 + delta) / massDenominator : kNoBound;
    return std::min(fromDeterminant, fromMass) / 1000.0;  // N/m -> N/mm
}

bool slopeRingDeviceLoopStable(double K, double lambda, double m, double b, double T) {
    // Exact discretisation of m x'' + b x' = -R over a period (R held): x' = x + a v - (R / b)(T - a),
    // v' = delta v - (1 - delta) R / b, a = tau (1 - delta); R_n = lambda R_{n-1} + c x_n, c = K (1 - lambda).
    const double tau = m / b;
    const double oneMinusDelta = -std::expm1(-T / tau), delta = 1.0 - oneMinusDelta;
    const double a = tau * oneMinusDelta;
    const double c = K * (1.0 - lambda);
    const double px = (T - a) / b, pv = oneMinusDelta / b;  // x and v per unit of held force
    const double A[3][3] = {{1.0 - px * c, a, -px * lambda}, {-pv * c, delta, -pv * lambda}, {c, 0.0, lambda}};
    const auto minor = [&](int i, int j) { return A[i][i] * A[j][j] - A[i][j] * A[j][i]; };
    const double trace = A[0][0] + A[1][1] + A[2][2];
    const double minors = minor(0, 1) + minor(0, 2) + minor(1, 2);
    const double det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
                       A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                       A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
    // z^3 + a2 z^2 + a1 z + a0; Jury: |a0| < 1, p(1) > 0, p(-1) < 0, |a0^2 - 1| > |a0 a2 - a1|.
    const double a2 = -trace, a1 = minors, a0 = -det;
    return std::abs(a0) < 1.0 && 1.0 + a2 + a1 + a0 > 0.0 && -1.0 + a2 - a1 + a0 < 0.0 &&
           std::abs(a0 * a0 - 1.0) > std::abs(a0 * a2 - a1);
}

double slopeRingDeviceLoopMaxStiffnessNPerMm(double lambda, double m, double b, double T) {
    if (!(m > 0.0) || !(b > 0.0) || !(T > 0.0) || !(std::abs(lambda) < 1.0)) return 0.0;
    // Stable for small K (the device's own damping), unstable for large: bisect in log K (N/m),
    // starting from a bracket around Colgate's 2 b / T.
    double lo = 1e-3 * 2.0 * b / T, hi = 1e4 * 2.0 * b / T;
    if (!slopeRingDeviceLoopStable(lo, lambda, m, b, T)) return 0.0;
    if (slopeRingDeviceLoopStable(hi, lambda, m, b, T)) return kNoBound;
    for (int i = 0; i < 80; ++i) {
        const double mid = std::sqrt(lo * hi);
        (slopeRingDeviceLoopStable(mid, lambda, m, b, T) ? lo : hi) = mid;
    }
    return lo / 1000.0;  // N/m -> N/mm
}

double inversionMaxTangentialForceN(double m1, double m2, double height) {
    const double relative = std::abs(std::abs(m1) - std::abs(m2));
    return relative > 0.0 ? height / relative : kNoBound;
}

double inversionMaxForceAlongNormalN(const TissueMesh& mesh, VertexId v, double m1, double m2) {
    const double relative = std::abs(m1) - std::abs(m2);
    if (!(relative > 0.0)) return kNoBound;
    const auto& start = mesh.neighbourStart();
    const auto& nb = mesh.neighbours();
    const auto& rest = mesh.restPositionsMm();
    const glm::dvec3 n(mesh.restNormals()[v]), t(rest[v]);
    double best = kNoBound;
    for (std::uint32_t i = start[v]; i < start[v + 1]; ++i)
        for (std::uint32_t k = i + 1; k < start[v + 1]; ++k) {
            const VertexId a = nb[i], b = nb[k];
            if (!std::binary_search(nb.begin() + start[a], nb.begin() + start[a + 1], b)) continue;
            const glm::dvec3 pa(rest[a]), pb(rest[b]);
            const glm::dvec3 normal = glm::cross(pa - t, pb - t);
            // v moves by delta n with delta = -relative F: the normal becomes N - delta n x (b - a).
            const double denominator = glm::dot(normal, glm::cross(n, pb - pa));
            if (denominator == 0.0) continue;
            const double delta = glm::dot(normal, normal) / denominator;
            const double force = -delta / relative;
            if (force > 0.0) best = std::min(best, force);
        }
    return best;
}

double minHeightOverOppositeEdgeMm(const TissueMesh& mesh, VertexId v) {
    const auto& rest = mesh.restPositionsMm();
    double best = kNoBound;
    for (const auto& t : mesh.triangles()) {
        int k = t[0] == v ? 0 : t[1] == v ? 1 : t[2] == v ? 2 : -1;
        if (k < 0) continue;
        const glm::dvec3 p(rest[v]), a(rest[t[(k + 1) % 3]]), b(rest[t[(k + 2) % 3]]);
        const glm::dvec3 edge = b - a;
        const double len = glm::length(edge);
        if (len <= 0.0) continue;
        best = std::min(best, glm::length(glm::cross(p - a, edge)) / len);
    }
    return best;
}

}  // namespace palpate
