#include "engine/models/slopering/SlopeRingParams.h"

#include <cmath>
#include <sstream>

namespace palpate {

namespace {
std::string number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}
std::string slopeName(int r) { return "m" + std::to_string(r + 1); }
}  // namespace

std::vector<std::string> validateSlopeRingParams(const SlopeRingParams& p) {
    std::vector<std::string> errors;
    auto finitePositive = [&](double v, const char* name, const char* unit) {
        if (!std::isfinite(v) || v <= 0.0) {
            errors.push_back(std::string(name) + " = " + number(v) + " " + unit + " must be a positive finite number");
            return false;
        }
        return true;
    };
    if (p.ringCount < 0 || p.ringCount > kMaxRings)
        errors.push_back("ringCount = " + std::to_string(p.ringCount) + " must be in 0.." + std::to_string(kMaxRings));
    const bool limitOk = finitePositive(p.slopeLimitMmPerN, "slopeLimit", "mm/N");
    if (limitOk && p.slopeLimitMmPerN > 100.0)
        errors.push_back("slopeLimit = " + number(p.slopeLimitMmPerN) + " mm/N is above the hard maximum 100 mm/N");
    const int used = std::min(std::max(p.ringCount, 0), kMaxRings) + 1;
    for (int r = 0; r < used; ++r) {
        const double m = p.slopeMagnitudeMmPerN[std::size_t(r)];
        const std::string name = "|" + slopeName(r) + "|";
        if (!std::isfinite(m) || m <= 0.0) {
            errors.push_back(name + " = " + number(m) + " mm/N must be greater than 0 (the paper excludes 0)");
            continue;
        }
        if (limitOk && m >= p.slopeLimitMmPerN)
            errors.push_back(name + " = " + number(m) + " mm/N must be below the slope limit " +
                             number(p.slopeLimitMmPerN) + " mm/N" +
                             (p.slopeLimitMmPerN == 1.0 ? " (the paper's range is (0, 1))" : ""));
        if (r > 0) {
            const double outer = p.slopeMagnitudeMmPerN[std::size_t(r - 1)];
            if (std::isfinite(outer) && !(m < outer))
                errors.push_back("slopes must decrease outward: |" + slopeName(r - 1) + "| = " + number(outer) +
                                 " mm/N is not greater than " + name + " = " + number(m) + " mm/N");
        }
    }
    finitePositive(p.contactStiffnessNPerMm, "contactStiffness", "N/mm");
    finitePositive(p.springStiffnessNPerMm, "springStiffness", "N/mm");
    finitePositive(p.vertexMassKg, "vertexMass", "kg");
    if (!std::isfinite(p.dampingRatio) || p.dampingRatio < 0.0 || p.dampingRatio > 100.0)
        errors.push_back("dampingRatio = " + number(p.dampingRatio) + " must be in 0..100");
    if (!std::isfinite(p.forceRelaxation) || p.forceRelaxation < 0.0 || p.forceRelaxation > 1.0)
        errors.push_back("forceRelaxation = " + number(p.forceRelaxation) + " must be in (0, 1], or 0 for automatic");
    if (errors.empty()) {
        const double alpha = p.effectiveRelaxation();
        const double gain = p.loopGain();
        if (alpha * (1.0 + gain) >= 2.0)
            errors.push_back("unstable: loop gain |m1| * contactStiffness = " + number(gain) +
                             " with forceRelaxation " + number(alpha) + " gives alpha * (1 + gain) = " +
                             number(alpha * (1.0 + gain)) + ", which must stay below 2");
    }
    return errors;
}

}  // namespace palpate
