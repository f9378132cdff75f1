#pragma once
// A wait-free triple buffer: one writer publishes whole values, one reader takes the newest.
// Neither ever waits for the other and the reader never sees a half-written value: the writer
// fills a buffer the reader cannot hold, then swaps it with the shared middle slot.

#include <atomic>
#include <cstdint>
#include <memory>

namespace palpate {

template <typename T>
class TripleBuffer {
public:
    TripleBuffer() : mBuffers(std::make_unique<T[]>(3)) {}

    /// Writer only: the buffer to fill. Stays the writer's until publish().
    T& back() { return mBuffers[mBack]; }

    /// Writer only: makes back() the newest value and hands the writer another buffer.
    void publish() {
        const std::uint8_t previous = mMiddle.exchange(std::uint8_t(mBack | kFresh), std::memory_order_acq_rel);
        mBack = previous & kIndexMask;
    }

    /// Reader only: the newest published value (or the last one read if nothing new). The
    /// reference stays valid and unchanged until the reader's next call.
    const T& newest() {
        if (mMiddle.load(std::memory_order_relaxed) & kFresh) {
            const std::uint8_t previous = mMiddle.exchange(mFront, std::memory_order_acq_rel);
            mFront = previous & kIndexMask;
        }
        return mBuffers[mFront];
    }

private:
    static constexpr std::uint8_t kFresh = 4;
    static constexpr std::uint8_t kIndexMask = 3;
    std::unique_ptr<T[]> mBuffers;
    std::uint8_t mBack = 0;                  // writer's
    std::atomic<std::uint8_t> mMiddle{1};    // shared
    std::uint8_t mFront = 2;                 // reader's
};

}  // namespace palpate
