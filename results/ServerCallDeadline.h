#pragma once
// A deadline on every call to the class's server (docs/results-store.md, "Timeouts"). libpq waits on
// its socket without a limit once connected, so a server that took the connection and then stalls
// (a stopped process, a machine asleep behind a live switch) would hang the caller, and the
// window's exit with it. A watchdog thread shuts the socket down when a call outlives its deadline:
// libpq then fails the call at once ("server closed the connection"), the connection is spent, and
// the caller reports that the server did not answer in time. Qt-free.

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace palpate {

class ServerCallDeadline {
public:
    explicit ServerCallDeadline(std::chrono::milliseconds limit);
    ~ServerCallDeadline();
    ServerCallDeadline(const ServerCallDeadline&) = delete;
    ServerCallDeadline& operator=(const ServerCallDeadline&) = delete;

    /// One call: from construction to destruction the socket must answer within the limit. Calls
    /// may nest (a call made inside another); only the outermost sets the deadline.
    class Call {
    public:
        Call(ServerCallDeadline* deadline, int socketFd);
        ~Call();
        Call(const Call&) = delete;
        Call& operator=(const Call&) = delete;

    private:
        ServerCallDeadline* mDeadline;
        bool mOutermost = false;
    };

    /// Whether the last call ran out of time (its socket was shut down). Cleared by the next call.
    bool expired() const;
    std::chrono::milliseconds limit() const { return mLimit; }

private:
    void watch();

    const std::chrono::milliseconds mLimit;
    mutable std::mutex mMutex;
    std::condition_variable mWake;
    int mDepth = 0;
    int mSocket = -1;  ///< the socket of the call in flight; -1 when none
    std::chrono::steady_clock::time_point mDue;
    bool mExpired = false;
    bool mStopping = false;
    std::thread mWatcher;
};

}  // namespace palpate
