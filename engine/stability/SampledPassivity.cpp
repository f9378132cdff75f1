#include "engine/stability/SampledPassivity.h"

#include "engine/stability/StabilityBounds.h"

#include <cmath>
#include <numbers>

namespace palpate {

namespace {

/// (2 / T) b_req(theta): T / (2 (1 - cos theta)) Re{(1 - e^{-j theta}) H} with 1 - e^{-j theta} =
/// 2 sin^2(theta / 2) + j sin theta, so the ratio is Re H - cot(theta / 2) Im H, free of the
/// cancellation in 1 - cos theta at small theta.
double requiredStiffness(const RenderedTransfer& transfer, double theta) {
    const std::complex<double> h = transfer(theta);
    return h.real() - h.imag() / std::tan(0.5 * theta);
}

}  // namespace

PassivitySweep sweepPassivity(const RenderedTransfer& transfer) {
    constexpr double kPi = std::numbers::pi;
    constexpr int kEven = 2048, kEnds = 48;
    PassivitySweep best;
    best.passiveEquivalentNPerMm = -kNoBound;
    const auto consider = [&](double theta) {
        const double k = requiredStiffness(transfer, theta);
        if (!(k <= best.passiveEquivalentNPerMm)) {  // also takes NaN, which then stays
            best.passiveEquivalentNPerMm = k;
            best.worstThetaRad = theta;
        }
    };
    for (int i = 1; i <= kEven; ++i) consider(kPi * double(i) / kEven);
    for (int i = 0; i < kEnds; ++i) {
        const double offset = std::pow(10.0, -7.0 + 6.0 * double(i) / (kEnds - 1));  // 1e-7 .. 0.1
        consider(offset);
        consider(kPi - offset);
    }
    return best;
}

double requiredDeviceDampingNsPerMm(const RenderedTransfer& transfer, double periodS) {
    return 0.5 * periodS * sweepPassivity(transfer).passiveEquivalentNPerMm;
}

double devicePassiveStiffnessNPerMm(double passiveAt1kHzNPerMm, double periodS) {
    return passiveMaxStiffnessNPerMm(0.5 * passiveAt1kHzNPerMm * 1e-3, periodS);
}

}  // namespace palpate
