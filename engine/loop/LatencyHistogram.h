#pragma once
// A fixed-bin histogram of durations in microseconds: recording is O(1) and allocation-free (the
// haptic tick records into it); percentiles are read once the loop has stopped or by the thread
// that records.

#include <cstdint>
#include <vector>

namespace palpate {

struct LatencySummary {
    std::uint64_t count = 0;
    double p50Us = 0.0, p99Us = 0.0, p999Us = 0.0, maxUs = 0.0, meanUs = 0.0;
};

class LatencyHistogram {
public:
    /// `binUs` wide bins from 0 to binUs * binCount; larger values land in the last bin (the
    /// maximum is tracked exactly).
    LatencyHistogram(double binUs, std::size_t binCount);

    void record(double us) {
        if (!(us >= 0.0)) us = 0.0;
        std::size_t bin = std::size_t(us / mBinUs);
        if (bin >= mBins.size()) bin = mBins.size() - 1;
        ++mBins[bin];
        ++mCount;
        mSumUs += us;
        if (us > mMaxUs) mMaxUs = us;
    }
    /// Reads the bin a value would land in (see HapticLoop::warmUp).
    std::uint64_t peek(double us) const {
        std::size_t bin = us >= 0.0 ? std::size_t(us / mBinUs) : 0;
        return mBins[bin < mBins.size() ? bin : mBins.size() - 1] + mCount;
    }
    void clear();
    /// Percentiles from bin upper edges (conservative), capped at the exact maximum.
    LatencySummary summary() const;

private:
    double mBinUs;
    std::vector<std::uint64_t> mBins;
    std::uint64_t mCount = 0;
    double mSumUs = 0.0;
    double mMaxUs = 0.0;
};

}  // namespace palpate
