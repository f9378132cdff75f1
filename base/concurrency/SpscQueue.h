#pragma once
// A bounded single-producer single-consumer queue of trivially copyable items. Lock-free: one
// thread pushes (the GUI or a controller), one thread pops (the haptic thread), neither waits.

#include <array>
#include <atomic>
#include <cstddef>
#include <type_traits>

namespace palpate {

template <typename T, std::size_t Capacity>
class SpscQueue {
    static_assert(std::is_trivially_copyable_v<T>, "queued items are copied bytewise");
    static_assert(Capacity >= 2 && (Capacity & (Capacity - 1)) == 0, "capacity must be a power of two");

public:
    /// Producer only. False when full (nothing is queued).
    bool push(const T& item) {
        const std::size_t head = mHead.load(std::memory_order_relaxed);
        if (head - mTail.load(std::memory_order_acquire) == Capacity) return false;
        mItems[head & (Capacity - 1)] = item;
        mHead.store(head + 1, std::memory_order_release);
        return true;
    }

    /// Consumer only. False when empty.
    bool pop(T& item) {
        const std::size_t tail = mTail.load(std::memory_order_relaxed);
        if (tail == mHead.load(std::memory_order_acquire)) return false;
        item = mItems[tail & (Capacity - 1)];
        mTail.store(tail + 1, std::memory_order_release);
        return true;
    }

    bool empty() const { return mTail.load(std::memory_order_acquire) == mHead.load(std::memory_order_acquire); }

private:
    std::array<T, Capacity> mItems{};
    alignas(64) std::atomic<std::size_t> mHead{0};
    alignas(64) std::atomic<std::size_t> mTail{0};
};

}  // namespace palpate
