#pragma once
// A sequence lock over a small trivially copyable value: readers never block writers and never
// see a half-written value; nobody takes a mutex. Used where one thread (the GUI, the haptic loop)
// publishes a value that another thread polls.
//
// The value is kept in std::atomic words accessed with release/acquire ordering rather than
// plain memory plus fences (Boehm, "Can seqlocks get along with programming language memory
// models?", 2012): it has no data race in the C++ model, needs no std::atomic_thread_fence (which
// ThreadSanitizer does not model) and costs plain moves on x86-64.

#include <array>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace palpate {

template <typename T>
class SeqLock {
    static_assert(std::is_trivially_copyable_v<T>, "SeqLock holds trivially copyable values only");

public:
    SeqLock() : SeqLock(T{}) {}
    explicit SeqLock(const T& initial) {
        std::array<std::uint64_t, kWordCount> words{};
        std::memcpy(words.data(), &initial, sizeof(T));
        for (std::size_t i = 0; i < kWordCount; ++i) mWords[i].store(words[i], std::memory_order_relaxed);
    }
    SeqLock(const SeqLock&) = delete;
    SeqLock& operator=(const SeqLock&) = delete;

    /// Publishes a value. Wait-free with one writer; concurrent writers take turns on the
    /// sequence word (a writer only ever waits for another writer, never for a reader).
    void store(const T& value) {
        std::array<std::uint64_t, kWordCount> words{};
        std::memcpy(words.data(), &value, sizeof(T));

        // Claim the sequence: even -> odd. Acquire so that we follow the previous writer's words.
        std::uint64_t seq = mSequence.load(std::memory_order_relaxed);
        for (;;) {
            if ((seq & 1u) == 0u &&
                mSequence.compare_exchange_weak(seq, seq + 1u, std::memory_order_acquire,
                                                std::memory_order_relaxed))
                break;
            seq = mSequence.load(std::memory_order_relaxed);
        }
        // Release stores: a reader that sees any new word also sees the odd sequence above.
        for (std::size_t i = 0; i < kWordCount; ++i) mWords[i].store(words[i], std::memory_order_release);
        mSequence.store(seq + 2u, std::memory_order_release);
    }

    /// The latest complete value, trying at most `maxAttempts` times. Returns false (and leaves
    /// `out` alone) when every attempt met a write in progress. Real-time readers use this: a
    /// writer preempted mid-write (the GUI thread, on a busy core) must not stall the haptic tick.
    bool tryLoad(T& out, int maxAttempts = 64) const {
        std::array<std::uint64_t, kWordCount> words{};
        for (int attempt = 0; attempt < maxAttempts; ++attempt) {
            const std::uint64_t before = mSequence.load(std::memory_order_acquire);
            if ((before & 1u) != 0u) continue;  // a writer is mid-way
            for (std::size_t i = 0; i < kWordCount; ++i) words[i] = mWords[i].load(std::memory_order_acquire);
            const std::uint64_t after = mSequence.load(std::memory_order_relaxed);
            if (before == after) {
                // void*: T is trivially copyable (asserted above) even when its default member
                // initialisers make it non-trivial, which -Wclass-memaccess would flag.
                std::memcpy(static_cast<void*>(&out), words.data(), sizeof(T));
                return true;
            }
        }
        return false;
    }

    /// The latest complete value; retries until no write is in progress. For non-real-time
    /// readers (GUI, tests), where waiting out a preempted writer is harmless.
    T load() const {
        T value{};
        while (!tryLoad(value)) {
        }
        return value;
    }

    /// How many stores have completed; lets a reader tell whether anything changed.
    std::uint64_t version() const { return mSequence.load(std::memory_order_acquire) / 2u; }

private:
    static constexpr std::size_t kWordCount = (sizeof(T) + sizeof(std::uint64_t) - 1) / sizeof(std::uint64_t);

    std::atomic<std::uint64_t> mSequence{0};
    std::array<std::atomic<std::uint64_t>, kWordCount> mWords{};
};

}  // namespace palpate
