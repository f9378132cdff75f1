#pragma once
// Counts heap allocations (per thread and per process), to prove that real-time paths (the safety
// filter, device reads and writes) do not allocate. The test binary replaces global operator new.

#include <cstdint>

namespace palpate::test {

/// Allocations by this thread since the program started.
std::uint64_t threadAllocationCount();
/// Allocations by every thread since the program started (for a thread the test cannot enter,
/// such as the haptic loop's: count while the test thread itself does nothing).
std::uint64_t processAllocationCount();

/// Allocations by this thread since construction.
class AllocationCounter {
public:
    AllocationCounter() : mStart(threadAllocationCount()) {}
    std::uint64_t count() const { return threadAllocationCount() - mStart; }

private:
    std::uint64_t mStart;
};

}  // namespace palpate::test
