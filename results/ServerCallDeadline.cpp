#include "results/ServerCallDeadline.h"

#include <sys/socket.h>

namespace palpate {

ServerCallDeadline::ServerCallDeadline(std::chrono::milliseconds limit)
    : mLimit(limit), mWatcher([this] { watch(); }) {}

ServerCallDeadline::~ServerCallDeadline() {
    {
        std::lock_guard lock(mMutex);
        mStopping = true;
    }
    mWake.notify_all();
    mWatcher.join();
}

bool ServerCallDeadline::expired() const {
    std::lock_guard lock(mMutex);
    return mExpired;
}

ServerCallDeadline::Call::Call(ServerCallDeadline* deadline, int socketFd) : mDeadline(deadline) {
    if (!mDeadline) return;
    {
        std::lock_guard lock(mDeadline->mMutex);
        mOutermost = mDeadline->mDepth++ == 0;
        if (!mOutermost) return;
        mDeadline->mSocket = socketFd;
        mDeadline->mDue = std::chrono::steady_clock::now() + mDeadline->mLimit;
        mDeadline->mExpired = false;
    }
    mDeadline->mWake.notify_all();
}

ServerCallDeadline::Call::~Call() {
    if (!mDeadline) return;
    std::lock_guard lock(mDeadline->mMutex);
    --mDeadline->mDepth;
    // Under the lock: once the call is over, the watchdog can no longer shut its socket.
    if (mOutermost) mDeadline->mSocket = -1;
}

void ServerCallDeadline::watch() {
    std::unique_lock lock(mMutex);
    while (!mStopping) {
        if (mSocket < 0) {
            mWake.wait(lock);
            continue;
        }
        const int socket = mSocket;
        if (mWake.wait_until(lock, mDue) == std::cv_status::timeout && mSocket == socket &&
            std::chrono::steady_clock::now() >= mDue) {
            // Both directions: libpq's poll() wakes and its read sees the end of the stream.
            ::shutdown(socket, SHUT_RDWR);
            mExpired = true;
            mSocket = -1;
        }
    }
}

}  // namespace palpate
