#include "engine/bench/FeelMetrics.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace palpate {

namespace {

/// The normal and tangential parts of a tick's force (a tick without a normal: all normal).
void split(const FeelTick& t, double& normalN, glm::dvec3& tangentialN) {
    const glm::dvec3 f(t.forceN), n(t.normal);
    const double nLength = glm::length(n);
    if (nLength < 0.5) {
        normalN = glm::length(f);
        tangentialN = glm::dvec3(0.0);
        return;
    }
    const glm::dvec3 unit = n / nLength;
    normalN = glm::dot(f, unit);
    tangentialN = f - normalN * unit;
}

}  // namespace

FeelMetrics feelMetrics(std::span<const FeelTick> ticks) {
    FeelMetrics m;
    m.ticks = ticks.size();
    if (ticks.empty()) {
        m.maxStepPct = m.maxNormalStepPct = m.ripplePct = std::numeric_limits<double>::quiet_NaN();
        return m;
    }
    double sumF = 0.0, sumN = 0.0, sumT = 0.0, maxStep = 0.0, maxNormalStep = 0.0;
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0, previousNormal = 0.0;
    for (std::size_t i = 0; i < ticks.size(); ++i) {
        const double magnitude = glm::length(glm::dvec3(ticks[i].forceN));
        double normalN = 0.0;
        glm::dvec3 tangential;
        split(ticks[i], normalN, tangential);
        sumF += magnitude;
        sumN += normalN;
        sumT += glm::length(tangential);
        lo = std::min(lo, magnitude);
        hi = std::max(hi, magnitude);
        if (i > 0) {
            maxStep = std::max(maxStep,
                               double(glm::length(glm::dvec3(ticks[i].forceN) - glm::dvec3(ticks[i - 1].forceN))));
            maxNormalStep = std::max(maxNormalStep, std::abs(normalN - previousNormal));
        }
        previousNormal = normalN;
    }
    const double count = double(ticks.size());
    m.meanForceN = sumF / count;
    m.meanNormalN = sumN / count;
    m.meanTangentialN = sumT / count;
    m.frictionRatio = m.meanNormalN > 0.0 ? m.meanTangentialN / m.meanNormalN : 0.0;
    if (m.meanForceN > 0.0) {
        m.maxStepPct = 100.0 * maxStep / m.meanForceN;
        m.maxNormalStepPct = 100.0 * maxNormalStep / m.meanForceN;
        m.ripplePct = 100.0 * (hi - lo) / m.meanForceN;
    } else {
        m.maxStepPct = m.maxNormalStepPct = m.ripplePct = std::numeric_limits<double>::quiet_NaN();
    }
    return m;
}

std::size_t countDropouts(std::span<const FeltTick> ticks, std::size_t begin, std::size_t end, int halfWidth,
                          double fraction) {
    std::size_t dropouts = 0;
    end = std::min(end, ticks.size());
    for (std::size_t i = begin; i < end; ++i) {
        if (!ticks[i].contact) continue;
        double sum = 0.0;
        int count = 0;
        for (int k = -halfWidth; k <= halfWidth; ++k) {
            if (k == 0) continue;
            const long long j = (long long)(i) + k;
            if (j < 0 || j >= (long long)(ticks.size())) continue;
            sum += ticks[std::size_t(j)].forceN;
            ++count;
        }
        if (count > 0 && ticks[i].forceN < fraction * (sum / count)) ++dropouts;
    }
    return dropouts;
}

}  // namespace palpate
