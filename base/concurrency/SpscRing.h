#pragma once
// A bounded single-producer single-consumer ring of trivially copyable items, sized at run time
// (engine/SpscQueue is sized at compile time). The haptic thread pushes, the recorder's writer
// thread pops; neither waits. Storage is allocated once, at construction.

#include <atomic>
#include <cstddef>
#include <memory>
#include <type_traits>

namespace palpate {

template <typename T>
class SpscRing {
    static_assert(std::is_trivially_copyable_v<T>, "ring items are copied bytewise");

public:
    /// Capacity rounded up to a power of two (at least 2).
    explicit SpscRing(std::size_t capacity) {
        std::size_t c = 2;
        while (c < capacity) c <<= 1;
        mMask = c - 1;
        mItems = std::make_unique<T[]>(c);
    }

    std::size_t capacity() const { return mMask + 1; }

    /// Producer only. False when full (nothing is queued). Wait-free.
    bool push(const T& item) {
        const std::size_t head = mHead.load(std::memory_order_relaxed);
        if (head - mTail.load(std::memory_order_acquire) > mMask) return false;
        mItems[head & mMask] = item;
        mHead.store(head + 1, std::memory_order_release);
        return true;
    }

    /// Consumer only. False when empty.
    bool pop(T& item) {
        const std::size_t tail = mTail.load(std::memory_order_relaxed);
        if (tail == mHead.load(std::memory_order_acquire)) return false;
        item = mItems[tail & mMask];
        mTail.store(tail + 1, std::memory_order_release);
        return true;
    }

    /// Items queued (exact for the consumer, a lower bound for the producer).
    std::size_t size() const {
        return mHead.load(std::memory_order_acquire) - mTail.load(std::memory_order_acquire);
    }

private:
    std::unique_ptr<T[]> mItems;
    std::size_t mMask = 1;
    alignas(64) std::atomic<std::size_t> mHead{0};
    alignas(64) std::atomic<std::size_t> mTail{0};
};

}  // namespace palpate
