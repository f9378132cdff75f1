#pragma once
// The I/O thread of a hardware device (docs/architecture.md: one per USB device, so that the haptic tick
// never waits on USB). A std::thread with a stop request and a sleep that a stop cuts short, so
// that close() returns promptly even while the thread waits to retry a lost device.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace palpate {

class IoThread {
public:
    IoThread() = default;
    IoThread(const IoThread&) = delete;
    IoThread& operator=(const IoThread&) = delete;
    ~IoThread() { stop(); }

    /// Starts `body`, which should return when stopRequested() becomes true.
    void start(std::function<void()> body) {
        stop();
        mStop.store(false, std::memory_order_release);
        mThread = std::thread(std::move(body));
    }
    /// Requests a stop, wakes a sleeping body and joins it. Idempotent.
    void stop() {
        {
            std::lock_guard lock(mMutex);
            mStop.store(true, std::memory_order_release);
        }
        mWake.notify_all();
        if (mThread.joinable() && mThread.get_id() != std::this_thread::get_id()) mThread.join();
    }
    bool running() const { return mThread.joinable() && !stopRequested(); }
    bool stopRequested() const { return mStop.load(std::memory_order_acquire); }
    /// Sleeps for `duration`, until stop() or until wake(); returns false when stopped.
    template <class Rep, class Period>
    bool sleepFor(std::chrono::duration<Rep, Period> duration) {
        std::unique_lock lock(mMutex);
        mWake.wait_for(lock, duration, [this] { return stopRequested() || mWoken; });
        mWoken = false;
        return !stopRequested();
    }
    /// Cuts a sleepFor short (e.g. a hotplug arrival: try to reconnect now).
    void wake() {
        {
            std::lock_guard lock(mMutex);
            mWoken = true;
        }
        mWake.notify_all();
    }

private:
    std::thread mThread;
    std::atomic<bool> mStop{true};
    std::mutex mMutex;
    std::condition_variable mWake;
    bool mWoken = false;
};

}  // namespace palpate
