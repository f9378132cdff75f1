#include "engine/loop/LatencyHistogram.h"

#include <algorithm>

namespace palpate {

LatencyHistogram::LatencyHistogram(double binUs, std::size_t binCount)
    : mBinUs(binUs), mBins(std::max<std::size_t>(binCount, 1), 0) {}

void LatencyHistogram::clear() {
    std::fill(mBins.begin(), mBins.end(), 0);
    mCount = 0;
    mSumUs = 0.0;
    mMaxUs = 0.0;
}

LatencySummary LatencyHistogram::summary() const {
    LatencySummary s;
    s.count = mCount;
    if (mCount == 0) return s;
    s.maxUs = mMaxUs;
    s.meanUs = mSumUs / double(mCount);
    auto percentile = [&](double fraction) {
        const auto rank = std::uint64_t(fraction * double(mCount - 1)) + 1;  // 1-based
        std::uint64_t seen = 0;
        for (std::size_t b = 0; b < mBins.size(); ++b) {
            seen += mBins[b];
            if (seen >= rank) return std::min(mMaxUs, double(b + 1) * mBinUs);
        }
        return mMaxUs;
    };
    s.p50Us = percentile(0.50);
    s.p99Us = percentile(0.99);
    s.p999Us = percentile(0.999);
    return s;
}

}  // namespace palpate
