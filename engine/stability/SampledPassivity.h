#pragma once
// The sampled-data passivity condition of Colgate and Schenkel (docs/stability.md, "Rendered
// stiffness and passivity"): a virtual environment with transfer H(z) from the sampled tool
// position (mm) to the force it holds over the next period T (N), on a device with physical
// damping b, is passive iff for every 0 < omega <= pi / T
//
//     b > T / (2 (1 - cos omega T)) Re{(1 - e^{-j omega T}) H(e^{j omega T})}
//       = (T / 2) (Re H - cot(omega T / 2) Im H).
//
// For H = K + B (1 - z^-1) / T that is Colgate and Brown's b > K T / 2 + |B|. The required damping
// as a stiffness, K_eq = 2 b_req / T, is the passive-equivalent stiffness: a pure spring K has
// K_eq = K. Qt-free, not real-time.

#include <complex>
#include <functional>

namespace palpate {

/// H(e^{j theta}) in N/mm at the normalised frequency theta = omega T in (0, pi].
using RenderedTransfer = std::function<std::complex<double>(double thetaRad)>;

/// The sweep's result: the largest (2 / T) b_req(theta) and where it is.
struct PassivitySweep {
    double passiveEquivalentNPerMm = 0.0;  ///< K_eq = sup (Re H - cot(theta / 2) Im H), N/mm
    double worstThetaRad = 0.0;            ///< theta of the supremum (small: low frequency; pi: Nyquist)
};

/// The supremum over a sweep of theta in (0, pi]: 2048 even steps, and 48 log-spaced points towards
/// each end (down to 1e-7 from 0 and from pi), where the supremum of a lag (theta -> 0) or of an
/// alternation (theta = pi) lies.
PassivitySweep sweepPassivity(const RenderedTransfer& transfer);

/// The device damping (N s/mm) that makes the environment passive at period T: K_eq T / 2.
double requiredDeviceDampingNsPerMm(const RenderedTransfer& transfer, double periodS);

/// The largest stiffness a device renders passively at period T, N/mm, for a device passive up to
/// `passiveAt1kHzNPerMm` at 1 kHz (DeviceSpec::maxStiffnessNPerMm read as such): its damping is
/// b = K_1kHz x 1 ms / 2 (Colgate and Brown), so 2 b / T = K_1kHz (1 ms / T).
double devicePassiveStiffnessNPerMm(double passiveAt1kHzNPerMm, double periodS);

}  // namespace palpate
