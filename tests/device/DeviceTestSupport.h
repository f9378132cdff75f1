#pragma once
// Helpers for tests of devices with an I/O thread: wait for something the thread will do. The
// deadline is only a guard against a hang (a failed test, not a timing assertion).

#include <chrono>
#include <functional>
#include <thread>

namespace palpate::test {

inline bool waitUntil(const std::function<bool()>& condition, std::chrono::seconds guard = std::chrono::seconds(20)) {
    const auto deadline = std::chrono::steady_clock::now() + guard;
    while (!condition()) {
        if (std::chrono::steady_clock::now() > deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return true;
}

}  // namespace palpate::test
